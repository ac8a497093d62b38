using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a ray and a triangle (3D): never negative (neither is solid); crossing (or lying in its plane across it), 0 with one common point as both witnesses; ParameterA t ≥ 0 with PointA = Origin + t·Direction (pointing away: the origin); where the minimum is not unique (the ray parallel to the triangle over it, or parallel to an edge it passes beside), the first minimum among the crossing, the ends of the ray's stretch over the triangle against it, and the ray against edges AB, BC, CA. Algorithm: in the frame of vertex A, the ray clipped to the stretch of the vertices' projections onto it (widened by their rounding, cut at 0), then segment–triangle: plane crossing tested against the edges along the normal (formed with exact products), else the endpoint–triangle and segment–edge candidates (Ericson RTCD §5.1.5, §5.1.9; Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Ray3 a, in Triangle3 b, out bool inRange) => Kernels.LinearTriangle(a.Origin, a.Direction, true, b.A, b.B, b.C, out inRange);
        /// <summary>Closest distance between a ray and a triangle (2D): negative when the ray enters the solid triangle: minus the least translation that clears it, sideways (min(highest vertex, −lowest vertex) over the ray's normal) or back along the outward normal of an edge the ray leaves through (n·Direction ≥ 0), by the distance from the origin to that edge's line (equal pushes: the first over the normals of AB, AC, BC, then the ray's normal); witnesses the closest pair of the just-touching ray (the first minimum over edges AB, BC, CA), PointA moved back; apart, the closest pair against the edges (the first minimum over AB, BC, CA); touching, one common point as both witnesses; ParameterA t ≥ 0 with PointA = Origin + t·Direction; a degenerate triangle is the segment or point it is (never negative). Algorithm: in the frame of vertex A, the ray clipped to the triangle's projection (widened by its diameter, cut at 0), then the separating-axis test and depth over the edge normals and the ray's normal (Ericson RTCD §4.4, §5.2.1) and segment–edge distances (Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Ray2 a, in Triangle2 b, out bool inRange) => Kernels.LinearTriangle2(a.Origin.To3(), a.Direction.To3(), true, b.A.To3(), b.B.To3(), b.C.To3(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray3 a, in Triangle3 b, out bool inRange) => Kernels.LinearTriangle(a.Origin, a.Direction, true, b.A, b.B, b.C, out inRange).DistanceSquared == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray2 a, in Triangle2 b, out bool inRange) => Kernels.LinearTriangleOverlaps2(a.Origin.To3(), a.Direction.To3(), true, b.A.To3(), b.B.To3(), b.C.To3(), out inRange);
    }
}
