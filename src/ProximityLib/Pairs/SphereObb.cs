using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an OBB (3D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–box from the center in the box frame, less the radius; overlap by Arvo's squared test.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and a sphere (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Sphere b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a circle and an OBB (2D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–box from the center in the box frame, less the radius; overlap by Arvo's squared test.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and a circle (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Circle b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Sphere a, Obb3 b, out bool inRange) => Kernels.PointBox(a.Center, b.ToBox(), out inRange).AsSphereFirst(a.Center, a.Radius);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Circle a, Obb2 b, out bool inRange) => Kernels.PointBox(a.Center.To3(), b.ToBox(), out inRange).AsSphereFirst(a.Center.To3(), a.Radius).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Sphere a, Obb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Circle a, Obb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and an OBB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Whether an OBB and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Sphere b) => Overlaps(b, a);
        /// <summary>Whether a circle and an OBB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Whether an OBB and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Circle b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Sphere a, Obb3 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointBoxDistanceSquared(a.Center, b.ToBox()), a.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Circle a, Obb2 b, out bool inRange) => Kernels.WithinRadius(Kernels.PointBoxDistanceSquared(a.Center.To3(), b.ToBox()), a.Radius, out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Sphere a, Obb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Circle a, Obb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an OBB (3D), computed in double: negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Obb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an OBB and a sphere (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Sphere b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a circle and an OBB (2D), computed in double: negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Obb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an OBB and a circle (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Circle b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and an OBB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Obb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an OBB and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Sphere b) => Overlaps(b, a);
        /// <summary>Whether a circle and an OBB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Obb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an OBB and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Circle b) => Overlaps(b, a);
    }
}
