// Copied from src/ProximityLib/Batch/Workers.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;

namespace ProximityLib.Batch
{
    internal static class Workers
    {
        public static bool Values<TK>(TK kernel, int count, Span<float> result) where TK : struct, IKernel => false;
        public static bool NonPositive<TK>(TK kernel, int count, Span<bool> result) where TK : struct, IKernel => false;
    }
}
