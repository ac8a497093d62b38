// Copied from src/ProximityLib/Raycasts/Ray.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a ray (2D): the target ray is a wall the ray crosses (its origin included); Normal is its normal on the side the ray comes from; a ray running along the target hits at T = 0 when its origin lies on the target, else at the target's origin when that lies ahead, with Normal −Direction. Algorithm: T = ((target.Origin − Origin) × e) / (Direction × e), the target's parameter checked non-negative.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Ray2 shape, out bool inRange) => Kernels.RayLine2(ray.Origin, ray.Direction, shape.Origin, shape.Direction, true, out inRange);
    }
}
