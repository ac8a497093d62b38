using System;
using System.Collections.Generic;
using System.Linq;
using ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// Finds the candidates of the two cheap certificates in the local double copies of two shapes:
    /// <list type="bullet">
    /// <item>closest-pair candidates (primal): a pair of points, one in each shape, is an upper bound on the distance; the
    /// search tries alternating projections from every vertex, the other shape's projections, random points and every
    /// edge pair (for polytopes, vertex–box projections and edge–edge pairs include the closest pair);</item>
    /// <item>separating directions (dual): for any direction n, min over B of x·n − max over A of x·n (per |n|) is a lower
    /// bound on the signed distance, apart or overlapping; candidates are the face normals, edge × edge directions, the
    /// in-plane normals of 2D edges and the directions of the best candidate pairs. Against a line, ray or half-space
    /// (support +∞ in most directions) each candidate is first fitted exactly (<see cref="Core.Fit"/>) so that both
    /// supports can be finite, and the exact fitted direction is what the caller evaluates.</item>
    /// </list>
    /// Only the ranking happens in doubles: the caller re-evaluates the best candidates exactly.
    /// </summary>
    public static class Search
    {
        public readonly struct Pair
        {
            public readonly Vector3D A, B;
            public readonly double Distance;
            public Pair(Vector3D a, Vector3D b, double d) { A = a; B = b; Distance = d; }
        }

        /// <summary>The best <paramref name="keep"/> candidate pairs of parameters (local distance, ascending).</summary>
        public static List<Pair> BestPairs(Core a, Core b, IEnumerable<Vector3D> seedsA, IEnumerable<Vector3D> seedsB, Rng rng, int keep)
        {
            var best = new List<Pair>();
            void Consider(Vector3D pa, Vector3D pb)
            {
                double d = (a.LocalPoint(pa) - b.LocalPoint(pb)).Length;
                if (!double.IsFinite(d)) return;
                if (best.Count == keep && d >= best[keep - 1].Distance) return;
                int i = best.Count;
                while (i > 0 && best[i - 1].Distance > d) i--;
                best.Insert(i, new Pair(pa, pb, d));
                if (best.Count > keep) best.RemoveAt(keep);
            }
            void FromA(Vector3D pa)
            {
                for (int k = 0; k < 4; k++)
                {
                    var pb = b.Project(a.LocalPoint(pa));
                    Consider(pa, pb);
                    pa = a.Project(b.LocalPoint(pb));
                    Consider(pa, pb);
                }
            }
            void FromB(Vector3D pb)
            {
                for (int k = 0; k < 4; k++)
                {
                    var pa = a.Project(b.LocalPoint(pb));
                    Consider(pa, pb);
                    pb = b.Project(a.LocalPoint(pa));
                    Consider(pa, pb);
                }
            }
            foreach (var v in a.LocalVertices) FromA(a.Project(v));
            foreach (var v in b.LocalVertices) FromB(b.Project(v));
            foreach (var s in seedsA) FromA(a.Project(s));
            foreach (var s in seedsB) FromB(b.Project(s));
            for (int k = 0; k < 2; k++)
            {
                FromA(a.RandomParam(rng));
                FromB(b.RandomParam(rng));
            }
            foreach (var ea in a.LocalEdges)
                foreach (var eb in b.LocalEdges)
                {
                    var (s, t) = SegmentSegment(ea.A, ea.B, eb.A, eb.B);
                    var pa = a.Project(ea.A + (ea.B - ea.A) * s);
                    var pb = b.Project(eb.A + (eb.B - eb.A) * t);
                    Consider(pa, pb);
                    Consider(pa, b.Project(a.LocalPoint(pa)));
                    Consider(a.Project(b.LocalPoint(pb)), pb);
                }
            return best;
        }

        /// <summary>Closest parameters of two segments: the best of the clamped interior solution and the four end projections.</summary>
        public static (double S, double T) SegmentSegment(Vector3D p0, Vector3D p1, Vector3D q0, Vector3D q1)
        {
            var d1 = p1 - p0;
            var d2 = q1 - q0;
            var r = p0 - q0;
            double a = Vector3D.Dot(d1, d1), e = Vector3D.Dot(d2, d2), b = Vector3D.Dot(d1, d2);
            double c = Vector3D.Dot(d1, r), f = Vector3D.Dot(d2, r);
            static double Clamp(double x) => double.IsFinite(x) ? Math.Min(Math.Max(x, 0), 1) : 0;
            double bestS = 0, bestT = 0, best = double.PositiveInfinity;
            void Try(double s, double t)
            {
                double d = (p0 + d1 * s - (q0 + d2 * t)).LengthSquared;
                if (d < best) { best = d; bestS = s; bestT = t; }
            }
            Try(0, e > 0 ? Clamp(f / e) : 0);
            Try(1, e > 0 ? Clamp((f + b) / e) : 0);
            Try(a > 0 ? Clamp(-c / a) : 0, 0);
            Try(a > 0 ? Clamp((b - c) / a) : 0, 1);
            double denom = a * e - b * b;
            if (denom > 0 && e > 0)
            {
                double s = Clamp((b * f - c * e) / denom);
                double t = Clamp((b * s + f) / e);
                s = a > 0 ? Clamp((b * t - c) / a) : 0;
                Try(s, t);
            }
            return (bestS, bestT);
        }

        /// <summary>A candidate direction: rounded to doubles (about unit length; for ranking and messages) and exact (for the bound).</summary>
        public readonly struct Direction
        {
            public readonly Vector3D N;
            public readonly DyVec Exact;
            public Direction(Vector3D n, DyVec exact) { N = n; Exact = exact; }
        }

        /// <summary>
        /// Candidate directions n (from A toward B) for the lower bound (min_B x·n − max_A x·n − shift·n)/|n| − rA − rB,
        /// ranked in the local copy: every one within <see cref="Tie"/> of the best (local rounding cannot rank those),
        /// at most <paramref name="keep"/>. Cross products of edge directions are formed exactly and only then rounded,
        /// so the normal of two nearly parallel edges is accurate (in doubles it would be cancellation noise).
        /// <paramref name="shift"/> moves A (local units). With bounded shapes the exact direction is the rounded one;
        /// with an unbounded one it is the candidate (exact cross products unrounded) fitted to both shapes, and the
        /// candidates that cannot be fitted (both supports finite) are dropped.
        /// </summary>
        public static List<Direction> BestDirections(Core a, Core b, double ra, double rb, IEnumerable<Vector3D> extra,
            Vector3D shift, int keep)
        {
            bool unbounded = a.IsUnbounded || b.IsUnbounded;
            bool planar = a.Planar || b.Planar;
            var da = new List<DyVec>(a.Directions());
            var db = new List<DyVec>(b.Directions());
            var ranked = new List<(Direction N, double G)>();
            void Rank(Direction n)
            {
                double g = -b.LocalSupport(-n.N) - a.LocalSupport(n.N) - Vector3D.Dot(shift, n.N) - ra - rb;
                if (double.IsFinite(g)) ranked.Add((n, g));
            }
            if (!unbounded)
            {
                var dirs = new List<Vector3D> { Vector3D.UnitX, Vector3D.UnitY };
                if (!planar) dirs.Add(Vector3D.UnitZ);
                foreach (var d in da.Concat(db))
                {
                    dirs.Add(Round(d));
                    if (planar) dirs.Add(Round(new DyVec(-d.Y, d.X, Dy.Zero)));
                }
                if (!planar)
                    foreach (var u in da)
                        foreach (var v in db)
                            dirs.Add(Round(Cross(u, v)));
                dirs.AddRange(extra);
                foreach (var d0 in dirs)
                {
                    var d = planar ? new Vector3D(d0.X, d0.Y, 0) : d0;
                    double len = d.Length;
                    if (!(len > 0) || !double.IsFinite(len)) continue;
                    d = d / len;
                    foreach (var n in new[] { d, -d }) Rank(new Direction(n, DyVec.From(n)));
                }
            }
            else
            {
                // Exact candidates (cross products unrounded), each fitted to A along +n and to B along −n.
                var dirs = new List<DyVec> { DyVec.From(Vector3D.UnitX), DyVec.From(Vector3D.UnitY) };
                if (!planar) dirs.Add(DyVec.From(Vector3D.UnitZ));
                foreach (var d in da.Concat(db))
                {
                    dirs.Add(d);
                    if (planar) dirs.Add(new DyVec(-d.Y, d.X, Dy.Zero));
                }
                if (!planar)
                    foreach (var u in da)
                        foreach (var v in db)
                            dirs.Add(Cross(u, v));
                dirs.AddRange(extra.Where(e => e.IsFinite).Select(DyVec.From));
                foreach (var d0 in dirs)
                {
                    var e0 = planar ? new DyVec(d0.X, d0.Y, Dy.Zero) : d0;
                    foreach (var e in new[] { e0, -e0 })
                    {
                        // Re-fit to A when fitting to B changed the direction (a ray of A may need it).
                        var f = a.Fit(b.Fit(a.Fit(e, 1), -1), 1);
                        if (!a.TrySupport(f, out _) || !b.TrySupport(-f, out _)) continue;
                        var r = Round(f);
                        double len = r.Length;
                        if (!(len > 0) || !double.IsFinite(len)) continue;
                        Rank(new Direction(r / len, f));
                    }
                }
            }
            ranked.Sort((x, y) => y.G.CompareTo(x.G));
            var best = new List<Direction>();
            foreach (var (n, g) in ranked)
            {
                if (best.Count >= keep || (best.Count > 0 && g < ranked[0].G - Tie)) break;
                best.Add(n);
            }
            return best;
        }

        /// <summary>Local gaps closer than this to the best (local units, the configuration's size ~1) are ties.</summary>
        public const double Tie = 1e-9;

        private static DyVec Cross(DyVec u, DyVec v) => new DyVec(u.Y * v.Z - u.Z * v.Y, u.Z * v.X - u.X * v.Z, u.X * v.Y - u.Y * v.X);

        /// <summary>An exact direction rounded to doubles after scaling it to about unit length (no under- or overflow).</summary>
        private static Vector3D Round(DyVec v)
        {
            var m = Dy.Max(Dy.Abs(v.X), Dy.Max(Dy.Abs(v.Y), Dy.Abs(v.Z)));
            return m.IsZero ? default : v.Times2(-m.Log2).ToDouble();
        }
    }
}
