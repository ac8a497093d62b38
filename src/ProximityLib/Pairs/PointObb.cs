using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an OBB (3D): negative inside (depth to the nearest face). Algorithm: clamp in the box frame (Ericson RTCD §5.1.4); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3D a, Obb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Vector3D b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and an OBB (2D): negative inside (depth to the nearest face). Algorithm: clamp in the box frame (Ericson RTCD §5.1.4); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2D a, Obb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange && !b.Extreme ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an OBB and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Vector2D b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Obb3 b, out bool inRange) => Kernels.PointBox(a, b.ToBox(), out inRange).AsPointFirst(a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Obb2 b, out bool inRange) => Kernels.PointBox(a.To3(), b.ToBox(), out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Vector3D a, Obb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Vector2D a, Obb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and an OBB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3D a, Obb3 b) => b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Whether an OBB and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Vector3D b) => Overlaps(b, a);
        /// <summary>Whether a point and an OBB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2D a, Obb2 b) => b.Extreme ? Slow(a, b) : Core(a, b);
        /// <summary>Whether an OBB and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Vector2D b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Obb3 b) => Kernels.PointInBox(a, b.ToBox());
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Obb2 b) => Kernels.PointInBox(a.To3(), b.ToBox());
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector3D a, Obb3 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Slow(Vector2D a, Obb2 b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y));
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an OBB (3D), computed in double: negative inside (depth to the nearest face).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3 a, Obb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core((Dbl.Vector3D)a, b.Inner, out _));
        /// <summary>Closest distance between an OBB and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Obb3 a, Vector3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and an OBB (2D), computed in double: negative inside (depth to the nearest face).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2 a, Obb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core((Dbl.Vector2D)a, b.Inner, out _));
        /// <summary>Closest distance between an OBB and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Obb2 a, Vector2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and an OBB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3 a, Obb3 b) => Dbl.ProximityQuery.Core((Dbl.Vector3D)a, b.Inner);
        /// <summary>Whether an OBB and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb3 a, Vector3 b) => Overlaps(b, a);
        /// <summary>Whether a point and an OBB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2 a, Obb2 b) => Dbl.ProximityQuery.Core((Dbl.Vector2D)a, b.Inner);
        /// <summary>Whether an OBB and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Obb2 a, Vector2 b) => Overlaps(b, a);
    }
}
