using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a half-space (3D): Normal·(point − Point), negative inside (minus the depth); witnesses the point and its foot on the boundary. Algorithm: one dot product from the stored boundary point (Ericson RTCD §5.1.1).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, HalfSpace b, out bool inRange) => Kernels.BallHalfSpace(a, 0, b.Normal, b.Point, 0, out inRange);
        /// <summary>Closest distance between a point and a half-plane (2D): Normal·(point − Point), negative inside (minus the depth); witnesses the point and its foot on the boundary. Algorithm: one dot product from the stored boundary point (Ericson RTCD §5.1.1).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in HalfPlane b, out bool inRange) => Kernels.BallHalfSpace(a.To3(), 0, b.Normal.To3(), b.Point.To3(), 0, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in HalfSpace b, out bool inRange) => Kernels.BallHalfSpaceDistance(a, 0, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in HalfPlane b, out bool inRange) => Kernels.BallHalfSpaceDistance(a.To3(), 0, b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
