using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a segment (3D): never negative; ParameterB is the clamped projection parameter. Algorithm: clamped projection with the residual formed from the nearer endpoint (robust form of paper Eq. 9–11; Eq. 10 cancels).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Segment3 b, out bool inRange) => Kernels.PointSegment(a, b.Start, b.End, out inRange);
        /// <summary>Closest distance between a point and a segment (2D): never negative; ParameterB is the clamped projection parameter. Algorithm: clamped projection with the residual formed from the nearer endpoint (robust form of paper Eq. 9–11; Eq. 10 cancels).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Segment2 b, out bool inRange) => Kernels.PointSegment(a.To3(), b.Start.To3(), b.End.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Vector3D a, in Segment3 b, out bool inRange) => Kernels.PointSegmentDistance(a, b.Start, b.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Segment2 b, out bool inRange) => Kernels.PointSegmentDistance(a.To3(), b.Start.To3(), b.End.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Vector3D a, in Segment3 b, out bool inRange) => Kernels.PointOnSegment(a, b.Start, b.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Segment2 b, out bool inRange) => Kernels.PointOnSegment(a.To3(), b.Start.To3(), b.End.To3(), out inRange);
    }
}
