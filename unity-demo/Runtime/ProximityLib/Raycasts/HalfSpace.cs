// Copied from src/ProximityLib/Raycasts/HalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a half-space (3D): the closed solid Normal·(x − Point) ≤ 0; Normal is the half-space's; a ray parallel to the boundary (or leaving) misses unless it starts in the solid; an origin on the boundary is a hit at T = 0. Algorithm: T = s / (−Normal·Direction), s = Normal·(Origin − Point).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, HalfSpace shape, out bool inRange) => Kernels.RayHalfSpace(ray.Origin, ray.Direction, shape.Normal, shape.Point, out inRange);

        /// <summary>First hit of a ray on a half-plane (2D): the closed solid Normal·(x − Point) ≤ 0; Normal is the half-plane's; a ray parallel to the boundary (or leaving) misses unless it starts in the solid; an origin on the boundary is a hit at T = 0. Algorithm: T = s / (−Normal·Direction), s = Normal·(Origin − Point).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, HalfPlane shape, out bool inRange) => Kernels.RayHalfSpace(ray.Origin.To3(), ray.Direction.To3(), shape.Normal.To3(), shape.Point.To3(), out inRange).To2();
    }
}
