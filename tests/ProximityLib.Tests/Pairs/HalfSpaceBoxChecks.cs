using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// Invariant checks and exact rational references for the half-space pairs and the line/ray/capsule–box pairs. A
    /// configuration is given as a function of a scale factor f (every coordinate and length multiplied by f, directions
    /// and normals unchanged), so 2^k scaling can be checked bit for bit through the slow path.
    /// </summary>
    public static class HalfSpaceBoxChecks
    {
        public const double U = 1.1102230246251565e-16; // 2^-53

        public static (dynamic r, bool overlaps) Query(object a, object b) =>
            (Api.Between(a, b), (bool)Api.Overlaps(a, b));

        private static bool Scales(object shape) => shape is Line3 || shape is Line2 || shape is Ray3 || shape is Ray2;

        private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);

        private static Vector3D P3(object v) => v is Vector2D w ? new Vector3D(w.X, w.Y, 0) : (Vector3D)v;

        /// <summary>Every invariant of the contract on one configuration; returns its result at scale 1.</summary>
        public static (double D, Vector3D PA, Vector3D PB, double TA, double TB) Check(Func<double, (object a, object b)> make, double witnessTol = 1e-9)
        {
            var (a, b) = make(1);
            var r = Api.Between(a, b);
            var s = Api.Between(b, a);
            double d = r.Distance;
            Vector3D pa = P3(r.PointA), pb = P3(r.PointB);
            string what = $"{a} / {b}: D={d:R} PA={pa} PB={pb}";
            Assert.That(double.IsNaN(d) || double.IsPositiveInfinity(d), Is.False, what);
            Assert.That(Bits(s.Distance), Is.EqualTo(Bits(d)), "swap " + what);
            Assert.That(Bits(s.DistanceSquared), Is.EqualTo(Bits(r.DistanceSquared)), "swap " + what);
            Assert.That(P3(s.PointA) == pb && P3(s.PointB) == pa, Is.True, "swap witnesses " + what);
            Assert.That(s.ParameterA == r.ParameterB && s.ParameterB == r.ParameterA, Is.True, "swap parameters " + what);
            Assert.That(Bits(Api.Distance(a, b)), Is.EqualTo(Bits(d)), "Distance " + what);
            Assert.That(Bits(Api.Distance(b, a)), Is.EqualTo(Bits(d)), "Distance swapped " + what);
            bool ov = Api.Overlaps(a, b);
            Assert.That((bool)Api.Overlaps(b, a), Is.EqualTo(ov), "Overlaps swapped " + what);
            if (Math.Abs(d) > 1e-300) Assert.That(ov, Is.EqualTo(d <= 0), "Overlaps vs Distance " + what);
            Assert.That(Finite(pa) && Finite(pb), Is.True, "finite witnesses " + what);
            double scale = Math.Max(1, Math.Max(Range(pa), Range(pb)));
            if (double.IsNegativeInfinity(d))
            {
                Assert.That(pa == pb, Is.True, "unbounded: one common point " + what);
                Assert.That(r.DistanceSquared, Is.EqualTo(0), what);
            }
            else
            {
                Assert.That((pa - pb).Length, Is.EqualTo(Math.Abs(d)).Within(witnessTol * scale), "|PA − PB| " + what);
                Assert.That(r.DistanceSquared, Is.EqualTo(d > 0 ? d * d : 0).Within(1e-12 * scale * scale), what);
            }
            Assert.That(Inside(a, pa, witnessTol * scale), Is.True, "PointA in A " + what);
            Assert.That(Inside(b, pb, witnessTol * scale), Is.True, "PointB in B " + what);
            foreach (int k in new[] { -900, -40, 40, 900 })
            {
                double f = Math.Pow(2, k);
                var (ka, kb) = make(f);
                var q = Api.Between(ka, kb);
                string w = $"2^{k}: {what} got D={q.Distance:R} PA={P3(q.PointA)} PB={P3(q.PointB)}";
                Assert.That(Bits(q.Distance), Is.EqualTo(Bits(d * f)), w);
                Assert.That(P3(q.PointA) == pa * f && P3(q.PointB) == pb * f, Is.True, w);
                Assert.That(q.ParameterA, Is.EqualTo(Scales(a) ? r.ParameterA * f : r.ParameterA), w);
                Assert.That(q.ParameterB, Is.EqualTo(Scales(b) ? r.ParameterB * f : r.ParameterB), w);
                if (Math.Abs(k) < 100) Assert.That(q.DistanceSquared, Is.EqualTo(r.DistanceSquared * f * f), w);
                Assert.That((bool)Api.Overlaps(ka, kb), Is.EqualTo(ov), w);
                Assert.That(Bits(Api.Distance(ka, kb)), Is.EqualTo(Bits(d * f)), w);
            }
            return (d, pa, pb, r.ParameterA, r.ParameterB);
        }

        private static bool Finite(Vector3D v) => double.IsFinite(v.X) && double.IsFinite(v.Y) && double.IsFinite(v.Z);
        private static double Range(Vector3D v) => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));

        /// <summary>Whether p lies in (or within tol of) the shape.</summary>
        public static bool Inside(object shape, Vector3D p, double tol)
        {
            switch (shape)
            {
                case Vector3D v: return (p - v).Length <= tol;
                case Vector2D v: return (p - P3(v)).Length <= tol;
                case Segment3 s: return SegDist(p, s.Start, s.End) <= tol;
                case Segment2 s: return SegDist(p, P3(s.Start), P3(s.End)) <= tol;
                case Sphere s: return (p - s.Center).Length <= s.Radius + tol;
                case Circle s: return (p - P3(s.Center)).Length <= s.Radius + tol;
                case Capsule3 c: return SegDist(p, c.Start, c.End) <= c.Radius + tol;
                case Capsule2 c: return SegDist(p, P3(c.Start), P3(c.End)) <= c.Radius + tol;
                case Line3 l: return LineDist(p, l.Origin, l.Direction, false) <= tol;
                case Line2 l: return LineDist(p, P3(l.Origin), P3(l.Direction), false) <= tol;
                case Ray3 l: return LineDist(p, l.Origin, l.Direction, true) <= tol;
                case Ray2 l: return LineDist(p, P3(l.Origin), P3(l.Direction), true) <= tol;
                case HalfSpace h: return Vector3D.Dot(h.Normal, p - h.Point) <= tol;
                case HalfPlane h: return Vector3D.Dot(P3(h.Normal), p - P3(h.Point)) <= tol;
                case Triangle3 t: return InTriangle(p, t.A, t.B, t.C, tol);
                case Triangle2 t: return InTriangle(p, P3(t.A), P3(t.B), P3(t.C), tol);
                case Aabb3 x: return In(p.X, x.Min.X, x.Max.X, tol) && In(p.Y, x.Min.Y, x.Max.Y, tol) && In(p.Z, x.Min.Z, x.Max.Z, tol);
                case Aabb2 x: return In(p.X, x.Min.X, x.Max.X, tol) && In(p.Y, x.Min.Y, x.Max.Y, tol) && p.Z == 0;
                case Obb3 o:
                {
                    var d = p - o.Center;
                    return Math.Abs(Vector3D.Dot(d, o.AxisX)) <= o.HalfExtents.X + tol && Math.Abs(Vector3D.Dot(d, o.AxisY)) <= o.HalfExtents.Y + tol
                        && Math.Abs(Vector3D.Dot(d, o.AxisZ)) <= o.HalfExtents.Z + tol;
                }
                case Obb2 o:
                {
                    var d = p - P3(o.Center);
                    return Math.Abs(Vector3D.Dot(d, P3(o.AxisX))) <= o.HalfExtents.X + tol && Math.Abs(Vector3D.Dot(d, P3(o.AxisY))) <= o.HalfExtents.Y + tol;
                }
                default: throw new ArgumentException(shape.GetType().Name);
            }
        }

        private static bool In(double x, double lo, double hi, double tol) => x >= lo - tol && x <= hi + tol;

        private static double SegDist(Vector3D p, Vector3D a, Vector3D b)
        {
            var d = b - a;
            double dd = d.LengthSquared, t = dd > 0 ? Math.Clamp(Vector3D.Dot(p - a, d) / dd, 0, 1) : 0;
            return (p - (a + d * t)).Length;
        }

        private static double LineDist(Vector3D p, Vector3D o, Vector3D u, bool ray)
        {
            double t = Vector3D.Dot(p - o, u);
            if (ray) t = Math.Max(t, 0);
            return (p - (o + u * t)).Length;
        }

        private static bool InTriangle(Vector3D p, Vector3D a, Vector3D b, Vector3D c, double tol) =>
            // Good enough for witnesses at vertices (the only ones the half-space pairs return).
            (p - a).Length <= tol || (p - b).Length <= tol || (p - c).Length <= tol;

        // ---- exact references ----

        /// <summary>The configuration's scale S: the largest coordinate spread of its defining points, or the largest length.</summary>
        public static double Scale(IEnumerable<Vector3D> points, double length = 0)
        {
            var list = points.ToList();
            double s = length;
            s = Math.Max(s, list.Max(p => p.X) - list.Min(p => p.X));
            s = Math.Max(s, list.Max(p => p.Y) - list.Min(p => p.Y));
            s = Math.Max(s, list.Max(p => p.Z) - list.Min(p => p.Z));
            return s;
        }

        /// <summary>E = |d − exact| / (u·S).</summary>
        public static double E(double d, Rational exact, double s) => Math.Abs(((Rational)d - exact).ToDouble()) / (U * s);

        /// <summary>The exact signed height (n·(x − p))/|n| of the lowest of the points above the stored plane (n, p), less r.</summary>
        public static Rational ExactHeight(Vector3D n, Vector3D p, IEnumerable<Vector3D> points, double r = 0)
        {
            var rn = RVec.From(n);
            var len = Rational.Sqrt(rn.LengthSquared, 200);
            return points.Select(x => RVec.Dot(rn, RVec.From(x) - RVec.From(p)) / len).Aggregate(Rational.Min) - (Rational)r;
        }

        public static Rational ExactHeight(Vector3D n, Vector3D p, IEnumerable<RVec> points, double r = 0)
        {
            var rn = RVec.From(n);
            var len = Rational.Sqrt(rn.LengthSquared, 200);
            return points.Select(x => RVec.Dot(rn, x - RVec.From(p)) / len).Aggregate(Rational.Min) - (Rational)r;
        }

        /// <summary>
        /// Runs <see cref="Check"/> on <paramref name="count"/> seeded configurations of both dimensions and measures E
        /// against <paramref name="exact"/> (null: no finite exact value, e.g. an unbounded case the function verified
        /// itself); returns the worst E.
        /// </summary>
        public static double RunRandom(int seed, int count, Func<Random, int, Func<double, (object a, object b)>> gen,
            Func<object, object, double, (Rational? exact, double s)> exact)
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(seed + dim);
                for (int i = 0; i < count; i++)
                {
                    var make = gen(rng, dim);
                    var r = Check(make);
                    var (a, b) = make(1);
                    var (x, sc) = exact(a, b, r.D);
                    if (x == null) continue;
                    double e = E(r.D, x.Value, sc);
                    Assert.That(e, Is.LessThanOrEqualTo(32), $"E {a} / {b}: D={r.D:R} exact={x.Value.ToDouble():R}");
                    worst = Math.Max(worst, e);
                }
            }
            return worst;
        }

        /// <summary>The eight corners of an OBB (four of an Obb2, z = 0), exactly as stored: centre ± half-extent × axis.</summary>
        public static IEnumerable<RVec> Corners(Vector3D c, Vector3D[] axes, Vector3D h)
        {
            for (int i = 0; i < 8; i++)
            {
                var v = RVec.From(c);
                v = v + RVec.From(axes[0]) * ((i & 1) != 0 ? (Rational)h.X : -(Rational)h.X);
                v = v + RVec.From(axes[1]) * ((i & 2) != 0 ? (Rational)h.Y : -(Rational)h.Y);
                v = v + RVec.From(axes[2]) * ((i & 4) != 0 ? (Rational)h.Z : -(Rational)h.Z);
                yield return v;
            }
        }

        /// <summary>
        /// The exact signed distance between the parameter stretch [t0, t1] of the line o + t·u (t0 = −∞ / t1 = +∞
        /// allowed: a ray or a line) and the AABB [lo, hi]. Apart: the convex piecewise-quadratic squared distance minimised
        /// exactly over the stretch, cut to the box's projection on the line (where every closest point lies), then the
        /// root. Meeting: minus the least push over the separating-axis candidates (box normals, where the stretch's cover
        /// is bounded on the pushed side, and u × box axis).
        /// </summary>
        public static Rational ExactLineAabb(Vector3D o, Vector3D u, double t0, double t1, Vector3D lo, Vector3D hi, bool planar)
        {
            var O = RVec.From(o);
            var D = RVec.From(u);
            Rational[] Oa = { O.X, O.Y, O.Z }, Da = { D.X, D.Y, D.Z }, L = { lo.X, lo.Y, lo.Z }, H = { hi.X, hi.Y, hi.Z };
            var dd = D.LengthSquared;
            // The box's projection onto the line, in t.
            Rational pmin = 0, pmax = 0;
            for (int i = 0; i < 3; i++)
            {
                var x = Da[i] * L[i]; var y = Da[i] * H[i];
                pmin += Rational.Min(x, y); pmax += Rational.Max(x, y);
            }
            var od = RVec.Dot(O, D);
            // A point-like stretch (u = 0, a segment of zero length): t0 alone.
            Rational T0 = dd.IsZero ? (Rational)t0 : (pmin - od) / dd, T1 = dd.IsZero ? (Rational)t0 : (pmax - od) / dd;
            if (!double.IsInfinity(t0)) { T0 = Rational.Max(T0, t0); T1 = Rational.Max(T1, t0); }
            if (!double.IsInfinity(t1)) { T0 = Rational.Min(T0, t1); T1 = Rational.Min(T1, t1); }
            // Breakpoints in (T0, T1), sorted.
            var pts = new List<Rational> { T0, T1 };
            for (int i = 0; i < 3; i++)
                if (!Da[i].IsZero)
                    foreach (var bnd in new[] { L[i], H[i] })
                    {
                        var b = (bnd - Oa[i]) / Da[i];
                        if (b > T0 && b < T1) pts.Add(b);
                    }
            pts.Sort();
            Rational best = F(Oa, Da, L, H, T0);
            for (int j = 0; j + 1 < pts.Count; j++)
            {
                Rational p = pts[j], q = pts[j + 1], mid = (p + q) / 2, num = 0, den = 0;
                for (int i = 0; i < 3; i++)
                {
                    var e = Oa[i] + Da[i] * mid;
                    Rational? bound = e < L[i] ? L[i] : e > H[i] ? H[i] : (Rational?)null;
                    if (bound == null) continue;
                    num += Da[i] * (bound.Value - Oa[i]);
                    den += Da[i] * Da[i];
                }
                var t = den.IsZero ? p : Rational.Max(p, Rational.Min(q, num / den));
                best = Rational.Min(best, Rational.Min(F(Oa, Da, L, H, t), F(Oa, Da, L, H, q)));
            }
            if (best.Sign > 0) return Rational.Sqrt(best, 200);

            // Meeting: relative to the centre.
            Rational[] C = new Rational[3], h = new Rational[3], M = new Rational[3];
            for (int i = 0; i < 3; i++) { C[i] = (L[i] + H[i]) / 2; h[i] = (H[i] - L[i]) / 2; M[i] = Oa[i] - C[i]; }
            Rational? depth = null;
            void Take(Rational v) { if (depth == null || v < depth.Value) depth = v; }
            for (int i = 0; i < (planar ? 2 : 3); i++)
            {
                // The stretch's cover of axis i: M + t·D over [t0, t1].
                bool lowFinite = Da[i].IsZero || (Da[i].Sign > 0 ? !double.IsInfinity(t0) : !double.IsInfinity(t1));
                bool highFinite = Da[i].IsZero || (Da[i].Sign > 0 ? !double.IsInfinity(t1) : !double.IsInfinity(t0));
                Rational tl = Da[i].Sign > 0 ? Or(t0) : Or(t1), th = Da[i].Sign > 0 ? Or(t1) : Or(t0);
                if (lowFinite) Take(h[i] - (M[i] + Da[i] * tl));   // push up
                if (highFinite) Take(M[i] + Da[i] * th + h[i]);    // push down
            }
            var axes = planar ? new[] { 2 } : new[] { 0, 1, 2 };
            foreach (int k in axes)
            {
                // w = D × e_k
                var e = new RVec(k == 0 ? 1 : 0, k == 1 ? 1 : 0, k == 2 ? 1 : 0);
                var w = RVec.Cross(D, e);
                if (w.IsZero) continue;
                var p = RVec.Dot(w, new RVec(M[0], M[1], M[2]));
                var rad = h[0] * Rational.Abs(w.X) + h[1] * Rational.Abs(w.Y) + h[2] * Rational.Abs(w.Z);
                var len = Rational.Sqrt(w.LengthSquared, 200);
                Take((rad - Rational.Abs(p)) / len);
            }
            return -depth!.Value;
        }

        private static Rational Or(double t) => double.IsInfinity(t) ? Rational.Zero : (Rational)t;

        private static Rational F(Rational[] o, Rational[] d, Rational[] lo, Rational[] hi, Rational t)
        {
            Rational s = 0;
            for (int i = 0; i < 3; i++)
            {
                var e = o[i] + d[i] * t;
                var g = e < lo[i] ? lo[i] - e : e > hi[i] ? e - hi[i] : Rational.Zero;
                s += g * g;
            }
            return s;
        }

    }
}

namespace ProximityTests.Pairs
{
    /// <summary>Seeded random dyadic inputs for the half-space and box pair tests.</summary>
    public static class Rand
    {
        public static double F(Random rng, double lo, double hi) => Math.Round((lo + (hi - lo) * rng.NextDouble()) * (1 << 22)) / (1 << 22);
        public static Vector3D P(Random rng, int dim, double range = 2) =>
            new Vector3D(F(rng, -range, range), F(rng, -range, range), dim == 3 ? F(rng, -range, range) : 0);
        /// <summary>A non-zero direction; now and then exactly axis-aligned or with a zero component, to hit the level cases.</summary>
        public static Vector3D Dir(Random rng, int dim)
        {
            Vector3D v;
            do
            {
                v = P(rng, dim, 1);
                int pick = rng.Next(6);
                if (pick == 0) v = new Vector3D(v.X, 0, v.Z);
                else if (pick == 1) v = new Vector3D(0, 0, 0) + new Vector3D(rng.Next(2) == 0 ? 1 : -1, 0, 0);
            } while (v.X == 0 && v.Y == 0 && v.Z == 0);
            return v;
        }
        public static Vector3D[] Axes(Random rng, int dim)
        {
            if (dim == 2)
            {
                double a = F(rng, 0, 6.3);
                return new[] { new Vector3D(Math.Cos(a), Math.Sin(a), 0), new Vector3D(-Math.Sin(a), Math.Cos(a), 0), Vector3D.UnitZ };
            }
            var o = new Obb3(default, System.Numerics.Quaternion.Normalize(new System.Numerics.Quaternion((float)F(rng, -1, 1), (float)F(rng, -1, 1), (float)F(rng, -1, 1), (float)F(rng, -1, 1) + 0.01f)), default);
            return new[] { o.AxisX, o.AxisY, o.AxisZ };
        }
        private static Vector2D T2(Vector3D v) => new Vector2D(v.X, v.Y);
        public static object Pt(int dim, Vector3D p) => dim == 3 ? p : (object)T2(p);
        public static object Hs(int dim, Vector3D p, Vector3D n) => dim == 3 ? HalfSpace.FromPointNormal(p, n) : (object)HalfPlane.FromPointNormal(T2(p), T2(n));
        public static object Seg(int dim, Vector3D a, Vector3D b) => dim == 3 ? new Segment3(a, b) : (object)new Segment2(T2(a), T2(b));
        public static object Cap(int dim, Vector3D a, Vector3D b, double r) => dim == 3 ? new Capsule3(a, b, r) : (object)new Capsule2(T2(a), T2(b), r);
        public static object Sph(int dim, Vector3D c, double r) => dim == 3 ? new Sphere(c, r) : (object)new Circle(T2(c), r);
        public static object Tri(int dim, Vector3D a, Vector3D b, Vector3D c) => dim == 3 ? new Triangle3(a, b, c) : (object)new Triangle2(T2(a), T2(b), T2(c));
        public static object Ln(int dim, Vector3D o, Vector3D d) => dim == 3 ? new Line3(o, d) : (object)new Line2(T2(o), T2(d));
        public static object Ry(int dim, Vector3D o, Vector3D d) => dim == 3 ? new Ray3(o, d) : (object)new Ray2(T2(o), T2(d));
        public static object Ab(int dim, Vector3D min, Vector3D max) => dim == 3 ? new Aabb3(min, max) : (object)new Aabb2(T2(min), T2(max));
        public static object Ob(int dim, Vector3D c, Vector3D[] axes, Vector3D h) =>
            dim == 3 ? new Obb3(c, axes[0], axes[1], axes[2], h) : (object)new Obb2(T2(c), T2(axes[0]), T2(h));
        /// <summary>A box's stored frame and corners as the kernels see them (an Obb2's z extent 0).</summary>
        public static (Vector3D c, Vector3D[] axes, Vector3D h) Frame(object box) => box switch
        {
            Obb3 o => (o.Center, new[] { o.AxisX, o.AxisY, o.AxisZ }, o.HalfExtents),
            Obb2 o => (new Vector3D(o.Center.X, o.Center.Y, 0), new[] { new Vector3D(o.AxisX.X, o.AxisX.Y, 0), new Vector3D(o.AxisY.X, o.AxisY.Y, 0), Vector3D.UnitZ }, new Vector3D(o.HalfExtents.X, o.HalfExtents.Y, 0)),
            _ => throw new ArgumentException(),
        };
    }
}
