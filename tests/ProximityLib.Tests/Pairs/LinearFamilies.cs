using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using Api = ProximityReference.Api;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// Seeded configurations for the linear pairs: general position, nearly parallel (θ = 10^-3 … 10^-14, lines that
    /// cross or pass at a small offset), nearly collinear overlapping, a ray's origin near the other's line, origins
    /// 1e6 away along the direction; each checked against <see cref="LinearExact"/>; and exact 2^k scaling across the
    /// slow path, tiny and huge magnitudes.
    /// </summary>
    internal static class LinearFamilies
    {
        /// <summary>A shape of the named kind from two points and a radius: a point at p; a segment or capsule p–q; a line or ray from p toward q; a sphere at p.</summary>
        public static object Make(string kind, int dim, Vector3D p, Vector3D q, double r)
        {
            var p2 = new Vector2D(p.X, p.Y);
            var q2 = new Vector2D(q.X, q.Y);
            switch (kind)
            {
                case "point": return dim == 3 ? p : (object)p2;
                case "segment": return dim == 3 ? new Segment3(p, q) : (object)new Segment2(p2, q2);
                case "line": return dim == 3 ? new Line3(p, q - p) : (object)new Line2(p2, q2 - p2);
                case "ray": return dim == 3 ? new Ray3(p, q - p) : (object)new Ray2(p2, q2 - p2);
                case "sphere": return dim == 3 ? new Sphere(p, r) : (object)new Circle(p2, r);
                case "capsule": return dim == 3 ? new Capsule3(p, q, r) : (object)new Capsule2(p2, q2, r);
            }
            throw new ArgumentException(kind);
        }

        private static Vector3D Rand(Random rng, int dim, double s = 1) =>
            new Vector3D((rng.NextDouble() * 2 - 1) * s, (rng.NextDouble() * 2 - 1) * s, dim == 3 ? (rng.NextDouble() * 2 - 1) * s : 0);

        private static Vector3D Unit(Random rng, int dim)
        {
            while (true)
            {
                var v = Rand(rng, dim);
                if (v.LengthSquared > 0.01 && v.LengthSquared <= 1) return v / v.Length;
            }
        }

        /// <summary>The configurations of one family for the pair of kinds.</summary>
        public static IEnumerable<(object A, object B)> Family(string ka, string kb, int dim, int family, int seed, int count)
        {
            var rng = new Random(seed * 31 + family * 7 + dim);
            for (int i = 0; i < count; i++)
            {
                double ra = rng.NextDouble() * 0.5, rb = rng.NextDouble() * 0.5;
                Vector3D pa, qa, pb, qb;
                switch (family)
                {
                    case 0: // general position
                        pa = Rand(rng, dim); qa = Rand(rng, dim); pb = Rand(rng, dim); qb = Rand(rng, dim);
                        break;
                    case 1: // nearly parallel, crossing or at a small offset, shifted along
                    {
                        double theta = Math.Pow(10, -(3 + i % 12));
                        var u = Unit(rng, dim);
                        var m = dim == 3 ? Vector3D.Cross(u, Unit(rng, dim)) : new Vector3D(-u.Y, u.X, 0);
                        m /= m.Length;
                        var h = dim == 3 ? Vector3D.Cross(u, m) * ((i / 12) % 2 == 0 ? 0 : 1e-3) : m * ((i / 12) % 2 == 0 ? 0 : 1e-3);
                        var c = Rand(rng, dim);
                        var da = u * Math.Cos(theta / 2) + m * Math.Sin(theta / 2);
                        var db = u * Math.Cos(theta / 2) - m * Math.Sin(theta / 2);
                        double sa = rng.NextDouble() - 0.5, sb = rng.NextDouble() - 0.5;
                        pa = c + da * (sa - 0.5); qa = c + da * (sa + 0.5);
                        pb = c + h + db * (sb - 0.5); qb = c + h + db * (sb + 0.5);
                        if (rng.Next(2) == 0) (pb, qb) = (qb, pb);
                        ra *= 1e-3; rb *= 1e-3;
                        break;
                    }
                    case 2: // nearly collinear, overlapping
                    {
                        var u = Unit(rng, dim);
                        var c = Rand(rng, dim);
                        pa = c + u * (rng.NextDouble() * 2 - 1); qa = c + u * (1.5 + rng.NextDouble());
                        pb = c + u * (rng.NextDouble() * 2 - 0.5); qb = c + u * (2 + rng.NextDouble());
                        if (rng.Next(2) == 0) (pb, qb) = (qb, pb);
                        break;
                    }
                    case 3: // A's start near B's line
                    {
                        pb = Rand(rng, dim); qb = Rand(rng, dim);
                        var d = qb - pb;
                        pa = pb + d * (rng.NextDouble() * 3 - 1) + Unit(rng, dim) * Math.Pow(2, -20 - rng.Next(30));
                        qa = pa + Unit(rng, dim);
                        break;
                    }
                    default: // origins 1e6 away along the direction
                    {
                        var u = Unit(rng, dim);
                        var c = Rand(rng, dim);
                        double far = 1e6 * (rng.Next(2) == 0 ? 1 : -1);
                        pa = c + u * far; qa = pa + (u + Rand(rng, dim, 1e-3));
                        pb = c + Rand(rng, dim); qb = pb + (u * (rng.Next(2) == 0 ? 1 : -1) + Rand(rng, dim, 1e-2));
                        break;
                    }
                }
                if ((qa - pa).LengthSquared == 0 || (qb - pb).LengthSquared == 0) continue;
                yield return (Make(ka, dim, pa, qa, ra), Make(kb, dim, pb, qb, rb));
            }
        }

        /// <summary>Every family in 2D and 3D, each configuration checked (<see cref="LinearExact.Check"/>); returns the worst E.</summary>
        public static double CheckAll(string ka, string kb, int count = 60, double bound = 32)
        {
            double worst = 0;
            for (int dim = 2; dim <= 3; dim++)
                for (int family = 0; family < 5; family++)
                    foreach (var (a, b) in Family(ka, kb, dim, family, 12, count))
                        worst = Math.Max(worst, LinearExact.Check(a, b, bound));
            TestContext.Progress.WriteLine($"{ka}-{kb}: worst E = {worst:F3}");
            return worst;
        }

        /// <summary>
        /// 2^k-scaled inputs give 2^k-scaled answers bit for bit (k = ±900 crosses into the slow path), and coordinates
        /// mixing 1e-300 and 1e300 give finite answers.
        /// </summary>
        public static void CheckScaling(string ka, string kb)
        {
            var rng = new Random(99);
            for (int dim = 2; dim <= 3; dim++)
                for (int i = 0; i < 20; i++)
                {
                    Vector3D pa = Rand(rng, dim), qa = Rand(rng, dim), pb = Rand(rng, dim), qb = Rand(rng, dim);
                    double ra = rng.NextDouble() * 0.5, rb = rng.NextDouble() * 0.5;
                    dynamic a = Make(ka, dim, pa, qa, ra), b = Make(kb, dim, pb, qb, rb);
                    var r = Api.Between(a, b);
                    foreach (int k in new[] { -900, -300, 7, 300, 900 })
                    {
                        double f = Math.Pow(2, k);
                        dynamic sa = Make(ka, dim, pa * f, qa * f, ra * f), sb = Make(kb, dim, pb * f, qb * f, rb * f);
                        var s = Api.Between(sa, sb);
                        string at = $"k={k}: {a} vs {b}: {r} / {s}";
                        Assert.That((double)s.Distance, Is.EqualTo((double)r.Distance * f), at);
                        Assert.That((double)Api.Distance(sa, sb), Is.EqualTo((double)r.Distance * f), at);
                        Assert.That((bool)Api.Overlaps(sa, sb), Is.EqualTo((bool)Api.Overlaps(a, b)), at);
                        Assert.That((double)s.ParameterA, Is.EqualTo(Param(ka, (double)r.ParameterA, f)), at);
                        Assert.That((double)s.ParameterB, Is.EqualTo(Param(kb, (double)r.ParameterB, f)), at);
                    }
                    // Mixed magnitudes: finite answers, no NaN.
                    foreach (var (x, y) in new[] { (1e-300, 1e300), (1e300, 1e-300), (1e-300, 1e-300), (1e300, 1e300) })
                    {
                        dynamic ma = Make(ka, dim, pa * x, qa * y, ra * x), mb = Make(kb, dim, pb * y, qb * x, rb * y);
                        var m = Api.Between(ma, mb);
                        string at = $"mixed {x}/{y}: {ma} vs {mb}: {m}";
                        Assert.That(double.IsFinite((double)m.Distance), Is.True, at);
                        Assert.That(Finite(m.PointA) && Finite(m.PointB), Is.True, at);
                        Assert.That(double.IsFinite((double)m.ParameterA) && double.IsFinite((double)m.ParameterB), Is.True, at);
                        Assert.That((double)Api.Distance(ma, mb), Is.EqualTo((double)m.Distance), at);
                    }
                }
        }

        /// <summary>
        /// Distance and Overlaps against Between, bit for bit, in both argument orders, 2D and 3D, for a segment, line, ray
        /// or capsule (kindA) against a capsule: A starts 2^-60..2^-10 of the reach off the capsule's axis (or on it) around
        /// the near-touch threshold (2^-26 of the reach) and leaves in a random direction; one case in ten A is the
        /// capsule's own axis, and for a segment or capsule one in ten a point. Radii of the reach's size or of the gap's
        /// (2^-70..2^-10), so the axes cross, meet, lie within the radii or nearly touch beyond them; scales 1, 2^±300.
        /// </summary>
        public static void CheckAgainstBetweenAcrossTheNearTouchBand(string kindA, int seed)
        {
            var rng = new Random(seed);
            double U(double lo, double hi) => lo + (hi - lo) * rng.NextDouble();
            Vector3D R() => new Vector3D(U(-1, 1), U(-1, 1), U(-1, 1));
            double Radius(double scale) => (rng.Next(2) == 0 ? U(0.01, 0.5) : Math.ScaleB(U(1, 2), -rng.Next(10, 71))) * scale;
            bool pointOk = kindA == "segment" || kindA == "capsule";
            for (int i = 0; i < 20000; i++)
            {
                double scale = Math.ScaleB(1, rng.Next(3) switch { 0 => 0, 1 => -300, _ => 300 });
                var b0 = R();
                var b1 = R();
                double gap = rng.Next(5) == 0 ? 0 : Math.ScaleB(U(1, 2), -rng.Next(10, 61));
                var p = b0 + (b1 - b0) * U(-0.2, 1.2) + R() * gap;
                var q = pointOk && rng.Next(10) == 0 ? p : R();
                if (rng.Next(10) == 0) { p = b0; q = b1; }
                double ra = Radius(scale), rb = Radius(scale);
                for (int dim = 2; dim <= 3; dim++)
                {
                    dynamic a = Make(kindA, dim, p * scale, q * scale, ra), b = Make("capsule", dim, b0 * scale, b1 * scale, rb);
                    string at = $"case {i}, {dim}D: {a} vs {b}";
                    double ab = Api.Between(a, b).Distance, ba = Api.Between(b, a).Distance;
                    Assert.That(BitConverter.DoubleToInt64Bits((double)Api.Distance(a, b)), Is.EqualTo(BitConverter.DoubleToInt64Bits(ab)), "Distance, " + at);
                    Assert.That(BitConverter.DoubleToInt64Bits((double)Api.Distance(b, a)), Is.EqualTo(BitConverter.DoubleToInt64Bits(ba)), "Distance swapped, " + at);
                    Assert.That((bool)Api.Overlaps(a, b), Is.EqualTo(ab <= 0), "Overlaps, " + at);
                    Assert.That((bool)Api.Overlaps(b, a), Is.EqualTo(ba <= 0), "Overlaps swapped, " + at);
                }
            }
        }

        /// <summary>A line's or ray's parameter is a length and scales; a segment's or capsule's is a fraction and does not.</summary>
        private static double Param(string kind, double t, double f) => kind == "line" || kind == "ray" ? t * f : t;

        private static bool Finite(Vector3D v) => v.IsFinite;
        private static bool Finite(Vector2D v) => v.IsFinite;
    }
}
