// Copied from src/ProximityLib/Pairs/SegmentSegment.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D): never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint). Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Segment3 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Closest distance between a segment and a segment (2D): never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint). Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Segment2 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);

        // The kernel's steps are not symmetric: it runs on the pair in canonical order (one call site, so it inlines once).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Segment3 a, Segment3 b)
        {
            bool swap = Order.Swap(a, b);
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.SegmentSegment(p.Start, p.End, q.Start, q.End);
            return swap ? r.Swapped() : r;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Segment2 a, Segment2 b)
        {
            bool swap = Order.Swap(a, b);
            var p = swap ? b : a;
            var q = swap ? a : b;
            var r = Kernels.SegmentSegment(p.Start.To3(), p.End.To3(), q.Start.To3(), q.End.To3()).To2();
            return swap ? r.Swapped() : r;
        }
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Segment3 a, Segment3 b) => Wide.Between(a, b, static (x, y) => Core(x, y));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Segment2 a, Segment2 b) => Wide.Between(a, b, static (x, y) => Core(x, y));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Segment3 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Whether a segment and a segment (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Segment2 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment3 a, Segment3 b)
        {
            bool swap = Order.Swap(a, b);
            var p = swap ? b : a;
            var q = swap ? a : b;
            return Kernels.SegmentSegmentCore(p.Start, p.End, q.Start, q.End, out _, out _) == 0;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment2 a, Segment2 b)
        {
            bool swap = Order.Swap(a, b);
            var p = swap ? b : a;
            var q = swap ? a : b;
            return Kernels.SegmentSegmentCore(p.Start.To3(), p.End.To3(), q.Start.To3(), q.End.To3(), out _, out _) == 0;
        }
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment3 a, Segment3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment2 a, Segment2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Segment3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner));
        /// <summary>Closest distance between a segment and a segment (2D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Segment2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Segment3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
        /// <summary>Whether a segment and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Segment2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
    }
}
