using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a sphere (3D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3D a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a sphere and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Vector3D b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a circle (2D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2D a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a circle and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Vector2D b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Sphere b, out bool inRange) => Kernels.PointSphere(a, b.Center, b.Radius, out inRange).AsPointFirst(a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Circle b, out bool inRange) => Kernels.PointSphere(a.To3(), b.Center.To3(), b.Radius, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Vector3D a, Sphere b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Vector2D a, Circle b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a sphere (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3D a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a sphere and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Vector3D b) => Overlaps(b, a);
        /// <summary>Whether a point and a circle (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2D a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a circle and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Vector2D b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Sphere b, out bool inRange) => Kernels.PointInSphere(a, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Circle b, out bool inRange) => Kernels.PointInSphere(a.To3(), b.Center.To3(), b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector3D a, Sphere b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector2D a, Circle b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a sphere (3D), computed in double: negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3 a, Sphere b) => new DistanceResult3(Dbl.ClosestDistance.Core((Dbl.Vector3D)a, b.Inner, out _));
        /// <summary>Closest distance between a sphere and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Vector3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a circle (2D), computed in double: negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2 a, Circle b) => new DistanceResult2(Dbl.ClosestDistance.Core((Dbl.Vector2D)a, b.Inner, out _));
        /// <summary>Closest distance between a circle and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Vector2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3 a, Sphere b) => Dbl.ProximityQuery.Core((Dbl.Vector3D)a, b.Inner, out _);
        /// <summary>Whether a sphere and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Vector3 b) => Overlaps(b, a);
        /// <summary>Whether a point and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2 a, Circle b) => Dbl.ProximityQuery.Core((Dbl.Vector2D)a, b.Inner, out _);
        /// <summary>Whether a circle and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Vector2 b) => Overlaps(b, a);
    }
}
