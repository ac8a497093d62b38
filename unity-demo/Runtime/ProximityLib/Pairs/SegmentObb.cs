// Copied from src/ProximityLib/Pairs/SegmentObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and an OBB (3D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Obb3 b, out bool inRange) => Kernels.SegmentObb(a.Start, a.End, b, out inRange);
        /// <summary>Closest distance between a segment and an OBB (2D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Obb2 b, out bool inRange) => Kernels.SegmentBox2(a.Start, a.End, b.ToBox2(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in Obb3 b, out bool inRange) => Kernels.SegmentObbDistance(a.Start, a.End, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment2 a, in Obb2 b, out bool inRange) => Kernels.SegmentBoxDistance2(a.Start, a.End, b.ToBox2(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Obb3 b, out bool inRange) => Kernels.SegmentBoxOverlaps(a.Start, a.End, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Obb2 b, out bool inRange) => Kernels.SegmentBoxOverlaps2(a.Start, a.End, b.ToBox2(), out inRange);
    }
}
