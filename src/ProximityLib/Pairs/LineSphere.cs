using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a sphere (3D): negative when the line enters the sphere (depth = radius − distance from the center to the line); PointB on the sphere along the normal from the line (a center on the line: PointB = center − <c>AnyPerpendicular</c>(direction)·radius); ParameterA is the line's t = Direction·(center − Origin). Algorithm: orthogonal projection of the center (residual formed from differences, Eberly), less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Line3 a, in Sphere b, out bool inRange) => Kernels.SphereLinear(b.Center, b.Radius, a.Origin, a.Direction, false, out inRange).Swapped();
        /// <summary>Closest distance between a line and a circle (2D): negative when the line enters the circle (depth = radius − distance from the center to the line); PointB on the circle along the normal from the line (a center on the line: PointB = center − (y, −x)·radius for the direction (x, y)); ParameterA is the line's t = Direction·(center − Origin). Algorithm: orthogonal projection of the center (residual formed from differences, Eberly), less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in Circle b, out bool inRange) => Kernels.SphereLinear(b.Center.To3(), b.Radius, a.Origin.To3(), a.Direction.To3(), false, out inRange).Swapped().To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line3 a, in Sphere b, out bool inRange) => Kernels.PointLinearDistance(b.Center, a.Origin, a.Direction, false, out inRange) - b.Radius;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line2 a, in Circle b, out bool inRange) => Kernels.PointLinearDistance(b.Center.To3(), a.Origin.To3(), a.Direction.To3(), false, out inRange) - b.Radius;
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in Sphere b, out bool inRange) => Kernels.LinearInBall(b.Center, a.Origin, a.Direction, false, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in Circle b, out bool inRange) => Kernels.LinearInBall(b.Center.To3(), a.Origin.To3(), a.Direction.To3(), false, b.Radius, out inRange);
    }
}
