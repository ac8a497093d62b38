// Copied from src/ProximityLib/Pairs/SphereSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a sphere (3D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is. Algorithm: |cb − ca| − (ra + rb) (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a circle and a circle (2D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is. Algorithm: |cb − ca| − (ra + rb) (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Sphere a, Sphere b, out bool inRange) => Kernels.SphereSphere(a.Center, a.Radius, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Circle a, Circle b, out bool inRange) => Kernels.SphereSphere(a.Center.To3(), a.Radius, b.Center.To3(), b.Radius, out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Sphere a, Sphere b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Circle a, Circle b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and a sphere (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a circle and a circle (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Sphere a, Sphere b, out bool inRange) => Kernels.PointInSphere(b.Center, a.Center, a.Radius + b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Circle a, Circle b, out bool inRange) => Kernels.PointInSphere(b.Center.To3(), a.Center.To3(), a.Radius + b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Sphere a, Sphere b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Circle a, Circle b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a sphere (3D), computed in double: negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Sphere b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between a circle and a circle (2D), computed in double: negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Circle b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Sphere b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether a circle and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Circle b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
    }
}
