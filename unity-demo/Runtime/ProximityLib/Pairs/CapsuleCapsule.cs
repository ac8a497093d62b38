// Copied from src/ProximityLib/Pairs/CapsuleCapsule.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a capsule and a capsule (3D): negative when they overlap (depth = sum of the radii − distance of the axes: their Minkowski difference is flat); witnesses pushed by each radius along the unit residual of the axes' closest pair, for meeting axes along the common normal (parallel axes: <c>AnyPerpendicular</c> of the first direction); parallel overlapping axes: the segment kernel's first endpoint minimum; computed on the canonically ordered pair (src/ProximityLib/Double/Order.cs, then the radius), so the same in either argument order; ParameterA/B are the axis parameters. Algorithm: robust segment–segment distance of the axes (Eberly; Lagrange-identity determinant) less both radii.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Capsule3 a, in Capsule3 b, out bool inRange)
        {
            // A call site per order (the kernel is out of line): choosing the shapes first copied both capsules and the
            // 80-byte result once more, and on mixed inputs the capsule–capsule query took 1.2x as long.
            return Kernels.SwapCapsules(a.Start, a.End, a.Radius, b.Start, b.End, b.Radius)
                ? Kernels.CapsuleCapsule(b.Start, b.End, b.Radius, a.Start, a.End, a.Radius, false, out inRange).Swapped()
                : Kernels.CapsuleCapsule(a.Start, a.End, a.Radius, b.Start, b.End, b.Radius, false, out inRange);
        }
        /// <summary>Closest distance between a capsule and a capsule (2D): negative when they overlap; separated axes give their distance less both radii; crossing axes give −(both radii + the crossing depth of the axes, the smallest push of one axis off the other along a face normal of their Minkowski difference), the witnesses an endpoint and its image across that face pushed by the radii; computed on the canonically ordered pair (src/ProximityLib/Double/Order.cs, then the radius), so the same in either argument order; ParameterA/B are the axis parameters. Algorithm: robust segment–segment distance of the axes (Eberly) less both radii; crossing depth by the separating-axis test over the axes' normals and directions (Gottschalk).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Capsule2 a, in Capsule2 b, out bool inRange)
        {
            return Kernels.SwapCapsules(a.Start.To3(), a.End.To3(), a.Radius, b.Start.To3(), b.End.To3(), b.Radius)
                ? Kernels.CapsuleCapsule(b.Start.To3(), b.End.To3(), b.Radius, a.Start.To3(), a.End.To3(), a.Radius, true, out inRange).Swapped().To2()
                : Kernels.CapsuleCapsule(a.Start.To3(), a.End.To3(), a.Radius, b.Start.To3(), b.End.To3(), b.Radius, true, out inRange).To2();
        }
        /// <summary>
        /// The Distance of <see cref="Core(in Capsule3, in Capsule3, out bool)"/>, bit for bit, without its witnesses: in 3D the
        /// axes' Minkowski difference is flat, so every path of Core (the fast one, and LinearCapsule's for nearly touching
        /// or meeting axes, which calls the same segment kernel) answers the axes' distance less ra + rb, in either
        /// argument order (the kernel's squared distance is the same bits in both; ra + rb = rb + ra).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule3 a, in Capsule3 b, out bool inRange)
        {
            double dist = Math.Sqrt(Kernels.SegmentSegmentInline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange));
            double r = a.Radius + b.Radius;
            inRange &= r <= double.MaxValue;
            return dist - r;
        }
        /// <summary>
        /// The Distance of <see cref="Core(in Capsule2, in Capsule2, out bool)"/>, bit for bit: the planar segment kernel gives the
        /// lifted one's squared distance and range verdict, bit for bit; axes clear of each other in either argument order
        /// (<see cref="Kernels.AxesClear(double, Vector3D, Vector3D, Vector3D, Vector3D)"/>) take Core's fast path in both,
        /// the axes' distance less ra + rb; nearer axes may cross (Core's crossing depth), so anything else asks Core.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule2 a, in Capsule2 b, out bool inRange)
        {
            double dist = Math.Sqrt(Kernels.SegmentSegment2Inline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange));
            if (!Kernels.AxesClear(dist, a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3())) return Core(a, b, out inRange).Distance;
            double r = a.Radius + b.Radius;
            inRange &= r <= double.MaxValue;
            return dist - r;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule3 a, in Capsule3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        // Between's Distance ≤ 0, without its crossing depth where the verdict does not need it (Kernels.OverlapsByAxes).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule2 a, in Capsule2 b, out bool inRange)
        {
            double dist = Math.Sqrt(Kernels.SegmentSegment2Inline(a.Start, a.End, b.Start, b.End, out _, out _, out inRange));
            int verdict = Kernels.OverlapsByAxes(dist, a.Radius + b.Radius, a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3(), ref inRange);
            return verdict == 0 ? ClosestDistance.Core(a, b, out inRange).Distance <= 0 : verdict > 0;
        }
    }
}
