// Copied from src/ProximityLib/Pairs/PointSegment.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a segment (3D): never negative; ParameterB is the clamped projection parameter. Algorithm: clamped projection with the residual formed from the nearer endpoint (robust form of paper Eq. 9–11; Eq. 10 cancels).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3D a, Segment3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a segment and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Vector3D b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a segment (2D): never negative; ParameterB is the clamped projection parameter. Algorithm: clamped projection with the residual formed from the nearer endpoint (robust form of paper Eq. 9–11; Eq. 10 cancels).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2D a, Segment2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a segment and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Vector2D b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Segment3 b, out bool inRange) => Kernels.PointSegment(a, b.Start, b.End, false, out inRange).AsPointFirst(a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Segment2 b, out bool inRange) => Kernels.PointSegment(a.To3(), b.Start.To3(), b.End.To3(), false, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Vector3D a, Segment3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Vector2D a, Segment2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a segment (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3D a, Segment3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a segment and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Vector3D b) => Overlaps(b, a);
        /// <summary>Whether a point and a segment (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2D a, Segment2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Whether a segment and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Vector2D b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Segment3 b, out bool inRange) => Kernels.PointOnSegment(a, b.Start, b.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Segment2 b, out bool inRange) => Kernels.PointOnSegment(a.To3(), b.Start.To3(), b.End.To3(), out inRange);
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector3D a, Segment3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector2D a, Segment2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a segment (3D), computed in double: never negative; ParameterB is the clamped projection parameter.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3 a, Segment3 b) => new DistanceResult3(Dbl.ClosestDistance.Core((Dbl.Vector3D)a, b.Inner, out _));
        /// <summary>Closest distance between a segment and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Segment3 a, Vector3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a segment (2D), computed in double: never negative; ParameterB is the clamped projection parameter.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2 a, Segment2 b) => new DistanceResult2(Dbl.ClosestDistance.Core((Dbl.Vector2D)a, b.Inner, out _));
        /// <summary>Closest distance between a segment and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Segment2 a, Vector2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a segment (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3 a, Segment3 b) => Dbl.ProximityQuery.Core((Dbl.Vector3D)a, b.Inner, out _);
        /// <summary>Whether a segment and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment3 a, Vector3 b) => Overlaps(b, a);
        /// <summary>Whether a point and a segment (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2 a, Segment2 b) => Dbl.ProximityQuery.Core((Dbl.Vector2D)a, b.Inner, out _);
        /// <summary>Whether a segment and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Segment2 a, Vector2 b) => Overlaps(b, a);
    }
}
