// Copied from src/ProximityLib/Raycasts/Line.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a line (2D): the line is a wall the ray crosses; Normal is its normal on the side the ray comes from; a ray on the line hits at T = 0 with Normal −Direction, a parallel one misses. Algorithm: T = ((line.Origin − Origin) × e) / (Direction × e).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Line2 shape, out bool inRange) => Kernels.RayLine2(ray.Origin, ray.Direction, shape.Origin, shape.Direction, false, out inRange);
    }
}
