using System;
using System.Collections.Generic;
using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>One configuration of a hard-case family: two double-API shapes.</summary>
    public sealed class Case
    {
        public Case(string family, object a, object b) { Family = family; A = a; B = b; }
        public string Family { get; }
        public object A { get; }
        public object B { get; }
        public string Pair => Shapes.Name(A) + "–" + Shapes.Name(B);
        public override string ToString() => $"{Family}: {Shapes.Describe(A)} vs {Shapes.Describe(B)}";
    }

    /// <summary>
    /// The seeded, parametrised hard-case families. Every generator takes a count (per parameter value where it
    /// has one) and a seed, so the CI run and the larger offline run draw from the same distributions.
    /// </summary>
    public static class Families
    {
        public static readonly string[] Names =
        {
            "random", "nearly-parallel", "parallel", "dot-perp", "tiny-segments", "far-along-line", "far-from-origin",
            "range-limits", "near-contact", "box-boundaries", "stacked-obbs", "obb-inputs", "crossing-lines", "tiny-against-long",
            "parallel-shifted", "identical-rotations", "mixed-scales",
        };

        public static IEnumerable<Case> Get(string name, int count, int seed)
        {
            var rng = new Random(seed);
            return name switch
            {
                "random" => RandomPairs(rng, count),
                "nearly-parallel" => NearlyParallel(rng, count),
                "parallel" => Parallel(rng, count),
                "dot-perp" => DotPerp(rng, count),
                "tiny-segments" => TinySegments(rng, count),
                "far-along-line" => FarAlongLine(rng, count),
                "far-from-origin" => FarFromOrigin(rng, count),
                "range-limits" => RangeLimits(rng, count),
                "near-contact" => NearContact(rng, count),
                "box-boundaries" => BoxBoundaries(rng, count),
                "stacked-obbs" => StackedObbs(rng, count),
                "obb-inputs" => ObbInputs(rng, count),
                "crossing-lines" => CrossingLines(rng, count),
                "tiny-against-long" => TinyAgainstLong(rng, count),
                "parallel-shifted" => ParallelShifted(rng, count),
                "identical-rotations" => IdenticalRotations(rng, count),
                "mixed-scales" => MixedScales(rng, count),
                _ => throw new ArgumentException(name),
            };
        }

        // ---- helpers -------------------------------------------------------------------------------------------

        private static double U(Random r, double lo, double hi) => lo + (hi - lo) * r.NextDouble();
        private static Vector3D V(Random r, double range) => new Vector3D(U(r, -range, range), U(r, -range, range), U(r, -range, range));
        private static Vector2D V2(Vector3D v) => new Vector2D(v.X, v.Y);

        /// <summary>A uniformly random rotation as three orthonormal columns.</summary>
        public static Vector3D[] Rotation(Random r)
        {
            double x = Gauss(r), y = Gauss(r), z = Gauss(r), w = Gauss(r);
            var o = Obb3.FromQuaternion(default, x, y, z, w, default);
            return new[] { o.AxisX, o.AxisY, o.AxisZ };
        }

        private static double Gauss(Random r) => Math.Sqrt(-2 * Math.Log(1 - r.NextDouble())) * Math.Cos(2 * Math.PI * r.NextDouble());
        private static Vector3D Apply(Vector3D[] m, Vector3D v) => m[0] * v.X + m[1] * v.Y + m[2] * v.Z;

        /// <summary>A random shape of a kind at about unit size around c (3D, or 2D in the z = 0 plane).</summary>
        public static object Shape(Random r, string kind, int dim, Vector3D c, double size = 1)
        {
            if (dim == 2) c = new Vector3D(c.X, c.Y, 0);
            Vector3D Ext() => new Vector3D(U(r, 0.1, 1) * size, U(r, 0.1, 1) * size, dim == 3 ? U(r, 0.1, 1) * size : 0);
            switch (kind)
            {
                case "point": return dim == 3 ? (object)c : V2(c);
                case "segment":
                    var d = V(r, size);
                    return dim == 3 ? (object)new Segment3(c - d, c + d) : new Segment2(V2(c - d), V2(c + d));
                case "sphere": return dim == 3 ? (object)new Sphere(c, U(r, 0.1, 1) * size) : new Circle(V2(c), U(r, 0.1, 1) * size);
                case "aabb":
                    var h = Ext();
                    return dim == 3 ? (object)new Aabb3(c - h, c + h) : new Aabb2(V2(c - h), V2(c + h));
                default:
                    var e = Ext();
                    if (dim == 2) return new Obb2(V2(c), U(r, 0, 2 * Math.PI), V2(e));
                    var m = Rotation(r);
                    return new Obb3(c, m[0], m[1], m[2], e);
            }
        }

        public static readonly string[] Kinds = { "point", "segment", "sphere", "aabb", "obb" };

        // ---- the families -------------------------------------------------------------------------------------

        /// <summary>Every pair, both dimensions: random unit-scale configurations, apart and overlapping.</summary>
        private static IEnumerable<Case> RandomPairs(Random r, int count)
        {
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < Kinds.Length; i++)
                    for (int j = i; j < Kinds.Length; j++)
                        for (int k = 0; k < count; k++)
                            yield return new Case("random", Shape(r, Kinds[i], dim, V(r, 1.5)), Shape(r, Kinds[j], dim, V(r, 1.5)));
        }

        /// <summary>Segments at angle 10^-k (k = 1..14), offsets 0 and 1e-3, random shifts along, randomly placed.</summary>
        private static IEnumerable<Case> NearlyParallel(Random r, int count)
        {
            for (int k = 1; k <= 14; k++)
                foreach (double offset in new[] { 0.0, 1e-3 })
                    for (int n = 0; n < count; n++)
                    {
                        double angle = Math.Pow(10, -k);
                        double la = U(r, 0.5, 2), lb = U(r, 0.5, 2), shift = U(r, -1, 1);
                        var a0 = new Vector3D(0, 0, 0);
                        var a1 = new Vector3D(la, 0, 0);
                        // B turned by `angle` about z (in 3D also lifted by `offset` out of the plane).
                        var dir = new Vector3D(Math.Cos(angle), Math.Sin(angle), 0);
                        var b0 = new Vector3D(shift, offset, offset);
                        var b1 = b0 + dir * lb;
                        var m = Rotation(r);
                        var t = V(r, 1);
                        yield return new Case("nearly-parallel", new Segment3(Apply(m, a0) + t, Apply(m, a1) + t), new Segment3(Apply(m, b0) + t, Apply(m, b1) + t));
                        double c = Math.Cos(U(r, 0, 6.3)), s = Math.Sqrt(1 - c * c);
                        Vector2D R2(Vector3D v) => new Vector2D(c * v.X - s * v.Y, s * v.X + c * v.Y);
                        yield return new Case("nearly-parallel", new Segment2(R2(a0), R2(a1)), new Segment2(R2(b0), R2(b1)));
                    }
        }

        /// <summary>
        /// Two segments given in a local frame (z dropped for 2D), turned at random (in the plane for 2D), placed, and
        /// scaled by 2^j (j in [−24, 24], inside the batch queries' range).
        /// </summary>
        private static Case Placed(Random r, string family, int dim, Vector3D a0, Vector3D a1, Vector3D b0, Vector3D b1)
        {
            double scale = Math.Pow(2, r.Next(-24, 25));
            var t = V(r, 4) * (r.Next(4) == 0 ? 0 : 1);
            if (dim == 3)
            {
                var m = Rotation(r);
                Vector3D P(Vector3D v) => (Apply(m, v) + t) * scale;
                return new Case(family, new Segment3(P(a0), P(a1)), new Segment3(P(b0), P(b1)));
            }
            double angle = U(r, 0, 2 * Math.PI), c = Math.Cos(angle), s = Math.Sin(angle);
            Vector2D Q(Vector3D v) => new Vector2D(c * v.X - s * v.Y + t.X, s * v.X + c * v.Y + t.Y) * scale;
            return new Case(family, new Segment2(Q(a0), Q(a1)), new Segment2(Q(b0), Q(b1)));
        }

        /// <summary>
        /// Segments whose lines cross (2D), or pass at a gap g = 0 or 10^-U(0,7) of a's length (3D), at random points
        /// inside or just outside both, at angles 10^-(k+U(0,1)) for k = 0..6 and 0 (collinear up to rounding): the
        /// lines' stationary point is the answer and ill-conditioned. Random lengths, turns, positions and 2^j scales.
        /// </summary>
        private static IEnumerable<Case> CrossingLines(Random r, int count)
        {
            foreach (int k in new[] { 0, 1, 2, 3, 4, 5, 6, -1 })
                for (int n = 0; n < count; n++)
                    foreach (int dim in new[] { 3, 2 })
                    {
                        double angle = k < 0 ? 0 : Math.Pow(10, -k - r.NextDouble());
                        double la = U(r, 0.25, 2), lb = U(r, 0.25, 2), ua = U(r, -0.2, 1.2), ub = U(r, -0.2, 1.2);
                        double gap = dim == 2 || n % 3 == 0 ? 0 : la * Math.Pow(10, -U(r, 0, 7)) * (r.Next(2) == 0 ? 1 : -1);
                        var ea = new Vector3D(1, 0, 0);
                        var eb = new Vector3D(Math.Cos(angle), Math.Sin(angle), 0);
                        var up = new Vector3D(0, 0, gap);
                        var b0 = up - eb * (ub * lb);
                        var b1 = up + eb * ((1 - ub) * lb);
                        if (r.Next(2) == 0) (b0, b1) = (b1, b0);
                        yield return Placed(r, "crossing-lines", dim, ea * (-ua * la), ea * ((1 - ua) * la), b0, b1);
                    }
        }

        /// <summary>
        /// A segment 2^-k (k = 1, 4, …, 28) as long as the other, near a random point of it (gap 0 or 2^-U(0,30) of the
        /// length) in a random direction or nearly parallel (10^-U(1,7)); and, in 3D, two segments that short whose
        /// lines cross in projection at random inside points, stacked a unit apart along the common normal.
        /// </summary>
        private static IEnumerable<Case> TinyAgainstLong(Random r, int count)
        {
            for (int k = 1; k <= 28; k += 3)
                for (int n = 0; n < count; n++)
                    foreach (int dim in new[] { 3, 2 })
                    {
                        double lb = U(r, 0.5, 2), la = lb * Math.Pow(2, -k) * U(r, 1, 2);
                        double angle = n % 2 == 0 ? U(r, 0, 2 * Math.PI) : Math.Pow(10, -U(r, 1, 7));
                        var ea = new Vector3D(Math.Cos(angle), Math.Sin(angle), 0);
                        var side = new Vector3D(0, 1, 0);
                        if (dim == 3 && n % 2 == 0)
                        {
                            ea = V(r, 1);
                            ea /= ea.Length;
                            side = V(r, 1);
                            side /= side.Length;
                        }
                        double gap = n % 3 == 0 ? 0 : lb * Math.Pow(2, -U(r, 0, 30));
                        var c = new Vector3D(U(r, -0.1, 1.1) * lb, 0, 0) + side * gap;
                        double ua = U(r, -0.5, 1.5);
                        var a0 = c - ea * (ua * la);
                        var a1 = c + ea * ((1 - ua) * la);
                        var placed = Placed(r, "tiny-against-long", dim, a0, a1, new Vector3D(0, 0, 0), new Vector3D(lb, 0, 0));
                        yield return r.Next(2) == 0 ? placed : new Case(placed.Family, placed.B, placed.A);
                        if (dim == 2) continue;
                        // Both short: crossing in projection, a unit apart along z.
                        var eb = new Vector3D(Math.Cos(angle + 1), Math.Sin(angle + 1), 0);
                        double lc = la * U(r, 0.5, 2), uc = U(r, 0, 1);
                        yield return Placed(r, "tiny-against-long", 3, ea * (-ua * la), ea * ((1 - ua) * la),
                            new Vector3D(0, 0, 1) - eb * (uc * lc), new Vector3D(0, 0, 1) + eb * ((1 - uc) * lc));
                    }
        }

        /// <summary>Exactly parallel, collinear and antiparallel segments: overlapping, touching end to end, disjoint.</summary>
        private static IEnumerable<Case> Parallel(Random r, int count)
        {
            for (int n = 0; n < count; n++)
            {
                // Integer-valued directions keep "parallel" exact after scaling by the float-exact parameters below.
                var d = new Vector3D(r.Next(-8, 9), r.Next(-8, 9), r.Next(1, 9));
                var p = new Vector3D(r.Next(-8, 9), r.Next(-8, 9), r.Next(-8, 9)) * 0.25;
                var side = new Vector3D(-d.Y, d.X, 0) * (r.Next(0, 3) * 0.5);
                foreach (double start in new[] { 0.5, 1.0, 1.5 })
                    foreach (bool anti in new[] { false, true })
                    {
                        // start 0.5 overlaps, 1.0 touches end to end (when not shifted sideways), 1.5 is disjoint.
                        var b0 = p + d * start + side;
                        var b1 = b0 + d;
                        if (anti) (b0, b1) = (b1, b0);
                        yield return new Case("parallel", new Segment3(p, p + d), new Segment3(b0, b1));
                        yield return new Case("parallel", new Segment2(V2(p), V2(p + d)), new Segment2(V2(b0), V2(b1)));
                    }
            }
        }

        /// <summary>The 2D pair whose dot-perp rounds to 0 but is −3.94e-17, and random near-zero determinants.</summary>
        private static IEnumerable<Case> DotPerp(Random r, int count)
        {
            yield return new Case("dot-perp",
                new Segment2(new Vector2D(2.2352092822407803, -1.7068004885705972), new Vector2D(1.4357507764403734, -4.4188128129047435)),
                new Segment2(new Vector2D(1.8515323877379666, -1.5936985848524166), new Vector2D(1.2171034035398707, -3.7458793566829809)));
            for (int n = 0; n < count; n++)
            {
                // Directions within a few ulps of each other: the rounded determinant is 0, tiny positive or tiny negative.
                var a0 = new Vector2D(U(r, -3, 3), U(r, -3, 3));
                double angle = U(r, 0, 2 * Math.PI);
                var d = new Vector2D(Math.Cos(angle), Math.Sin(angle)) * U(r, 1, 3);
                var e = new Vector2D(d.X * (1 + U(r, -4, 4) * 1e-16), d.Y * (1 + U(r, -4, 4) * 1e-16)) * U(r, 0.5, 1.5);
                var b0 = a0 + new Vector2D(-d.Y, d.X) * U(r, -1e-3, 1e-3) + d * U(r, -0.5, 0.5);
                yield return new Case("dot-perp", new Segment2(a0, a0 + d), new Segment2(b0, b0 + e));
            }
        }

        /// <summary>Zero-length and 2^-k-long segments (k = 10..60), and whole configurations scaled by 2^±k.</summary>
        private static IEnumerable<Case> TinySegments(Random r, int count)
        {
            for (int n = 0; n < count; n++)
                for (int k = 10; k <= 60; k += 10)
                {
                    double len = Math.Pow(2, -k);
                    var c = V(r, 1);
                    var d = V(r, 1);
                    d /= d.Length;
                    var tiny = new Segment3(c, c + d * len);
                    var zero = new Segment3(c, c);
                    var other = (Segment3)Shape(r, "segment", 3, V(r, 1));
                    yield return new Case("tiny-segments", tiny, other);
                    yield return new Case("tiny-segments", zero, other);
                    yield return new Case("tiny-segments", V(r, 1), tiny);
                    yield return new Case("tiny-segments", tiny, Shape(r, "sphere", 3, V(r, 1)));
                    yield return new Case("tiny-segments", tiny, Shape(r, "obb", 3, V(r, 1)));
                    yield return new Case("tiny-segments", new Segment2(V2(c), V2(c + d * len)), Shape(r, "aabb", 2, V(r, 1)));
                }
            // Whole configurations scaled toward both ends of the float range (floats reach 2^±126 as normal numbers).
            foreach (int k in new[] { -120, -60, 60, 120 })
                for (int n = 0; n < count; n++)
                {
                    double s = Math.Pow(2, k);
                    var c = V(r, 1) * s;
                    var d = V(r, 1) * (s * Math.Pow(2, -r.Next(0, 30)));
                    yield return new Case("tiny-segments", new Segment3(c, c + d), Shape(r, "segment", 3, V(r, 1) * s, s));
                    yield return new Case("tiny-segments", V(r, 1) * s, new Segment3(c, c + d));
                }
        }

        /// <summary>A point at distance h from a segment's line and D along it, D/h = 10^k.</summary>
        private static IEnumerable<Case> FarAlongLine(Random r, int count)
        {
            for (int k = 0; k <= 15; k++)
                for (int n = 0; n < count; n++)
                {
                    double h = U(r, 0.5, 1), big = h * Math.Pow(10, k);
                    var m = Rotation(r);
                    var a = Apply(m, new Vector3D(-big * U(r, 0.5, 2), 0, 0));
                    var b = Apply(m, new Vector3D(big * U(r, 0.5, 2), 0, 0));
                    var p = Apply(m, new Vector3D(big * U(r, -0.4, 0.4), h, 0));
                    yield return new Case("far-along-line", p, new Segment3(a, b));
                    yield return new Case("far-along-line", new Vector2D(p.X, p.Y), new Segment2(new Vector2D(a.X, a.Y), new Vector2D(b.X, b.Y)));
                }
        }

        /// <summary>Unit-size configurations about 1e-3 apart (or overlapping), translated by T = 10^3 … 10^12.</summary>
        private static IEnumerable<Case> FarFromOrigin(Random r, int count)
        {
            for (int e = 3; e <= 12; e++)
                for (int n = 0; n < count; n++)
                {
                    var t = V(r, 1);
                    t = t / t.Length * Math.Pow(10, e);
                    int dim = n % 2 == 0 ? 3 : 2;
                    string ka = Kinds[r.Next(Kinds.Length)], kb = Kinds[r.Next(Kinds.Length)];
                    var off = V(r, 1.2);
                    yield return new Case("far-from-origin", Shape(r, ka, dim, t), Shape(r, kb, dim, t + off));
                }
        }

        /// <summary>Every pair at scales 2^±240 … 2^±1000 (the whole double range; past 2^±400 the slow, rescaling path).</summary>
        private static IEnumerable<Case> RangeLimits(Random r, int count)
        {
            foreach (int k in new[] { -1000, -900, -720, -480, -240, 240, 480, 720, 900, 1000 })
                for (int n = 0; n < count; n++)
                {
                    double s = Math.Pow(2, k);
                    int dim = n % 2 == 0 ? 3 : 2;
                    string ka = Kinds[r.Next(Kinds.Length)], kb = Kinds[r.Next(Kinds.Length)];
                    yield return new Case("range-limits", Shape(r, ka, dim, V(r, 1.5) * s, s), Shape(r, kb, dim, V(r, 1.5) * s, s));
                }
        }

        /// <summary>Spheres and circles with gap 10^-k·R, R from 1e-6 to 1e6, and coincident centers.</summary>
        private static IEnumerable<Case> NearContact(Random r, int count)
        {
            foreach (double radius in new[] { 1e-6, 1e-3, 1, 1e3, 1e6 })
                for (int k = 1; k <= 15; k += 2)
                    for (int n = 0; n < count; n++)
                    {
                        double ra = radius * U(r, 0.5, 1), rb = radius * U(r, 0.5, 1);
                        var dir = V(r, 1);
                        dir /= dir.Length;
                        var ca = V(r, radius);
                        double gap = Math.Pow(10, -k) * radius * (n % 3 == 0 ? -1 : 1);
                        var cb = ca + dir * (ra + rb + gap);
                        yield return new Case("near-contact", new Sphere(ca, ra), new Sphere(cb, rb));
                        yield return new Case("near-contact", new Circle(V2(ca), ra), new Circle(V2(ca) + new Vector2D(dir.X, dir.Y) / Math.Sqrt(dir.X * dir.X + dir.Y * dir.Y) * (ra + rb + gap), rb));
                        yield return new Case("near-contact", ca + dir * (ra + gap), new Sphere(ca, ra));
                        yield return new Case("near-contact", new Sphere(ca, ra), new Sphere(ca, rb));
                        var box = Obb3Around(r, cb, radius);
                        yield return new Case("near-contact", new Sphere(ca, ra), box);
                    }
        }

        private static Obb3 Obb3Around(Random r, Vector3D c, double size)
        {
            var m = Rotation(r);
            return new Obb3(c, m[0], m[1], m[2], new Vector3D(U(r, 0.2, 1), U(r, 0.2, 1), U(r, 0.2, 1)) * size);
        }

        /// <summary>Points exactly on faces, edges and corners of boxes and one ulp either side; inside; AABBs touching exactly.</summary>
        private static IEnumerable<Case> BoxBoundaries(Random r, int count)
        {
            for (int n = 0; n < count; n++)
            {
                var min = new Vector3D(U(r, -2, 0), U(r, -2, 0), U(r, -2, 0));
                var max = min + new Vector3D(U(r, 0.1, 2), U(r, 0.1, 2), U(r, 0.1, 2));
                var box = new Aabb3(min, max);
                var inner = new Vector3D(U(r, min.X, max.X), U(r, min.Y, max.Y), U(r, min.Z, max.Z));
                var onFace = new Vector3D(max.X, inner.Y, inner.Z);
                var onEdge = new Vector3D(max.X, min.Y, inner.Z);
                var onCorner = max;
                foreach (var p in new[] { onFace, onEdge, onCorner })
                    foreach (int ulps in new[] { -1, 0, 1 })
                        yield return new Case("box-boundaries", Nudge(p, ulps), box);
                yield return new Case("box-boundaries", inner, box);
                yield return new Case("box-boundaries", new Vector2D(max.X, inner.Y), new Aabb2(new Vector2D(min.X, min.Y), new Vector2D(max.X, max.Y)));
                // AABBs touching exactly on a face, an edge, a corner.
                var size = new Vector3D(U(r, 0.1, 1), U(r, 0.1, 1), U(r, 0.1, 1));
                yield return new Case("box-boundaries", box, new Aabb3(new Vector3D(max.X, inner.Y, inner.Z), new Vector3D(max.X, inner.Y, inner.Z) + size));
                yield return new Case("box-boundaries", box, new Aabb3(new Vector3D(max.X, max.Y, inner.Z), new Vector3D(max.X, max.Y, inner.Z) + size));
                yield return new Case("box-boundaries", box, new Aabb3(max, max + size));
                // An OBB and a sphere with a point on the box's face.
                var obb = Obb3Around(r, V(r, 1), 1);
                var face = obb.Center + obb.AxisX * obb.HalfExtents.X + obb.AxisY * (obb.HalfExtents.Y * U(r, -1, 1));
                yield return new Case("box-boundaries", face, obb);
                yield return new Case("box-boundaries", new Sphere(face + obb.AxisX * 0.25, 0.25), obb);
            }
        }

        private static Vector3D Nudge(Vector3D p, int ulps) =>
            ulps == 0 ? p : new Vector3D(BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(p.X) + (p.X >= 0 ? ulps : -ulps)), p.Y, p.Z);

        /// <summary>
        /// OBBs stacked with 10–50% penetration whose axes are one rotation rounded through different paths (residual
        /// angles 0, 1e-18 … 1e-6); pairs separated only along an edge × edge axis; near-touching stacks.
        /// </summary>
        private static IEnumerable<Case> StackedObbs(Random r, int count)
        {
            foreach (double residual in new[] { 0, 1e-18, 1e-15, 1e-12, 1e-9, 1e-6 })
                for (int n = 0; n < count; n++)
                {
                    double x = Gauss(r), y = Gauss(r), z = Gauss(r), w = Gauss(r);
                    // Path 1: the quaternion; path 2: the same rotation as axes, perturbed by the residual angle.
                    var a = Obb3.FromQuaternion(V(r, 1), x, y, z, w, new Vector3D(U(r, 0.3, 1), U(r, 0.3, 1), U(r, 0.3, 1)));
                    var tilt = Obb3.FromQuaternion(default, residual * Gauss(r), residual * Gauss(r), residual * Gauss(r), 1, default);
                    var bx = Apply(new[] { tilt.AxisX, tilt.AxisY, tilt.AxisZ }, a.AxisX);
                    var by = Apply(new[] { tilt.AxisX, tilt.AxisY, tilt.AxisZ }, a.AxisY);
                    var bz = Apply(new[] { tilt.AxisX, tilt.AxisY, tilt.AxisZ }, a.AxisZ);
                    var hb = new Vector3D(U(r, 0.3, 1), U(r, 0.3, 1), U(r, 0.3, 1));
                    double penetration = U(r, 0.1, 0.5) * Math.Min(a.HalfExtents.Z, hb.Z) * 2;
                    var slide = a.AxisX * U(r, -0.3, 0.3) + a.AxisY * U(r, -0.3, 0.3);
                    var cb = a.Center + a.AxisZ * (a.HalfExtents.Z + hb.Z - penetration) + slide;
                    yield return new Case("stacked-obbs", a, new Obb3(cb, bx, by, bz, hb));
                    // Near-touching: a gap of 1e-12 of the size, either side.
                    var touch = a.Center + a.AxisZ * (a.HalfExtents.Z + hb.Z + (n % 2 == 0 ? 1e-12 : -1e-12)) + slide;
                    yield return new Case("stacked-obbs", a, new Obb3(touch, bx, by, bz, hb));
                }
            // Edge against edge: two cubes turned so that only the cross axis of their leading edges separates them.
            double s = Math.Sqrt(0.5);
            for (int n = 0; n < count; n++)
            {
                double gap = Math.Pow(10, -r.Next(1, 12)) * (n % 2 == 0 ? 1 : -1);
                var m = Rotation(r);
                var a = new Obb3(default, Apply(m, new Vector3D(s, s, 0)), Apply(m, new Vector3D(-s, s, 0)), Apply(m, new Vector3D(0, 0, 1)), new Vector3D(1, 1, 1));
                var b = new Obb3(Apply(m, new Vector3D(2 * Math.Sqrt(2) + gap, 0, 0)), Apply(m, new Vector3D(s, 0, s)), Apply(m, new Vector3D(0, 1, 0)),
                    Apply(m, new Vector3D(-s, 0, s)), new Vector3D(1, 1, 1));
                yield return new Case("stacked-obbs", a, b);
            }
        }

        /// <summary>
        /// Issue 10's family for nearly parallel 3D segments: unit length, angle 10^-k (k = 3..14), offset 0 or 1e-3 along
        /// the common normal, the lines crossing inside both and each segment shifted along itself by up to half its
        /// length, randomly oriented and placed (the existing nearly-parallel family never crosses inside both).
        /// </summary>
        private static IEnumerable<Case> ParallelShifted(Random r, int count)
        {
            for (int k = 3; k <= 14; k++)
                foreach (double h in new[] { 0.0, 1e-3 })
                    for (int n = 0; n < count; n++)
                    {
                        double theta = Math.Pow(10, -k);
                        var m = Rotation(r);
                        var c = V(r, 1);
                        var da = Apply(m, new Vector3D(Math.Cos(theta / 2), Math.Sin(theta / 2), 0));
                        var db = Apply(m, new Vector3D(Math.Cos(theta / 2), -Math.Sin(theta / 2), 0));
                        var lift = Apply(m, new Vector3D(0, 0, h));
                        double sa = U(r, -0.5, 0.5), sb = U(r, -0.5, 0.5);
                        yield return new Case("parallel-shifted", new Segment3(c + da * (sa - 0.5), c + da * (sa + 0.5)),
                            new Segment3(c + lift + db * (sb - 0.5), c + lift + db * (sb + 0.5)));
                    }
        }

        /// <summary>
        /// Issue 10's family for boxes with nearly identical rotations (quaternions 1e-6 … 1e-16 apart): full boxes edge
        /// to edge diagonally with gaps and overlaps down to 1e-13 of their size, and crossing edge-like boxes (one
        /// non-zero extent), where only an edge × edge axis of nearly parallel edges gives the depth.
        /// </summary>
        private static IEnumerable<Case> IdenticalRotations(Random r, int count)
        {
            foreach (double delta in new[] { 1e-6, 1e-9, 1e-12, 1e-16 })
                for (int n = 0; n < count; n++)
                {
                    double x = Gauss(r), y = Gauss(r), z = Gauss(r), w = Gauss(r);
                    double gap = Math.Pow(10, -r.Next(6, 14)) * (r.Next(2) == 0 ? 1 : -1);
                    var ha = new Vector3D(U(r, 0.2, 1), U(r, 0.2, 1), U(r, 0.2, 1));
                    var hb = new Vector3D(U(r, 0.2, 1), U(r, 0.2, 1), U(r, 0.2, 1));
                    var a = Obb3.FromQuaternion(V(r, 1), x, y, z, w, ha);
                    var diagonal = (a.AxisX + a.AxisY) * Math.Sqrt(0.5);
                    var cb = a.Center + a.AxisX * (ha.X + hb.X) + a.AxisY * (ha.Y + hb.Y) + diagonal * gap;
                    yield return new Case("identical-rotations", a, Obb3.FromQuaternion(cb, x + delta * Gauss(r), y + delta * Gauss(r), z, w, hb));
                    // Two crossing "edges": boxes with only one non-zero extent, nearly parallel, through nearly one point.
                    var e1 = Obb3.FromQuaternion(V(r, 1), x, y, z, w, new Vector3D(0, U(r, 0.2, 1), 0));
                    var e2 = Obb3.FromQuaternion(e1.Center + e1.AxisX * gap, x + delta * Gauss(r), y, z + delta * Gauss(r), w, new Vector3D(0, U(r, 0.2, 1), 0));
                    yield return new Case("identical-rotations", e1, e2);
                }
        }

        /// <summary>Every pair with the two shapes at scales 2^4 … 2^120 apart, the small one at or inside the large one's boundary.</summary>
        private static IEnumerable<Case> MixedScales(Random r, int count)
        {
            foreach (int k in new[] { 4, 20, 40, 60, 120 })
                for (int n = 0; n < count; n++)
                {
                    int dim = n % 2 == 0 ? 3 : 2;
                    string ka = Kinds[r.Next(Kinds.Length)], kb = Kinds[r.Next(Kinds.Length)];
                    var big = Shape(r, ka, dim, V(r, 1.5));
                    var near = PointNear(big, r);
                    yield return new Case("mixed-scales", big, Shape(r, kb, dim, near, Math.Pow(2, -k)));
                }
        }

        /// <summary>A point on or near a shape's boundary (a vertex, an end, a surface point), so a tiny shape there meets it.</summary>
        private static Vector3D PointNear(object shape, Random r) => shape switch
        {
            Vector3D p => p,
            Vector2D p => new Vector3D(p.X, p.Y, 0),
            Segment3 x => x.PointAt(r.NextDouble()),
            Segment2 x => new Vector3D(x.PointAt(r.NextDouble()).X, x.PointAt(r.NextDouble()).Y, 0),
            Sphere x => x.Center + new Vector3D(x.Radius, 0, 0),
            Circle x => new Vector3D(x.Center.X, x.Center.Y + x.Radius, 0),
            Aabb3 x => x.Max,
            Aabb2 x => new Vector3D(x.Max.X, x.Min.Y, 0),
            Obb3 x => x.Center + x.AxisX * x.HalfExtents.X + x.AxisY * x.HalfExtents.Y,
            Obb2 x => new Vector3D(x.Center.X, x.Center.Y, 0) + new Vector3D(x.AxisX.X, x.AxisX.Y, 0) * x.HalfExtents.X,
            _ => throw new ArgumentException(shape.GetType().Name),
        };

        /// <summary>OBBs from unnormalised quaternions and from slightly non-orthonormal float axes.</summary>
        private static IEnumerable<Case> ObbInputs(Random r, int count)
        {
            for (int n = 0; n < count; n++)
            {
                double scale = Math.Pow(10, U(r, -3, 3));
                var q = Obb3.FromQuaternion(V(r, 1), Gauss(r) * scale, Gauss(r) * scale, Gauss(r) * scale, Gauss(r) * scale, new Vector3D(U(r, 0.2, 1), U(r, 0.2, 1), U(r, 0.2, 1)));
                // Float-rounded axes with a perturbation well inside the tolerance.
                var m = Rotation(r);
                Vector3D F(Vector3D v) => new Vector3D((float)(v.X + U(r, -1e-6, 1e-6)), (float)(v.Y + U(r, -1e-6, 1e-6)), (float)(v.Z + U(r, -1e-6, 1e-6)));
                var f = new Obb3(V(r, 1), F(m[0]), F(m[1]), F(m[2]), new Vector3D(U(r, 0.2, 1), U(r, 0.2, 1), U(r, 0.2, 1)));
                yield return new Case("obb-inputs", q, f);
                yield return new Case("obb-inputs", V(r, 1.5), f);
                yield return new Case("obb-inputs", Shape(r, "segment", 3, V(r, 1.5)), q);
                yield return new Case("obb-inputs", Shape(r, "sphere", 3, V(r, 1.5)), f);
                yield return new Case("obb-inputs", Shape(r, "aabb", 3, V(r, 1.5)), q);
            }
        }
    }
}
