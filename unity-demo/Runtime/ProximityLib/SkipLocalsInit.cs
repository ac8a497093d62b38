// Copied from src/ProximityLib/SkipLocalsInit.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
// The library's locals are not zeroed on entry to its methods: C#'s definite assignment already guarantees that every
// local is written before it is read (the few stackalloc buffers are filled before use), and the zeroing cost without
// dynamic PGO, where the JIT clears a method's struct locals (Box forms of 152 bytes, 80-byte results) in its prolog.
[module: System.Runtime.CompilerServices.SkipLocalsInit]

#if !NET
namespace System.Runtime.CompilerServices
{
    /// <summary>The compiler's SkipLocalsInit, which netstandard2.1 lacks; the compiler recognises it by name.</summary>
    [AttributeUsage(AttributeTargets.Module | AttributeTargets.Class | AttributeTargets.Struct | AttributeTargets.Interface
        | AttributeTargets.Constructor | AttributeTargets.Method | AttributeTargets.Property | AttributeTargets.Event, Inherited = false)]
    internal sealed class SkipLocalsInitAttribute : Attribute
    {
    }
}
#endif
