using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a ray (3D): zero thickness, so hit when the ray passes through the target ray, within <see cref="PassThroughTolerance"/> of the larger of |target.Origin − Origin| and the crossing's offset from Origin (largest coordinate): the origin on the target (T = 0), else the crossing point when it lies on the target, else the target's origin when it lies on the ray (a ray parallel to the target to rounding, |Direction × target.Direction| below 2^-45, has no crossing); Point on the target, Normal −Direction. Algorithm: the origin's residual from the target, and the lines' closest approach from cross products (Lagrange's identity), the target's parameter clamped at 0.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Ray3 shape, out bool inRange) => Kernels.RayLinear(ray.Origin, ray.Direction, shape.Origin, shape.Direction, true, out inRange);
        /// <summary>First hit of a ray on a ray (2D): the target ray is a wall the ray crosses (its origin included); Normal is its normal on the side the ray comes from; a ray running along the target hits at T = 0 when its origin lies on the target, else at the target's origin when that lies ahead, with Normal −Direction. Algorithm: T = ((target.Origin − Origin) × e) / (Direction × e), the target's parameter of the ray's point there checked non-negative.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Ray2 shape, out bool inRange) => Kernels.RayLine2(ray.Origin, ray.Direction, shape.Origin, shape.Direction, true, out inRange);
    }
}
