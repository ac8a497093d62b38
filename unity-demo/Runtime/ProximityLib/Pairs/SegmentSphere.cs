// Copied from src/ProximityLib/Pairs/SegmentSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a sphere (3D): negative when the segment enters the sphere (depth = radius − distance from center to segment). Algorithm: point–segment distance from the center, less the radius (paper Eq. 16).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a sphere and a segment (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Segment3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a segment and a circle (2D): negative when the segment enters the sphere (depth = radius − distance from center to segment). Algorithm: point–segment distance from the center, less the radius (paper Eq. 16).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a circle and a segment (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Segment2 b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Segment3 a, Sphere b, out bool inRange) => Kernels.PointSegment(b.Center, a.Start, a.End, true, out inRange).AsSphereFirst(b.Center, b.Radius).Swapped();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Segment2 a, Circle b, out bool inRange) => Kernels.PointSegment(b.Center.To3(), a.Start.To3(), a.End.To3(), true, out inRange).AsSphereFirst(b.Center.To3(), b.Radius).Swapped().To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Segment3 a, Sphere b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Segment2 a, Circle b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a sphere (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Sphere b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a sphere and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Segment3 b) => Overlaps(b, a);
        /// <summary>Whether a segment and a circle (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Circle b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a circle and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Segment2 b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment3 a, Sphere b, out bool inRange) => Kernels.SegmentInSphere(a.Start, a.End, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment2 a, Circle b, out bool inRange) => Kernels.SegmentInSphere(a.Start.To3(), a.End.To3(), b.Center.To3(), b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment3 a, Sphere b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment2 a, Circle b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a sphere (3D), computed in double: negative when the segment enters the sphere (depth = radius − distance from center to segment).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Sphere b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between a sphere and a segment (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Sphere a, Segment3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a segment and a circle (2D), computed in double: negative when the segment enters the sphere (depth = radius − distance from center to segment).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Circle b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between a circle and a segment (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Circle a, Segment2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a sphere (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Sphere b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether a sphere and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Sphere a, Segment3 b) => Overlaps(b, a);
        /// <summary>Whether a segment and a circle (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Circle b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether a circle and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Circle a, Segment2 b) => Overlaps(b, a);
    }
}
