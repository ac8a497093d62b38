// Copied from src/ProximityLib/Pairs/LineTriangle.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a triangle (3D): never negative (neither is solid); crossing (or lying in its plane across it), 0 with one common point as both witnesses; ParameterA t with PointA = Origin + t·Direction; where the minimum is not unique (the line parallel to the triangle over it, or parallel to an edge it passes beside), the first minimum among the crossing, the ends of the line's stretch over the triangle against it, and the line against edges AB, BC, CA. Algorithm: in the frame of vertex A, the line clipped to the stretch of the vertices' projections onto it (widened by their rounding), then segment–triangle: plane crossing tested against the edges along the normal (formed with exact products), else the endpoint–triangle and segment–edge candidates (Ericson RTCD §5.1.5, §5.1.9; Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Line3 a, in Triangle3 b, out bool inRange) => Kernels.LinearTriangle(a.Origin, a.Direction, false, b.A, b.B, b.C, out inRange);
        /// <summary>Closest distance between a line and a triangle (2D): negative when the line crosses the solid triangle: minus the least sideways translation that clears it, min(highest vertex, −lowest vertex) over the line's normal; witnesses the closest pair of the just-touching line (the first minimum over edges AB, BC, CA), PointA moved back; apart, the closest pair against the edges (the first minimum over AB, BC, CA; a line parallel to the nearest edge: one end of the common stretch); touching, one common point as both witnesses; ParameterA t with PointA = Origin + t·Direction; a degenerate triangle is the segment or point it is (never negative). Algorithm: in the frame of vertex A, the line clipped to the triangle's projection (widened by its diameter so the cut ends never lower the depth), then the separating-axis test and depth over the edge normals and the line's normal (Ericson RTCD §4.4, §5.2.1) and segment–edge distances (Eberly's robust segment distance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in Triangle2 b, out bool inRange) => Kernels.LinearTriangle2(a.Origin.To3(), a.Direction.To3(), false, b.A.To3(), b.B.To3(), b.C.To3(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in Triangle3 b, out bool inRange) => Kernels.LinearTriangle(a.Origin, a.Direction, false, b.A, b.B, b.C, out inRange).DistanceSquared == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in Triangle2 b, out bool inRange) => Kernels.LinearTriangleOverlaps2(a.Origin.To3(), a.Direction.To3(), false, b.A.To3(), b.B.To3(), b.C.To3(), out inRange);
    }
}
