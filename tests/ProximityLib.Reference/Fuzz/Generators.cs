using System;
using System.Collections.Generic;
using System.Linq;
using ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>The ranges a generator draws from: the whole double range, or the float range for the float API.</summary>
    public sealed class Precision
    {
        public bool Float { get; }
        /// <summary>Configuration scales 2^[MinExp, MaxExp]: the whole range, up to where distances overflow.</summary>
        public int MinExp => Float ? -125 : -1020;
        public int MaxExp => Float ? 125 : 1021;
        /// <summary>Subnormal scales 2^[SubMin, SubMax].</summary>
        public int SubMin => Float ? -149 : -1074;
        public int SubMax => Float ? -126 : -1022;
        /// <summary>Common translations up to 2^TransMax·S (past the significand's width).</summary>
        public int TransMax => Float ? 40 : 90;
        /// <summary>Size ratios up to 2^MixMax between the two shapes.</summary>
        public int MixMax => Float ? 60 : 120;

        private Precision(bool isFloat) { Float = isFloat; }
        public static readonly Precision Double = new Precision(false), Single = new Precision(true);
    }

    /// <summary>
    /// The seeded generators. Each draws one configuration of a given (unordered) kind pair from an <see cref="Rng"/>
    /// seeded by (seed, index), so a case is reproducible from those two numbers alone. They build double values;
    /// float cases round every constructor argument to float at the end (the constructions that must stay exact —
    /// touching, collinear — use small integers on a power-of-two grid, which floats hold exactly).
    /// </summary>
    public static class Generators
    {
        public delegate (Spec A, Spec B) Make(Rng rng, Kind ka, Kind kb, int dim, Precision p);

        public static readonly (string Name, Make Make, Func<Kind, Kind, bool> Applies)[] All =
        {
            ("random", RandomPair, (_, _) => true),
            ("magnitudes", Magnitudes, (_, _) => true),
            ("mixed-scales", MixedScales, (_, _) => true),
            ("range-edges", RangeEdges, (_, _) => true),
            ("translated", Translated, (_, _) => true),
            ("degenerate", Degenerate, (_, _) => true),
            ("subnormal", Subnormal, (_, _) => true),
            ("touching", Touching, (_, _) => true),
            ("nearly-parallel", NearlyParallel, (a, b) => Edged(a) && Edged(b) && !(a == Kind.Aabb && b == Kind.Aabb)),
            ("collinear", Collinear, (a, b) => (a == Kind.Point && b == Kind.Segment) || (Edged(a) && Edged(b))),
            ("rotations", Rotations, (a, b) => b == Kind.Obb && (a == Kind.Aabb || a == Kind.Obb)),
            // Issue 12's hard cases (appended: the original pairs' generator lists are unchanged).
            ("grazing", Grazing, (a, b) => !Kinds.IsOriginal(a) || !Kinds.IsOriginal(b)),
            ("parallel", Parallel, (a, b) => !Kinds.IsOriginal(a) || !Kinds.IsOriginal(b)),
            ("slivers", Slivers, (a, b) => a == Kind.Triangle || b == Kind.Triangle),
            ("far-along", FarAlong, (a, b) => Kinds.IsLinear(a) || Kinds.IsLinear(b)),
            ("edge-parallel", EdgeParallel, (a, b) => (a == Kind.Triangle && Axial(b)) || (b == Kind.Triangle && Axial(a))),
            ("far-crossing", FarCrossing, (a, b) => Kinds.IsLinear(a) ? Kinds.IsLinear(b) || b == Kind.HalfSpace : Kinds.IsLinear(b) && a == Kind.HalfSpace),
        };

        private static bool Axial(Kind k) => k == Kind.Segment || k == Kind.Line || k == Kind.Ray || k == Kind.Capsule;

        private static bool Edged(Kind k) => k == Kind.Segment || k == Kind.Aabb || k == Kind.Obb;

        public static string[] Names => All.Select(g => g.Name).ToArray();

        /// <summary>The generators that apply to a pair (ka ≤ kb).</summary>
        public static int[] For(Kind ka, Kind kb) => Enumerable.Range(0, All.Length).Where(i => All[i].Applies(ka, kb)).ToArray();

        // ---- helpers ------------------------------------------------------------------------------------------------

        private static Vector3D U3(Rng r, double range, int dim) =>
            new Vector3D(r.Range(-range, range), r.Range(-range, range), dim == 3 ? r.Range(-range, range) : 0);

        private static Vector3D Dir(Rng r, int dim)
        {
            while (true)
            {
                var v = new Vector3D(r.Gauss(), r.Gauss(), dim == 3 ? r.Gauss() : 0);
                double len = v.Length;
                if (len > 1e-3) return v / len;
            }
        }

        /// <summary>A unit vector perpendicular to the unit vector d (in the plane for 2D).</summary>
        private static Vector3D Perp(Rng r, Vector3D d, int dim)
        {
            if (dim == 2) return new Vector3D(-d.Y, d.X, 0);
            while (true)
            {
                var c = Vector3D.Cross(d, Dir(r, 3));
                double len = c.Length;
                if (len > 1e-3) return c / len;
            }
        }

        /// <summary>d turned by angle θ toward the perpendicular p.</summary>
        private static Vector3D Turn(Vector3D d, Vector3D p, double theta) => d * Math.Cos(theta) + p * Math.Sin(theta);

        private static double[] RandomQuaternion(Rng r)
        {
            double s = r.Pow2(-3, 3);
            return new[] { r.Gauss() * s, r.Gauss() * s, r.Gauss() * s, r.Gauss() * s };
        }

        /// <summary>Quaternions whose axes are exact (signed permutations): components in {0, ±1}.</summary>
        private static readonly double[][] ExactQuaternions =
        {
            new double[] { 0, 0, 0, 1 }, new double[] { 1, 0, 0, 0 }, new double[] { 0, 1, 0, 0 }, new double[] { 0, 0, 1, 0 },
            new double[] { 0, 0, 1, 1 }, new double[] { 1, 0, 0, 1 }, new double[] { 0, 1, 0, 1 }, new double[] { 1, 1, 0, 0 },
            new double[] { 0, 1, -1, 0 }, new double[] { 1, 1, 1, 1 }, new double[] { 1, -1, 1, 1 }, new double[] { -1, 1, 1, 1 },
        };

        public static Vector3D[] AxesOf(double[] q)
        {
            var o = Obb3.FromQuaternion(default, q[0], q[1], q[2], q[3], default);
            return new[] { o.AxisX, o.AxisY, o.AxisZ };
        }

        /// <summary>q·dq (Hamilton product), for composing a small rotation onto a frame.</summary>
        private static double[] Mul(double[] a, double[] b) => new[]
        {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
        };

        /// <summary>A rotation by θ about the unit axis n, as a quaternion.</summary>
        private static double[] AxisAngle(Vector3D n, double theta)
        {
            double s = Math.Sin(theta / 2);
            return new[] { n.X * s, n.Y * s, n.Z * s, Math.Cos(theta / 2) };
        }

        /// <summary>An OBB with rotation q (3D: quaternion or axes form), or angle/axis (2D).</summary>
        private static Spec Obb(Rng r, int dim, Vector3D c, Vector3D h, double[] q, double angle)
        {
            if (dim == 2)
                return r.Chance(0.5) ? Spec.Obb2Angle(c, angle, h) : Spec.Obb2Axis(c, Math.Cos(angle), Math.Sin(angle), h);
            if (r.Chance(0.7)) return Spec.ObbQuaternion(c, q[0], q[1], q[2], q[3], h);
            var ax = AxesOf(q);
            return Spec.ObbAxes(c, ax[0], ax[1], ax[2], h);
        }

        private static Vector3D Extents(Rng r, int dim, double size, bool degenerate)
        {
            var h = new Vector3D(r.Range(0.1, 1), r.Range(0.1, 1), dim == 3 ? r.Range(0.1, 1) : 0) * size;
            if (!degenerate) return h;
            switch (r.Int(4))
            {
                case 0: return new Vector3D(0, h.Y, h.Z);
                case 1: return new Vector3D(h.X, 0, h.Z);
                case 2: return new Vector3D(h.X, h.Y, 0);
                default: return default;
            }
        }

        /// <summary>A random shape of the kind around c at the given size; one in eight has a zero size.</summary>
        public static Spec RandomShape(Rng r, Kind kind, int dim, Vector3D c, double size)
        {
            bool degenerate = r.Chance(0.125);
            switch (kind)
            {
                case Kind.Point: return Spec.Point(dim, c);
                case Kind.Segment:
                    var d = degenerate ? default : Dir(r, dim) * (size * r.Range(0.2, 2));
                    var a = c - d * r.Unit();
                    return Spec.Segment(dim, a, a + d);
                case Kind.Sphere: return Spec.Sphere(dim, c, degenerate ? 0 : size * r.Range(0.1, 1));
                case Kind.Aabb:
                    var h = Extents(r, dim, size, degenerate);
                    return Spec.Aabb(dim, c - h, c + h);
                case Kind.Line: case Kind.Ray: case Kind.Capsule: case Kind.Triangle: case Kind.HalfSpace:
                    return RandomNewShape(r, kind, dim, c, size, degenerate);
                default:
                    return Obb(r, dim, c, Extents(r, dim, size, degenerate), RandomQuaternion(r), r.Range(0, 2 * Math.PI));
            }
        }

        /// <summary>
        /// A random line (origin near c), ray (passing near c), capsule, triangle or half-space (boundary through c; one
        /// in three in the offset form) at the given size; degenerate ones are axis-aligned lines and rays, capsules with
        /// a zero axis or radius, collinear or coincident triangles. Normals and directions get random lengths (the
        /// constructors normalise them).
        /// </summary>
        private static Spec RandomNewShape(Rng r, Kind kind, int dim, Vector3D c, double size, bool degenerate)
        {
            var d = degenerate ? Axis(r, dim) * r.Sign() : Dir(r, dim);
            var length = d * r.Pow2(-8, 8);
            switch (kind)
            {
                case Kind.Line: return Spec.Line(dim, c + d * (size * r.Range(-2, 2)), length);
                case Kind.Ray: return Spec.Ray(dim, c - d * (size * r.Range(-0.5, 2)), length);
                case Kind.Capsule:
                {
                    var w = degenerate && r.Chance(0.5) ? default : Dir(r, dim) * (size * r.Range(0.2, 2));
                    var a = c - w * r.Unit();
                    return Spec.Capsule(dim, a, a + w, degenerate && w != default ? 0 : size * r.Range(0.05, 1));
                }
                case Kind.Triangle:
                {
                    var a = c + U3(r, 1, dim) * size;
                    var b = c + U3(r, 1, dim) * size;
                    if (!degenerate) return Spec.Triangle(dim, a, b, c + U3(r, 1, dim) * size);
                    return r.Int(3) switch
                    {
                        0 => Spec.Triangle(dim, a, b, a + (b - a) * r.Range(-1, 2)),
                        1 => Spec.Triangle(dim, a, a, b),
                        _ => Spec.Triangle(dim, a, a, a),
                    };
                }
                default:
                    // The offset form only where the offset is finite (a point near 1e307 times a normal of 20 is not).
                    double offset = Vector3D.Dot(c, length);
                    if (r.Chance(1.0 / 3) && double.IsFinite(offset)) return Spec.HalfSpaceOffset(dim, length, offset);
                    return Spec.HalfSpace(dim, c, length);
            }
        }

        private static Vector3D Axis(Rng r, int dim) => r.Int(dim) switch { 0 => Vector3D.UnitX, 1 => Vector3D.UnitY, _ => Vector3D.UnitZ };

        private static (Spec, Spec) Finish(Spec a, Spec b, Precision p) => p.Float ? (a.ToFloat(), b.ToFloat()) : (a, b);

        // ---- the generators -------------------------------------------------------------------------------------

        /// <summary>Plain random configurations at scales 2^±4, apart and overlapping.</summary>
        private static (Spec, Spec) RandomPair(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-4, 4);
            return Finish(RandomShape(r, ka, dim, U3(r, 1.5, dim) * s, s), RandomShape(r, kb, dim, U3(r, 1.5, dim) * s, s), p);
        }

        /// <summary>Random configurations at a log-uniform scale across the whole range (2^−1020…2^1021 double, 2^±125 float).</summary>
        private static (Spec, Spec) Magnitudes(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(p.MinExp, p.MaxExp);
            return Finish(RandomShape(r, ka, dim, U3(r, 1.5, dim) * s, s), RandomShape(r, kb, dim, U3(r, 1.5, dim) * s, s), p);
        }

        /// <summary>A point on (or near) a shape's boundary, from its double form.</summary>
        private static Vector3D SurfacePoint(Rng r, Spec s)
        {
            var c = Core.Of(s.Build());
            switch (c.Kind)
            {
                case Kind.Point: return c.P;
                case Kind.Segment: return c.P + (c.Q - c.P) * r.Unit();
                case Kind.Sphere: return c.P + Dir(r, c.Planar ? 2 : 3) * c.R;
                case Kind.Line: case Kind.Ray:
                {
                    double scale = Math.Max(Math.Abs(c.P.X), Math.Max(Math.Abs(c.P.Y), Math.Abs(c.P.Z)));
                    return c.P + c.Q * (r.Range(c.Kind == Kind.Ray ? 0 : -1, 1) * (scale > 0 ? scale : 1));
                }
                case Kind.Capsule: return c.P + (c.Q - c.P) * r.Range(-0.2, 1.2) + Dir(r, c.Planar ? 2 : 3) * c.R;
                case Kind.Triangle:
                {
                    double u = r.Unit(), v = r.Unit() * (1 - u);
                    if (c.Planar || r.Chance(0.3)) v = 1 - u;
                    return c.P + (c.Q - c.P) * u + (c.H - c.P) * v;
                }
                case Kind.HalfSpace:
                {
                    double scale = Math.Max(Math.Abs(c.P.X), Math.Max(Math.Abs(c.P.Y), Math.Abs(c.P.Z)));
                    return c.P + Perp(r, c.Q, c.Planar ? 2 : 3) * (r.Range(-1, 1) * (scale > 0 ? scale : 1));
                }
                case Kind.Aabb:
                {
                    var x = new[] { r.Range(c.P.X, c.Q.X), r.Range(c.P.Y, c.Q.Y), r.Range(c.P.Z, c.Q.Z) };
                    int i = r.Int(c.Planar ? 2 : 3);
                    x[i] = r.Chance(0.5) ? (i == 0 ? c.P.X : i == 1 ? c.P.Y : c.P.Z) : (i == 0 ? c.Q.X : i == 1 ? c.Q.Y : c.Q.Z);
                    return new Vector3D(x[0], x[1], x[2]);
                }
                default:
                {
                    int n = c.Planar ? 2 : 3, face = r.Int(n);
                    var h = new[] { c.H.X, c.H.Y, c.H.Z };
                    var x = c.P;
                    for (int i = 0; i < n; i++)
                        x += c.Axes[i] * (i == face ? r.Sign() * h[i] : r.Range(-h[i], h[i]) * (r.Chance(0.3) ? 1 : 0));
                    return x;
                }
            }
        }

        /// <summary>
        /// A 2^−k-sized shape next to a large one, at the large one's boundary: size ratios 2^4…2^120 (double) or
        /// 2^4…2^60 (float), the large shape at 2^±300 (double) or 2^±40 (float).
        /// </summary>
        private static (Spec, Spec) MixedScales(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double big = p.Float ? r.Pow2(-40, 40) : r.Pow2(-300, 300);
            double small = big * r.Pow2(-p.MixMax, -4);
            bool aBig = r.Chance(0.5);
            var host = RandomShape(r, aBig ? ka : kb, dim, U3(r, 1, dim) * big, big);
            var at = SurfacePoint(r, host) + Dir(r, dim) * (small * r.Range(-2, 2));
            var guest = RandomShape(r, aBig ? kb : ka, dim, at, small);
            return Finish(aBig ? host : guest, aBig ? guest : host, p);
        }

        /// <summary>
        /// Configurations whose size sits near the edges of the documented ranges — the double API's fast path (2^±400)
        /// and promise (2^±1000), the SIMD batch API's 2^±28 (float) — with a large and a small shape (ratio up to 2^24)
        /// at the large one's boundary, where squares of the small sizes leave the range first.
        /// </summary>
        private static (Spec, Spec) RangeEdges(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            // Double: the fast path's edge (values at 2^±400, src/ProximityLib/Double/Wide.cs) and the end of the promised
            // range (2^±1000); float: the batch's 2^±28.
            int edge = p.Float ? 28 : (r.Chance(0.5) ? 400 : 1000);
            double e = r.Chance(0.25) ? r.Range(-edge, edge) : r.Sign() * (edge - r.Range(-2, 8));
            double big = Math.Pow(2, e);
            double small = big * r.Pow2(-24, 0);
            bool aBig = r.Chance(0.5);
            var host = RandomShape(r, aBig ? ka : kb, dim, U3(r, 1, dim) * big, big);
            var at = SurfacePoint(r, host) + Dir(r, dim) * (small * r.Range(-1, 1));
            var guest = RandomShape(r, aBig ? kb : ka, dim, at, small);
            return Finish(aBig ? host : guest, aBig ? guest : host, p);
        }

        /// <summary>A unit-ish configuration under a common translation of 2^0…2^90 times its size (2^40 in float).</summary>
        private static (Spec, Spec) Translated(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            var a = RandomShape(r, ka, dim, U3(r, 1.5, dim) * s, s);
            var b = RandomShape(r, kb, dim, U3(r, 1.5, dim) * s, s);
            var t = Dir(r, dim) * (s * r.Pow2(0, p.TransMax));
            return Finish(a.Translated(t), b.Translated(t), p);
        }

        /// <summary>An integer vector (components in [−n, n]) times g.</summary>
        private static Vector3D Grid(Rng r, int n, double g, int dim) =>
            new Vector3D(r.Int(-n, n) * g, r.Int(-n, n) * g, dim == 3 ? r.Int(-n, n) * g : 0);

        private static Vector3D GridNonNeg(Rng r, int n, double g, int dim) =>
            new Vector3D(r.Int(0, n) * g, r.Int(0, n) * g, dim == 3 ? r.Int(0, n) * g : 0);

        /// <summary>A signed permutation frame (exact axes) as a spec: quaternion or axes form (3D), axis form (2D).</summary>
        private static Spec ExactObb(Rng r, int dim, Vector3D c, Vector3D h)
        {
            if (dim == 2)
            {
                var axis = r.Pick(new Vector3D(1, 0, 0), new Vector3D(0, 1, 0), new Vector3D(-1, 0, 0), new Vector3D(0, -1, 0));
                return Spec.Obb2Axis(c, axis.X, axis.Y, h);
            }
            var q = r.Pick(ExactQuaternions);
            if (r.Chance(0.5)) return Spec.ObbQuaternion(c, q[0], q[1], q[2], q[3], h);
            var ax = AxesOf(q);
            return Spec.ObbAxes(c, ax[0] * r.Sign(), ax[1] * r.Sign(), ax[2] * r.Sign(), h);
        }

        /// <summary>
        /// Zero-size and coincident shapes: zero-length segments, zero radius, zero extents, shapes sharing a point
        /// (as an end, center, corner or surface point), identical shapes.
        /// </summary>
        private static (Spec, Spec) Degenerate(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = Math.Pow(2, r.Int(-8, 8)), g = s / 8;
            var shared = Grid(r, 8, g, dim);
            Spec Make(Kind k)
            {
                var w = Grid(r, 6, g, dim);
                var ext = GridNonNeg(r, 6, g, dim);
                if (r.Chance(0.5)) ext = r.Int(3) switch { 0 => new Vector3D(0, ext.Y, ext.Z), 1 => new Vector3D(ext.X, 0, 0), _ => default };
                switch (k)
                {
                    case Kind.Point: return Spec.Point(dim, r.Chance(0.8) ? shared : shared + w);
                    case Kind.Segment:
                        return r.Int(4) switch
                        {
                            0 => Spec.Segment(dim, shared, shared),
                            1 => Spec.Segment(dim, shared, shared + w),
                            2 => Spec.Segment(dim, shared + w, shared),
                            _ => Spec.Segment(dim, shared - w, shared + w),
                        };
                    case Kind.Sphere:
                    {
                        double radius = r.Chance(0.4) ? 0 : r.Int(1, 6) * g;
                        if (r.Chance(0.5)) return Spec.Sphere(dim, shared, radius);
                        var axis = r.Pick(Vector3D.UnitX, Vector3D.UnitY, dim == 3 ? Vector3D.UnitZ : Vector3D.UnitX) * r.Sign();
                        return Spec.Sphere(dim, shared + axis * radius, radius);
                    }
                    case Kind.Line: case Kind.Ray:
                    {
                        var d = w != default ? w : Axis(r, dim) * g;
                        var o = r.Chance(0.6) ? shared : shared - d * r.Int(0, 3);
                        return k == Kind.Line ? Spec.Line(dim, o, d) : Spec.Ray(dim, o, d * r.Sign());
                    }
                    case Kind.Capsule:
                    {
                        double radius = r.Chance(0.4) ? 0 : r.Int(1, 6) * g;
                        return r.Int(4) switch
                        {
                            0 => Spec.Capsule(dim, shared, shared, radius),
                            1 => Spec.Capsule(dim, shared, shared + w, radius),
                            2 => Spec.Capsule(dim, shared + w, shared, radius),
                            _ => Spec.Capsule(dim, shared - w, shared + w, radius),
                        };
                    }
                    case Kind.Triangle:
                    {
                        var w2 = Grid(r, 6, g, dim);
                        return r.Int(5) switch
                        {
                            0 => Spec.Triangle(dim, shared, shared, shared),
                            1 => Spec.Triangle(dim, shared, shared, shared + w),
                            2 => Spec.Triangle(dim, shared - w, shared, shared + w * r.Int(-2, 3)),
                            3 => Spec.Triangle(dim, shared + w, shared + w2, shared),
                            _ => Spec.Triangle(dim, shared, shared + w, shared + w2),
                        };
                    }
                    case Kind.HalfSpace:
                    {
                        var nrm = w != default ? w : Axis(r, dim) * g;
                        double offset = Vector3D.Dot(shared, nrm);
                        return r.Chance(0.25) && double.IsFinite(offset) ? Spec.HalfSpaceOffset(dim, nrm, offset) : Spec.HalfSpace(dim, shared, nrm);
                    }
                    case Kind.Aabb:
                        return r.Int(3) switch
                        {
                            0 => Spec.Aabb(dim, shared, shared),
                            1 => Spec.Aabb(dim, shared, shared + new Vector3D(ext.X * r.Sign(), ext.Y * r.Sign(), ext.Z * r.Sign())),
                            _ => Spec.Aabb(dim, shared - ext, shared + ext),
                        };
                    default:
                        var h = ext * 0.5;
                        if (r.Chance(0.5)) return ExactObb(r, dim, shared, h);
                        var q = RandomQuaternion(r);
                        return Obb(r, dim, shared, h, q, r.Range(0, 2 * Math.PI));
                }
            }
            var a = Make(ka);
            var b = ka == kb && r.Chance(0.35) ? a : Make(kb);
            return Finish(a, b, p);
        }

        /// <summary>Configurations at subnormal scales, alone or beside a small normal-sized shape.</summary>
        private static (Spec, Spec) Subnormal(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(p.SubMin, p.SubMax + 4);
            var a = RandomShape(r, ka, dim, U3(r, 1.5, dim) * s, s);
            double sb = r.Chance(0.5) ? s : r.Pow2(p.SubMax, p.SubMax + 40);
            var b = RandomShape(r, kb, dim, U3(r, 1.5, dim) * sb, sb);
            // With equal kinds either one may be the subnormal one.
            return ka == kb && r.Chance(0.5) ? Finish(b, a, p) : Finish(a, b, p);
        }

        /// <summary>
        /// Exact touching: a host shape on a power-of-two grid gives a contact point p on its boundary and an outward
        /// normal n (an axis, so everything stays exact; one case in four uses a general rotation and is touching only
        /// to rounding); the guest is built in the half-space (x − p)·n ≥ 0 containing p, so the exact distance is 0.
        /// </summary>
        private static (Spec, Spec) Touching(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            if (!Kinds.IsOriginal(ka) || !Kinds.IsOriginal(kb)) return Contact(r, ka, kb, dim, p, exact: r.Chance(0.75), offset: false, parallel: false);
            double s = Math.Pow(2, p.Float ? r.Int(-10, 10) : r.Int(-30, 30)), g = s / 4;
            bool hostIsA = r.Chance(0.5);
            Kind hostKind = hostIsA ? ka : kb, guestKind = hostIsA ? kb : ka;
            bool general = r.Chance(0.25);
            int axisCount = dim == 3 ? 3 : 2;
            int ai = r.Int(axisCount);
            double sign = r.Sign();
            Vector3D UnitAxis(int i) => i == 0 ? Vector3D.UnitX : (i == 1 ? Vector3D.UnitY : Vector3D.UnitZ);
            var n = UnitAxis(ai) * sign;
            if (general && hostKind != Kind.Aabb) n = Dir(r, dim);
            Spec host;
            Vector3D contact;
            var c = Grid(r, 8, g, dim);
            switch (hostKind)
            {
                case Kind.Point: host = Spec.Point(dim, c); contact = c; break;
                case Kind.Segment:
                {
                    var w = Grid(r, 6, g, dim);
                    if (r.Chance(0.5) && !general)
                    {
                        // Interior contact: the segment lies in the plane x_ai = c_ai.
                        w = Set(w, ai, 0);
                        host = Spec.Segment(dim, c - w, c + w);
                        contact = c;
                    }
                    else
                    {
                        // End contact: the segment leaves c into (x − c)·n ≤ 0.
                        if (!general) w = Set(w, ai, -Math.Abs(Get(w, ai)) * sign);
                        else if (Vector3D.Dot(w, n) > 0) w = -w;
                        host = r.Chance(0.5) ? Spec.Segment(dim, c, c + w) : Spec.Segment(dim, c + w, c);
                        contact = c;
                    }
                    break;
                }
                case Kind.Sphere:
                {
                    double radius = r.Int(0, 6) * g;
                    host = Spec.Sphere(dim, c, radius);
                    contact = c + n * radius;
                    break;
                }
                default:
                {
                    var ext = GridNonNeg(r, 6, g, dim);
                    if (hostKind == Kind.Aabb || !general)
                    {
                        var min = c;
                        var max = c + ext;
                        host = hostKind == Kind.Aabb ? Spec.Aabb(dim, min, max) : ExactObb(r, dim, (min + max) * 0.5, ext * 0.5);
                        if (hostKind == Kind.Obb) (min, max) = WorldBounds(host);
                        // A point of the face x_ai = min or max (its edges and corners included).
                        var x = new double[3];
                        for (int j = 0; j < 3; j++)
                        {
                            double lo = Get(min, j), hi = Get(max, j);
                            x[j] = r.Int(3) switch { 0 => lo, 1 => hi, _ => (lo + hi) * 0.5 };
                        }
                        x[ai] = sign > 0 ? Get(max, ai) : Get(min, ai);
                        contact = new Vector3D(x[0], x[1], dim == 3 ? x[2] : 0);
                    }
                    else
                    {
                        var q = RandomQuaternion(r);
                        double angle = r.Range(0, 2 * Math.PI);
                        var h = ext * 0.5 + new Vector3D(g, g, dim == 3 ? g : 0);
                        host = Obb(r, dim, c, h, q, angle);
                        var core = Core.Of(host.Build());
                        int face = r.Int(axisCount);
                        double fs = r.Sign();
                        var hh = new[] { core.H.X, core.H.Y, core.H.Z };
                        contact = core.P;
                        for (int i = 0; i < axisCount; i++)
                            contact += core.Axes[i] * (i == face ? fs * hh[i] : r.Int(3) switch { 0 => hh[i], 1 => -hh[i], _ => r.Range(-hh[i], hh[i]) });
                        n = core.Axes[face] * fs;
                    }
                    break;
                }
            }
            bool axial = Math.Abs(n.X) + Math.Abs(n.Y) + Math.Abs(n.Z) == 1;
            Spec guest;
            switch (guestKind)
            {
                case Kind.Point: guest = Spec.Point(dim, contact); break;
                case Kind.Segment:
                {
                    var w = Grid(r, 6, g, dim);
                    if (axial) w = Set(w, AxisOf(n), Math.Abs(Get(w, AxisOf(n))) * Sign(n) * (r.Chance(0.3) ? 0 : 1));
                    else if (Vector3D.Dot(w, n) < 0) w = -w;
                    guest = r.Int(3) switch
                    {
                        0 => Spec.Segment(dim, contact, contact + w),
                        1 => Spec.Segment(dim, contact + w, contact),
                        _ => axial && Get(w, AxisOf(n)) == 0 ? Spec.Segment(dim, contact - w, contact + w) : Spec.Segment(dim, contact, contact + w),
                    };
                    break;
                }
                case Kind.Sphere:
                {
                    double radius = r.Int(0, 6) * g;
                    guest = Spec.Sphere(dim, contact + n * radius, radius);
                    break;
                }
                case Kind.Aabb:
                {
                    // The orthant of n at the contact (free along axes n is perpendicular to).
                    var lo = new double[3];
                    var hi = new double[3];
                    for (int j = 0; j < 3; j++)
                    {
                        double pj = Get(contact, j), nj = Get(n, j), e = r.Int(0, 6) * g;
                        if (j == 2 && dim == 2) { lo[j] = hi[j] = 0; continue; }
                        if (nj > 0) { lo[j] = pj; hi[j] = pj + e; }
                        else if (nj < 0) { lo[j] = pj - e; hi[j] = pj; }
                        else { lo[j] = pj - r.Int(0, 6) * g; hi[j] = pj + r.Int(0, 6) * g; }
                    }
                    guest = Spec.Aabb(dim, new Vector3D(lo[0], lo[1], lo[2]), new Vector3D(hi[0], hi[1], hi[2]));
                    break;
                }
                default:
                {
                    var ext = GridNonNeg(r, 6, g, dim);
                    if (axial)
                    {
                        // An exactly axis-aligned OBB (signed permutation) whose face lies on the contact plane.
                        var world = ext * 0.5;
                        int k = AxisOf(n);
                        var center = contact + n * Get(world, k);
                        for (int j = 0; j < (dim == 3 ? 3 : 2); j++)
                            if (j != k) center = Set(center, j, Get(center, j) + r.Int(-1, 1) * Get(world, j));
                        guest = ExactObbWithWorldHalf(r, dim, center, world);
                    }
                    else
                    {
                        var q = RandomQuaternion(r);
                        double angle = r.Range(0, 2 * Math.PI);
                        var h = ext * 0.5;
                        var probe = Core.Of(Obb(r, dim, default, h, q, angle).Build());
                        var center = contact;
                        var hh = new[] { h.X, h.Y, h.Z };
                        for (int i = 0; i < (dim == 3 ? 3 : 2); i++)
                            center += probe.Axes[i] * (hh[i] * (Vector3D.Dot(probe.Axes[i], n) >= 0 ? 1 : -1));
                        guest = dim == 3 ? Obb(r, 3, center, h, q, angle) : Spec.Obb2Axis(center, probe.Axes[0].X, probe.Axes[0].Y, h);
                    }
                    break;
                }
            }
            var (a, b) = hostIsA ? (host, guest) : (guest, host);
            return Finish(a, b, p);
        }

        private static double Get(Vector3D v, int i) => i == 0 ? v.X : (i == 1 ? v.Y : v.Z);
        private static Vector3D Set(Vector3D v, int i, double x) =>
            i == 0 ? new Vector3D(x, v.Y, v.Z) : (i == 1 ? new Vector3D(v.X, x, v.Z) : new Vector3D(v.X, v.Y, x));
        private static int AxisOf(Vector3D unitAxis) => unitAxis.X != 0 ? 0 : (unitAxis.Y != 0 ? 1 : 2);
        private static double Sign(Vector3D unitAxis) => unitAxis.X + unitAxis.Y + unitAxis.Z;

        /// <summary>The world bounds of an exact (signed-permutation) OBB spec, exactly.</summary>
        private static (Vector3D, Vector3D) WorldBounds(Spec obb)
        {
            var c = Core.Of(obb.Build());
            var w = new double[3];
            var h = new[] { c.H.X, c.H.Y, c.H.Z };
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                    w[j] += Math.Abs(Get(c.Axes[i], j)) * h[i];
            var half = new Vector3D(w[0], w[1], c.Planar ? 0 : w[2]);
            return (c.P - half, c.P + half);
        }

        /// <summary>An exact OBB whose world half-extents along x, y, z are the given ones.</summary>
        private static Spec ExactObbWithWorldHalf(Rng r, int dim, Vector3D center, Vector3D world)
        {
            var probe = ExactObb(r, dim, center, default);
            var c = Core.Of(probe.Build());
            var h = new double[3];
            for (int i = 0; i < (dim == 3 ? 3 : 2); i++) h[i] = Get(world, AxisOf(new Vector3D(Math.Abs(c.Axes[i].X), Math.Abs(c.Axes[i].Y), Math.Abs(c.Axes[i].Z))));
            var half = new Vector3D(h[0], h[1], h[2]);
            return probe.Form switch
            {
                ObbForm.Quaternion => Spec.ObbQuaternion(center, probe.Rot[0], probe.Rot[1], probe.Rot[2], probe.Rot[3], half),
                ObbForm.Axes => Spec.ObbAxes(center, new Vector3D(probe.Rot[0], probe.Rot[1], probe.Rot[2]), new Vector3D(probe.Rot[3], probe.Rot[4], probe.Rot[5]),
                    new Vector3D(probe.Rot[6], probe.Rot[7], probe.Rot[8]), half),
                _ => Spec.Obb2Axis(center, probe.Rot[0], probe.Rot[1], half),
            };
        }

        /// <summary>
        /// Nearly parallel segments and box edges: angles 10^−3…10^−15, offsets 0 or 10^0…10^−16 of the size either side,
        /// random shifts along both; box–box pairs differ by a small rotation and are stacked face to face or edge to edge.
        /// </summary>
        private static (Spec, Spec) NearlyParallel(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            double theta = r.Pow10Neg(3, 15) * r.Sign();
            double Offset() => r.Chance(0.25) ? 0 : s * r.Pow10Neg(0, 16) * r.Sign();
            if (ka == Kind.Segment && kb == Kind.Segment)
            {
                var d = Dir(r, dim);
                var d2 = Turn(d, Perp(r, d, dim), theta);
                double la = s * r.Range(0.5, 2), lb = s * r.Range(0.5, 2);
                var a0 = U3(r, 1, dim) * s;
                var b0 = a0 + d * (r.Range(-1, 1.2) * la) + Perp(r, d, dim) * Offset();
                var a = Spec.Segment(dim, a0, a0 + d * la);
                var b = r.Chance(0.5) ? Spec.Segment(dim, b0, b0 + d2 * lb) : Spec.Segment(dim, b0 + d2 * lb, b0);
                return Finish(r.Chance(0.5) ? a : b, r.Chance(0.5) ? b : a, p);
            }
            if (ka == Kind.Segment)
            {
                // A segment along an edge of the box, turned by θ, just inside or outside.
                var (box, q) = RandomBox(r, kb, dim, s, p);
                var core = Core.Of(box.Build());
                int n = dim == 3 ? 3 : 2, i = r.Int(n);
                var h = new[] { core.H.X, core.H.Y, core.H.Z };
                var axes = core.IsBox && core.Kind == Kind.Aabb ? new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ } : core.Axes;
                var center = core.Kind == Kind.Aabb ? (core.P + core.Q) * 0.5 : core.P;
                if (core.Kind == Kind.Aabb) h = new[] { (core.Q.X - core.P.X) / 2, (core.Q.Y - core.P.Y) / 2, (core.Q.Z - core.P.Z) / 2 };
                var edge = center;
                var outward = default(Vector3D);
                for (int j = 0; j < n; j++)
                {
                    if (j == i) continue;
                    double sj = r.Sign();
                    edge += axes[j] * (sj * h[j]);
                    outward += axes[j] * (sj * r.Unit());
                }
                if (outward.LengthSquared > 0) outward /= outward.Length;
                var d = Turn(axes[i], Perp(r, axes[i], dim), theta);
                var start = edge + axes[i] * (r.Range(-1.5, 1.5) * Math.Max(h[i], s)) + outward * Offset();
                var seg = Spec.Segment(dim, start, start + d * (r.Range(0.5, 3) * Math.Max(h[i], s)));
                return Finish(seg, box, p);
            }
            {
                // Two boxes whose frames differ by a small rotation, face to face or edge to edge.
                var (a, qa) = RandomBox(r, ka, dim, s, p);
                var ca = Core.Of(a.Build());
                var axis = Dir(r, 3);
                var qb = Mul(qa, AxisAngle(axis, theta));
                var hb = Flatten(r, new Vector3D(r.Range(0.2, 1), r.Range(0.2, 1), dim == 3 ? r.Range(0.2, 1) : 0) * s);
                var center = Stack(r, ca, hb, dim, s * r.Pow10Neg(0, 16) * r.Sign());
                double angle = (ca.Kind == Kind.Aabb ? 0 : Math.Atan2(ca.Axes[0].Y, ca.Axes[0].X)) + theta;
                var b = dim == 3 ? Obb(r, 3, center, hb, qb, 0) : Spec.Obb2Angle(center, angle, hb);
                if (p.Float && dim == 2) b = Spec.Obb2Angle(center, theta, hb);
                return Finish(a, b, p);
            }
        }

        /// <summary>A box of the kind at scale s; OBBs take a random or (float-friendly) exact rotation. Returns its quaternion.</summary>
        private static (Spec, double[]) RandomBox(Rng r, Kind kind, int dim, double s, Precision p)
        {
            var c = U3(r, 1, dim) * s;
            var h = new Vector3D(r.Range(0.2, 1), r.Range(0.2, 1), dim == 3 ? r.Range(0.2, 1) : 0) * s;
            if (kind == Kind.Aabb) return (Spec.Aabb(dim, c - h, c + h), new double[] { 0, 0, 0, 1 });
            bool exact = p.Float || r.Chance(0.3);
            var q = exact ? r.Pick(ExactQuaternions) : RandomQuaternion(r);
            if (dim == 2)
            {
                if (exact) return (Spec.Obb2Axis(c, 1, 0, h), new double[] { 0, 0, 0, 1 });
                double angle = r.Range(0, 2 * Math.PI);
                return (Spec.Obb2Angle(c, angle, h), AxisAngle(Vector3D.UnitZ, angle));
            }
            return (Spec.ObbQuaternion(c, q[0], q[1], q[2], q[3], h), q);
        }

        /// <summary>The center for a box of half-extents hb stacked on box a along one of a's axes with the given gap (negative: overlap), or edge to edge.</summary>
        private static Vector3D Stack(Rng r, Core a, Vector3D hb, int dim, double gap)
        {
            int n = dim == 3 ? 3 : 2;
            var axes = a.Kind == Kind.Aabb ? new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ } : a.Axes;
            var ha = a.Kind == Kind.Aabb ? (a.Q - a.P) * 0.5 : a.H;
            var center = a.Kind == Kind.Aabb ? (a.P + a.Q) * 0.5 : a.P;
            var haa = new[] { ha.X, ha.Y, ha.Z };
            var hbb = new[] { hb.X, hb.Y, hb.Z };
            int k = r.Int(n);
            double sk = r.Sign();
            var c = center + axes[k] * (sk * (haa[k] + hbb[k] + gap));
            bool edge = r.Chance(0.3);
            for (int j = 0; j < n; j++)
            {
                if (j == k) continue;
                c += axes[j] * (edge ? r.Sign() * (haa[j] + hbb[j]) : r.Range(-0.5, 0.5) * haa[j]);
            }
            return c;
        }

        /// <summary>
        /// Collinear and coplanar features on an exact grid: collinear segments overlapping, nested, touching end to end,
        /// disjoint or identical (either orientation); a point on a segment's line; segments along a box's edge line or in
        /// a face plane; boxes sharing an edge line. One in five is built with a general direction (collinear to rounding).
        /// </summary>
        private static (Spec, Spec) Collinear(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = Math.Pow(2, p.Float ? r.Int(-10, 10) : r.Int(-30, 30)), g = s / 8;
            var basePoint = Grid(r, 8, g, dim);
            Vector3D IntDir()
            {
                while (true)
                {
                    var d = Grid(r, 3, g, dim);
                    if (d.LengthSquared > 0) return d;
                }
            }
            bool rounded = r.Chance(kb == Kind.Segment ? 0.5 : 0.2);
            if (kb == Kind.Segment)
            {
                var d = rounded ? Dir(r, dim) * (g * r.Pow2(0, 4)) : IntDir();
                (double, double) Interval() { int t0 = r.Int(-8, 8), t1 = t0 + r.Int(0, 8); return (t0 * 0.25, t1 * 0.25); }
                var (a0, a1) = Interval();
                double b0, b1;
                switch (r.Int(5))
                {
                    case 0: b0 = a1; b1 = a1 + r.Int(0, 8) * 0.25; break; // end to end
                    case 1: b0 = a0 + r.Int(0, 4) * 0.25; b1 = b0 + r.Int(0, 8) * 0.25; break; // overlapping or nested
                    case 2: b0 = a0; b1 = a1; break; // identical
                    case 3: b0 = a1 + r.Int(1, 4) * 0.25; b1 = b0 + r.Int(0, 8) * 0.25; break; // disjoint
                    default: (b0, b1) = Interval(); break;
                }
                if (r.Chance(0.5)) (b0, b1) = (b1, b0);
                Vector3D At(double t) => basePoint + d * t;
                if (ka == Kind.Point) return Finish(Spec.Point(dim, At(r.Chance(0.5) ? b0 : r.Int(-12, 12) * 0.25)), Spec.Segment(dim, At(a0), At(a1)), p);
                // Coplanar instead of collinear: B moved off A's line (or turned across it) within a plane.
                var off = default(Vector3D);
                var turn = d;
                if (r.Chance(0.3))
                {
                    var e = IntDir();
                    if (r.Chance(0.5)) off = e * r.Int(-2, 2); else turn = e;
                }
                var a = Spec.Segment(dim, At(a0), At(a1));
                var b = turn.Equals(d) ? Spec.Segment(dim, At(b0) + off, At(b1) + off) : Spec.Segment(dim, At(b0), At(b0) + turn * (b1 - b0));
                return Finish(r.Chance(0.5) ? a : b, r.Chance(0.5) ? b : a, p);
            }
            // A box (exact: AABB or signed-permutation OBB; or an OBB with a general rotation when rounded) and a segment
            // or box along its edge lines / face planes.
            rounded &= kb == Kind.Obb;
            Spec boxB;
            Vector3D min, max;
            var ext = GridNonNeg(r, 8, g, dim) + new Vector3D(g, g, dim == 3 ? g : 0);
            if (kb == Kind.Aabb)
            {
                boxB = Spec.Aabb(dim, basePoint, basePoint + ext);
                (min, max) = (basePoint, basePoint + ext);
            }
            else if (!rounded)
            {
                boxB = ExactObb(r, dim, basePoint + ext * 0.5, ext * 0.5);
                (min, max) = WorldBounds(boxB);
            }
            else
            {
                boxB = Obb(r, dim, basePoint, ext * 0.5, RandomQuaternion(r), r.Range(0, 2 * Math.PI));
                (min, max) = (default, default);
            }
            var coreB = Core.Of(boxB.Build());
            int n = dim == 3 ? 3 : 2;
            // A line along axis i through a corner/edge of the face pattern: coordinates j ≠ i at min, max or one step outside.
            int i = r.Int(n);
            Vector3D LinePoint(double ti)
            {
                if (rounded)
                {
                    var hh = new[] { coreB.H.X, coreB.H.Y, coreB.H.Z };
                    var x = coreB.P + coreB.Axes[i] * ti;
                    for (int j = 0; j < n; j++) if (j != i) x += coreB.Axes[j] * hh[j] * (j % 2 == 0 ? 1 : -1);
                    return x;
                }
                var v = new double[3];
                for (int j = 0; j < 3; j++)
                {
                    if (j == 2 && dim == 2) continue;
                    double lo = Get(min, j), hi = Get(max, j);
                    v[j] = j == i ? ti : r.Int(4) switch { 0 => lo, 1 => hi, 2 => hi + g, _ => (lo + hi) * 0.5 };
                }
                return new Vector3D(v[0], v[1], v[2]);
            }
            double span = rounded ? coreB.H.X + coreB.H.Y + coreB.H.Z : Get(max, i) - Get(min, i);
            double lo0 = rounded ? -span : Get(min, i);
            double t0 = lo0 + r.Int(-4, 8) * g, t1 = t0 + r.Int(0, 12) * g;
            if (ka == Kind.Segment)
            {
                var pa = LinePoint(t0);
                var pb = rounded ? LinePoint(t1) : Set(pa, i, t1);
                return Finish(Spec.Segment(dim, pa, pb), boxB, p);
            }
            // Box A shares an edge line (or face plane) with box B: take the line point as its corner.
            var corner = LinePoint(t0);
            var extA = GridNonNeg(r, 8, g, dim);
            var signs = new Vector3D(r.Sign(), r.Sign(), r.Sign());
            var other = corner + new Vector3D(extA.X * signs.X, extA.Y * signs.Y, extA.Z * signs.Z);
            Spec boxA = ka == Kind.Aabb ? Spec.Aabb(dim, corner, other)
                : rounded ? Obb(r, dim, (corner + other) * 0.5, extA * 0.5, RandomQuaternion(r), 0)
                : ExactObbWithWorldHalf(r, dim, (corner + other) * 0.5, new Vector3D(extA.X, extA.Y, extA.Z) * 0.5);
            return Finish(boxA, boxB, p);
        }

        /// <summary>One box in two is flat: half of those are edges (one non-zero extent), the rest lose each extent with probability 1/2.</summary>
        private static Vector3D Flatten(Rng r, Vector3D h)
        {
            if (r.Chance(0.5)) return h;
            if (r.Chance(0.5))
            {
                int keep = r.Int(3);
                return new Vector3D(keep == 0 ? h.X : 0, keep == 1 ? h.Y : 0, keep == 2 ? h.Z : 0);
            }
            return new Vector3D(r.Chance(0.5) ? 0 : h.X, r.Chance(0.5) ? 0 : h.Y, r.Chance(0.5) ? 0 : h.Z);
        }

        /// <summary>
        /// Two boxes whose rotations differ by 10^−6…10^−16 (quaternion components perturbed), stacked with 10–50%
        /// penetration, near-touching, nested or nearly identical; some flat (zero extents).
        /// </summary>
        private static (Spec, Spec) Rotations(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10), delta = r.Pow10Neg(6, 16);
            var ha = Flatten(r, new Vector3D(r.Range(0.3, 1), r.Range(0.3, 1), dim == 3 ? r.Range(0.3, 1) : 0) * s);
            var hb = r.Chance(0.5) ? ha : Flatten(r, new Vector3D(r.Range(0.3, 1), r.Range(0.3, 1), dim == 3 ? r.Range(0.3, 1) : 0) * s);
            var ca = U3(r, 1, dim) * s;
            double[] qa, qb;
            if (ka == Kind.Aabb) qa = new double[] { 0, 0, 0, 1 };
            else qa = p.Float || r.Chance(0.3) ? r.Pick(ExactQuaternions) : RandomQuaternion(r);
            // Perturb every component (double) or only the zero ones (so a float quaternion keeps the perturbation).
            qb = (double[])qa.Clone();
            for (int k = 0; k < 4; k++)
                if (!p.Float || qa[k] == 0) qb[k] += delta * r.Gauss() * (p.Float ? 1 : Math.Max(Math.Abs(qa[k]), 1));
            double angleA = ka == Kind.Aabb || p.Float ? 0 : r.Range(0, 2 * Math.PI), angleB = angleA + delta * r.Sign();
            var a = ka == Kind.Aabb ? Spec.Aabb(dim, ca - ha, ca + ha)
                : dim == 3 ? Spec.ObbQuaternion(ca, qa[0], qa[1], qa[2], qa[3], ha) : Spec.Obb2Angle(ca, angleA, ha);
            var coreA = Core.Of(a.Build());
            Vector3D cb;
            switch (r.Int(4))
            {
                case 0: // stacked with 10–50% penetration
                {
                    double pen = r.Range(0.1, 0.5) * 2 * Math.Min(Math.Min(ha.X, hb.X), Math.Min(ha.Y, hb.Y));
                    cb = Stack(r, coreA, hb, dim, -pen);
                    break;
                }
                case 1: cb = Stack(r, coreA, hb, dim, s * r.Pow10Neg(0, 16) * r.Sign()); break; // near-touching
                case 2: cb = ca; break; // nested / concentric
                default: cb = ca + U3(r, 1, dim) * (s * r.Pow10Neg(0, 12)); break; // nearly identical
            }
            var b = dim == 3 ? (r.Chance(0.7) ? Spec.ObbQuaternion(cb, qb[0], qb[1], qb[2], qb[3], hb) : Spec.ObbAxes(cb, AxesOf(qb)[0], AxesOf(qb)[1], AxesOf(qb)[2], hb))
                : Spec.Obb2Angle(cb, p.Float ? delta * r.Sign() : angleB, hb);
            if (ka == kb && r.Chance(0.5)) (a, b) = (b, a);
            return Finish(a, b, p);
        }
        // ---- issue 12: contacts between any two kinds ------------------------------------------------------------------

        /// <summary>
        /// A host of the kind with a contact point on its boundary and an outward normal n (the host lies in
        /// (x − contact)·n ≤ 0): exact (grid coordinates, n an axis, box axes signed permutations) or general (random
        /// rotation, touching to rounding). Boxes touch at a face, an edge or a vertex (a general n at an edge or vertex is
        /// a supporting plane through it); capsules on their side or a cap; triangles at a vertex, or (3D) lying in the
        /// plane around the contact.
        /// </summary>
        private static (Spec Host, Vector3D Contact, Vector3D N) HostContact(Rng r, Kind kind, int dim, double s, double g, bool exact)
        {
            var n = exact ? Axis(r, dim) * r.Sign() : Dir(r, dim);
            var c = exact ? Grid(r, 8, g, dim) : U3(r, 1, dim) * s;
            Vector3D W() => exact ? Grid(r, 6, g, dim) : U3(r, 1.5, dim) * s;
            Vector3D Inward() => -Side(W(), n, exact);
            Vector3D Along() => NonZero(r, Flat(W(), n, exact), n, dim, exact, g);
            double Radius() => exact ? r.Int(0, 6) * g : s * r.Range(0.05, 1);
            switch (kind)
            {
                case Kind.Point: return (Spec.Point(dim, c), c, n);
                case Kind.Segment:
                    if (r.Chance(0.5)) { var f = Flat(W(), n, exact); return (Spec.Segment(dim, c - f, c + f), c, n); }
                    return (r.Chance(0.5) ? Spec.Segment(dim, c, c + Inward()) : Spec.Segment(dim, c + Inward(), c), c, n);
                case Kind.Line:
                {
                    var d = Along();
                    return (Spec.Line(dim, c - d * r.Int(-3, 3), d * r.Sign()), c, n);
                }
                case Kind.Ray:
                {
                    var d = r.Chance(0.5) ? Along() : NonZero(r, Inward(), n, dim, exact, g);
                    return (Spec.Ray(dim, c, d), c, n);
                }
                case Kind.Sphere:
                {
                    double radius = Radius();
                    return (Spec.Sphere(dim, c, radius), c + n * radius, n);
                }
                case Kind.Capsule:
                {
                    double radius = Radius();
                    var w = r.Chance(0.5) ? Flat(W(), n, exact) : Inward();
                    return (r.Chance(0.5) ? Spec.Capsule(dim, c, c + w, radius) : Spec.Capsule(dim, c + w, c, radius), c + n * radius, n);
                }
                case Kind.Triangle:
                {
                    if (dim == 3 && r.Chance(0.4))
                    {
                        // Lying in the plane through c: c is its centroid.
                        Vector3D f1 = Flat(W(), n, exact), f2 = Flat(W(), n, exact);
                        return (Spec.Triangle(dim, c + f1, c + f2, c - f1 - f2), c, n);
                    }
                    return (Spec.Triangle(dim, c, c + Inward(), c + Inward()), c, n);
                }
                case Kind.HalfSpace:
                {
                    var normal = n * (exact ? Math.Pow(2, r.Int(-4, 4)) : r.Pow2(-4, 4));
                    return (Spec.HalfSpace(dim, c + Flat(W(), n, exact), normal), c, n);
                }
                default:
                {
                    // A box at center c: per axis the contact coordinate is at +h, −h or inside; n combines the outward
                    // normals of the faces it is on (exact: one face).
                    var h = exact ? GridNonNeg(r, 6, g, dim) + new Vector3D(g, g, dim == 3 ? g : 0) : new Vector3D(r.Range(0.1, 1), r.Range(0.1, 1), dim == 3 ? r.Range(0.1, 1) : 0) * s;
                    var box = kind == Kind.Aabb ? Spec.Aabb(dim, c - h, c + h)
                        : exact ? ExactObb(r, dim, c, h) : Obb(r, dim, c, h, RandomQuaternion(r), r.Range(0, 2 * Math.PI));
                    var core = Core.Of(box.Build());
                    var axes = kind == Kind.Aabb ? new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ } : core.Axes;
                    var hh = kind == Kind.Aabb ? new[] { h.X, h.Y, h.Z } : new[] { core.H.X, core.H.Y, core.H.Z };
                    var center = kind == Kind.Aabb ? (core.P + core.Q) * 0.5 : core.P;
                    int k = r.Int(dim);
                    var contact = center;
                    var normal = default(Vector3D);
                    for (int i = 0; i < dim; i++)
                    {
                        int role = i == k ? 1 + r.Int(2) : r.Int(3); // 0 inside, 1 at +h, 2 at −h
                        double sign = role == 2 ? -1 : 1;
                        double coord = role == 0 ? (exact ? r.Int(-1, 1) * 0.5 * hh[i] : r.Range(-1, 1) * hh[i]) : sign * hh[i];
                        contact += axes[i] * coord;
                        if (role != 0 && (i == k || !exact)) normal += axes[i] * (sign * (i == k ? 1 : r.Unit()));
                    }
                    return (box, contact, normal / normal.Length);
                }
            }
        }

        /// <summary>w turned onto the side w·n ≥ 0 (exact: the axis component made non-negative; else reflected).</summary>
        private static Vector3D Side(Vector3D w, Vector3D n, bool exact)
        {
            if (exact) { int k = AxisOf(n); return Set(w, k, Math.Abs(Get(w, k)) * Sign(n)); }
            double dot = Vector3D.Dot(w, n);
            return dot >= 0 ? w : w - n * (2 * dot);
        }

        /// <summary>w made perpendicular to n (exact: the axis component zeroed).</summary>
        private static Vector3D Flat(Vector3D w, Vector3D n, bool exact) =>
            exact ? Set(w, AxisOf(n), 0) : w - n * Vector3D.Dot(w, n);

        /// <summary>w, or a tangent of n of the grid's size when w is zero (a direction must not be).</summary>
        private static Vector3D NonZero(Rng r, Vector3D w, Vector3D n, int dim, bool exact, double g)
        {
            if (w.LengthSquared > 0) return w;
            if (exact) { int k = (AxisOf(n) + 1 + r.Int(dim - 1)) % dim; return Set(default, k, g * r.Sign()); }
            return Perp(r, n, dim) * g;
        }

        /// <summary>
        /// A guest of the kind in (x − at)·n ≥ 0 touching at (n unit; exact when at is on the grid and n an axis). With
        /// <paramref name="parallel"/> lines, rays, segments, capsule axes and triangles run parallel to the plane.
        /// </summary>
        private static Spec GuestAt(Rng r, Kind kind, int dim, Vector3D at, Vector3D n, double s, double g, bool exact, bool parallel)
        {
            Vector3D W() => exact ? Grid(r, 6, g, dim) : U3(r, 1.5, dim) * s;
            Vector3D Out() => parallel ? Flat(W(), n, exact) : Side(W(), n, exact);
            Vector3D Along() => NonZero(r, Flat(W(), n, exact), n, dim, exact, g);
            double Radius() => exact ? r.Int(0, 6) * g : s * r.Range(0.05, 1);
            switch (kind)
            {
                case Kind.Point: return Spec.Point(dim, at);
                case Kind.Segment:
                {
                    var w = Out();
                    return r.Int(3) switch { 0 => Spec.Segment(dim, at, at + w), 1 => Spec.Segment(dim, at + w, at), _ => Spec.Segment(dim, at - Flat(w, n, exact), at + w) };
                }
                case Kind.Line:
                {
                    var d = Along();
                    return Spec.Line(dim, at + d * r.Int(-3, 3), d * r.Sign());
                }
                case Kind.Ray:
                {
                    if (parallel || r.Chance(0.3)) { var d = Along(); return Spec.Ray(dim, at - d * r.Int(0, 3), d); }
                    return Spec.Ray(dim, at, NonZero(r, Side(W(), n, exact), n, dim, exact, g));
                }
                case Kind.Sphere: { double radius = Radius(); return Spec.Sphere(dim, at + n * radius, radius); }
                case Kind.Capsule:
                {
                    double radius = Radius();
                    var start = at + n * radius;
                    return r.Chance(0.5) ? Spec.Capsule(dim, start, start + Out(), radius) : Spec.Capsule(dim, start - Flat(W(), n, exact), start + Out(), radius);
                }
                case Kind.Triangle:
                {
                    if (dim == 3 && (parallel || r.Chance(0.3)))
                    {
                        Vector3D f1 = Flat(W(), n, exact), f2 = Flat(W(), n, exact);
                        return r.Chance(0.5) ? Spec.Triangle(dim, at + f1, at + f2, at - f1 - f2) : Spec.Triangle(dim, at, at + f1, at + f2);
                    }
                    return Spec.Triangle(dim, at, at + Out(), at + Out());
                }
                case Kind.HalfSpace:
                    return Spec.HalfSpace(dim, at + Flat(W(), n, exact), -n * (exact ? Math.Pow(2, r.Int(-4, 4)) : r.Pow2(-4, 4)));
                case Kind.Aabb:
                {
                    var lo = new double[3];
                    var hi = new double[3];
                    for (int j = 0; j < dim; j++)
                    {
                        double pj = Get(at, j), nj = Get(n, j), e = exact ? r.Int(0, 6) * g : r.Range(0, 1.5) * s;
                        if (nj > 0) { lo[j] = pj; hi[j] = pj + e; }
                        else if (nj < 0) { lo[j] = pj - e; hi[j] = pj; }
                        else { lo[j] = pj - (exact ? r.Int(0, 6) * g : e); hi[j] = pj + (exact ? r.Int(0, 6) * g : e); }
                    }
                    return Spec.Aabb(dim, new Vector3D(lo[0], lo[1], lo[2]), new Vector3D(hi[0], hi[1], hi[2]));
                }
                default:
                {
                    var ext = exact ? GridNonNeg(r, 6, g, dim) : new Vector3D(r.Range(0, 1), r.Range(0, 1), dim == 3 ? r.Range(0, 1) : 0) * s;
                    if (exact)
                    {
                        var world = ext * 0.5;
                        int k = AxisOf(n);
                        var center = at + n * Get(world, k);
                        for (int j = 0; j < dim; j++)
                            if (j != k) center = Set(center, j, Get(center, j) + r.Int(-1, 1) * Get(world, j));
                        return ExactObbWithWorldHalf(r, dim, center, world);
                    }
                    var q = RandomQuaternion(r);
                    double angle = r.Range(0, 2 * Math.PI);
                    var h = ext * 0.5;
                    var probe = Core.Of(Obb(r, dim, default, h, q, angle).Build());
                    var c = at;
                    var hh = new[] { h.X, h.Y, h.Z };
                    for (int i = 0; i < dim; i++) c += probe.Axes[i] * (hh[i] * (Vector3D.Dot(probe.Axes[i], n) >= 0 ? 1 : -1));
                    return dim == 3 ? Obb(r, 3, c, h, q, angle) : Spec.Obb2Axis(c, probe.Axes[0].X, probe.Axes[0].Y, h);
                }
            }
        }

        /// <summary>
        /// Two shapes in contact (host and guest, either one first), exact or general, optionally moved apart or into
        /// each other along the normal by 10^0…10^−16 of the size (or 0).
        /// </summary>
        private static (Spec, Spec) Contact(Rng r, Kind ka, Kind kb, int dim, Precision p, bool exact, bool offset, bool parallel)
        {
            double s = exact ? Math.Pow(2, p.Float ? r.Int(-10, 10) : r.Int(-30, 30)) : r.Pow2(-10, 10), g = s / 4;
            bool hostIsA = r.Chance(0.5);
            var (host, contact, n) = HostContact(r, hostIsA ? ka : kb, dim, s, g, exact);
            if (offset && !r.Chance(0.25)) contact += n * (s * r.Pow10Neg(0, 16) * r.Sign());
            var guest = GuestAt(r, hostIsA ? kb : ka, dim, contact, n, s, g, exact, parallel);
            return Finish(hostIsA ? host : guest, hostIsA ? guest : host, p);
        }

        /// <summary>
        /// Exact tiny gaps (the gap index space, <see cref="FuzzCase.GapBase"/>): an exact contact (grid host, axis normal)
        /// moved to the origin, the guest built at ±2^-57…2^-120 of the grid along the normal (one case in ten: 0), so its
        /// contact coordinate holds the offset exactly (0 + offset). The gap is 2^57 or more below the size: the checker's
        /// aimed 2^k scaling takes it where its square underflows while every shape stays in range, where a kernel that
        /// takes a zero squared gap for touching answers 0 (and a capsule overlap).
        /// </summary>
        public static (Spec, Spec) TinyGap(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = Math.Pow(2, r.Int(-30, 30)), g = s / 4;
            bool hostIsA = r.Chance(0.5);
            var (host, contact, n) = HostContact(r, hostIsA ? ka : kb, dim, s, g, exact: true);
            host = host.Translated(-contact);
            var at = n * (r.Chance(0.1) ? 0 : r.Sign() * Math.ScaleB(g, -r.Int(57, 120)));
            var guest = GuestAt(r, hostIsA ? kb : ka, dim, at, n, s, g, exact: true, parallel: r.Chance(0.6));
            return Finish(hostIsA ? host : guest, hostIsA ? guest : host, p);
        }

        /// <summary>
        /// Nearly touching cores (the near index space, <see cref="FuzzCase.NearBase"/>): a host in contact at a general
        /// rotation, the guest's core (a sphere's centre, a capsule's axis; any other kind itself) placed 2^-20…2^-52 of
        /// the size off the contact along the normal, either side (one in ten: on it); a rounded host is met at its core.
        /// Rounded shapes then overlap by about their radii (0.05…1 of the size) while their cores nearly touch: the
        /// push-out must follow the features' normal, where the rounded residual's direction is off by u·S/gap (radius·
        /// (u·S/gap)²/2 of overlap left), and the other kinds' witnesses and distances sit at rounding-sized gaps.
        /// </summary>
        public static (Spec, Spec) NearCore(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10), g = s / 4;
            bool hostIsA = r.Chance(0.5);
            var (host, contact, n) = HostContact(r, hostIsA ? ka : kb, dim, s, g, exact: false);
            if (host.Kind == Kind.Sphere || host.Kind == Kind.Capsule) contact -= n * host.R;
            double gap = r.Chance(0.1) ? 0 : r.Sign() * s * Math.ScaleB(1, -r.Int(20, 52));
            var at = contact + n * gap;
            var kind = hostIsA ? kb : ka;
            bool parallel = r.Chance(0.5);
            Spec guest;
            if (kind == Kind.Sphere) guest = Spec.Sphere(dim, at, s * r.Range(0.05, 1));
            else if (kind == Kind.Capsule)
            {
                var axis = GuestAt(r, Kind.Segment, dim, at, n, s, g, exact: false, parallel);
                guest = Spec.Capsule(dim, axis.P, axis.Q, s * r.Range(0.05, 1));
            }
            else guest = GuestAt(r, kind, dim, at, n, s, g, exact: false, parallel);
            return Finish(hostIsA ? host : guest, hostIsA ? guest : host, p);
        }

        /// <summary>Kinds with an edge or axis that <see cref="ShallowCross"/> can cross: linear kinds, capsules, triangles, boxes.</summary>
        public static bool HasEdge(Kind k) => Axial(k) || k == Kind.Triangle || k == Kind.Aabb || k == Kind.Obb;

        /// <summary>The pairs of the shallow index space: both kinds with edges, not two boxes (a box is only ever the host).</summary>
        public static bool Crosses(Kind a, Kind b) => HasEdge(a) && HasEdge(b) && !(IsBox(a) && IsBox(b));

        private static bool IsBox(Kind k) => k == Kind.Aabb || k == Kind.Obb;

        /// <summary>
        /// Edges crossing at a shallow angle (the shallow index space, <see cref="FuzzCase.ShallowBase"/>): an edge of the
        /// host (a segment, a stretch of a line or ray, a capsule's axis, a triangle's edge, a box's edge) and the guest's
        /// segment, line, ray, capsule axis or triangle edge through a point inside it at 10^-0.5…10^-3 rad (3D: apart
        /// along their common normal by 0 or ±10^0…10^-16 of the size, half the time plus the capsules' radii). Between
        /// the nearly parallel generator's 10^-3…10^-15 and random angles: the lines' stationary parameters carry u/sin²θ
        /// and a normal from a plain cross product u/sin θ of turn, so a gap taken along it was off by u·|w|/sin θ (a 3D
        /// segment–line case at sin θ = 0.015 had E = 40).
        /// </summary>
        public static (Spec, Spec) ShallowCross(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            bool hostIsA = IsBox(ka) || (!IsBox(kb) && r.Chance(0.5));
            var (host, e0, e1) = HostEdge(r, hostIsA ? ka : kb, dim, s, p);
            var kind = hostIsA ? kb : ka;
            var d = (e1 - e0) / (e1 - e0).Length;
            var x = e0 + (e1 - e0) * r.Range(0.05, 0.95);
            var d2 = Turn(d, Perp(r, d, dim), r.Pow10Neg(0.5, 3)) * r.Sign();
            double radius = kind == Kind.Capsule ? s * r.Range(0.05, 0.5) : 0;
            var at = x;
            if (dim == 3)
            {
                var n = Vector3D.Cross(d, d2);
                n /= n.Length;
                double gap = r.Chance(0.3) ? 0 : s * r.Pow10Neg(0, 16) * r.Sign();
                double radii = host.Kind == Kind.Capsule ? host.R + radius : radius;
                if (radii > 0 && r.Chance(0.5)) gap += radii * (gap < 0 ? -1 : 1);
                at += n * gap;
            }
            double length = s * r.Range(0.5, 2), u = r.Range(0.05, 0.95);
            var g0 = at - d2 * (u * length);
            var g1 = at + d2 * ((1 - u) * length);
            Spec guest = kind switch
            {
                Kind.Segment => r.Chance(0.5) ? Spec.Segment(dim, g0, g1) : Spec.Segment(dim, g1, g0),
                Kind.Line => Spec.Line(dim, g0, d2 * r.Pow2(-2, 2)),
                Kind.Ray => r.Chance(0.5) ? Spec.Ray(dim, g0, d2) : Spec.Ray(dim, g1, -d2),
                Kind.Capsule => Spec.Capsule(dim, g0, g1, radius),
                _ => r.Int(3) switch // a triangle with this edge
                {
                    0 => Spec.Triangle(dim, g0, g1, at + Dir(r, dim) * (s * r.Range(0.3, 1))),
                    1 => Spec.Triangle(dim, at + Dir(r, dim) * (s * r.Range(0.3, 1)), g0, g1),
                    _ => Spec.Triangle(dim, g1, at + Dir(r, dim) * (s * r.Range(0.3, 1)), g0),
                },
            };
            return Finish(hostIsA ? host : guest, hostIsA ? guest : host, p);
        }

        /// <summary>A random host of a kind with edges near the origin at size s, and one of its edges (or a stretch of its line).</summary>
        private static (Spec Host, Vector3D E0, Vector3D E1) HostEdge(Rng r, Kind kind, int dim, double s, Precision p)
        {
            var c = U3(r, 1, dim) * s;
            Vector3D Span() => Dir(r, dim) * (s * r.Range(0.5, 2));
            switch (kind)
            {
                case Kind.Segment: { var w = Span(); return (Spec.Segment(dim, c, c + w), c, c + w); }
                case Kind.Capsule: { var w = Span(); return (Spec.Capsule(dim, c, c + w, s * r.Range(0.05, 0.5)), c, c + w); }
                case Kind.Line: { var d = Dir(r, dim); return (Spec.Line(dim, c, d * r.Pow2(-2, 2)), c - d * s, c + d * s); }
                case Kind.Ray: { var d = Dir(r, dim); return (Spec.Ray(dim, c, d * r.Pow2(-2, 2)), c, c + d * (2 * s)); }
                case Kind.Triangle:
                {
                    Vector3D a = c, b = c + Span(), t = c + Span();
                    return r.Int(3) switch
                    {
                        0 => (Spec.Triangle(dim, a, b, t), a, b),
                        1 => (Spec.Triangle(dim, a, b, t), b, t),
                        _ => (Spec.Triangle(dim, a, b, t), t, a),
                    };
                }
                default:
                {
                    var (box, _) = RandomBox(r, kind, dim, s, p);
                    var core = Core.Of(box.Build());
                    var axes = kind == Kind.Aabb ? new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ } : core.Axes;
                    var center = kind == Kind.Aabb ? (core.P + core.Q) * 0.5 : core.P;
                    var h = kind == Kind.Aabb
                        ? new[] { (core.Q.X - core.P.X) / 2, (core.Q.Y - core.P.Y) / 2, (core.Q.Z - core.P.Z) / 2 }
                        : new[] { core.H.X, core.H.Y, core.H.Z };
                    int i = r.Int(dim);
                    var mid = center;
                    for (int j = 0; j < dim; j++) if (j != i) mid += axes[j] * (r.Sign() * h[j]);
                    return (box, mid - axes[i] * h[i], mid + axes[i] * h[i]);
                }
            }
        }

        /// <summary>
        /// Grazing contacts with a general rotation: lines and rays tangent to spheres and capsules (sides and caps),
        /// through box edges and vertices, planes through box edges and vertices, shapes at triangle vertices and on
        /// triangle planes — apart or overlapping by 10^0…10^−16 of the size, or touching to rounding.
        /// </summary>
        private static (Spec, Spec) Grazing(Rng r, Kind ka, Kind kb, int dim, Precision p) =>
            Contact(r, ka, kb, dim, p, exact: false, offset: true, parallel: r.Chance(0.3));

        /// <summary>
        /// Exactly parallel contacts: lines, rays, segments, capsules and triangles parallel to box faces, half-space
        /// boundaries and triangle planes (exact axes), at exact offsets of 0 or ±2^−k of the size, or 10^−k ones.
        /// </summary>
        private static (Spec, Spec) Parallel(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            if (r.Chance(0.5)) return Contact(r, ka, kb, dim, p, exact: true, offset: true, parallel: true);
            // Exact offsets: a power of two below the grid, kept exact by the float and double grids.
            double s = Math.Pow(2, p.Float ? r.Int(-10, 10) : r.Int(-30, 30)), g = s / 4;
            bool hostIsA = r.Chance(0.5);
            var (host, contact, n) = HostContact(r, hostIsA ? ka : kb, dim, s, g, exact: true);
            contact += n * (r.Chance(0.2) ? 0 : r.Sign() * Math.ScaleB(g, -r.Int(0, p.Float ? 12 : 40)));
            var guest = GuestAt(r, hostIsA ? kb : ka, dim, contact, n, s, g, exact: true, parallel: r.Chance(0.7));
            return Finish(hostIsA ? host : guest, hostIsA ? guest : host, p);
        }

        /// <summary>
        /// Needle triangles (two vertices 10^−3…10^−15 of the size apart) and sliver triangles (a vertex that close to
        /// the opposite edge's line), against a shape near their boundary, and against each other.
        /// </summary>
        private static (Spec, Spec) Slivers(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            Spec Sliver()
            {
                var a = U3(r, 1, dim) * s;
                var b = a + Dir(r, dim) * (s * r.Range(0.5, 2));
                double tiny = s * r.Pow10Neg(3, 15);
                var c = r.Chance(0.5) ? a + Dir(r, dim) * tiny
                    : a + (b - a) * r.Range(-0.5, 1.5) + Perp(r, (b - a) / (b - a).Length, dim) * tiny;
                return r.Int(3) switch { 0 => Spec.Triangle(dim, a, b, c), 1 => Spec.Triangle(dim, c, a, b), _ => Spec.Triangle(dim, b, c, a) };
            }
            bool triA = ka == Kind.Triangle && (kb != Kind.Triangle || r.Chance(0.5));
            var tri = Sliver();
            Kind other = triA ? kb : ka;
            Spec guest;
            if (other == Kind.Triangle && r.Chance(0.5)) guest = Sliver();
            else
            {
                double small = s * r.Pow2(-20, 0);
                guest = RandomShape(r, other, dim, SurfacePoint(r, tri) + Dir(r, dim) * (small * r.Range(-1, 1)), small);
            }
            return Finish(triA ? tri : guest, triA ? guest : tri, p);
        }

        /// <summary>
        /// A segment, line, ray or capsule axis along an edge of a triangle (general, needle, sliver or flat), turned by
        /// 10^−3…10^−15, through the triangle or just off it (0 or 10^0…10^−16 of the size), shifted along itself: the
        /// axis × edge directions of the depth are then nearly zero cross products (they were rounded by u/sinθ).
        /// </summary>
        private static (Spec, Spec) EdgeParallel(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            var a = U3(r, 1, dim) * s;
            var b = a + Dir(r, dim) * (s * r.Range(0.5, 2));
            var c = r.Int(4) switch
            {
                0 => a + (b - a) * r.Range(-0.5, 1.5) + Perp(r, (b - a) / (b - a).Length, dim) * (s * r.Pow10Neg(3, 15)), // sliver
                1 => b + Dir(r, dim) * (s * r.Pow10Neg(3, 15)),                                                            // needle
                2 => a + (b - a) * 0.25,                                                                                   // flat
                _ => a + U3(r, 1, dim) * s,
            };
            var corners = new[] { a, b, c };
            int i = r.Int(3);
            var e = corners[(i + 1) % 3] - corners[i];
            if (e.LengthSquared == 0) e = Dir(r, dim);
            var d = Turn(e / e.Length, Perp(r, e / e.Length, dim), r.Pow10Neg(3, 15) * r.Sign());
            double u = r.Unit(), v = r.Unit() * (1 - u);
            var through = a + (b - a) * u + (c - a) * v;
            if (!r.Chance(0.25)) through += Dir(r, dim) * (s * r.Pow10Neg(0, 16));
            double len = s * r.Range(0.25, 2);
            var start = through - d * (len * r.Range(-0.5, 1.5));
            Kind other = ka == Kind.Triangle ? kb : ka;
            var axial = other switch
            {
                Kind.Line => Spec.Line(dim, start, d),
                Kind.Ray => Spec.Ray(dim, start, r.Chance(0.5) ? d : -d),
                Kind.Capsule => Spec.Capsule(dim, start, start + d * len, r.Chance(0.25) ? 0 : s * r.Pow10Neg(0, 12)),
                _ => Spec.Segment(dim, start, start + d * len),
            };
            var tri = Spec.Triangle(dim, a, b, c);
            return Finish(ka == Kind.Triangle ? tri : axial, ka == Kind.Triangle ? axial : tri, p);
        }

        /// <summary>
        /// Two lines or rays, or a line or ray and a half-space, so nearly parallel that they meet (or come closest) far
        /// away: near the end of the precision's range (half the cases, within 2^±8 of it, so on either side), or at up
        /// to 2^1100 of their own size (angles down to the subnormal range). Directions are sometimes axis-aligned before
        /// the turn, so a tiny angle survives rounding (float too). In 3D a line pair is offset out of its plane by up to
        /// its size, so the distance is not 0.
        /// </summary>
        private static (Spec, Spec) FarCrossing(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(p.MinExp / 2, p.MaxExp - 4);
            double range = p.Float ? float.MaxValue : double.MaxValue;
            double far = r.Chance(0.5) ? range * r.Pow2(-8, 8) : s * r.Pow2(10, p.Float ? 260 : 1100);
            Vector3D d = r.Chance(0.5) ? Dir(r, dim) : AxisDir(r, dim);
            var side = Perp(r, d, dim);
            var o = U3(r, 1.5, dim) * s;
            double h = s * r.Pow2(-4, 1);
            double theta = Math.Min(1, h / far);
            bool halfA = ka == Kind.HalfSpace, halfB = kb == Kind.HalfSpace;
            Spec Linear(Kind k, Vector3D origin, Vector3D dir) =>
                k == Kind.Line ? Spec.Line(dim, origin, dir) : Spec.Ray(dim, origin, r.Chance(0.8) ? dir : -dir);
            if (halfA || halfB)
            {
                // The boundary through o with normal `side`; the line starts h above it and descends at θ: it meets the
                // boundary about h/θ ahead.
                var line = Linear(halfA ? kb : ka, o + side * h, d - side * theta);
                var half = Spec.HalfSpace(dim, o + d * (s * r.Range(-2, 2)), r.Chance(0.8) ? side : -side);
                return Finish(halfA ? half : line, halfA ? line : half, p);
            }
            // A through o along d; B through o + h·side (plus an offset out of the plane in 3D), turned back by θ: they
            // cross (or pass closest) about h/θ ahead of o, on A's side of B's origin.
            var lift = dim == 3 && r.Chance(0.7) ? Vector3D.Cross(d, side) * (s * r.Range(-1, 1)) : default;
            var a = Linear(ka, o, d);
            var b = Linear(kb, o + side * h + d * (s * r.Range(-2, 2)) + lift, d - side * theta);
            return Finish(a, b, p);
        }

        /// <summary>A signed coordinate axis (a direction whose tiny turns stay exact).</summary>
        private static Vector3D AxisDir(Rng r, int dim)
        {
            int i = r.Int(dim);
            double sign = r.Sign();
            return new Vector3D(i == 0 ? sign : 0, i == 1 ? sign : 0, i == 2 ? sign : 0);
        }

        /// <summary>
        /// A line's or ray's origin moved far along it (2^10…2^60 of the size; 2^30 in float), the rest as "random":
        /// parameters and witnesses far from the origin, where cancellation in Origin + t·Direction shows.
        /// </summary>
        private static (Spec, Spec) FarAlong(Rng r, Kind ka, Kind kb, int dim, Precision p)
        {
            double s = r.Pow2(-10, 10);
            Spec Move(Spec x)
            {
                if (!Kinds.IsLinear(x.Kind)) return x;
                var d = x.Q / x.Q.Length;
                double far = s * r.Pow2(10, p.Float ? 30 : 60);
                // A ray moves backwards (it still reaches the configuration); a line either way.
                var o = x.P - d * (far * (x.Kind == Kind.Ray ? 1 : r.Sign()));
                return x.Kind == Kind.Line ? Spec.Line(dim, o, x.Q) : Spec.Ray(dim, o, x.Q);
            }
            var a = RandomShape(r, ka, dim, U3(r, 1.5, dim) * s, s);
            var b = RandomShape(r, kb, dim, U3(r, 1.5, dim) * s, s);
            return Finish(Move(a), Move(b), p);
        }
    }
}
