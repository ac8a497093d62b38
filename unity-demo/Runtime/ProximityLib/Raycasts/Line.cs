// Copied from src/ProximityLib/Raycasts/Line.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a line (3D): zero thickness, so hit when the ray passes through it, within <see cref="PassThroughTolerance"/> of the larger of |line.Origin − Origin| and the crossing's offset from Origin (largest coordinate): the origin on the line (T = 0), else the crossing point; Point on the line, Normal −Direction; a parallel ray (to rounding: |Direction × line.Direction| below 2^-45, where the crossing's place is rounding) misses unless its origin lies on the line. Algorithm: the origin's residual from the line, and the lines' closest approach from cross products (Lagrange's identity).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Line3 shape, out bool inRange) => Kernels.RayLinear(ray.Origin, ray.Direction, shape.Origin, shape.Direction, false, out inRange);
        /// <summary>First hit of a ray on a line (2D): the line is a wall the ray crosses; Normal is its normal on the side the ray comes from; a ray on the line hits at T = 0 with Normal −Direction, a parallel one misses. Algorithm: T = ((line.Origin − Origin) × e) / (Direction × e), Point the ray's point's foot on the line.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Line2 shape, out bool inRange) => Kernels.RayLine2(ray.Origin, ray.Direction, shape.Origin, shape.Direction, false, out inRange);
    }
}
