// Copied from src/ProximityLib/Pairs/LineLine.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a line (3D): never negative; parallel lines: the canonically first line's origin and its projection on the other (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the lines' t. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel lines. Algorithm: gap and closest parameters from the common normal dA × dB formed with exact products (Dekker), so nearly parallel lines keep u·|ΔOrigin| accuracy (Eberly, distance between lines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Line3 a, in Line3 b, double range, out bool inRange) =>
            Kernels.OrderedUnboundedPair(a.Origin, a.Direction, b.Origin, b.Direction, false, range, out inRange);
        /// <summary>Closest distance between a line and a line (2D): 0 at the crossing point unless parallel; parallel lines: the canonically first line's origin and its projection on the other (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the lines' t. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel lines. Algorithm: crossing parameters from the cross product formed with exact products (Dekker), so nearly parallel lines keep their accuracy (Eberly, distance between lines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in Line2 b, double range, out bool inRange) =>
            Kernels.OrderedUnboundedPair(a.Origin.To3(), a.Direction.To3(), b.Origin.To3(), b.Direction.To3(), false, range, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line3 a, in Line3 b, out bool inRange) =>
            Kernels.OrderedUnboundedDistance(a.Origin, a.Direction, b.Origin, b.Direction, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line2 a, in Line2 b, out bool inRange) =>
            Kernels.OrderedUnboundedDistance(a.Origin.To3(), a.Direction.To3(), b.Origin.To3(), b.Direction.To3(), false, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in Line3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in Line2 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
