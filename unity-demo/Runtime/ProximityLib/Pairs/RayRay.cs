// Copied from src/ProximityLib/Pairs/RayRay.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a ray and a ray (3D): never negative; where the minimum is not unique (parallel rays) the canonically first ray's origin and its nearest point on the other when that is no farther, else the other's origin and its nearest point on the first (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the rays' t ≥ 0. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel rays. Algorithm: the lines' closest parameters from the common normal dA × dB formed with exact products (Dekker); when either is negative, the better of each origin against the other ray (convex objective: the minimum lies on the boundary of the parameter quadrant; Eberly, distance between linear components).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Ray3 a, in Ray3 b, double range, out bool inRange) =>
            Kernels.OrderedUnboundedPair(a.Origin, a.Direction, b.Origin, b.Direction, true, range, out inRange);
        /// <summary>Closest distance between a ray and a ray (2D): never negative (0 where they cross); where the minimum is not unique (parallel rays) the canonically first ray's origin and its nearest point on the other when that is no farther, else the other's origin and its nearest point on the first (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the rays' t ≥ 0. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel rays. Algorithm: the lines' crossing parameters from the cross product formed with exact products (Dekker); when either is negative, the better of each origin against the other ray (Eberly, distance between linear components).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Ray2 a, in Ray2 b, double range, out bool inRange) =>
            Kernels.OrderedUnboundedPair(a.Origin.To3(), a.Direction.To3(), b.Origin.To3(), b.Direction.To3(), true, range, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Ray3 a, in Ray3 b, out bool inRange) =>
            Kernels.OrderedUnboundedDistance(a.Origin, a.Direction, b.Origin, b.Direction, true, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Ray2 a, in Ray2 b, out bool inRange) =>
            Kernels.OrderedUnboundedDistance(a.Origin.To3(), a.Direction.To3(), b.Origin.To3(), b.Direction.To3(), true, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray3 a, in Ray3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray2 a, in Ray2 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
