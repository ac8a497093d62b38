using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class Raycast
    {
        /// <summary>First hit of a ray on a triangle (3D): two-sided and zero thickness, edges and vertices included; Normal is the unit normal on the side the ray comes from; watertight: a ray through an edge shared by two triangles hits at least one of them. A ray in the triangle's plane to rounding, or a triangle degenerate to rounding (a determinant below its rounding error), is answered edge-on: T = 0 when its origin lies in the triangle, else where it first meets an edge (as a 3D segment, Normal −Direction); a degenerate triangle is the segment or point it is. Algorithm: watertight ray–triangle (Woop, Benthin and Wald, JCGT 2013), edge functions of the sheared vertices relative to the origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Core(Ray3 ray, Triangle3 shape, out bool inRange) => Kernels.RayTriangle(ray.Origin, ray.Direction, shape.A, shape.B, shape.C, out inRange);

        /// <summary>First hit of a ray on a triangle (2D): the closed solid; an origin on the boundary is a hit at T = 0 with the outward normal of the first edge through it (A→B, B→C, C→A, counter-clockwise); a degenerate triangle is the segment (crossed as a wall) or point it is. Algorithm: the ray clipped by the three edges' inner sides (Cyrus–Beck) and the bounding box (a sliver's nearly parallel edges do not bound it far from its vertices).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Core(Ray2 ray, Triangle2 shape, out bool inRange) => Kernels.RayTriangle2(ray.Origin, ray.Direction, shape.A, shape.B, shape.C, out inRange);
    }
}
