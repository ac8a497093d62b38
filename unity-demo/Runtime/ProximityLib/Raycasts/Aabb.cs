// Copied from src/ProximityLib/Raycasts/Aabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on an AABB (3D): the closed box; a ray grazing an edge or running along a face hits where it first touches; the normal is the entry face's (at an edge or corner: the first of the equal entry axes x, y, z); an origin on the surface is a hit at T = 0 with the first face through it (a flat box's face toward the ray). Algorithm: slab test (Kay and Kajiya 1986) with axes the ray does not move along tested by containment (no 0·∞).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Aabb3 shape, out bool inRange) => Kernels.RayAabb(ray.Origin, ray.Direction, shape.Min, shape.Max, false, out inRange);

        /// <summary>First hit of a ray on an AABB (2D): the closed rectangle; a ray grazing a corner or running along a side hits where it first touches; the normal is the entry side's (at a corner: x before y); an origin on the boundary is a hit at T = 0 with the first side through it (a flat box's side toward the ray). Algorithm: slab test (Kay and Kajiya 1986) with axes the ray does not move along tested by containment (no 0·∞).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Aabb2 shape, out bool inRange) => Kernels.RayAabb(ray.Origin.To3(), ray.Direction.To3(), shape.Min.To3(), shape.Max.To3(), true, out inRange).To2();
    }
}
