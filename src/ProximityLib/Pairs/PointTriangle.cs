using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a triangle (3D): never negative (the triangle is two-sided, not solid); a degenerate triangle is the segment or point it is. Algorithm: the height along the normal (formed with exact products, so slivers keep their accuracy) when the point projects into the triangle, else the nearest edge by clamped projection (Ericson RTCD §5.1.5, with Eberly's robust point–segment residual).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Triangle3 b, out bool inRange) => Kernels.PointTriangle(a, b.A, b.B, b.C, false, out inRange).AsPointFirst(a);
        /// <summary>Closest distance between a point and a triangle (2D): negative inside the solid triangle, minus the distance to the nearest edge, with PointB the point on that edge (the first of equal edges AB, BC, CA); a degenerate triangle is the segment or point it is (never negative). Algorithm: orientation signs against the exactly-signed area, then the nearest edge by clamped projection (Ericson RTCD §5.1.5).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Triangle2 b, out bool inRange) => Kernels.PointTriangle2(a.To3(), b.A.To3(), b.B.To3(), b.C.To3(), false, out inRange).AsPointFirst(a.To3()).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Triangle3 b, out bool inRange) => Kernels.PointOnTriangle(a, b.A, b.B, b.C, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Triangle2 b, out bool inRange) => Kernels.PointTriangle2(a.To3(), b.A.To3(), b.B.To3(), b.C.To3(), false, out inRange).Distance <= 0;
    }
}
