// Copied from src/ProximityLib/Pairs/PointPoint.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a point (3D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3D a, Vector3D b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }
        /// <summary>Closest distance between a point and a point (2D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2D a, Vector2D b)
        {
            var r = Core(a, b, out bool inRange);
            return inRange ? r : Slow(a, b);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Vector3D b, out bool inRange) => Kernels.PointPoint(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Vector2D b, out bool inRange) => Kernels.PointPoint(a.To3(), b.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Slow(Vector3D a, Vector3D b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult2 Slow(Vector2D a, Vector2D b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a point (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3D a, Vector3D b) => Core(a, b);
        /// <summary>Whether a point and a point (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2D a, Vector2D b) => Core(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Vector3D b) => a == b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Vector2D b) => a == b;
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a point (3D), computed in double: never negative; Distance = |b − a|.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 Between(Vector3 a, Vector3 b) => new DistanceResult3(Dbl.ClosestDistance.Core((Dbl.Vector3D)a, (Dbl.Vector3D)b, out _));
        /// <summary>Closest distance between a point and a point (2D), computed in double: never negative; Distance = |b − a|.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 Between(Vector2 a, Vector2 b) => new DistanceResult2(Dbl.ClosestDistance.Core((Dbl.Vector2D)a, (Dbl.Vector2D)b, out _));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a point (3D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector3 a, Vector3 b) => Dbl.ProximityQuery.Core((Dbl.Vector3D)a, (Dbl.Vector3D)b);
        /// <summary>Whether a point and a point (2D) touch or overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Overlaps(Vector2 a, Vector2 b) => Dbl.ProximityQuery.Core((Dbl.Vector2D)a, (Dbl.Vector2D)b);
    }
}
