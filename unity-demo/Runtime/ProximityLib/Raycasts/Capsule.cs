// Copied from src/ProximityLib/Raycasts/Capsule.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a capsule (3D): the closed solid; an origin on the surface is a hit at T = 0 (radius 0 with the origin on the axis: Normal −Direction). Algorithm: the earliest of the two end balls and the cylinder's side within the axis (each by the sphere's stable quadratic).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Capsule3 shape, out bool inRange) => Kernels.RayCapsule(ray.Origin, ray.Direction, shape.Start, shape.End, shape.Radius, out inRange);

        /// <summary>First hit of a ray on a capsule (2D): the closed solid (a stadium); an origin on the boundary is a hit at T = 0 (radius 0 with the origin on the axis: Normal −Direction). Algorithm: the earliest of the two end discs and the two sides within the axis (each by the sphere's stable quadratic).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Capsule2 shape, out bool inRange) => Kernels.RayCapsule(ray.Origin.To3(), ray.Direction.To3(), shape.Start.To3(), shape.End.To3(), shape.Radius, out inRange).To2();
    }
}
