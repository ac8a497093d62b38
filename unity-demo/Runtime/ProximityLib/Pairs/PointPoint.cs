// Copied from src/ProximityLib/Pairs/PointPoint.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a point (3D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, Vector3D b, out bool inRange) => Kernels.PointPoint(a, b, out inRange);
        /// <summary>Closest distance between a point and a point (2D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Vector2D b, out bool inRange) => Kernels.PointPoint(a.To3(), b.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, Vector3D b, out bool inRange) => Kernels.PointPointDistance(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, Vector2D b, out bool inRange) => Kernels.PointPointDistance(a.To3(), b.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, Vector3D b) => a == b;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Vector2D b) => a == b;
    }
}
