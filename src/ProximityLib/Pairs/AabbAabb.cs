using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an AABB (3D): negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle. Algorithm: per-axis interval gaps (paper Eq. 18).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and an AABB (2D): negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle. Algorithm: per-axis interval gaps (paper Eq. 18).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Aabb3 a, Aabb3 b, out bool inRange) => Kernels.AabbAabb(a.Min, a.Max, b.Min, b.Max, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Aabb2 a, Aabb2 b, out bool inRange) => Kernels.AabbAabb(a.Min.To3(), a.Max.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Aabb3 a, Aabb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Aabb2 a, Aabb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an AABB and an AABB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Aabb3 b) => Core(a, b);
        /// <summary>Whether an AABB and an AABB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Aabb2 b) => Core(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Aabb3 a, Aabb3 b) => Kernels.AabbAabbOverlaps(a.Min, a.Max, b.Min, b.Max);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Aabb2 a, Aabb2 b) => Kernels.AabbAabbOverlaps(a.Min.To3(), a.Max.To3(), b.Min.To3(), b.Max.To3());
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an AABB (3D), computed in double: negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Aabb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an AABB and an AABB (2D), computed in double: negative when overlapping (least per-axis overlap); shared intervals put the witnesses at their middle.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Aabb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether an AABB and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Aabb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
        /// <summary>Whether an AABB and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Aabb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner);
    }
}
