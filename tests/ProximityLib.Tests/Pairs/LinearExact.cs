using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// Exact rational reference for the linear pairs (point, segment, line, ray, sphere/circle, capsule), written for
    /// these tests from the definitions, independent of the kernels: the squared distance of two linear components is
    /// the minimum of a convex quadratic over their parameter box (the interior stationary point from Cramer's rule,
    /// else the minimum over the box's finite edges, each a clamped 1D minimum), all in BigInteger rationals; the
    /// signed distance subtracts the radii, and in 2D axes that meet give −(radii + the crossing depth: the least
    /// distance of an endpoint of one to the other's line, the nearest face of their Minkowski difference).
    /// </summary>
    internal static class LinearExact
    {
        public const double U = 1.0 / (1L << 53);

        /// <summary>A shape as P + s·D, s in [Lo, Hi] (null: unbounded), thickened by R.</summary>
        public sealed class Lin
        {
            public RVec P, D;
            public bool HasLo, HasHi;
            public Rational R = Rational.Zero;
            public bool Planar, Solid;
            public List<RVec> Defining = new List<RVec>();
        }

        public static Lin Of(object shape)
        {
            switch (shape)
            {
                case Vector3D p: return Seg(RVec.From(p), RVec.From(p), false);
                case Vector2D p: return Seg(RVec.From(p), RVec.From(p), true);
                case Segment3 s: return Seg(RVec.From(s.Start), RVec.From(s.End), false);
                case Segment2 s: return Seg(RVec.From(s.Start), RVec.From(s.End), true);
                case Line3 l: return Unb(RVec.From(l.Origin), RVec.From(l.Direction), false, false);
                case Line2 l: return Unb(RVec.From(l.Origin), RVec.From(l.Direction), false, true);
                case Ray3 r: return Unb(RVec.From(r.Origin), RVec.From(r.Direction), true, false);
                case Ray2 r: return Unb(RVec.From(r.Origin), RVec.From(r.Direction), true, true);
                case Sphere s: { var x = Seg(RVec.From(s.Center), RVec.From(s.Center), false); x.R = s.Radius; x.Solid = true; return x; }
                case Circle c: { var x = Seg(RVec.From(c.Center), RVec.From(c.Center), true); x.R = c.Radius; x.Solid = true; return x; }
                case Capsule3 c: { var x = Seg(RVec.From(c.Start), RVec.From(c.End), false); x.R = c.Radius; x.Solid = true; return x; }
                case Capsule2 c: { var x = Seg(RVec.From(c.Start), RVec.From(c.End), true); x.R = c.Radius; x.Solid = true; return x; }
            }
            throw new ArgumentException(shape.GetType().Name);
        }

        private static Lin Seg(RVec a, RVec b, bool planar) =>
            new Lin { P = a, D = b - a, HasLo = true, HasHi = true, Planar = planar, Defining = { a, b } };

        private static Lin Unb(RVec o, RVec d, bool ray, bool planar) =>
            new Lin { P = o, D = d, HasLo = ray, HasHi = false, Planar = planar, Defining = { o } };

        /// <summary>The exact squared distance between the two components (radii ignored).</summary>
        public static Rational Distance2(Lin a, Lin b)
        {
            var r = a.P - b.P;
            Rational qa = RVec.Dot(a.D, a.D), qb = RVec.Dot(b.D, b.D), m = RVec.Dot(a.D, b.D);
            Rational c = RVec.Dot(a.D, r), f = RVec.Dot(b.D, r);
            Rational det = qa * qb - m * m;
            if (!det.IsZero)
            {
                var s = (-c * qb + m * f) / det;
                var t = (qa * f - m * c) / det;
                if (In(a, s) && In(b, t)) return (r + a.D * s - b.D * t).LengthSquared;
            }
            Rational? best = null;
            void Take(Rational v) { if (best == null || v < best.Value) best = v; }
            // Each finite end of one parameter: the other parameter's clamped 1D minimum.
            foreach (var s in Ends(a)) Take(PointTo(a.P + a.D * s, b));
            foreach (var t in Ends(b)) Take(PointTo(b.P + b.D * t, a));
            // Two lines: constant along them; no ends.
            if (best == null) Take(PointTo(a.P, b));
            return best!.Value;
        }

        private static IEnumerable<Rational> Ends(Lin x)
        {
            if (x.HasLo) yield return Rational.Zero;
            if (x.HasHi) yield return Rational.One;
        }

        private static bool In(Lin x, Rational s) => (!x.HasLo || s >= Rational.Zero) && (!x.HasHi || s <= Rational.One);

        private static Rational PointTo(RVec p, Lin x)
        {
            var w = p - x.P;
            var dd = RVec.Dot(x.D, x.D);
            var t = dd.IsZero ? Rational.Zero : RVec.Dot(w, x.D) / dd;
            if (x.HasLo && t < Rational.Zero) t = Rational.Zero;
            if (x.HasHi && t > Rational.One) t = Rational.One;
            return (w - x.D * t).LengthSquared;
        }

        /// <summary>The exact signed distance (as a 160-bit rational approximation of the square roots).</summary>
        public static Rational Signed(Lin a, Lin b)
        {
            var d2 = Distance2(a, b);
            var radii = a.R + b.R;
            if (!d2.IsZero || !a.Planar || !(a.Solid || b.Solid)) return Rational.Sqrt(d2) - radii;
            // 2D, meeting axes, a solid: the crossing depth of the axes' Minkowski difference.
            Rational? depth = null;
            void Face(RVec p, Lin line)
            {
                var dd = RVec.Dot(line.D, line.D);
                if (dd.IsZero) return;
                var cr = RVec.Cross(line.D, p - line.P).Z;
                var h = Rational.Sqrt(cr * cr / dd);
                if (depth == null || h < depth.Value) depth = h;
            }
            foreach (var s in Ends(a)) Face(a.P + a.D * s, b);
            foreach (var t in Ends(b)) Face(b.P + b.D * t, a);
            return -(radii + (depth ?? Rational.Zero));
        }

        public static double Scale(Lin a, Lin b)
        {
            var pts = new List<RVec>(a.Defining);
            pts.AddRange(b.Defining);
            double s = Math.Max(a.R.ToDouble(), b.R.ToDouble());
            foreach (Func<RVec, Rational> axis in new Func<RVec, Rational>[] { p => p.X, p => p.Y, p => p.Z })
            {
                Rational lo = axis(pts[0]), hi = lo;
                foreach (var p in pts) { lo = Rational.Min(lo, axis(p)); hi = Rational.Max(hi, axis(p)); }
                s = Math.Max(s, (hi - lo).ToDouble());
            }
            return s;
        }

        /// <summary>E = |d − exact|/(u·S) for the pair (a, b).</summary>
        public static double Error(object a, object b, double d)
        {
            Lin la = Of(a), lb = Of(b);
            if (!double.IsFinite(d)) return double.PositiveInfinity;
            double diff = Math.Abs((Rational.FromDouble(d) - Signed(la, lb)).ToDouble());
            if (diff == 0) return 0;
            double s = Scale(la, lb);
            return s > 0 ? diff / (U * s) : double.PositiveInfinity;
        }

        /// <summary>The exact signed distance rounded, for messages.</summary>
        public static double Exact(object a, object b) => Signed(Of(a), Of(b)).ToDouble();

        /// <summary>
        /// The contract on one pair, returning E: within <paramref name="bound"/> of the exact answer; Distance and Between
        /// agree bit for bit; the swapped call is the swapped result bit for bit; Overlaps matches the sign (outside a
        /// band of 4u·S); separated witnesses realise the distance; no NaN.
        /// </summary>
        public static double Check(object a, object b, double bound = 32)
        {
            dynamic da = a, db = b;
            var r = Api.Between(da, db);
            double d = r.Distance;
            string at = $"{a} vs {b}: D={d:R} exact {Exact(a, b):R}";
            double e = Error(a, b, d);
            Assert.That(e, Is.LessThanOrEqualTo(bound), at);
            Assert.That(BitConverter.DoubleToInt64Bits((double)Api.Distance(da, db)), Is.EqualTo(BitConverter.DoubleToInt64Bits(d)), "Distance, " + at);
            var q = Api.Between(db, da);
            Assert.That(q.Equals(r.Swapped()), Is.True, $"swap: {q} vs {r}, " + at);
            double s = Scale(Of(a), Of(b));
            bool o = Api.Overlaps(da, db);
            Assert.That((bool)Api.Overlaps(db, da), Is.EqualTo(o), "Overlaps symmetric, " + at);
            if (Math.Abs(d) > 4 * U * s) Assert.That(o, Is.EqualTo(d <= 0), "Overlaps, " + at);
            double len = Len(r.PointB - r.PointA);
            double mag = Math.Max(Len(r.PointA), Len(r.PointB));
            Assert.That(double.IsNaN(len), Is.False, at);
            if (d > 0) Assert.That(len, Is.EqualTo(d).Within(8 * U * (s + mag)), "witnesses, " + at);
            else Assert.That(len, Is.EqualTo(-d).Within(8 * U * (s + mag) + 1e-300), "witnesses (overlap), " + at);
            return e;
        }

        private static double Len(Vector3D v) => v.Length;
        private static double Len(Vector2D v) => v.Length;
    }
}
