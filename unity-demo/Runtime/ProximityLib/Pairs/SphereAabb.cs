// Copied from src/ProximityLib/Pairs/SphereAabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an AABB (3D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–AABB from the center, less the radius; overlap by Arvo's squared test (paper Eq. 23).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in Aabb3 b, out bool inRange) => Kernels.PointAabb(a.Center, b.Min, b.Max, false, out inRange).AsSphereFirst(a.Center, a.Radius);
        /// <summary>Closest distance between a circle and an AABB (2D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–AABB from the center, less the radius; overlap by Arvo's squared test (paper Eq. 23).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in Aabb2 b, out bool inRange) => Kernels.PointAabb(a.Center.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).AsSphereFirst(a.Center.To3(), a.Radius).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Sphere a, in Aabb3 b, out bool inRange) => Kernels.PointAabbDistance(a.Center, b.Min, b.Max, false, out inRange) - a.Radius;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Circle a, in Aabb2 b, out bool inRange) => Kernels.PointAabbDistance(a.Center.To3(), b.Min.To3(), b.Max.To3(), true, out inRange) - a.Radius;
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in Aabb3 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointAabbDistanceSquared(a.Center, b.Min, b.Max), a.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in Aabb2 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointAabbDistanceSquared(a.Center.To3(), b.Min.To3(), b.Max.To3()), a.Radius, out inRange);
    }
}
