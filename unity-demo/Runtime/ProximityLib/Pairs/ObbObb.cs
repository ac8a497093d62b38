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
        public static DistanceResult3 Between(Obb3 a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and an OBB (2D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 4 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; best edge–box pair when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        // The separating-axis steps work in A's frame: the pair runs in canonical order and the result is swapped back.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Obb3 a, Obb3 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.BoxBox(b.ToBox(), a.ToBox(), out inRange).Swapped() : Kernels.BoxBox(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Obb2 a, Obb2 b, out bool inRange) =>
            (Order.Swap(a, b) ? Kernels.BoxBox(b.ToBox(), a.ToBox(), out inRange).Swapped() : Kernels.BoxBox(a.ToBox(), b.ToBox(), out inRange)).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Obb3 a, Obb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Obb2 a, Obb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an OBB and an OBB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an OBB and an OBB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Obb3 a, Obb3 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.BoxBoxOverlaps(b.ToBox(), a.ToBox(), out inRange) : Kernels.BoxBoxOverlaps(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Obb2 a, Obb2 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.BoxBoxOverlaps(b.ToBox(), a.ToBox(), out inRange) : Kernels.BoxBoxOverlaps(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Obb3 a, Obb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Obb2 a, Obb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an OBB and an OBB (3D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Obb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an OBB and an OBB (2D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Obb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an OBB and an OBB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Obb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an OBB and an OBB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Obb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
    }
}
