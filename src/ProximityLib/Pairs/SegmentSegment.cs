using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D): never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order. Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Segment3 b, out bool inRange) => Kernels.SegmentSegment(a.Start, a.End, b.Start, b.End, out inRange);
        /// <summary>Closest distance between a segment and a segment (2D): never negative; for parallel overlapping segments one of the closest pairs (the first minimum among the endpoint pairs, docs/api.md), the same in either argument order. Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Segment2 b, out bool inRange) => Kernels.SegmentSegment2(a.Start, a.End, b.Start, b.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in Segment3 b, out bool inRange)
        {
            double d = Kernels.SegmentSegmentDistance(a.Start, a.End, b.Start, b.End);
            inRange = !double.IsNaN(d);
            return d;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment2 a, in Segment2 b, out bool inRange)
        {
            double d = Kernels.SegmentSegment2Distance(a.Start, a.End, b.Start, b.End);
            inRange = !double.IsNaN(d);
            return d;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Segment3 b, out bool inRange) => Kernels.SegmentSegmentInline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange) == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Segment2 b, out bool inRange) => Kernels.SegmentSegment2Inline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange) == 0;
    }
}
