// Copied from src/ProximityLib/Pairs/PointAabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an AABB (3D): negative inside (depth to the nearest face, ties to the lower axis, min face first). Algorithm: clamp to the box (Ericson RTCD §5.1.3; paper Eq. 22); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3D a, Aabb3 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Vector3D b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and an AABB (2D): negative inside (depth to the nearest face, ties to the lower axis, min face first). Algorithm: clamp to the box (Ericson RTCD §5.1.3; paper Eq. 22); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2D a, Aabb2 b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between an AABB and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Vector2D b) => Between(b, a).Swapped();

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Aabb3 b, out bool inRange) => Kernels.PointAabb(a, b.Min, b.Max, false, out inRange).AsPointFirst(a);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Aabb2 b, out bool inRange) => Kernels.PointAabb(a.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Vector3D a, Aabb3 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Vector2D a, Aabb2 b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and an AABB (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3D a, Aabb3 b) => Core(a, b);
        /// <summary>Whether an AABB and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Vector3D b) => Overlaps(b, a);
        /// <summary>Whether a point and an AABB (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2D a, Aabb2 b) => Core(a, b);
        /// <summary>Whether an AABB and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Vector2D b) => Overlaps(b, a);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Aabb3 b) => Kernels.PointInAabb(a, b.Min, b.Max);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Aabb2 b) => Kernels.PointInAabb(a.To3(), b.Min.To3(), b.Max.To3());
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an AABB (3D), computed in double: negative inside (depth to the nearest face, ties to the lower axis, min face first).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3 a, Aabb3 b) => new DistanceResult3(Dbl.ClosestDistance.Core((Dbl.Vector3D)a, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Aabb3 a, Vector3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and an AABB (2D), computed in double: negative inside (depth to the nearest face, ties to the lower axis, min face first).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2 a, Aabb2 b) => new DistanceResult2(Dbl.ClosestDistance.Core((Dbl.Vector2D)a, b.Inner, out _));
        /// <summary>Closest distance between an AABB and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Aabb2 a, Vector2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and an AABB (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3 a, Aabb3 b) => Dbl.ProximityQuery.Core((Dbl.Vector3D)a, b.Inner);
        /// <summary>Whether an AABB and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb3 a, Vector3 b) => Overlaps(b, a);
        /// <summary>Whether a point and an AABB (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2 a, Aabb2 b) => Dbl.ProximityQuery.Core((Dbl.Vector2D)a, b.Inner);
        /// <summary>Whether an AABB and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Aabb2 a, Vector2 b) => Overlaps(b, a);
    }
}
