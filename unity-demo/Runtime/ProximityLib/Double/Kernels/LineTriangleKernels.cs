// Copied from src/ProximityLib/Double/Kernels/LineTriangleKernels.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// A line (origin o, unit direction u) against a triangle, in the frame of the triangle's first vertex a (so a
        /// translation of the whole configuration adds no error): the triangle's edges b − a, c − a, the line's origin
        /// o − a, and the stretch [lo, hi] of the vertices' projections t = u·(v − o). Every common point, and every
        /// closest point of the line (the projection of a closest point of the triangle, a convex combination of the
        /// vertices), has t in that stretch (for a ray, clamped at 0). <paramref name="margin"/> covers the projections'
        /// rounding (a few u·|v − o|; 2^-40 of the largest offset), which could otherwise cut off a common point: a line
        /// through a vertex, or along the triangle's normal.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TriangleStretch(Vector3D o, Vector3D u, Vector3D a, Vector3D b, Vector3D c,
            out double lo, out double hi, out double margin, out Vector3D oa, out Vector3D eb, out Vector3D ec)
        {
            var wa = a - o;
            var wb = b - o;
            var wc = c - o;
            double ta = Vector3D.Dot(u, wa), tb = Vector3D.Dot(u, wb), tc = Vector3D.Dot(u, wc);
            lo = Math.Min(ta, Math.Min(tb, tc));
            hi = Math.Max(ta, Math.Max(tb, tc));
            margin = Range.MaxAbs(wa, wb, wc) * 9.094947017729282e-13;
            oa = -wa;
            eb = b - a;
            ec = c - a;
        }

        /// <summary>The triangle's frame at a = 0 (edges eb, ec), scaled by the power of two of the configuration's size with the segment [p0, p1]; <paramref name="sized"/>: that size is in the fast range and at least <paramref name="lowest2"/> (or everything is 0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static TriFrame StretchFrame(Vector3D eb, Vector3D ec, Vector3D p0, Vector3D p1, double lowest2, out bool sized)
        {
            double size2 = TriFrame.Size2(default, eb, ec, p0, p1);
            sized = (Range.In(size2) & size2 >= lowest2) | (eb == default & ec == default & p0 == default & p1 == default);
            return new TriFrame(default, eb, ec, InverseSizeScale(size2));
        }

        /// <summary>
        /// 2^-800: the least squared size of the 2D solid stretch's fast path. Its depth search and push pass through
        /// quantities far below the size (the rounding margin is 2^-40 of it); measured, the planar kernel stopped
        /// scaling exactly below a size of about 2^-445 (fuzz case 98:1000000011741), so the fast path keeps a wide
        /// margin above that and smaller configurations take the rescaling slow path.
        /// </summary>
        private const double PlanarLowest2 = 1.499696813895631e-241;

        /// <summary>
        /// The segment that answers a line or ray against a solid 2D triangle: the stretch (<see cref="TriangleStretch"/>)
        /// widened by its rounding margin and by twice the sum of the edges' largest components (at least the triangle's
        /// diameter), so a push with a component along the line clears the cut ends no sooner than a sideways one clears
        /// the line (the segment's depth is the line's), then for a ray clamped at 0. Inlined: without dynamic PGO the JIT
        /// left it a call (ab, 2 × 7, no PGO: 2D line and ray against a triangle 0.89–0.93; with PGO 0.94–1.01).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static TriFrame SolidStretch(Vector3D o, Vector3D u, bool ray, Vector3D a, Vector3D b, Vector3D c,
            out double lo, out double hi, out Vector3D p0, out Vector3D p1, out bool sized)
        {
            TriangleStretch(o, u, a, b, c, out lo, out hi, out double m, out var oa, out var eb, out var ec);
            m += 2 * (Range.MaxAbs(eb) + Range.MaxAbs(ec));
            lo -= m;
            hi += m;
            if (ray) { lo = Math.Max(lo, 0); hi = Math.Max(hi, 0); }
            p0 = oa + u * lo;
            p1 = oa + u * hi;
            return StretchFrame(eb, ec, p0, p1, PlanarLowest2, out sized);
        }

        /// <summary>The line's parameter at the clipped segment's parameter s (from the nearer end, as <see cref="SegmentPoint"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double StretchParameter(double lo, double hi, double s) => (s <= 0.5 ? lo + (hi - lo) * s : hi - (hi - lo) * (1 - s)) + 0;

        /// <summary>
        /// A line or ray (o, unit u) against a 3D triangle (not solid). A crossing of the plane inside the triangle is
        /// looked for on the stretch widened by its rounding margin (<see cref="TriangleStretch"/>); otherwise the
        /// segment–triangle kernel answers on the stretch itself (widened, an end could pull a witness off the minimum by
        /// the margin where the distance is flat to rounding). Apart: the closest pair, PointA = o + t·u; meeting: 0 with
        /// that point as both witnesses. <paramref name="inRange"/>: the configuration's squared size (relative to a) and
        /// the squared distance are in the fast range (or an exact 0: a crossing, or see <see cref="SegmentTriangle(Vector3D, Vector3D, in TriFrame, out double, out Vector3D, out Vector3D, out bool)"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 LinearTriangle(Vector3D o, Vector3D u, bool ray, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            TriangleStretch(o, u, a, b, c, out double lo, out double hi, out double m, out var oa, out var eb, out var ec);
            double wlo = lo - m, whi = hi + m;
            if (ray) { lo = Math.Max(lo, 0); hi = Math.Max(hi, 0); wlo = Math.Max(wlo, 0); whi = Math.Max(whi, 0); }
            var w0 = oa + u * wlo;
            var w1 = oa + u * whi;
            var f = StretchFrame(eb, ec, w0, w1, 0, out bool sized);
            double g, t;
            bool fine = true;
            Vector3D onTri;
            if (Crossing(w0, w1, f, out double s, out _))
            {
                g = 0;
                t = StretchParameter(wlo, whi, s);
                onTri = default;
            }
            else
            {
                g = SegmentTriangle(oa + u * lo, oa + u * hi, f, out s, out _, out onTri, out fine);
                t = StretchParameter(lo, hi, s);
            }
            inRange = sized & fine;
            var pa = o + u * t;
            return new DistanceResult3(Math.Sqrt(g), g, pa, g == 0 ? pa : onTri + a, t, 0);
        }

        /// <summary>
        /// A line or ray (o, unit u) against a solid 2D triangle (z = 0): the solid segment–triangle kernel on the clipped
        /// stretch, widened so its depth is the line's (<see cref="SolidStretch"/>): the separating-axis verdict over
        /// the edge normals and the line's normal; overlapping, the least push over the same axes (a line only sideways: an
        /// edge normal with a component along it cannot beat that; a ray also back along an edge normal n with n·u ≥ 0, by
        /// the distance from its origin to that edge's line) and the closest pair of the just-touching configuration, the
        /// line's point moved back. Whether the triangle is flat is decided by the exact orientation of the vertices as
        /// given; a flat one is the segment or point it is (never negative). Touching: one point as both witnesses.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 LinearTriangle2(Vector3D o, Vector3D u, bool ray, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            var f = SolidStretch(o, u, ray, a, b, c, out double lo, out double hi, out var p0, out var p1, out bool sized);
            double sd = SegmentTriangle2(p0, p1, f, Area2(f, a, b, c), false, out double s, out _, out var onTri, out _, out bool fine);
            inRange = sized & fine;
            double t = StretchParameter(lo, hi, s);
            var pa = o + u * t;
            return new DistanceResult3(sd, sd > 0 ? sd * sd : 0, pa, sd == 0 ? pa : onTri + a, t, 0);
        }

        /// <summary>Whether a line or ray meets a solid 2D triangle: the verdict of <see cref="LinearTriangle2"/> (separating axes, or for a flat triangle an exactly zero distance).</summary>
        public static bool LinearTriangleOverlaps2(Vector3D o, Vector3D u, bool ray, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            var f = SolidStretch(o, u, ray, a, b, c, out _, out _, out var p0, out var p1, out inRange);
            if (Area2(f, a, b, c) != 0) return SegmentTriangleOverlaps2(p0, p1, f);
            bool met = EdgesDistance(p0, p1, f, out _, out _, out _, out bool fine) == 0;
            inRange &= fine;
            return met;
        }
    }
}
