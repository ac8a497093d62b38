using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an AABB (3D): negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle. Algorithm: per-axis interval gaps (paper Eq. 18).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Aabb3 a, in Aabb3 b, out bool inRange) => Kernels.AabbAabb(a.Min, a.Max, b.Min, b.Max, false, out inRange);
        /// <summary>Closest distance between an AABB and an AABB (2D): negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle. Algorithm: per-axis interval gaps (paper Eq. 18).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Aabb2 a, in Aabb2 b, out bool inRange) => Kernels.AabbAabb(a.Min.To3(), a.Max.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Aabb3 a, in Aabb3 b, out bool inRange) => Kernels.AabbAabbDistance(a.Min, a.Max, b.Min, b.Max, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Aabb2 a, in Aabb2 b, out bool inRange) => Kernels.AabbAabbDistance(a.Min.To3(), a.Max.To3(), b.Min.To3(), b.Max.To3(), true, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Aabb3 a, in Aabb3 b) => Kernels.AabbAabbOverlaps(a.Min, a.Max, b.Min, b.Max);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Aabb2 a, in Aabb2 b) => Kernels.AabbAabbOverlaps(a.Min.To3(), a.Max.To3(), b.Min.To3(), b.Max.To3());
    }
}
