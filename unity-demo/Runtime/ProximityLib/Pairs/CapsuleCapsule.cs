// Copied from src/ProximityLib/Pairs/CapsuleCapsule.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a capsule and a capsule (3D): negative when they overlap (depth = sum of the radii − distance of the axes: their Minkowski difference is flat); witnesses pushed by each radius along the unit residual of the axes' closest pair, for meeting axes along the common normal (parallel axes: <c>AnyPerpendicular</c> of the first direction); parallel overlapping axes: the segment kernel's first endpoint minimum; computed on the canonically ordered pair (src/ProximityLib/Double/Order.cs, then the radius), so the same in either argument order; ParameterA/B are the axis parameters. Algorithm: robust segment–segment distance of the axes (Eberly; Lagrange-identity determinant) less both radii.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Capsule3 a, Capsule3 b, out bool inRange)
        {
            // One call site, so what is inlined is compiled once rather than once per order.
            bool swap = Kernels.SwapCapsules(a.Start, a.End, a.Radius, b.Start, b.End, b.Radius);
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.CapsuleCapsule(p.Start, p.End, p.Radius, q.Start, q.End, q.Radius, false, out inRange);
            return swap ? r.Swapped() : r;
        }
        /// <summary>Closest distance between a capsule and a capsule (2D): negative when they overlap; separated axes give their distance less both radii; crossing axes give −(both radii + the crossing depth of the axes, the smallest push of one axis off the other along a face normal of their Minkowski difference), the witnesses an endpoint and its image across that face pushed by the radii; computed on the canonically ordered pair (src/ProximityLib/Double/Order.cs, then the radius), so the same in either argument order; ParameterA/B are the axis parameters. Algorithm: robust segment–segment distance of the axes (Eberly) less both radii; crossing depth by the separating-axis test over the axes' normals and directions (Gottschalk).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Capsule2 a, Capsule2 b, out bool inRange)
        {
            bool swap = Kernels.SwapCapsules(a.Start.To3(), a.End.To3(), a.Radius, b.Start.To3(), b.End.To3(), b.Radius);
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.CapsuleCapsule(p.Start.To3(), p.End.To3(), p.Radius, q.Start.To3(), q.End.To3(), q.Radius, true, out inRange);
            return (swap ? r.Swapped() : r).To2();
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Capsule3 a, Capsule3 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).Distance <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Capsule2 a, Capsule2 b, out bool inRange) => ClosestDistance.Core(a, b, out inRange).Distance <= 0;
    }
}
