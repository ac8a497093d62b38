// Copied from src/ProximityLib/Spans.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace ProximityLib
{
    /// <summary>
    /// Reads read-only spans without their indexer. <c>ReadOnlySpan&lt;T&gt;</c>'s indexer (and <c>foreach</c> over
    /// one) returns <c>ref readonly T</c>, which Mono's class libraries (Unity's editor and Mono backend) declare
    /// without the modifier compilers emit: compiling against them gives CS0570, and a netstandard2.1 build run on
    /// Mono throws MissingMethodException. Slice and MemoryMarshal.GetReference return plain references, so they
    /// bind on every runtime (tests/ProximityLib.MonoCheck proves it in CI).
    /// </summary>
    internal static class Spans
    {
        /// <summary>Element <paramref name="i"/>, range-checked like the indexer.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static T At<T>(ReadOnlySpan<T> span, int i) => MemoryMarshal.GetReference(span.Slice(i, 1));
    }
}
