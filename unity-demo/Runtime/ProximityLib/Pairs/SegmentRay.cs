// Copied from src/ProximityLib/Pairs/SegmentRay.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a ray (3D): never negative; for a segment parallel to the ray the first endpoint minimum of the segment kernel on the cut ray; ParameterA is the segment parameter, ParameterB the ray's t ≥ 0. Algorithm: the ray cut to the stretch between the projections of the segment's endpoints clamped at 0 (it holds a closest point), then the robust segment–segment kernel (Eberly; Lagrange-identity determinant) in the frame of the ray's origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Ray3 b, out bool inRange) => Kernels.LinearCapsule(Linear.Ray(b.Origin, b.Direction), 0, a.Start, a.End, 0, false, false, out inRange).Swapped();
        /// <summary>Closest distance between a segment and a ray (2D): never negative (0 where they cross); for a segment parallel to the ray the first endpoint minimum of the segment kernel on the cut ray; ParameterA is the segment parameter, ParameterB the ray's t ≥ 0. Algorithm: the ray cut to the stretch between the projections of the segment's endpoints clamped at 0 (it holds a closest point), then the robust segment–segment kernel (Eberly; Lagrange-identity determinant) in the frame of the ray's origin.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Ray2 b, out bool inRange) => Kernels.LinearCapsule(Linear.Ray(b.Origin.To3(), b.Direction.To3()), 0, a.Start.To3(), a.End.To3(), 0, true, false, out inRange).Swapped().To2();
        /// <summary>The Distance of the 3D Core, bit for bit (Kernels.LinearCapsuleDistance).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Segment3 a, Ray3 b, out bool inRange) => Kernels.LinearCapsuleDistance(Linear.Ray(b.Origin, b.Direction), a.Start, a.End, 0, false, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Ray3 b, out bool inRange) => Kernels.LinearSegmentMeet(Linear.Ray(b.Origin, b.Direction), a.Start, a.End, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Ray2 b, out bool inRange) => Kernels.LinearSegmentMeet(Linear.Ray(b.Origin.To3(), b.Direction.To3()), a.Start.To3(), a.End.To3(), out inRange);
    }
}
