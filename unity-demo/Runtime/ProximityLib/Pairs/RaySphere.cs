// Copied from src/ProximityLib/Pairs/RaySphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a ray and a sphere (3D): negative when the ray enters the sphere (depth = radius − distance from the center to the ray); PointB on the sphere along the normal from the ray (a center on the ray: PointB = center − <c>AnyPerpendicular</c>(direction)·radius); ParameterA is the ray's t, the projection clamped at 0. Algorithm: projection of the center clamped at the origin (residual formed from differences, Eberly), less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Ray3 a, in Sphere b, out bool inRange) => Kernels.SphereLinear(b.Center, b.Radius, a.Origin, a.Direction, true, out inRange).Swapped();
        /// <summary>Closest distance between a ray and a circle (2D): negative when the ray enters the circle (depth = radius − distance from the center to the ray); PointB on the circle along the normal from the ray (a center on the ray: PointB = center − (y, −x)·radius for the direction (x, y)); ParameterA is the ray's t, the projection clamped at 0. Algorithm: projection of the center clamped at the origin (residual formed from differences, Eberly), less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Ray2 a, in Circle b, out bool inRange) => Kernels.SphereLinear(b.Center.To3(), b.Radius, a.Origin.To3(), a.Direction.To3(), true, out inRange).Swapped().To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Ray3 a, in Sphere b, out bool inRange) => Kernels.PointLinearDistance(b.Center, a.Origin, a.Direction, true, out inRange) - b.Radius;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Ray2 a, in Circle b, out bool inRange) => Kernels.PointLinearDistance(b.Center.To3(), a.Origin.To3(), a.Direction.To3(), true, out inRange) - b.Radius;
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray3 a, in Sphere b, out bool inRange) => Kernels.LinearInBall(b.Center, a.Origin, a.Direction, true, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray2 a, in Circle b, out bool inRange) => Kernels.LinearInBall(b.Center.To3(), a.Origin.To3(), a.Direction.To3(), true, b.Radius, out inRange);
    }
}
