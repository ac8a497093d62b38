// Copied from src/ProximityLib/Raycasts/Point.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a point (3D): zero thickness, so hit when the ray passes through it, within <see cref="PassThroughTolerance"/> of |point − Origin| (largest coordinate); T its distance along the ray, Point the point, Normal −Direction. Algorithm: the perpendicular residual of point − Origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Vector3D shape, out bool inRange) => Kernels.RayPoint(ray.Origin, ray.Direction, shape, out inRange);

        /// <summary>First hit of a ray on a point (2D): zero thickness, so hit when the ray passes through it, within <see cref="PassThroughTolerance"/> of |point − Origin| (largest coordinate); T its distance along the ray, Point the point, Normal −Direction. Algorithm: the perpendicular residual of point − Origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Vector2D shape, out bool inRange) => Kernels.RayPoint(ray.Origin.To3(), ray.Direction.To3(), shape.To3(), out inRange).To2();
    }
}
