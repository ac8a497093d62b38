// Copied from src/ProximityLib/Pairs/CapsuleAabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a capsule and an AABB (3D): the axis segment's solid signed distance to the box less the radius (negative when overlapping: the axis's depth plus the radius); PointA is the axis witness (ParameterA its t) moved by the radius toward the box (apart) or against the push (overlapping; the face's outward normal when the axis just touches), PointB on the box. Algorithm: segment–box (convex piecewise-quadratic minimisation in the box frame; separating-axis depth, Ericson RTCD §5.3.3), then sd(K ⊕ ball r) = sd(K) − r.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Capsule3 a, in Aabb3 b, out bool inRange) => Kernels.CapsuleBox(a.Start, a.End, a.Radius, b.ToBox(), out inRange);
        /// <summary>Closest distance between a capsule and an AABB (2D): the axis segment's solid signed distance to the box less the radius (negative when overlapping: the axis's depth plus the radius); PointA is the axis witness (ParameterA its t) moved by the radius toward the box (apart) or against the push (overlapping; the face's outward normal when the axis just touches), PointB on the box. Algorithm: segment–box (convex piecewise-quadratic minimisation in the box frame; separating-axis depth, Ericson RTCD §5.3.3), then sd(K ⊕ ball r) = sd(K) − r.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Capsule2 a, in Aabb2 b, out bool inRange) => Kernels.CapsuleBox(a.Start.To3(), a.End.To3(), a.Radius, b.ToBox(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule3 a, in Aabb3 b, out bool inRange) => Kernels.CapsuleBoxDistance(a.Start, a.End, a.Radius, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule2 a, in Aabb2 b, out bool inRange) => Kernels.CapsuleBoxDistance(a.Start.To3(), a.End.To3(), a.Radius, b.ToBox(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule3 a, in Aabb3 b, out bool inRange) => Kernels.CapsuleBoxOverlaps(a.Start, a.End, a.Radius, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule2 a, in Aabb2 b, out bool inRange) => Kernels.CapsuleBoxOverlaps(a.Start.To3(), a.End.To3(), a.Radius, b.ToBox(), out inRange);
    }
}
