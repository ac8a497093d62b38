// Copied from src/ProximityLib/Double/Kernels/TrianglePairKernels.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        // ---- Triangle against triangle ----

        /// <summary>
        /// Two 3D triangles (neither solid): the least of the six edge–triangle distances (<see cref="SegmentTriangle(Vector3D, Vector3D, in TriFrame, out double, out Vector3D, out Vector3D, out bool)"/>),
        /// A's edges first, the first of equal ones. Two triangles meet exactly when an edge of one meets the other (the
        /// intersection of two convex sets in a plane or across planes reaches a boundary of one of them), so 0 comes with a
        /// common point; no plane-crossing interval is intersected, which is where the classic tests fail on coplanar input.
        /// Both frames share one scale, from the whole configuration.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 TriangleTriangle(Vector3D a0, Vector3D a1, Vector3D a2, Vector3D b0, Vector3D b1, Vector3D b2, out bool inRange)
        {
            // In the frame of a0: a crossing or an edge point is then rounded at the configuration's scale, not at its
            // distance from the world origin, so a translation adds no error.
            var o = a0;
            a0 = default; a1 -= o; a2 -= o; b0 -= o; b1 -= o; b2 -= o;
            double size2 = TriFrame.Size2(a0, a1, a2, b0, b1) + (b2 - a0).LengthSquared;
            double k = InverseSizeScale(size2);
            var fa = new TriFrame(a0, a1, a2, k);
            var fb = new TriFrame(b0, b1, b2, k);
            double best = double.PositiveInfinity;
            bool fine = true;
            Vector3D pa = a0, pb = b0;
            for (int i = 0; i < 3 && best > 0; i++)
            {
                fa.Edge(i, out var v0, out var v1);
                double g = SegmentTriangle(v0, v1, fb, out _, out var x, out var q, out bool fineEdge);
                if (g < best) { best = g; pa = x; pb = q; fine = fineEdge; }
            }
            for (int i = 0; i < 3 && best > 0; i++)
            {
                fb.Edge(i, out var v0, out var v1);
                double g = SegmentTriangle(v0, v1, fa, out _, out var x, out var q, out bool fineEdge);
                if (g < best) { best = g; pa = q; pb = x; fine = fineEdge; }
            }
            inRange = (Range.In(size2) | (a0 == a1 & a0 == a2 & a0 == b0 & a0 == b1 & a0 == b2)) & fine;
            return new DistanceResult3(Math.Sqrt(best), best, pa + o, pb + o, 0, 0);
        }

        /// <summary>
        /// Two solid 2D triangles (z = 0). Both with area: the separating-axis test over the six edge normals (the facet
        /// normals of the Minkowski difference; strict, a zero axis separates nothing); apart, the least of the nine
        /// edge–edge distances (the closest pair of disjoint convex polygons has a vertex on one side); overlapping, the
        /// least push over the six axes, and the witnesses of A moved by it, just touching, moved back. A flat triangle is
        /// the segment (its longest edge) or point it is: against a solid one, <see cref="SegmentTriangle2(Vector3D, Vector3D, in TriFrame, bool, out double, out Vector3D, out Vector3D, out Vector3D, out bool)"/>;
        /// two flat ones, the nine edge–edge distances (never negative).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 TriangleTriangle2(Vector3D a0, Vector3D a1, Vector3D a2, Vector3D b0, Vector3D b1, Vector3D b2, out bool inRange)
        {
            double size2 = TriFrame.Size2(a0, a1, a2, b0, b1) + (b2 - a0).LengthSquared;
            double k = InverseSizeScale(size2);
            var fa = new TriFrame(a0, a1, a2, k);
            var fb = new TriFrame(b0, b1, b2, k);
            bool sized = Range.In(size2) | (a0 == a1 & a0 == a2 & a0 == b0 & a0 == b1 & a0 == b2);
            double areaA = Area2(fa), areaB = Area2(fb);
            double sd;
            bool fine = true;
            Vector3D pa, pb;
            if (areaA == 0 && areaB != 0)
            {
                LongestEdge(fa, out var v0, out var v1);
                sd = SegmentTriangle2(v0, v1, fb, false, out _, out pa, out pb, out _, out fine);
            }
            else if (areaB == 0 && areaA != 0)
            {
                LongestEdge(fb, out var v0, out var v1);
                sd = SegmentTriangle2(v0, v1, fa, false, out _, out pb, out pa, out _, out fine);
            }
            else if (areaA == 0 || !TriangleTriangleSat2(fa, fb, false, out _, out _))
            {
                double g = EdgePairs(fa, fb, default, out pa, out pb, out fine);
                sd = Math.Sqrt(g);
            }
            else
            {
                TriangleTriangleSat2(fa, fb, true, out double depth, out var dir);
                var push = dir * depth;
                EdgePairs(fa, fb, push, out pa, out pb, out fine); // a just-touching gap whose square underflowed may pick the wrong pair
                pa -= push;
                sd = depth > 0 ? -depth : 0;
            }
            inRange = sized & fine;
            return new DistanceResult3(sd, sd > 0 ? sd * sd : 0, pa, pb, 0, 0);
        }

        /// <summary>Whether two solid 2D triangles overlap (see <see cref="TriangleTriangle2"/>).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static bool TriangleTriangleOverlaps2(Vector3D a0, Vector3D a1, Vector3D a2, Vector3D b0, Vector3D b1, Vector3D b2, out bool inRange)
        {
            double size2 = TriFrame.Size2(a0, a1, a2, b0, b1) + (b2 - a0).LengthSquared;
            double k = InverseSizeScale(size2);
            var fa = new TriFrame(a0, a1, a2, k);
            var fb = new TriFrame(b0, b1, b2, k);
            inRange = Range.In(size2) | (a0 == a1 & a0 == a2 & a0 == b0 & a0 == b1 & a0 == b2);
            double areaA = Area2(fa), areaB = Area2(fb);
            if (areaA == 0 && areaB != 0)
            {
                LongestEdge(fa, out var v0, out var v1);
                return SegmentTriangleOverlaps2(v0, v1, fb);
            }
            if (areaB == 0 && areaA != 0)
            {
                LongestEdge(fb, out var v0, out var v1);
                return SegmentTriangleOverlaps2(v0, v1, fa);
            }
            if (areaA != 0) return TriangleTriangleSat2(fa, fb, false, out _, out _);
            bool met = EdgePairs(fa, fb, default, out _, out _, out bool fine) == 0;
            inRange &= fine;
            return met;
        }

        /// <summary>
        /// The separating-axis test of two solid 2D triangles over their six edge normals, projected relative to A's first
        /// vertex in the shared scaled frame; with <paramref name="measure"/>, also the least push of A (world length) and its direction.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool TriangleTriangleSat2(in TriFrame fa, in TriFrame fb, bool measure, out double depth, out Vector3D dir)
        {
            var b0 = (fb.A - fa.A) * fa.K;
            var b1 = b0 + fb.E1;
            var b2 = b0 + fb.E2;
            double best = double.PositiveInfinity;
            dir = default;
            bool separated = false;
            var zero = default(Vector3D);
            for (int i = 0; i < 6 && (measure || !separated); i++)
            {
                var e = i switch { 0 => fa.E1, 1 => fa.E2, 2 => fa.E3, 3 => fb.E1, 4 => fb.E2, _ => fb.E3 };
                var axis = Perp(e);
                Project(axis, zero, fa.E1, fa.E2, out double minA, out double maxA);
                Project(axis, b0, b1, b2, out double minB, out double maxB);
                separated |= minA > maxB || maxA < minB;
                if (measure) PushAxis(axis, minA, maxA, minB, maxB, ref best, ref dir);
            }
            depth = best < double.PositiveInfinity ? Math.Max(0, best) / fa.K : 0;
            if (dir == default) dir = Vector3D.UnitX;
            return !separated;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Project(Vector3D axis, Vector3D v0, Vector3D v1, Vector3D v2, out double min, out double max)
        {
            double p0 = Vector3D.Dot(v0, axis), p1 = Vector3D.Dot(v1, axis), p2 = Vector3D.Dot(v2, axis);
            min = Math.Min(p0, Math.Min(p1, p2));
            max = Math.Max(p0, Math.Max(p1, p2));
        }

        /// <summary>The least squared distance over the nine pairs of an edge of A (moved by <paramref name="shift"/>) and an edge of B (A's edges outer, the first of equal ones); <paramref name="fine"/>: that pair's own range check (in range or an exact 0).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double EdgePairs(in TriFrame fa, in TriFrame fb, Vector3D shift, out Vector3D pa, out Vector3D pb, out bool fine)
        {
            double best = double.PositiveInfinity;
            pa = fa.A; pb = fb.A;
            fine = true;
            for (int i = 0; i < 3; i++)
            {
                fa.Edge(i, out var a0, out var a1);
                a0 += shift;
                a1 += shift;
                for (int j = 0; j < 3; j++)
                {
                    fb.Edge(j, out var b0, out var b1);
                    double g = SegmentSegmentFlat(a0, a1, b0, b1, out double s, out double t, out bool fineEdge);
                    if (g < best) { best = g; pa = SegmentPoint(a0, a1, s); pb = SegmentPoint(b0, b1, t); fine = fineEdge; }
                }
            }
            return best;
        }

        /// <summary>The longest edge of a triangle (the first of equal ones), as its two vertices: a flat triangle's hull.</summary>
        private static void LongestEdge(in TriFrame f, out Vector3D v0, out Vector3D v1)
        {
            double l1 = f.E1.LengthSquared, l2 = f.E2.LengthSquared, l3 = f.E3.LengthSquared;
            int i = l1 >= l2 ? (l1 >= l3 ? 0 : 1) : (l2 >= l3 ? 2 : 1);
            f.Edge(i, out v0, out v1);
        }

        // ---- Triangle against box ----

        /// <summary>
        /// A triangle (3D: not solid; 2D: solid) against a solid box, in the box frame (triangle vertices made box-local
        /// once, the box exact there). Overlap: the separating-axis test (Akenine-Möller's 13 axes: box normals, the
        /// triangle's normal formed with exact products, edge × box-axis; 2D: box normals and edge normals), on a copy
        /// scaled by a power of two, projected honestly, so a zero or noisy axis can only fail to separate. Apart: the
        /// least of the triangle's edges against the box (the closed form of <see cref="SegmentBoxLocal"/>) and, in 3D,
        /// the box's twelve edges against the triangle (a closest point inside the triangle faces a box edge, vertex or
        /// a parallel face, whose boundary then attains it too), the first of equal ones. Overlapping: the least push over
        /// the same axes (the facet normals of the Minkowski difference; any direction overestimates), and the witnesses
        /// of the triangle moved by it, just touching, moved back.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 TriangleBox(Vector3D a, Vector3D b, Vector3D c, in Box box, out bool inRange)
        {
            var o = box.Origin;
            var ra = a - o;
            var rb = b - o;
            var rc = c - o;
            double size = Range.MaxAbs(ra, rb, rc, box.Hi - box.Lo);
            inRange = Range.Box(size);
            double k = Num.InversePowerOfTwo(size);
            var la = box.ToLocal(ra);
            var lb = box.ToLocal(rb);
            var lc = box.ToLocal(rc);
            Vector3D pa, pb;
            if (!TriangleBoxSat(la, lb, lc, box, true, out double depth, out var dir))
            {
                double g = TriangleBoxApart(la, lb, lc, box.Lo, box.Hi, box.Planar, k, out pa, out pb);
                // A subnormal squared gap has lost bits, and a zero one is rare here (found apart) and may have underflowed:
                // the slow path answers both at a scale where they have not (2^k-scaled inputs agree).
                inRange &= Range.In(g);
                return new DistanceResult3(Math.Sqrt(g), g, o + box.ToWorldOffset(pa), o + box.ToWorldOffset(pb), 0, 0);
            }
            var push = dir * depth;
            TriangleBoxApart(la + push, lb + push, lc + push, box.Lo, box.Hi, box.Planar, k, out pa, out pb);
            return new DistanceResult3(depth > 0 ? -depth : 0, 0, o + box.ToWorldOffset(pa - push), o + box.ToWorldOffset(pb), 0, 0);
        }

        /// <summary>Whether a triangle meets a solid box: the separating-axis test of <see cref="TriangleBox"/>.</summary>
        public static bool TriangleBoxOverlaps(Vector3D a, Vector3D b, Vector3D c, in Box box, out bool inRange)
        {
            var o = box.Origin;
            var ra = a - o;
            var rb = b - o;
            var rc = c - o;
            inRange = Range.Box(Range.MaxAbs(ra, rb, rc, box.Hi - box.Lo));
            return TriangleBoxSat(box.ToLocal(ra), box.ToLocal(rb), box.ToLocal(rc), box, false, out _, out _);
        }

        /// <summary>
        /// The separating-axis test of the box-local triangle (la, lb, lc) against the box, relative to its centre and
        /// scaled by a power of two; with <paramref name="measure"/>, the least push of the triangle (box-local, unscaled
        /// length) and its unit direction.
        /// </summary>
        private static bool TriangleBoxSat(Vector3D la, Vector3D lb, Vector3D lc, in Box box, bool measure, out double depth, out Vector3D dir)
        {
            var ctr = box.LocalCenter;
            var h = box.Half;
            var m0 = la - ctr;
            var m1 = lb - ctr;
            var m2 = lc - ctr;
            double m = Range.MaxAbs(m0, m1, m2, h);
            double k = m > 0 ? Num.InversePowerOfTwo(m) : 1;
            m0 *= k; m1 *= k; m2 *= k; h *= k;
            double best = double.PositiveInfinity;
            dir = default;
            bool separated = BoxAxis(Vector3D.UnitX, m0, m1, m2, h, measure, ref best, ref dir)
                | BoxAxis(Vector3D.UnitY, m0, m1, m2, h, measure, ref best, ref dir);
            var f0 = m1 - m0;
            var f1 = m2 - m1;
            var f2 = m0 - m2;
            if (box.Planar)
            {
                separated |= BoxAxis(Perp(f0), m0, m1, m2, h, measure, ref best, ref dir)
                    | BoxAxis(Perp(f1), m0, m1, m2, h, measure, ref best, ref dir)
                    | BoxAxis(Perp(f2), m0, m1, m2, h, measure, ref best, ref dir);
            }
            else
            {
                separated |= BoxAxis(Vector3D.UnitZ, m0, m1, m2, h, measure, ref best, ref dir)
                    | BoxAxis(AccurateCross(f0, m2 - m0), m0, m1, m2, h, measure, ref best, ref dir)
                    | EdgeAxes(f0, m0, m1, m2, h, measure, ref best, ref dir)
                    | EdgeAxes(f1, m0, m1, m2, h, measure, ref best, ref dir)
                    | EdgeAxes(f2, m0, m1, m2, h, measure, ref best, ref dir);
            }
            depth = best < double.PositiveInfinity ? Math.Max(0, best) / k : 0;
            return !separated;
        }

        /// <summary>The three axes edge f × box axis: (0, f.z, −f.y), (−f.z, 0, f.x), (f.y, −f.x, 0).</summary>
        private static bool EdgeAxes(Vector3D f, Vector3D m0, Vector3D m1, Vector3D m2, Vector3D h, bool measure, ref double best, ref Vector3D dir) =>
            BoxAxis(new Vector3D(0, f.Z, -f.Y), m0, m1, m2, h, measure, ref best, ref dir)
            | BoxAxis(new Vector3D(-f.Z, 0, f.X), m0, m1, m2, h, measure, ref best, ref dir)
            | BoxAxis(Perp(f), m0, m1, m2, h, measure, ref best, ref dir);

        /// <summary>Whether the axis separates the triangle (m0, m1, m2) from the centred box of half-extents h; with <paramref name="measure"/>, its push too.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool BoxAxis(Vector3D axis, Vector3D m0, Vector3D m1, Vector3D m2, Vector3D h, bool measure, ref double best, ref Vector3D dir)
        {
            Project(axis, m0, m1, m2, out double min, out double max);
            double r = h.X * Math.Abs(axis.X) + h.Y * Math.Abs(axis.Y) + h.Z * Math.Abs(axis.Z);
            if (measure) PushAxis(axis, min, max, -r, r, ref best, ref dir);
            return min > r || max < -r;
        }

        /// <summary>
        /// Squared distance between the box-local triangle (la, lb, lc) and the box [lo, hi] when they are apart (0 when
        /// they touch), and a closest pair (box-local): the triangle's edges against the box, then in 3D the box's edges
        /// against the triangle. All on the copy scaled by k, the power of two that brings the configuration's size near 1,
        /// unscaled at the end (exact, so elsewhere the same bits): at the small end of the fast range the squared gaps of
        /// a triangle just touching the box underflow to equal zeros, and the first of them is not the pair the same shapes
        /// scaled up would pick.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double TriangleBoxApart(Vector3D la, Vector3D lb, Vector3D lc, Vector3D lo, Vector3D hi, bool planar, double k, out Vector3D pa, out Vector3D pb)
        {
            la *= k; lb *= k; lc *= k; lo *= k; hi *= k;
            double ik = 1 / k;
            double best = double.PositiveInfinity;
            pa = la; pb = lo;
            for (int i = 0; i < 3; i++)
            {
                var v0 = i == 0 ? la : (i == 1 ? lb : lc);
                var v1 = i == 0 ? lb : (i == 1 ? lc : la);
                var d = v1 - v0;
                double g = SegmentBoxLocal(v0, d, lo, hi, out double t);
                if (g < best) { best = g; pa = SegmentPoint(v0, v1, t); pb = Clamp(v0 + d * t, lo, hi); }
            }
            if (planar || best == 0) return Unscaled(best, ik, ref pa, ref pb);
            double size2 = TriFrame.Size2(la, lb, lc, lo, hi);
            var f = new TriFrame(la, lb, lc, InverseSizeScale(size2));
            for (int i = 0; i < 3 && best > 0; i++)
            {
                for (int corner = 0; corner < 8 && best > 0; corner++)
                {
                    if ((corner & (1 << i)) != 0) continue;
                    var e0 = Corner(lo, hi, corner);
                    var e1 = Corner(lo, hi, corner | (1 << i));
                    double g = SegmentTriangle(e0, e1, f, out _, out var x, out var q, out _);
                    if (g < best) { best = g; pa = q; pb = x; }
                }
            }
            return Unscaled(best, ik, ref pa, ref pb);
        }

        /// <summary>A squared gap and its pair found on a copy scaled by 1/ik, unscaled (exact: ik is a power of two).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Unscaled(double g2, double ik, ref Vector3D pa, ref Vector3D pb)
        {
            pa *= ik;
            pb *= ik;
            return g2 * ik * ik;
        }
    }
}
