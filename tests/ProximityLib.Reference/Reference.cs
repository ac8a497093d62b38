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
    /// direction overestimates). Spheres reduce to their centers, less the radius. Squared quantities are exact
    /// rationals; only the final square root is an approximation, to about 2^-160 relative.
    /// </summary>
    public static class Exact
    {
        public static Rational SignedDistance(RShape a, RShape b)
        {
            var shrink = Centers(ref a, ref b);
            if (!Intersects(a, b)) return Rational.Sqrt(Distance2(a, b)) - shrink;
            return (a.IsSolid || b.IsSolid ? -Rational.Sqrt(Depth2(a, b)) : Rational.Zero) - shrink;
        }

        /// <summary>The exact verdict: do the closed shapes touch or overlap?</summary>
        public static bool Overlaps(RShape a, RShape b)
        {
            var shrink = Centers(ref a, ref b);
            return Intersects(a, b) || Distance2(a, b) <= shrink * shrink;
        }

        /// <summary>Replaces spheres by their centers; returns the radii to subtract.</summary>
        private static Rational Centers(ref RShape a, ref RShape b)
        {
            var shrink = Rational.Zero;
            if (a.Kind == RKind.Sphere) { shrink += a.Radius; a = a.WithCenter(a.Center); }
            if (b.Kind == RKind.Sphere) { shrink += b.Radius; b = b.WithCenter(b.Center); }
            return shrink;
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

        private static IEnumerable<(RVec Origin, RVec[] Dirs)> Features(RShape s)
        {
            foreach (var v in s.Vertices) yield return (v, Array.Empty<RVec>());
            foreach (var e in s.Edges) yield return (e.Origin, new[] { e.Dir });
            foreach (var f in s.Faces) yield return (f.Origin, new[] { f.U, f.V });
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
                    var d2 = FeaturePair(fa.Origin - fb.Origin, cols);
                    if (d2.HasValue && (best == null || d2.Value < best.Value)) best = d2;
                }
            return best ?? throw new InvalidOperationException("no feasible feature pair");
        }

        /// <summary>min |w0 + Σ z_i·W_i|² over the affine hull; null unless the minimiser has every z_i in [0, 1].</summary>
        private static Rational? FeaturePair(RVec w0, List<RVec> w)
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
                if (z0.Sign < 0 || z0 > Rational.One || z1.Sign < 0 || z1 > Rational.One) return null;
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
            // Only spheres set a radius (a default Rational is not a valid zero).
            var s = Rational.Max(a.Kind == RKind.Sphere ? a.Radius : Rational.Zero, b.Kind == RKind.Sphere ? b.Radius : Rational.Zero);
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
