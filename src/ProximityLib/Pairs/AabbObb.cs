using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an OBB (3D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 15 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; best edge–box pair when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and an AABB (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Aabb3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between an AABB and an OBB (2D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 4 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; best edge–box pair when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and an AABB (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Aabb2 b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Aabb3 a, Obb3 b, out bool inRange) => Kernels.BoxBox(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Aabb2 a, Obb2 b, out bool inRange) => Kernels.BoxBox(a.ToBox(), b.ToBox(), out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Aabb3 a, Obb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Aabb2 a, Obb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an AABB and an OBB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an OBB and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Aabb3 b) => Overlaps(b, a);
        /// <summary>Whether an AABB and an OBB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an OBB and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Aabb2 b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Aabb3 a, Obb3 b, out bool inRange) => Kernels.BoxBoxOverlaps(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Aabb2 a, Obb2 b, out bool inRange) => Kernels.BoxBoxOverlaps(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Aabb3 a, Obb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Aabb2 a, Obb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an OBB (3D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Obb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an OBB and an AABB (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Aabb3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between an AABB and an OBB (2D), computed in double: negative when overlapping (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Obb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an OBB and an AABB (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Aabb2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an AABB and an OBB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Obb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an OBB and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Aabb3 b) => Overlaps(b, a);
        /// <summary>Whether an AABB and an OBB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Obb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an OBB and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Aabb2 b) => Overlaps(b, a);
    }
}
