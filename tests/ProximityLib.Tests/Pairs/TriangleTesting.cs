using System;
using System.Collections.Generic;
using System.Reflection;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// Shared checks for the triangle pairs: the exact rational reference (tests/ProximityLib.Reference, used as is: a
    /// triangle is given to it as a polytope of three vertices, three edges and one face; a 3D triangle is not solid, a 2D
    /// one is, a flat one is the segment it is; a capsule is its axis's solid signed distance less the radius) and the
    /// contract's invariants: swap symmetry bit for bit, Distance = Between(..).Distance, Overlaps agreeing with the sign,
    /// witnesses on their shapes and realising |Distance|, exact 2^k scaling including the slow path at 2^±900.
    /// </summary>
    public static class TriangleTesting
    {
        public const double U = 1.0 / (1L << 53);

        private static readonly PropertyInfo KindProperty = typeof(RShape).GetProperty(nameof(RShape.Kind))!;
        private static readonly PropertyInfo PlanarProperty = typeof(RShape).GetProperty(nameof(RShape.Planar))!;

        /// <summary>
        /// A triangle for the reference: its vertices and edges (a 2D one with area is solid). Its face is left out: the
        /// reference takes a face as a parallelogram, so face–vertex pairs are measured here (<see cref="FaceVertex2"/>).
        /// </summary>
        public static RShape Tri(RVec a, RVec b, RVec c, bool planar)
        {
            var s = new RShape();
            bool solid = planar && !RVec.Cross(b - a, c - a).IsZero;
            KindProperty.SetValue(s, solid ? RKind.Box : RKind.Point);
            PlanarProperty.SetValue(s, planar);
            foreach (var v in new[] { a, b, c })
            {
                s.Vertices.Add(v);
                s.Defining.Add(v);
            }
            foreach (var (o, d) in new[] { (a, b - a), (b, c - b), (c, a - c) })
            {
                if (d.IsZero) continue;
                s.Edges.Add((o, d));
                s.Directions.Add(d);
            }
            return s;
        }

        /// <summary>The squared distance from p to the triangle's face when p projects into it (exact), else null.</summary>
        private static Rational? FaceVertex2(RVec a, RVec b, RVec c, RVec p)
        {
            var n = RVec.Cross(b - a, c - a);
            if (n.IsZero) return null;
            if (RVec.Dot(RVec.Cross(b - a, p - a), n).Sign < 0 || RVec.Dot(RVec.Cross(c - b, p - b), n).Sign < 0 || RVec.Dot(RVec.Cross(a - c, p - c), n).Sign < 0) return null;
            var h = RVec.Dot(p - a, n);
            return h * h / n.LengthSquared;
        }

        /// <summary>The core shape (a sphere's center, a capsule's axis) and the radius around it.</summary>
        public static RShape Ref(object shape, out Rational radius)
        {
            radius = Rational.Zero;
            switch (shape)
            {
                case Triangle3 t: return Tri(RVec.From(t.A), RVec.From(t.B), RVec.From(t.C), false);
                case Triangle2 t: return Tri(RVec.From(t.A), RVec.From(t.B), RVec.From(t.C), true);
                case Capsule3 c: radius = c.Radius; return RShape.Segment(c.Start, c.End);
                case Capsule2 c: radius = c.Radius; return RShape.Segment(new Vector3D(c.Start.X, c.Start.Y, 0), new Vector3D(c.End.X, c.End.Y, 0), true);
                case Sphere c: radius = c.Radius; return RShape.Point(c.Center);
                case Circle c: radius = c.Radius; return RShape.Point(c.Center);
                default: return RShape.FromAny(shape);
            }
        }

        private static bool IsSolid(object shape) => shape switch
        {
            Sphere or Circle or Capsule3 or Capsule2 or Aabb3 or Aabb2 or Obb3 or Obb2 => true,
            Triangle2 t => !RVec.Cross(RVec.From(t.B) - RVec.From(t.A), RVec.From(t.C) - RVec.From(t.A)).IsZero,
            _ => false,
        };

        /// <summary>The exact signed distance: the cores' solid signed distance (when either shape is solid), less the radii.</summary>
        public static Rational ExactSigned(object a, object b)
        {
            var ra = Ref(a, out var rA);
            var rb = Ref(b, out var rB);
            // A line or ray against a bounded shape: its exact clipped segment (the reference's Clip; exact for distance,
            // meeting and depth).
            if (ra.IsLinear) ra = Exact.Clip(ra, rb);
            else if (rb.IsLinear) rb = Exact.Clip(rb, ra);
            Rational sd;
            if (Exact.Intersects(ra, rb)) sd = IsSolid(a) || IsSolid(b) ? -Rational.Sqrt(Exact.Depth2(ra, rb)) : Rational.Zero;
            else
            {
                var d2 = Exact.Distance2(ra, rb);
                if (a is Triangle3) foreach (var v in rb.Vertices) { var f = FaceVertex2(ra.Vertices[0], ra.Vertices[1], ra.Vertices[2], v); if (f.HasValue && f.Value < d2) d2 = f.Value; }
                if (b is Triangle3) foreach (var v in ra.Vertices) { var f = FaceVertex2(rb.Vertices[0], rb.Vertices[1], rb.Vertices[2], v); if (f.HasValue && f.Value < d2) d2 = f.Value; }
                sd = Rational.Sqrt(d2);
            }
            return sd - rA - rB;
        }

        private static double Radius(object shape) => shape switch { Capsule3 c => c.Radius, Capsule2 c => c.Radius, Sphere c => c.Radius, Circle c => c.Radius, _ => 0 };

        /// <summary>The local scale S: the largest coordinate spread of the defining points, or radius.</summary>
        public static double Scale(object a, object b) => Math.Max(Exact.Scale(Ref(a, out _), Ref(b, out _)), Math.Max(Radius(a), Radius(b)));

        /// <summary>E = |d − exact| / (u·S).</summary>
        public static double Error(object a, object b, double d) => Exact.Error(d, ExactSigned(a, b), U, Scale(a, b));

        /// <summary>The exact signed distance from a point to a shape (in a solid: negative).</summary>
        private static double PointToShape(Vector3D p, object shape, bool planar) =>
            ExactSigned(planar ? new Vector2D(p.X, p.Y) : (object)p, shape).ToDouble();

        public static DistanceResult3 Between(object a, object b) => AsResult3(Api.Between(a, b));

        private static DistanceResult3 AsResult3(object r) => r switch
        {
            DistanceResult3 r3 => r3,
            DistanceResult2 r2 => Lift(r2),
            _ => throw new ArgumentException(r.GetType().Name),
        };

        private static DistanceResult3 Lift(DistanceResult2 r) =>
            (DistanceResult3)typeof(DistanceResult3).GetConstructor(BindingFlags.NonPublic | BindingFlags.Instance, null,
                new[] { typeof(double), typeof(double), typeof(Vector3D), typeof(Vector3D), typeof(double), typeof(double) }, null)!
                .Invoke(new object[] { r.Distance, r.DistanceSquared, new Vector3D(r.PointA.X, r.PointA.Y, 0), new Vector3D(r.PointB.X, r.PointB.Y, 0), r.ParameterA, r.ParameterB });

        private static double MaxAbs(Vector3D v) => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));

        private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);

        /// <summary>
        /// Every invariant of the contract on one configuration, and E against the exact reference (returned). Overlaps may
        /// disagree with the sign only within <paramref name="band"/>·u·S of touching.
        /// </summary>
        public static double Check(object a, object b, string at, double band = 64) => Check(a, b, ref at, band);

        public static double Check(object a, object b, ref string at, double band = 64, double witnessE = 64)
        {
            var r = Between(a, b);
            var rs = Between(b, a);
            bool planar = a is Vector2D || a.GetType().Name.EndsWith("2") || a is Circle;
            at += $" {a} | {b} → {r}";
            Assert.That(double.IsNaN(r.Distance) || double.IsInfinity(r.Distance), Is.False, at);
            // Swap symmetry, bit for bit.
            Assert.That(Bits(rs.Distance), Is.EqualTo(Bits(r.Distance)), "swapped distance " + at);
            Assert.That(rs.PointA == r.PointB && rs.PointB == r.PointA, Is.True, "swapped witnesses " + at);
            Assert.That(Bits(rs.ParameterA) == Bits(r.ParameterB) && Bits(rs.ParameterB) == Bits(r.ParameterA), Is.True, "swapped parameters " + at);
            // The distance-only entry points.
            Assert.That(Bits((double)Api.Distance(a, b)), Is.EqualTo(Bits(r.Distance)), "Distance " + at);
            Assert.That(Bits((double)Api.Distance(b, a)), Is.EqualTo(Bits(r.Distance)), "Distance swapped " + at);
            double s = Scale(a, b);
            double e = Error(a, b, r.Distance);
            // Overlaps agrees with the sign outside a tiny band, and is symmetric.
            bool o = Api.Overlaps(a, b);
            Assert.That((bool)Api.Overlaps(b, a), Is.EqualTo(o), "Overlaps swapped " + at);
            if (Math.Abs(r.Distance) > band * U * s) Assert.That(o, Is.EqualTo(r.Distance <= 0), "Overlaps " + at);
            // The witnesses: on (in) their shapes, and |PointA − PointB| = |Distance|.
            // Witnesses are positions: rounded at the scale of their coordinates too.
            double tol = witnessE * U * (s + Math.Max(MaxAbs(r.PointA), MaxAbs(r.PointB)));
            Assert.That(PointToShape(r.PointA, a, planar), Is.LessThanOrEqualTo(tol), "PointA on A " + at);
            Assert.That(PointToShape(r.PointB, b, planar), Is.LessThanOrEqualTo(tol), "PointB on B " + at);
            Assert.That(Math.Abs((r.PointA - r.PointB).Length - Math.Abs(r.Distance)), Is.LessThanOrEqualTo(tol + 1e-6 * Math.Abs(r.Distance)), "|PA − PB| " + at);
            if (r.Distance > 0) Assert.That(r.DistanceSquared, Is.EqualTo(r.Distance * r.Distance).Within(4 * U * r.Distance * r.Distance), "DistanceSquared " + at);
            else Assert.That(r.DistanceSquared, Is.EqualTo(0), "DistanceSquared " + at);
            return e;
        }

        /// <summary>2^k-scaled inputs give 2^k-scaled answers bit for bit, for every k given (the slow path included).</summary>
        public static void CheckScaling(object a, object b, string at, params int[] ks)
        {
            // Against the copy scaled by 1: a line's direction is normalised again on construction, as in every scaled copy.
            var r = Between(Scaled(a, 1), Scaled(b, 1));
            foreach (int k in ks)
            {
                double f = Math.Pow(2, k);
                var q = Between(Scaled(a, f), Scaled(b, f));
                string w = $"{at} {a} | {b} 2^{k}: {r} vs {q}";
                Assert.That(q.Distance, Is.EqualTo(r.Distance * f), w);
                Assert.That(q.PointA == r.PointA * f && q.PointB == r.PointB * f, Is.True, w);
                // A line's or ray's parameter is a length: it scales too.
                Assert.That(q.ParameterA == r.ParameterA * (IsLinear(a) ? f : 1) && q.ParameterB == r.ParameterB * (IsLinear(b) ? f : 1), Is.True, w);
                Assert.That((bool)Api.Overlaps(Scaled(a, f), Scaled(b, f)), Is.EqualTo((bool)Api.Overlaps(Scaled(a, 1), Scaled(b, 1))), w);
            }
        }

        private static bool IsLinear(object shape) => shape is Line3 || shape is Line2 || shape is Ray3 || shape is Ray2;

        public static object Scaled(object shape, double f) => shape switch
        {
            Line3 l => new Line3(l.Origin * f, l.Direction),
            Line2 l => new Line2(l.Origin * f, l.Direction),
            Ray3 l => new Ray3(l.Origin * f, l.Direction),
            Ray2 l => new Ray2(l.Origin * f, l.Direction),
            Vector3D p => p * f,
            Vector2D p => p * f,
            Segment3 s => new Segment3(s.Start * f, s.End * f),
            Segment2 s => new Segment2(s.Start * f, s.End * f),
            Sphere s => new Sphere(s.Center * f, s.Radius * f),
            Circle c => new Circle(c.Center * f, c.Radius * f),
            Capsule3 c => new Capsule3(c.Start * f, c.End * f, c.Radius * f),
            Capsule2 c => new Capsule2(c.Start * f, c.End * f, c.Radius * f),
            Triangle3 t => new Triangle3(t.A * f, t.B * f, t.C * f),
            Triangle2 t => new Triangle2(t.A * f, t.B * f, t.C * f),
            Aabb3 b => new Aabb3(b.Min * f, b.Max * f),
            Aabb2 b => new Aabb2(b.Min * f, b.Max * f),
            _ => throw new ArgumentException(shape.GetType().Name),
        };

        // ---- Random configurations (seeded) ----

        public static Vector3D P3(Random g, double s = 1) => new Vector3D(Next(g) * s, Next(g) * s, Next(g) * s);
        public static Vector2D P2(Random g, double s = 1) => new Vector2D(Next(g) * s, Next(g) * s);

        /// <summary>A value in [−1, 1) on a 2^-20 grid half the time (exact ties and touching), else any double there.</summary>
        public static double Next(Random g) => g.Next(2) == 0 ? Math.Round((g.NextDouble() * 2 - 1) * (1 << 20)) / (1 << 20) : g.NextDouble() * 2 - 1;

        /// <summary>Triangles of the hard families: general, needle, sliver, nearly flat, flat (collinear), coincident vertices.</summary>
        public static Triangle3 Tri3(Random g, int family)
        {
            var a = P3(g);
            var b = P3(g);
            switch (family % 6)
            {
                case 1: return new Triangle3(a, b, b + P3(g, 1e-6));                   // needle
                case 2: return new Triangle3(a, b, a + (b - a) * g.NextDouble() + P3(g, 1e-9)); // sliver
                case 3: return new Triangle3(a, b, a + (b - a) * 0.375 + P3(g, 1e-15)); // nearly flat
                case 4: return new Triangle3(a, b, a + (b - a) * 0.25);               // flat (exactly collinear when representable)
                case 5: return new Triangle3(a, a, g.Next(2) == 0 ? a : b);           // coincident vertices
                default: return new Triangle3(a, b, P3(g));
            }
        }

        public static Triangle2 Tri2(Random g, int family)
        {
            var t = Tri3(g, family);
            return new Triangle2(new Vector2D(t.A.X, t.A.Y), new Vector2D(t.B.X, t.B.Y), new Vector2D(t.C.X, t.C.Y));
        }

        /// <summary>A point near the triangle: near a vertex, an edge, over the interior, or anywhere.</summary>
        public static Vector3D Near(Random g, Triangle3 t)
        {
            double u = g.NextDouble(), v = g.NextDouble() * (1 - u);
            var p = (g.Next(4)) switch
            {
                0 => t.A,
                1 => t.A + (t.B - t.A) * u,
                2 => t.A + (t.B - t.A) * u + (t.C - t.A) * v,
                _ => P3(g),
            };
            return p + P3(g, Math.Pow(2, -g.Next(60)));
        }

        public static Vector2D Near(Random g, Triangle2 t)
        {
            var p = Near(g, new Triangle3(new Vector3D(t.A.X, t.A.Y, 0), new Vector3D(t.B.X, t.B.Y, 0), new Vector3D(t.C.X, t.C.Y, 0)));
            return new Vector2D(p.X, p.Y);
        }

        /// <summary>Collects the worst E of a run and reports it.</summary>
        public sealed class Worst
        {
            private readonly string _name;
            public double E;
            private string _at = "";
            public Worst(string name) { _name = name; }
            public void Add(double e, string at = "") { if (e > E) { E = e; _at = at; } }
            public void Report(double bound = 32)
            {
                TestContext.Out.WriteLine($"{_name}: worst E = {E:F3}");
                Assert.That(E, Is.LessThanOrEqualTo(bound), _name + " at " + _at);
            }
        }
    }
}
