// Copied from src/ProximityLib/Pairs/PointAabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an AABB (3D): negative inside (depth to the nearest face, ties to the lower axis, min face first). Algorithm: clamp to the box (Ericson RTCD §5.1.3; paper Eq. 22); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Aabb3 b, out bool inRange) => Kernels.PointAabbPair(a, b.Min, b.Max, false, out inRange);
        /// <summary>Closest distance between a point and an AABB (2D): negative inside (depth to the nearest face, ties to the lower axis, min face first). Algorithm: clamp to the box (Ericson RTCD §5.1.3; paper Eq. 22); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Aabb2 b, out bool inRange) => Kernels.PointAabbPair(a.To3(), b.Min.To3(), b.Max.To3(), true, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Vector3D a, in Aabb3 b, out bool inRange) => Kernels.PointAabbDistance(a, b.Min, b.Max, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Aabb2 b, out bool inRange) => Kernels.PointAabbDistance(a.To3(), b.Min.To3(), b.Max.To3(), true, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Vector3D a, in Aabb3 b) => Kernels.PointInAabb(a, b.Min, b.Max);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Aabb2 b) => Kernels.PointInAabb(a.To3(), b.Min.To3(), b.Max.To3());
    }
}
