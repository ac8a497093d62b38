// Copied from src/ProximityLib/Pairs/SegmentTriangle.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a triangle (3D): never negative (neither is solid); crossing, 0 with the crossing point as both witnesses; where the minimum is not unique (a segment parallel to the triangle over it, or lying in its plane across it), the first minimum among the crossing, the endpoints Start and End against the triangle, and the segment against edges AB, BC, CA. Algorithm: plane crossing tested against the edges along the normal (formed with exact products), else the endpoint–triangle and segment–edge candidates (Ericson RTCD §5.1.5 and §5.1.9; Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Triangle3 b, out bool inRange) => Kernels.SegmentTriangle(a.Start, a.End, b.A, b.B, b.C, out inRange);
        /// <summary>Closest distance between a segment and a triangle (2D): negative when the segment enters the solid triangle (minimum translation over the separating-axis candidates: the edge normals and the segment's normal); apart, the closest pair against the edges (the first minimum over AB, BC, CA); a degenerate triangle is the segment or point it is (never negative). Algorithm: separating-axis test and depth (Ericson RTCD §4.4, §5.2.1), segment–edge distances (Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Triangle2 b, out bool inRange) => Kernels.SegmentTriangle2(a.Start.To3(), a.End.To3(), b.A.To3(), b.B.To3(), b.C.To3(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Triangle3 b, out bool inRange) => Kernels.SegmentTriangle(a.Start, a.End, b.A, b.B, b.C, out inRange).DistanceSquared == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Triangle2 b, out bool inRange) => Kernels.SegmentTriangleOverlaps2(a.Start.To3(), a.End.To3(), b.A.To3(), b.B.To3(), b.C.To3(), out inRange);
    }
}
