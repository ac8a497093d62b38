using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an AABB (3D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–AABB from the center, less the radius; overlap by Arvo's squared test (paper Eq. 23).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a sphere (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Sphere b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a circle and an AABB (2D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–AABB from the center, less the radius; overlap by Arvo's squared test (paper Eq. 23).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a circle (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Circle b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Sphere a, Aabb3 b, out bool inRange) => Kernels.PointAabb(a.Center, b.Min, b.Max, false, out inRange).AsSphereFirst(a.Center, a.Radius);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Circle a, Aabb2 b, out bool inRange) => Kernels.PointAabb(a.Center.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).AsSphereFirst(a.Center.To3(), a.Radius).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Sphere a, Aabb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Circle a, Aabb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and an AABB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an AABB and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Sphere b) => Overlaps(b, a);
        /// <summary>Whether a circle and an AABB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an AABB and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Circle b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Sphere a, Aabb3 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointAabbDistanceSquared(a.Center, b.Min, b.Max), a.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Circle a, Aabb2 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointAabbDistanceSquared(a.Center.To3(), b.Min.To3(), b.Max.To3()), a.Radius, out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Sphere a, Aabb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Circle a, Aabb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an AABB (3D), computed in double: negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Aabb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a sphere (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Sphere b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a circle and an AABB (2D), computed in double: negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Aabb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a circle (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Circle b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Aabb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an AABB and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Sphere b) => Overlaps(b, a);
        /// <summary>Whether a circle and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Aabb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an AABB and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Circle b) => Overlaps(b, a);
    }
}
