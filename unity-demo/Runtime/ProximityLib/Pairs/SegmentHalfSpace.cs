// Copied from src/ProximityLib/Pairs/SegmentHalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a half-space (3D): the lower endpoint's height Normal·(end − Point), negative when the segment enters (minus the depth of its deepest end); witnesses that endpoint (ParameterA 0 or 1) and its foot on the boundary. A segment parallel to the boundary (equal heights) is witnessed at Start. Algorithm: the height is linear along the segment, so an endpoint is lowest; two dot products from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Segment3 a, HalfSpace b, out bool inRange) => Kernels.CapsuleHalfSpace(a.Start, a.End, 0, b.Normal, b.Point, out inRange);
        /// <summary>Closest distance between a segment and a half-plane (2D): the lower endpoint's height Normal·(end − Point), negative when the segment enters (minus the depth of its deepest end); witnesses that endpoint (ParameterA 0 or 1) and its foot on the boundary. A segment parallel to the boundary (equal heights) is witnessed at Start. Algorithm: the height is linear along the segment, so an endpoint is lowest; two dot products from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in HalfPlane b, out bool inRange) => Kernels.CapsuleHalfSpace(a.Start.To3(), a.End.To3(), 0, b.Normal.To3(), b.Point.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in HalfSpace b, out bool inRange) => Kernels.CapsuleHalfSpaceDistance(a.Start, a.End, 0, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment2 a, in HalfPlane b, out bool inRange) => Kernels.CapsuleHalfSpaceDistance(a.Start.To3(), a.End.To3(), 0, b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment3 a, HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Segment2 a, HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
