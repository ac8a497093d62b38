// Copied from src/ProximityLib/Raycasts/Sphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a sphere (3D): the closed ball; a grazing ray hits at the touch point; an origin on the surface is a hit at T = 0 (a zero-radius sphere at the origin: Normal −Direction). Algorithm: half-chord from the perpendicular distance, √((r − h)(r + h)), and the non-cancelling root (|w|² − r²)/(−b + half-chord) (Numerical Recipes §5.6).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Sphere shape, out bool inRange) => Kernels.RaySphere(ray.Origin, ray.Direction, shape.Center, shape.Radius, out inRange);

        /// <summary>First hit of a ray on a circle (2D): the closed disc; a grazing ray hits at the touch point; an origin on the boundary is a hit at T = 0 (a zero-radius circle at the origin: Normal −Direction). Algorithm: half-chord from the perpendicular distance, √((r − h)(r + h)), and the non-cancelling root (|w|² − r²)/(−b + half-chord) (Numerical Recipes §5.6).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Circle shape, out bool inRange) => Kernels.RaySphere(ray.Origin.To3(), ray.Direction.To3(), shape.Center.To3(), shape.Radius, out inRange).To2();
    }
}
