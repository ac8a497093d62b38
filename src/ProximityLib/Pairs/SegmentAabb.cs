using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and an AABB (3D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a segment (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Segment3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a segment and an AABB (2D): negative when the segment enters the box (minimum translation over the separating-axis candidates). Algorithm: convex piecewise-quadratic minimisation along the segment in the box frame; SAT for overlap (Ericson RTCD §5.3.3).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a segment (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Segment2 b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Segment3 a, Aabb3 b, out bool inRange) => Kernels.SegmentBox(a.Start, a.End, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Segment2 a, Aabb2 b, out bool inRange) => Kernels.SegmentBox(a.Start.To3(), a.End.To3(), b.ToBox(), out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Segment3 a, Aabb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Segment2 a, Aabb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and an AABB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an AABB and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Segment3 b) => Overlaps(b, a);
        /// <summary>Whether a segment and an AABB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether an AABB and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Segment2 b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment3 a, Aabb3 b, out bool inRange) => Kernels.SegmentBoxOverlaps(a.Start, a.End, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment2 a, Aabb2 b, out bool inRange) => Kernels.SegmentBoxOverlaps(a.Start.To3(), a.End.To3(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment3 a, Aabb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Segment2 a, Aabb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and an AABB (3D), computed in double: negative when the segment enters the box (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Aabb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a segment (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Segment3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a segment and an AABB (2D), computed in double: negative when the segment enters the box (minimum translation over the separating-axis candidates).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Aabb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core(a.Inner, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a segment (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Segment2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Aabb3 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an AABB and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Segment3 b) => Overlaps(b, a);
        /// <summary>Whether a segment and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Aabb2 b) => Dbl.ProximityQuery.Core(a.Inner, b.Inner, out _);
        /// <summary>Whether an AABB and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Segment2 b) => Overlaps(b, a);
    }
}
