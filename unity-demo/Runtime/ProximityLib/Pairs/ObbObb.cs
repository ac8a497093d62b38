// Copied from src/ProximityLib/Pairs/ObbObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an OBB and an OBB (3D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 15 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; best edge–box pair when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Obb3 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Closest distance between an OBB and an OBB (2D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 4 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; best edge–box pair when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Obb2 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);

        // The kernel's steps are not symmetric: it runs on the pair in canonical order (one call site).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Obb3 a, Obb3 b)
        {
            bool swap = Order.Swap(a, b);
            var r = Kernels.BoxBox((swap ? b : a).ToBox(), (swap ? a : b).ToBox());
            return swap ? r.Swapped() : r;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Obb2 a, Obb2 b)
        {
            bool swap = Order.Swap(a, b);
            var r = Kernels.BoxBox((swap ? b : a).ToBox(), (swap ? a : b).ToBox()).To2();
            return swap ? r.Swapped() : r;
        }
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Obb3 a, Obb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Obb2 a, Obb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an OBB and an OBB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Obb3 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Whether an OBB and an OBB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Obb2 b) =>
            a.Extreme | b.Extreme ? Slow(a, b) : Core(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Obb3 a, Obb3 b)
        {
            bool swap = Order.Swap(a, b);
            return Kernels.BoxBoxOverlaps((swap ? b : a).ToBox(), (swap ? a : b).ToBox());
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Obb2 a, Obb2 b)
        {
            bool swap = Order.Swap(a, b);
            return Kernels.BoxBoxOverlaps((swap ? b : a).ToBox(), (swap ? a : b).ToBox());
        }
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Obb3 a, Obb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Obb2 a, Obb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an OBB and an OBB (3D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Obb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner));
        /// <summary>Closest distance between an OBB and an OBB (2D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Obb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an OBB and an OBB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Obb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
        /// <summary>Whether an OBB and an OBB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Obb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
    }
}
