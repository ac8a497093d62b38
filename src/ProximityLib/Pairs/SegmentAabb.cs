using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and an AABB (3D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Aabb3 b, out bool inRange) => Kernels.SegmentAabb(a.Start, a.End, b.Min, b.Max, false, out inRange);
        /// <summary>Closest distance between a segment and an AABB (2D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Aabb2 b, out bool inRange) => Kernels.SegmentAabb2(a.Start, a.End, b.Min, b.Max, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in Aabb3 b, out bool inRange) => Kernels.SegmentAabbDistance(a.Start, a.End, b.Min, b.Max, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment2 a, in Aabb2 b, out bool inRange) => Kernels.SegmentAabbDistance2(a.Start, a.End, b.Min, b.Max, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Aabb3 b, out bool inRange) => Kernels.SegmentAabbOverlaps(a.Start, a.End, b.Min, b.Max, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Aabb2 b, out bool inRange) => Kernels.SegmentAabbOverlaps2(a.Start, a.End, b.Min, b.Max, out inRange);
    }
}
