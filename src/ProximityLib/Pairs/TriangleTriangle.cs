using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a triangle and a triangle (3D): never negative (neither is solid); meeting (crossing, coplanar overlapping, touching), 0 with a common point as both witnesses; where the minimum is not unique, the first among the edges AB, BC, CA of the canonically first triangle against the other, then the other's edges, the same in either argument order. Algorithm: the least of the six edge–triangle distances (see the segment–triangle query), which never intersects plane-crossing intervals (where Möller's and Guigue–Devillers' tests fail on coplanar input).</summary>
        internal static DistanceResult3 Core(in Triangle3 a, in Triangle3 b, out bool inRange) =>
            Order.Swap(a, b)
                ? Kernels.TriangleTriangle(b.A, b.B, b.C, a.A, a.B, a.C, out inRange).Swapped()
                : Kernels.TriangleTriangle(a.A, a.B, a.C, b.A, b.B, b.C, out inRange);
        /// <summary>Closest distance between a triangle and a triangle (2D): negative when the solid triangles overlap (minimum translation over the six edge normals); apart, the closest pair over the nine edge pairs; a degenerate triangle is the segment (longest edge) or point it is; the first minimum of the canonically first triangle's edges, the same in either argument order. Algorithm: separating-axis test and depth over the edge normals (Ericson RTCD §4.4; Gottschalk et al. 1996), edge–edge distances (Eberly's robust segment distance).</summary>
        internal static DistanceResult2 Core(in Triangle2 a, in Triangle2 b, out bool inRange) =>
            Order.Swap(a, b)
                ? Kernels.TriangleTriangle2(b.A.To3(), b.B.To3(), b.C.To3(), a.A.To3(), a.B.To3(), a.C.To3(), out inRange).Swapped().To2()
                : Kernels.TriangleTriangle2(a.A.To3(), a.B.To3(), a.C.To3(), b.A.To3(), b.B.To3(), b.C.To3(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        internal static bool Core(in Triangle3 a, in Triangle3 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).DistanceSquared == 0;
        internal static bool Core(in Triangle2 a, in Triangle2 b, out bool inRange) =>
            Order.Swap(a, b)
                ? Kernels.TriangleTriangleOverlaps2(b.A.To3(), b.B.To3(), b.C.To3(), a.A.To3(), a.B.To3(), a.C.To3(), out inRange)
                : Kernels.TriangleTriangleOverlaps2(a.A.To3(), a.B.To3(), a.C.To3(), b.A.To3(), b.B.To3(), b.C.To3(), out inRange);
    }
}
