using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a line (3D): never negative; for a segment parallel to the line the closest pair at the segment's start (the segment kernel's first endpoint minimum on the cut line); ParameterA is the segment parameter, ParameterB the line's t. Algorithm: the line cut to the stretch between the projections of the segment's endpoints (it holds a closest point), then the robust segment–segment kernel (Eberly; Lagrange-identity determinant) in the frame of the line's origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Line3 b, out bool inRange) => Kernels.LinearCapsule(Linear.Line(b.Origin, b.Direction), 0, a.Start, a.End, 0, false, false, out inRange).Swapped();
        /// <summary>Closest distance between a segment and a line (2D): never negative (0 where the segment crosses the line); for a segment parallel to the line the closest pair at the segment's start; ParameterA is the segment parameter, ParameterB the line's t. Algorithm: the line cut to the stretch between the projections of the segment's endpoints (it holds a closest point), then the robust segment–segment kernel (Eberly; Lagrange-identity determinant) in the frame of the line's origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Line2 b, out bool inRange) => Kernels.LinearCapsule(Linear.Line(b.Origin.To3(), b.Direction.To3()), 0, a.Start.To3(), a.End.To3(), 0, true, false, out inRange).Swapped().To2();
        /// <summary>The Distance of the 3D Core, bit for bit (Kernels.LinearCapsuleDistance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Segment3 a, Line3 b, out bool inRange) => Kernels.LinearCapsuleDistance(Linear.Line(b.Origin, b.Direction), a.Start, a.End, 0, false, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Line3 b, out bool inRange) => Kernels.LinearSegmentMeet(Linear.Line(b.Origin, b.Direction), a.Start, a.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Line2 b, out bool inRange) => Kernels.LinearSegmentMeet(Linear.Line(b.Origin.To3(), b.Direction.To3()), a.Start.To3(), a.End.To3(), out inRange);
    }
}
