// Copied from src/ProximityLib/Pairs/SegmentSegment.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D): never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order. Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Segment3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a segment and a segment (2D): never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order. Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Segment2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Segment3 a, Segment3 b, out bool inRange) => Kernels.SegmentSegment(a.Start, a.End, b.Start, b.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Segment2 a, Segment2 b, out bool inRange) => Kernels.SegmentSegment(a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Segment3 a, Segment3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Segment2 a, Segment2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Segment3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a segment and a segment (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Segment2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment3 a, Segment3 b, out bool inRange) => Kernels.SegmentSegmentCore(a.Start, a.End, b.Start, b.End, out _, out _, out inRange) == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment2 a, Segment2 b, out bool inRange) => Kernels.SegmentSegmentCore(a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3(), out _, out _, out inRange) == 0;
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment3 a, Segment3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment2 a, Segment2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Segment3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between a segment and a segment (2D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Segment2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Segment3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether a segment and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Segment2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
    }
}
