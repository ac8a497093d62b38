using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a triangle (3D): negative when the triangle enters the sphere (depth = radius − distance from the center to the triangle); a center on the triangle is pushed along the triangle's normal (B − A) × (C − A) (a degenerate triangle: a direction perpendicular to its edge, +X for a point). Algorithm: point–triangle distance from the center, less the radius (Ericson RTCD §5.2.7).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in Triangle3 b, out bool inRange) => Kernels.PointTriangle(a.Center, b.A, b.B, b.C, true, out inRange).AsSphereFirst(a.Center, a.Radius);
        /// <summary>Closest distance between a circle and a triangle (2D): negative when they overlap (depth = radius − distance from the center, or radius + the center's depth below the nearest edge when it is inside the solid triangle, pushed out through that edge). Algorithm: signed point–triangle distance from the center, less the radius (Ericson RTCD §5.2.7).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in Triangle2 b, out bool inRange) => Kernels.PointTriangle2(a.Center.To3(), b.A.To3(), b.B.To3(), b.C.To3(), true, out inRange).AsSphereFirst(a.Center.To3(), a.Radius).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in Triangle3 b, out bool inRange) => Kernels.PointTriangle(a.Center, b.A, b.B, b.C, false, out inRange).Distance - a.Radius <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in Triangle2 b, out bool inRange) => Kernels.PointTriangle2(a.Center.To3(), b.A.To3(), b.B.To3(), b.C.To3(), false, out inRange).Distance - a.Radius <= 0;
    }
}
