using System;
using System.Collections.Generic;
using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>
    /// Exact signed distances and overlap verdicts, written without the library's case analysis:
    /// overlap by an exact separating-axis test over a generous candidate set (edge directions, their pairwise cross
    /// products and, for lower-dimensional shapes, the triple products); distance between disjoint polytopes as the
    /// minimum over every pair of features (vertex, edge, face) with dimensions summing to at most 2, each solved
    /// exactly as a least-squares problem on the features' affine hulls and kept only when its parameters lie inside
    /// both (the KKT/active-set enumeration); penetration depth of polytopes as the minimum over the same candidate
    /// directions of the projected overlap (the facet normals of the Minkowski difference are among them, and any
    /// direction overestimates). Spheres reduce to their centers and capsules to their axes, less the radius
    /// (sd(K ⊕ ball r) = sd(K) − r with the SOLID signed distance of K whenever either shape is solid). Lines and rays
    /// against a bounded partner are clipped exactly to a segment (see <see cref="Clip"/>); line/ray pairs are a
    /// two-variable convex QP solved by active sets; half-spaces are linear inequalities. Squared quantities are exact
    /// rationals; only the final square root (and a half-space's |Normal|) is an approximation, to about 2^-160 relative.
    /// <para>
    /// Unbounded penetration (the contract's −∞: a line crossing a half-space boundary, a ray with Normal·Direction &lt; 0,
    /// two half-spaces whose normals are not exactly opposite) is reported by <see cref="IsUnbounded"/>;
    /// <see cref="SignedDistance"/> throws <see cref="InvalidOperationException"/> for it, <see cref="SignedDistanceOrNull"/>
    /// returns null and <see cref="Approximate"/> returns double.NegativeInfinity.
    /// </para>
    /// </summary>
    public static class Exact
    {
        /// <summary>The exact signed distance (a rational within ~2^-160 relative); throws when <see cref="IsUnbounded"/>.</summary>
        public static Rational SignedDistance(RShape a, RShape b) =>
            SignedDistanceOrNull(a, b) ?? throw new InvalidOperationException("unbounded penetration: the signed distance is −∞ (test Exact.IsUnbounded first)");

        /// <summary>The signed distance, or null when it is −∞ (<see cref="IsUnbounded"/>).</summary>
        public static Rational? SignedDistanceOrNull(RShape a, RShape b)
        {
            if (IsUnbounded(a, b)) return null;
            if (a.Kind == RKind.HalfSpace || b.Kind == RKind.HalfSpace)
            {
                var (gap, q, r) = HalfSpaceGap(a, b);
                return SignedRoot(gap * gap / q, gap.Sign) - r;
            }
            if (a.IsLinear && b.IsLinear) return Rational.Sqrt(LinearDistance2(a, b));
            bool solid = a.IsSolid || b.IsSolid;
            var shrink = Reduce(ref a, ref b);
            if (!Intersects(a, b)) return Rational.Sqrt(Distance2(a, b)) - shrink;
            return (solid ? -Rational.Sqrt(Depth2(a, b)) : Rational.Zero) - shrink;
        }

        /// <summary>The signed distance as a double: double.NegativeInfinity when <see cref="IsUnbounded"/>, else the nearest double (for reporting).</summary>
        public static double Approximate(RShape a, RShape b) => SignedDistanceOrNull(a, b)?.ToDouble() ?? double.NegativeInfinity;

        /// <summary>The exact verdict: do the closed shapes touch or overlap?</summary>
        public static bool Overlaps(RShape a, RShape b)
        {
            if (IsUnbounded(a, b)) return true;
            if (a.Kind == RKind.HalfSpace || b.Kind == RKind.HalfSpace)
            {
                // gap/√q ≤ r, decided without a root.
                var (gap, q, r) = HalfSpaceGap(a, b);
                return gap.Sign <= 0 || gap * gap <= r * r * q;
            }
            if (a.IsLinear && b.IsLinear) return LinearDistance2(a, b).IsZero;
            var shrink = Reduce(ref a, ref b);
            return Intersects(a, b) || Distance2(a, b) <= shrink * shrink;
        }

        /// <summary>
        /// True when the penetration is unbounded (signed distance −∞): a line not exactly parallel to a half-space's
        /// boundary (Normal·Direction ≠ 0), a ray with Normal·Direction &lt; 0 (crossing the boundary inward, or starting
        /// inside heading inward), or two half-spaces whose normals are not exactly opposite (n × m ≠ 0 or n·m ≥ 0: their
        /// Minkowski difference is the whole space). Exactly opposite normals leave a slab or a gap: bounded.
        /// </summary>
        public static bool IsUnbounded(RShape a, RShape b)
        {
            if (a.Kind == RKind.HalfSpace && b.Kind == RKind.HalfSpace)
                return !RVec.Cross(a.Normal, b.Normal).IsZero || RVec.Dot(a.Normal, b.Normal).Sign >= 0;
            if (b.Kind == RKind.HalfSpace) return Escapes(a, b);
            if (a.Kind == RKind.HalfSpace) return Escapes(b, a);
            return false;
        }

        private static bool Escapes(RShape s, RShape h)
        {
            var k = RVec.Dot(h.Normal, s.Direction);
            return s.Kind == RKind.Line ? !k.IsZero : s.Kind == RKind.Ray && k.Sign < 0;
        }

        private static Rational SignedRoot(Rational square, int sign) => sign < 0 ? -Rational.Sqrt(square) : Rational.Sqrt(square);

        /// <summary>
        /// A half-space h = {x : n·(x − p) ≤ 0} against a partner with bounded penetration: the signed distance is
        /// gap/√q − r with q = |n|². Against a bounded convex K ⊕ ball r, gap = min over K's vertices of n·(v − p) (K − h
        /// is the half-space of points above that level); against a line (n·d = 0) or a ray (n·d ≥ 0), n·(origin − p)
        /// (the line is parallel; the ray's nearest or deepest point is its origin); against a half-space with an exactly
        /// opposite normal, n·(p' − p) (the gap, or minus the slab's width).
        /// </summary>
        private static (Rational Gap, Rational Q, Rational R) HalfSpaceGap(RShape a, RShape b)
        {
            var h = a.Kind == RKind.HalfSpace ? a : b;
            var other = ReferenceEquals(h, a) ? b : a;
            var n = h.Normal;
            var q = n.LengthSquared;
            if (other.Kind == RKind.HalfSpace || other.IsLinear) return (RVec.Dot(n, other.Center - h.Center), q, Rational.Zero);
            var core = other.Core();
            Rational? gap = null;
            foreach (var v in core.Vertices)
            {
                var g = RVec.Dot(n, v - h.Center);
                if (gap == null || g < gap.Value) gap = g;
            }
            return (gap!.Value, q, other.Radius);
        }

        /// <summary>
        /// Squared distance between two lines/rays O1 + s·d1 and O2 + t·d2 (s, t free for a line, ≥ 0 for a ray): the
        /// convex QP over the parameter intervals by active sets. The minimum (attained: a convex quadratic bounded below
        /// on a polyhedron) is at the interior stationary point when the system is regular and it is feasible, else on a
        /// bound s = 0 or t = 0 with the other parameter optimal for it (clamped), else — parallel with no active bound —
        /// on the minimising set, which meets s = 0 (a line in (s, t) along which s takes every value). The candidates
        /// (0, T(0)) and (S(0), 0) are feasible for both kinds, so taking the least of the feasible candidates is exact.
        /// </summary>
        public static Rational LinearDistance2(RShape a, RShape b)
        {
            if (!a.IsLinear || !b.IsLinear) throw new ArgumentException("lines or rays only");
            var d1 = a.Direction;
            var d2 = b.Direction;
            var w = a.Center - b.Center;
            Rational m11 = d1.LengthSquared, m12 = RVec.Dot(d1, d2), m22 = d2.LengthSquared, e = RVec.Dot(d1, w), f = RVec.Dot(d2, w);
            Rational Clamp(RShape s, Rational x) => s.Kind == RKind.Ray && x.Sign < 0 ? Rational.Zero : x;
            Rational Value(Rational s, Rational t) => (w + d1 * s - d2 * t).LengthSquared;
            // ∂/∂s: m11·s − m12·t + e = 0; ∂/∂t: −m12·s + m22·t − f = 0.
            var best = Rational.Min(Value(Rational.Zero, Clamp(b, f / m22)), Value(Clamp(a, -e / m11), Rational.Zero));
            var det = m11 * m22 - m12 * m12;
            if (!det.IsZero)
            {
                var s = (m12 * f - m22 * e) / det;
                var t = (m11 * f - m12 * e) / det;
                if ((a.Kind == RKind.Line || s.Sign >= 0) && (b.Kind == RKind.Line || t.Sign >= 0)) best = Rational.Min(best, Value(s, t));
            }
            return best;
        }

        /// <summary>
        /// Replaces spheres by their centers and capsules by their axes, then a line or ray by its clipped segment
        /// against the other (bounded) core; returns the radii to subtract.
        /// </summary>
        private static Rational Reduce(ref RShape a, ref RShape b)
        {
            var shrink = a.Radius + b.Radius;
            a = a.Core();
            b = b.Core();
            if (a.IsLinear) a = Clip(a, b);
            else if (b.IsLinear) b = Clip(b, a);
            return shrink;
        }

        /// <summary>
        /// The part of a line or ray L = O + t·d that matters against a bounded polytope K, as an exact segment: t over
        /// K's projection [tmin, tmax] (t = d·(v − O)/|d|²) widened by a margin M with M·|d| ≥ 2·diam K (a ray keeps its
        /// true end t = 0 and is cut only above). Why it is exact: (1) every common point and the point of L nearest K
        /// (the projection of K's nearest point, clamped at t = 0 for a ray) have t in [tmin, tmax], so intersection and
        /// distance are unchanged; (2) depth: along a direction n ⊥ d both project to the same point, so the overlaps
        /// (and the facets of L − K, all ⊥ d or K's own) are unchanged, while along a unit n = α·m + ε·d̂ (m ⊥ d unit,
        /// ε &gt; 0) the overlap on the side of a cut end is at least α·X + ε·(M·|d| − diam K) ≥ D, where X ≥ D is the
        /// overlap along m and D ≤ diam K the true depth (1 − α ≤ ε²), so a cut end never lowers the minimum over the
        /// candidates. diam K ≤ Σ coordinate spreads, and M = 2·Σ·max(1, 1/|d|²) + 1 gives M·|d| ≥ 2·Σ exactly.
        /// </summary>
        public static RShape Clip(RShape line, RShape k)
        {
            var o = line.Center;
            var d = line.Direction;
            var q = d.LengthSquared;
            Rational? lo = null, hi = null;
            foreach (var v in k.Vertices)
            {
                var t = RVec.Dot(d, v - o) / q;
                if (lo == null || t < lo.Value) lo = t;
                if (hi == null || t > hi.Value) hi = t;
            }
            var spread = Rational.Zero;
            foreach (Func<RVec, Rational> axis in new Func<RVec, Rational>[] { p => p.X, p => p.Y, p => p.Z })
            {
                Rational min = axis(k.Vertices[0]), max = min;
                foreach (var v in k.Vertices) { min = Rational.Min(min, axis(v)); max = Rational.Max(max, axis(v)); }
                spread += max - min;
            }
            var margin = spread * 2 * (q >= Rational.One ? Rational.One : Rational.One / q) + Rational.One;
            var from = line.Kind == RKind.Ray ? Rational.Zero : lo!.Value - margin;
            var to = (line.Kind == RKind.Ray ? Rational.Max(Rational.Zero, hi!.Value) : hi!.Value) + margin;
            return RShape.Segment(o + d * from, o + d * to, line.Planar);
        }

        private static IEnumerable<RVec> Candidates(RShape a, RShape b)
        {
            bool planar = a.Planar || b.Planar;
            var dirs = new List<RVec>(a.Directions);
            dirs.AddRange(b.Directions);
            dirs.Add(RVec.UnitX);
            dirs.Add(RVec.UnitY);
            if (planar)
            {
                foreach (var e in dirs)
                {
                    yield return e;
                    yield return new RVec(-e.Y, e.X, 0);
                }
                yield break;
            }
            dirs.Add(RVec.UnitZ);
            foreach (var e in dirs) yield return e;
            bool degenerate = a.IsDegenerate || b.IsDegenerate;
            for (int i = 0; i < dirs.Count; i++)
                for (int j = i + 1; j < dirs.Count; j++)
                {
                    var c = RVec.Cross(dirs[i], dirs[j]);
                    if (c.IsZero) continue;
                    yield return c;
                    if (degenerate)
                        foreach (var w in dirs)
                        {
                            var t = RVec.Cross(c, w);
                            if (!t.IsZero) yield return t;
                        }
                }
        }

        private static void Project(RShape s, RVec n, out Rational min, out Rational max)
        {
            min = max = RVec.Dot(s.Vertices[0], n);
            for (int i = 1; i < s.Vertices.Count; i++)
            {
                var p = RVec.Dot(s.Vertices[i], n);
                if (p < min) min = p;
                if (p > max) max = p;
            }
        }

        /// <summary>Exact separating-axis test for two polytopes (points, segments, boxes).</summary>
        public static bool Intersects(RShape a, RShape b)
        {
            foreach (var n in Candidates(a, b))
            {
                Project(a, n, out var minA, out var maxA);
                Project(b, n, out var minB, out var maxB);
                if (maxA < minB || maxB < minA) return false;
            }
            return true;
        }

        /// <summary>Squared penetration depth of two intersecting polytopes: min over candidates of overlap²/|n|².</summary>
        public static Rational Depth2(RShape a, RShape b)
        {
            Rational? best = null;
            foreach (var n in Candidates(a, b))
            {
                Project(a, n, out var minA, out var maxA);
                Project(b, n, out var minB, out var maxB);
                var overlap = Rational.Min(maxA - minB, maxB - minA);
                var d2 = overlap * overlap / n.LengthSquared;
                if (best == null || d2 < best.Value) best = d2;
            }
            return best ?? Rational.Zero;
        }

        private static IEnumerable<(RVec Origin, RVec[] Dirs, bool Triangular)> Features(RShape s)
        {
            foreach (var v in s.Vertices) yield return (v, Array.Empty<RVec>(), false);
            foreach (var e in s.Edges) yield return (e.Origin, new[] { e.Dir }, false);
            foreach (var f in s.Faces) yield return (f.Origin, new[] { f.U, f.V }, f.Triangular);
        }

        /// <summary>Squared distance between two disjoint polytopes by feature-pair enumeration.</summary>
        public static Rational Distance2(RShape a, RShape b)
        {
            Rational? best = null;
            foreach (var fa in Features(a))
                foreach (var fb in Features(b))
                {
                    if (fa.Dirs.Length + fb.Dirs.Length > 2) continue;
                    var cols = new List<RVec>(fa.Dirs);
                    foreach (var v in fb.Dirs) cols.Add(-v);
                    // At most one of the two is a face (dimensions sum to at most 2), so one flag covers the pair.
                    var d2 = FeaturePair(fa.Origin - fb.Origin, cols, fa.Triangular || fb.Triangular);
                    if (d2.HasValue && (best == null || d2.Value < best.Value)) best = d2;
                }
            return best ?? throw new InvalidOperationException("no feasible feature pair");
        }

        /// <summary>
        /// min |w0 + Σ z_i·W_i|² over the affine hull; null unless the minimiser has every z_i in [0, 1] (for a triangular
        /// face: z0, z1 ≥ 0 and z0 + z1 ≤ 1).
        /// </summary>
        private static Rational? FeaturePair(RVec w0, List<RVec> w, bool triangular)
        {
            var r = w0;
            if (w.Count == 1)
            {
                var m = w[0].LengthSquared;
                var z = -RVec.Dot(w[0], w0) / m;
                if (z.Sign < 0 || z > Rational.One) return null;
                r = w0 + w[0] * z;
            }
            else if (w.Count == 2)
            {
                var m00 = w[0].LengthSquared;
                var m01 = RVec.Dot(w[0], w[1]);
                var m11 = w[1].LengthSquared;
                var det = m00 * m11 - m01 * m01;
                if (det.IsZero) return null;
                var b0 = RVec.Dot(w[0], w0);
                var b1 = RVec.Dot(w[1], w0);
                var z0 = (m01 * b1 - m11 * b0) / det;
                var z1 = (m01 * b0 - m00 * b1) / det;
                if (z0.Sign < 0 || z1.Sign < 0) return null;
                if (triangular ? z0 + z1 > Rational.One : z0 > Rational.One || z1 > Rational.One) return null;
                r = w0 + w[0] * z0 + w[1] * z1;
            }
            return r.LengthSquared;
        }

        /// <summary>
        /// The configuration's local scale S: the largest coordinate difference between defining points, or radius.
        /// Exact (differences taken in rationals), so it does not overflow for coordinates near ±1e308.
        /// </summary>
        public static Rational LocalScale(RShape a, RShape b)
        {
            var pts = new List<RVec>(a.Defining);
            pts.AddRange(b.Defining);
            // Only spheres and capsules have a non-zero radius.
            var s = Rational.Max(a.Radius, b.Radius);
            foreach (Func<RVec, Rational> axis in new Func<RVec, Rational>[] { p => p.X, p => p.Y, p => p.Z })
            {
                Rational lo = axis(pts[0]), hi = lo;
                foreach (var p in pts)
                {
                    lo = Rational.Min(lo, axis(p));
                    hi = Rational.Max(hi, axis(p));
                }
                s = Rational.Max(s, hi - lo);
            }
            return s;
        }

        /// <summary>S as a double (+∞ only when S itself exceeds the double range).</summary>
        public static double Scale(RShape a, RShape b) => LocalScale(a, b).ToDouble();

        /// <summary>E of d against the pair (a, b) at its scale S: 0 when both the answer and the exact value are −∞ (<see cref="IsUnbounded"/>), +∞ when only one is.</summary>
        public static double Error(double d, RShape a, RShape b, double u)
        {
            if (IsUnbounded(a, b)) return double.IsNegativeInfinity(d) ? 0 : double.PositiveInfinity;
            return Error(d, SignedDistance(a, b), u, Scale(a, b));
        }

        /// <summary>E = |d − d*| / (u·S), in units of the precision's unit roundoff u at the configuration's scale.</summary>
        public static double Error(double d, Rational exact, double u, double scale)
        {
            // A non-finite answer to a finite question (the paper's formulas overflow at 2^±1000) is infinitely wrong.
            if (!double.IsFinite(d)) return double.PositiveInfinity;
            double diff = Math.Abs((Rational.FromDouble(d) - exact).ToDouble());
            if (diff == 0) return 0;
            return scale > 0 ? diff / (u * scale) : double.PositiveInfinity;
        }
    }
}
