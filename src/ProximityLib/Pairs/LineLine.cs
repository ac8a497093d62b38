using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a line (3D): never negative; parallel lines: the canonically first line's origin and its projection on the other (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the lines' t. Algorithm: gap and closest parameters from the common normal dA × dB formed with exact products (Dekker), so nearly parallel lines keep u·|ΔOrigin| accuracy (Eberly, distance between lines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Line3 a, Line3 b, out bool inRange)
        {
            // One call site, so the kernel is inlined once rather than once per order: two copies ran 1.5-3x slower.
            bool swap = Order.Swap(a.Origin, a.Direction, b.Origin, b.Direction);
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.UnboundedPair(p.Origin, p.Direction, false, q.Origin, q.Direction, false, out inRange);
            return swap ? r.Swapped() : r;
        }
        /// <summary>Closest distance between a line and a line (2D): 0 at the crossing point unless parallel; parallel lines: the canonically first line's origin and its projection on the other (src/ProximityLib/Double/Order.cs), the same in either argument order; ParameterA/B are the lines' t. Algorithm: crossing parameters from the cross product formed with exact products (Dekker), so nearly parallel lines keep their accuracy (Eberly, distance between lines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Line2 a, Line2 b, out bool inRange)
        {
            bool swap = Order.Swap(a.Origin.To3(), a.Direction.To3(), b.Origin.To3(), b.Direction.To3());
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.UnboundedPair(p.Origin.To3(), p.Direction.To3(), false, q.Origin.To3(), q.Direction.To3(), false, out inRange);
            return (swap ? r.Swapped() : r).To2();
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Line3 a, Line3 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).Distance <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Line2 a, Line2 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).Distance <= 0;
    }
}
