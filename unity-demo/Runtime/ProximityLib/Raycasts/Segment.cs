// Copied from src/ProximityLib/Raycasts/Segment.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a segment (3D): zero thickness, so hit when the ray passes through it, within <see cref="PassThroughTolerance"/> of the larger endpoint offset from Origin (largest coordinate): the origin on it (T = 0), or the first endpoint or crossing point on the ray; Point on the segment, Normal −Direction. Algorithm: point–segment residual at the origin, endpoints' residuals, and the lines' closest approach from cross products (Lagrange's identity).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Segment3 shape, out bool inRange) => Kernels.RaySegment(ray.Origin, ray.Direction, shape.Start, shape.End, out inRange);

        /// <summary>First hit of a ray on a segment (2D): the segment is a wall the ray crosses (its ends included); Normal is the segment's normal on the side the ray comes from; a ray along the segment hits its nearer end (T = 0 when the origin lies on it) with Normal −Direction; a zero-length segment is a point. Algorithm: each endpoint's side of the ray (so segments sharing an endpoint agree on it), the crossing as a convex combination of the endpoints' distances along the ray.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Segment2 shape, out bool inRange) => Kernels.RaySegment2(ray.Origin, ray.Direction, shape.Start, shape.End, out inRange);
    }
}
