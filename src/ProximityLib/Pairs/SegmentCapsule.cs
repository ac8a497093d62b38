using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        // 3D stays on LinearCapsule: a segment through the capsule's axis (axes meeting, which Kernels.CapsuleCapsule hands
        // back to LinearCapsule after its own segment kernel) is common for this pair, and forming that kernel twice made
        // the query 1.2–1.5x slower on the benchmark's mixed inputs; in the plane the separated case gains more than that.
        /// <summary>Closest distance between a segment and a capsule (3D): negative when the segment enters the capsule; 3D: distance of the axes less the radius (the axes' Minkowski difference is flat); witnesses pushed along the unit residual, or for meeting axes along the common normal A.dir × axis (parallel: <c>AnyPerpendicular</c> of A's direction); ParameterB is the axis parameter. Algorithm: robust segment–segment distance of segment and axis (Eberly; Lagrange-identity determinant) less the radius (capsule = segment ⊕ ball).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Segment3 a, in Capsule3 b, out bool inRange) => Kernels.LinearCapsule(Linear.Segment(a.Start, a.End), 0, b.Start, b.End, b.Radius, false, true, out inRange);
        /// <summary>Closest distance between a segment and a capsule (2D): negative when the segment enters the capsule; 2D: separated axes give their distance less the radius; crossing axes give −(radius + the crossing depth of the axes, the smallest push of one axis off the other along a face normal of their Minkowski difference), the witnesses an endpoint and its image across that face, pushed by the radius; ParameterB is the axis parameter. Algorithm: robust segment–segment distance of segment and axis (Eberly) less the radius; crossing depth by the separating-axis test over the axes' normals and directions (Gottschalk).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Segment2 a, in Capsule2 b, out bool inRange) => Kernels.CapsuleCapsule(a.Start.To3(), a.End.To3(), 0, b.Start.To3(), b.End.To3(), b.Radius, true, out inRange).To2();
        /// <summary>The Distance of the 3D Core, bit for bit: the segment kernel inline (LinearCapsule calls it for a segment).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Segment3 a, in Capsule3 b, out bool inRange)
        {
            double dist = Math.Sqrt(Kernels.SegmentSegmentInline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange));
            double r = 0 + b.Radius; // LinearCapsule's ra + rb
            inRange &= r <= double.MaxValue;
            return dist - r;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment3 a, in Capsule3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        // Between's Distance ≤ 0, without its crossing depth where the verdict does not need it (Kernels.OverlapsByAxes).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Segment2 a, in Capsule2 b, out bool inRange)
        {
            double dist = Math.Sqrt(Kernels.SegmentSegment2Inline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange));
            int verdict = Kernels.OverlapsByAxes(dist, 0 + b.Radius, a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3(), ref inRange);
            return verdict == 0 ? ClosestDistance.Core(a, b, out inRange).Distance <= 0 : verdict > 0;
        }
    }
}
