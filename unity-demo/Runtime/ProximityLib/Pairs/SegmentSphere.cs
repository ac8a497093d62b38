// Copied from src/ProximityLib/Pairs/SegmentSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a sphere (3D): negative when the segment enters the sphere (depth = radius − distance from center to segment). Algorithm: point–segment distance from the center, less the radius (paper Eq. 16).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Sphere b, out bool inRange) => Kernels.PointCapsule(b.Center, b.Radius, a.Start, a.End, 0, out inRange).Swapped();
        /// <summary>Closest distance between a segment and a circle (2D): negative when the segment enters the sphere (depth = radius − distance from center to segment). Algorithm: point–segment distance from the center, less the radius (paper Eq. 16).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Circle b, out bool inRange) => Kernels.PointCapsule(b.Center.To3(), b.Radius, a.Start.To3(), a.End.To3(), 0, out inRange).Swapped().To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in Sphere b, out bool inRange) => Kernels.PointSegmentDistance(b.Center, a.Start, a.End, out inRange) - b.Radius;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment2 a, in Circle b, out bool inRange) => Kernels.PointSegmentDistance(b.Center.To3(), a.Start.To3(), a.End.To3(), out inRange) - b.Radius;
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Sphere b, out bool inRange) => Kernels.SegmentInSphere(a.Start, a.End, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Circle b, out bool inRange) => Kernels.SegmentInSphere(a.Start.To3(), a.End.To3(), b.Center.To3(), b.Radius, out inRange);
    }
}
