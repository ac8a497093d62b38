using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a ray and a capsule (3D): negative when the ray enters the capsule; 3D: distance of the axes less the radius (the axes' Minkowski difference is flat); witnesses pushed along the unit residual, or for meeting axes along the common normal A.dir × axis (parallel: <c>AnyPerpendicular</c> of A's direction); ParameterA is the ray's t ≥ 0, ParameterB the axis parameter. Algorithm: the ray cut to the stretch that holds its closest point, then the robust segment–segment kernel (Eberly; Lagrange-identity determinant), less the radius (capsule = segment ⊕ ball).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Ray3 a, in Capsule3 b, out bool inRange) => Kernels.LinearCapsule(Linear.Ray(a.Origin, a.Direction), 0, b.Start, b.End, b.Radius, false, true, out inRange);
        /// <summary>Closest distance between a ray and a capsule (2D): negative when the ray enters the capsule; 2D: separated axes give their distance less the radius; crossing axes give −(radius + the crossing depth of the axes, the smallest push of one axis off the other along a face normal of their Minkowski difference), the witnesses an endpoint and its image across that face, pushed by the radius; ParameterA is the ray's t ≥ 0, ParameterB the axis parameter. Algorithm: the ray cut to the stretch that holds its closest point, then the robust segment–segment kernel (Eberly), less the radius; crossing depth by the separating-axis test over the normals and directions (Gottschalk).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Ray2 a, in Capsule2 b, out bool inRange) => Kernels.LinearCapsule(Linear.Ray(a.Origin.To3(), a.Direction.To3()), 0, b.Start.To3(), b.End.To3(), b.Radius, true, true, out inRange).To2();
        /// <summary>The Distance of the 3D Core, bit for bit (Kernels.LinearCapsuleDistance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Ray3 a, in Capsule3 b, out bool inRange) => Kernels.LinearCapsuleDistance(Linear.Ray(a.Origin, a.Direction), b.Start, b.End, b.Radius, true, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Ray3 a, Capsule3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray2 a, in Capsule2 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).Distance <= 0;
    }
}
