using System;
using System.Collections.Generic;
using System.Linq;
using ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// One ray-cast fuzz case: a ray and a target of one kind, dimension and precision, drawn by one generator from
    /// (seed, index). Its index space is its own (replay with <c>--fuzz-casts-replay SEED:INDEX</c>): index mod 40 picks
    /// the target kind (10), the dimension (3D, then 2D) and the precision (double, then float), so every block of 40
    /// consecutive cases calls all 40 public <c>Raycast.Cast</c> overloads; index / 40 rotates the generators.
    /// </summary>
    public sealed class CastCase
    {
        public long Seed { get; }
        public long Index { get; }
        public string Generator { get; }
        public int Dim { get; }
        public bool Float { get; }
        /// <summary>The ray (a <see cref="Kind.Ray"/> spec: origin and direction as given to the constructor).</summary>
        public Spec Ray { get; }
        public Spec Target { get; }
        /// <summary>The case's generator after the shapes are drawn: the checks draw their own choices from it.</summary>
        public Rng Rng { get; }

        public CastCase(long seed, long index, string generator, int dim, bool isFloat, Spec ray, Spec target, Rng rng)
        {
            Seed = seed; Index = index; Generator = generator; Dim = dim; Float = isFloat; Ray = ray; Target = target; Rng = rng;
        }

        /// <summary>"3D sphere", "2D half-plane", …</summary>
        public string TargetName => $"{Dim}D {Target.KindName}";
        public string PrecisionName => Float ? "float" : "double";

        public const int Slots = 40;

        public static (int Dim, Kind Kind, bool Float, long Round) Slot(long index)
        {
            int s = (int)(index % Slots);
            return ((s / 10) % 2 == 0 ? 3 : 2, Kinds.InOrder[s % 10], s >= 20, index / Slots);
        }

        /// <summary>The case's generator: SplitMix64 from (seed, index), salted so it does not repeat the pair fuzz's draws.</summary>
        public static Rng RngFor(long seed, long index) =>
            new Rng(Rng.Mix((ulong)seed * 0xD1B54A32D192ED03UL + 0x52617963UL) ^ Rng.Mix((ulong)index + 0x8CB92BA72F3D8DD7UL));

        public static CastCase Create(long seed, long index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index), "case indices are not negative");
            var (dim, kind, isFloat, round) = Slot(index);
            var g = CastGenerators.All[(int)(round % CastGenerators.All.Length)];
            var rng = RngFor(seed, index);
            var p = isFloat ? Precision.Single : Precision.Double;
            var (ray, target) = g.Make(rng, kind, dim, p);
            if (isFloat) { ray = ray.ToFloat(); target = target.ToFloat(); }
            return new CastCase(seed, index, g.Name, dim, isFloat, ray, target, rng);
        }
    }

    /// <summary>
    /// The ray-cast generators, aimed at the degeneracies of a first hit. Exact constructions put every coordinate on a
    /// power-of-two grid (small integers times 2^k, so floats hold them too) with directions whose components are 0 or
    /// ±1 (normalised, equal components stay equal, so the stored direction points exactly along them): a ray through
    /// a box's vertex or edge, tangent to a sphere or capsule, along a face or boundary, in a triangle's plane, or
    /// starting exactly on a surface is then exactly that.
    /// </summary>
    public static class CastGenerators
    {
        public delegate (Spec Ray, Spec Target) Make(Rng r, Kind kind, int dim, Precision p);

        public static readonly (string Name, Make Make)[] All =
        {
            ("random", RandomCase),
            ("aimed", Aimed),
            ("grazing", Grazing),
            ("parallel", Parallel),
            ("on-surface", OnSurface),
            ("inside", Inside),
            ("far", Far),
            ("magnitudes", Magnitudes),
            ("mixed-scales", MixedScales),
            ("degenerate", Degenerate),
        };

        public static string[] Names => All.Select(g => g.Name).ToArray();

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

        /// <summary>A non-zero direction with components in {−1, 0, 1} (an axis, a face or a body diagonal).</summary>
        private static Vector3D ExactDir(Rng r, int dim)
        {
            while (true)
            {
                var v = new Vector3D(r.Int(3) - 1, r.Int(3) - 1, dim == 3 ? r.Int(3) - 1 : 0);
                if (v != default) return v;
            }
        }

        /// <summary>An exact direction perpendicular to the small-integer vector n (n·v = 0 exactly), or any when n is 0.</summary>
        private static Vector3D ExactPerp(Rng r, Vector3D n, int dim)
        {
            if (n == default) return ExactDir(r, dim);
            for (int tries = 0; tries < 64; tries++)
            {
                var v = ExactDir(r, dim);
                if (Vector3D.Dot(v, n) == 0) return v;
            }
            // In 2D (or for a body diagonal) the perpendicular may need a 2: (−n.y, n.x[, 0]).
            var c = dim == 2 ? new Vector3D(-n.Y, n.X, 0) : Vector3D.Cross(n, Math.Abs(n.X) <= Math.Abs(n.Y) && Math.Abs(n.X) <= Math.Abs(n.Z) ? Vector3D.UnitX : Vector3D.UnitZ);
            return c == default ? ExactDir(r, dim) : c;
        }

        private static Vector3D Grid(Rng r, int n, double g, int dim) =>
            new Vector3D(r.Int(-n, n) * g, r.Int(-n, n) * g, dim == 3 ? r.Int(-n, n) * g : 0);

        private static Vector3D Axis(int i) => i == 0 ? Vector3D.UnitX : i == 1 ? Vector3D.UnitY : Vector3D.UnitZ;

        private static double Get(Vector3D v, int i) => i == 0 ? v.X : i == 1 ? v.Y : v.Z;

        /// <summary>A point of interest on an exactly constructed target: X on it (exactly), N its outward small-integer normal there (0: none, a thin target or a vertex).</summary>
        private readonly struct Feature
        {
            public readonly Vector3D X, N;
            public Feature(Vector3D x, Vector3D n) { X = x; N = n; }
        }

        /// <summary>The quaternions of Obb3.FromQuaternion whose stored axes are signed permutations (checked when used).</summary>
        private static readonly double[][] PermutationQuaternions =
        {
            new double[] { 0, 0, 0, 1 }, new double[] { 1, 0, 0, 0 }, new double[] { 0, 1, 0, 0 }, new double[] { 0, 0, 1, 0 },
            new double[] { 0, 0, 1, 1 }, new double[] { 1, 0, 0, 1 }, new double[] { 0, 1, 0, 1 }, new double[] { 1, 1, 1, 1 },
        };

        private static bool IsPermutation(Vector3D a) =>
            new[] { a.X, a.Y, a.Z }.Count(x => x == 0) == 2 && new[] { a.X, a.Y, a.Z }.Count(x => Math.Abs(x) == 1) == 1;

        /// <summary>
        /// A target on the grid g·{−n…n} and the features the exact generators start or aim from: box vertices, edge and
        /// face points; sphere and capsule surface points along the axes; triangle vertices and edge midpoints; a
        /// half-space's boundary points; segment ends and midpoints; line and ray points.
        /// </summary>
        private static (Spec, List<Feature>) ExactTarget(Rng r, Kind kind, int dim, double g)
        {
            var f = new List<Feature>();
            var c = Grid(r, 6, g, dim);
            switch (kind)
            {
                case Kind.Point:
                    f.Add(new Feature(c, default));
                    return (Spec.Point(dim, c), f);
                case Kind.Segment:
                {
                    var e = ExactDir(r, dim) * (r.Int(0, 4) * g);
                    f.Add(new Feature(c, default)); f.Add(new Feature(c + e, default)); f.Add(new Feature(c + e * 0.5, default));
                    return (Spec.Segment(dim, c, c + e), f);
                }
                case Kind.Line: case Kind.Ray:
                {
                    var e = ExactDir(r, dim);
                    f.Add(new Feature(c, default));
                    f.Add(new Feature(c + e * (r.Int(kind == Kind.Ray ? 0 : -4, 4) * g), default));
                    var stored = e * Math.ScaleB(1, r.Int(-3, 3));
                    return (kind == Kind.Line ? Spec.Line(dim, c, stored) : Spec.Ray(dim, c, stored), f);
                }
                case Kind.Sphere:
                {
                    double rad = r.Int(0, 4) * g;
                    for (int i = 0; i < dim; i++)
                        foreach (int s in new[] { -1, 1 })
                            f.Add(new Feature(c + Axis(i) * (s * rad), Axis(i) * s));
                    return (Spec.Sphere(dim, c, rad), f);
                }
                case Kind.Capsule:
                {
                    int j = r.Int(dim);
                    var e = Axis(j) * (r.Int(0, 4) * g * r.Sign());
                    double rad = r.Int(0, 3) * g;
                    var ej = Axis(j) * Math.Sign(Get(e, j) == 0 ? 1 : Get(e, j));
                    f.Add(new Feature(c - ej * rad, -ej));
                    f.Add(new Feature(c + e + ej * rad, ej));
                    for (int i = 0; i < dim; i++)
                    {
                        if (i == j) continue;
                        foreach (int s in new[] { -1, 1 })
                            foreach (double at in new[] { 0, 0.5, 1 })
                                f.Add(new Feature(c + e * at + Axis(i) * (s * rad), Axis(i) * s));
                    }
                    return (Spec.Capsule(dim, c, c + e, rad), f);
                }
                case Kind.Triangle:
                {
                    Vector3D a = c, b, cc;
                    if (r.Chance(0.4))
                    {
                        // Legs along exact directions (often in an axis plane, so in-plane rays are exact).
                        var u = ExactDir(r, dim);
                        var v = ExactPerp(r, u, dim);
                        b = a + u * (r.Int(1, 4) * g);
                        cc = a + v * (r.Int(1, 4) * g);
                    }
                    else
                    {
                        b = c + Grid(r, 4, g, dim);
                        cc = c + Grid(r, 4, g, dim);
                        if (dim == 3 && r.Chance(0.3)) { b = new Vector3D(b.X, b.Y, a.Z); cc = new Vector3D(cc.X, cc.Y, a.Z); }
                    }
                    foreach (var (p, q) in new[] { (a, b), (b, cc), (cc, a) })
                    {
                        f.Add(new Feature(p, default));
                        f.Add(new Feature(p + (q - p) * 0.5, dim == 2 ? Outward2(a, b, cc, p, q) : default));
                    }
                    return (Spec.Triangle(dim, a, b, cc), f);
                }
                case Kind.HalfSpace:
                {
                    var n = ExactDir(r, dim);
                    var t = ExactPerp(r, n, dim);
                    f.Add(new Feature(c, n));
                    f.Add(new Feature(c + t * (r.Int(-4, 4) * g), n));
                    return (Spec.HalfSpace(dim, c, n * Math.ScaleB(1, r.Int(-3, 3))), f);
                }
                case Kind.Aabb:
                {
                    var size = new Vector3D(r.Int(0, 4) * g, r.Int(0, 4) * g, dim == 3 ? r.Int(0, 4) * g : 0);
                    BoxFeatures(r, f, c, new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ }, size * 0.5, dim);
                    return (Spec.Aabb(dim, c - size * 0.5, c + size * 0.5), f);
                }
                default:
                {
                    var h = new Vector3D(r.Int(0, 3) * g, r.Int(0, 3) * g, dim == 3 ? r.Int(0, 3) * g : 0);
                    if (dim == 2)
                    {
                        var ax = r.Pick(new Vector3D(1, 0, 0), new Vector3D(0, 1, 0), new Vector3D(-1, 0, 0), new Vector3D(0, -1, 0));
                        BoxFeatures(r, f, c, new[] { ax, new Vector3D(-ax.Y, ax.X, 0), Vector3D.UnitZ }, h, dim);
                        return (Spec.Obb2Axis(c, ax.X, ax.Y, h), f);
                    }
                    var q = r.Pick(PermutationQuaternions);
                    var axes = Generators.AxesOf(q);
                    if (!axes.All(IsPermutation)) { q = PermutationQuaternions[0]; axes = Generators.AxesOf(q); }
                    BoxFeatures(r, f, c, axes, h, dim);
                    return (Spec.ObbQuaternion(c, q[0], q[1], q[2], q[3], h), f);
                }
            }
        }

        /// <summary>The outward small-integer normal of the 2D triangle abc's edge pq.</summary>
        private static Vector3D Outward2(Vector3D a, Vector3D b, Vector3D c, Vector3D p, Vector3D q)
        {
            double area = (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
            var e = q - p;
            var n = new Vector3D(e.Y, -e.X, 0) * Math.Sign(area);
            return area == 0 ? default : n;
        }

        /// <summary>Vertices, edge midpoints and face centres of the box center + Σ ±h_i·axis_i (axes signed permutations or axis-aligned).</summary>
        private static void BoxFeatures(Rng r, List<Feature> f, Vector3D c, Vector3D[] axes, Vector3D h, int dim)
        {
            for (int k = 0; k < 6; k++)
            {
                var x = c;
                var n = default(Vector3D);
                int face = r.Int(dim);
                for (int i = 0; i < dim; i++)
                {
                    // Each axis: a face (±h), or the middle (0) on the others; vertex when all are faces.
                    int s = i == face || r.Chance(0.5) ? (r.Chance(0.5) ? 1 : -1) : 0;
                    x += axes[i] * (s * Get(h, i));
                    if (i == face) n = axes[i] * s;
                }
                f.Add(new Feature(x, n));
            }
        }

        /// <summary>A point on or near the boundary of any target, from its stored form (rounded; for the inexact generators); size: how far along an unbounded one.</summary>
        private static Vector3D SurfacePoint(Rng r, Spec s, double size)
        {
            var c = Core.Of(s.Build());
            int dim = c.Planar ? 2 : 3;
            switch (c.Kind)
            {
                case Kind.Point: return c.P;
                case Kind.Segment: return c.P + (c.Q - c.P) * r.Unit();
                case Kind.Sphere: return c.P + Dir(r, dim) * c.R;
                case Kind.Line: case Kind.Ray: return c.P + c.Q * (r.Range(c.Kind == Kind.Ray ? 0 : -2, 2) * size);
                case Kind.Capsule: return c.P + (c.Q - c.P) * r.Range(-0.2, 1.2) + Dir(r, dim) * c.R;
                case Kind.Triangle:
                {
                    double u = r.Unit(), v = r.Unit() * (1 - u);
                    if (r.Chance(0.4)) v = 1 - u;
                    return c.P + (c.Q - c.P) * u + (c.H - c.P) * v;
                }
                case Kind.HalfSpace:
                {
                    var t = Vector3D.Cross(c.Q, Dir(r, 3));
                    if (dim == 2) t = new Vector3D(-c.Q.Y, c.Q.X, 0);
                    return c.P + t * (r.Range(-2, 2) * size);
                }
                case Kind.Aabb:
                {
                    var x = new[] { r.Range(c.P.X, c.Q.X), r.Range(c.P.Y, c.Q.Y), r.Range(c.P.Z, c.Q.Z) };
                    int i = r.Int(dim);
                    x[i] = r.Chance(0.5) ? Get(c.P, i) : Get(c.Q, i);
                    return new Vector3D(x[0], x[1], x[2]);
                }
                default:
                {
                    int face = r.Int(dim);
                    var x = c.P;
                    for (int i = 0; i < dim; i++)
                        x += c.Axes[i] * (i == face ? r.Sign() * Get(c.H, i) : r.Range(-1, 1) * Get(c.H, i));
                    return x;
                }
            }
        }

        private static double MaxAbs(Vector3D v) => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));

        /// <summary>A point inside a solid target (or on a thin one), from its stored form.</summary>
        private static Vector3D InnerPoint(Rng r, Spec s, double size)
        {
            var c = Core.Of(s.Build());
            int dim = c.Planar ? 2 : 3;
            double f = r.Chance(0.3) ? 1 - r.Pow2(-40, -1) : r.Unit();
            switch (c.Kind)
            {
                case Kind.Sphere: return c.P + Dir(r, dim) * (c.R * f);
                case Kind.Capsule: return c.P + (c.Q - c.P) * r.Unit() + Dir(r, dim) * (c.R * f);
                case Kind.HalfSpace: return SurfacePoint(r, s, size) - c.Q * (f * size * r.Pow2(-30, 2));
                case Kind.Aabb:
                case Kind.Obb:
                {
                    var mid = c.Kind == Kind.Aabb ? (c.P + c.Q) * 0.5 : c.P;
                    return mid + (SurfacePoint(r, s, size) - mid) * f;
                }
                case Kind.Triangle:
                {
                    double u = r.Unit(), v = r.Unit() * (1 - u);
                    return c.P + (c.Q - c.P) * u + (c.H - c.P) * v;
                }
                default: return SurfacePoint(r, s, size);
            }
        }

        /// <summary>A random target of the kind (the pair fuzz's shapes; one in eight degenerate) around c at the given size.</summary>
        private static Spec RandomTarget(Rng r, Kind kind, int dim, Vector3D c, double size) => Generators.RandomShape(r, kind, dim, c, size);

        /// <summary>A ray from o along d; a zero d (o on the aim) becomes a random direction.</summary>
        private static Spec Ray(Rng r, int dim, Vector3D o, Vector3D d)
        {
            if (dim == 2) { o = new Vector3D(o.X, o.Y, 0); d = new Vector3D(d.X, d.Y, 0); }
            if (d == default || !d.IsFinite) d = Dir(r, dim);
            return Spec.Ray(dim, o, d);
        }

        /// <summary>The exact grid's unit: 2^[−4, 4] (scaled per generator).</summary>
        private static double GridUnit(Rng r) => Math.ScaleB(1, r.Int(-4, 4));

        // ---- the generators -------------------------------------------------------------------------------------

        /// <summary>Random targets at 2^±4 and random rays near them, half aimed at a point near the target.</summary>
        private static (Spec, Spec) RandomCase(Rng r, Kind kind, int dim, Precision p)
        {
            double s = r.Pow2(-4, 4);
            var c = U3(r, 1.5, dim) * s;
            var target = RandomTarget(r, kind, dim, c, s);
            var o = c + U3(r, 3, dim) * s;
            var d = r.Chance(0.5) ? c + U3(r, 1, dim) * s - o : Dir(r, dim);
            return (Ray(r, dim, o, d), target);
        }

        /// <summary>Rays aimed at a point on the target (a face, a vertex, an edge, the surface), from 2^[−3, 3] of its size away.</summary>
        private static (Spec, Spec) Aimed(Rng r, Kind kind, int dim, Precision p)
        {
            double s = r.Pow2(-4, 4);
            Spec target;
            Vector3D x;
            if (r.Chance(0.5))
            {
                target = RandomTarget(r, kind, dim, U3(r, 1, dim) * s, s);
                x = SurfacePoint(r, target, s);
            }
            else
            {
                var (t, f) = ExactTarget(r, kind, dim, GridUnit(r) * s);
                target = t;
                x = r.Pick(f.ToArray()).X;
            }
            var o = x + Dir(r, dim) * (s * r.Pow2(-3, 3));
            return (Ray(r, dim, o, x - o), target);
        }

        /// <summary>
        /// Grazing rays: exactly tangent to a sphere or capsule at a surface point, through a box's vertex or edge along an
        /// exact direction, along a triangle's edge, through a thin target's point; a third tilted by 2^[−50, −10] toward or
        /// away from the surface; a third inexact tangents to random round targets.
        /// </summary>
        private static (Spec, Spec) Grazing(Rng r, Kind kind, int dim, Precision p)
        {
            double g = GridUnit(r);
            if (r.Chance(0.3) && (kind == Kind.Sphere || kind == Kind.Capsule))
            {
                double s = r.Pow2(-4, 4);
                var target = RandomTarget(r, kind, dim, U3(r, 1, dim) * s, s);
                var core = Core.Of(target.Build());
                var n = Dir(r, dim);
                var axisPoint = kind == Kind.Capsule ? core.P + (core.Q - core.P) * r.Range(-0.2, 1.2) : core.P;
                var touch = axisPoint + n * core.R;
                var along = kind == Kind.Capsule && r.Chance(0.5) ? core.Q - core.P : Dir(r, dim);
                var t = along - n * Vector3D.Dot(along, n);
                if (t.Length < 1e-6 * Math.Max(along.Length, 1e-300)) t = Dir(r, dim);
                var o = touch - t * (s * r.Pow2(-2, 4) / Math.Max(t.Length, 1e-300));
                return (Ray(r, dim, o, t), target);
            }
            var (spec, features) = ExactTarget(r, kind, dim, g);
            var fe = r.Pick(features.ToArray());
            Vector3D dir;
            if (kind == Kind.Triangle && r.Chance(0.5))
            {
                // Along an edge: from one vertex toward another (exact only for the exact legs).
                var core = Core.Of(spec.Build());
                var v = new[] { core.P, core.Q, core.H };
                int i = r.Int(3);
                dir = v[(i + 1) % 3] - v[i];
                fe = new Feature(v[i], default);
            }
            else dir = kind == Kind.Aabb || kind == Kind.Obb || fe.N == default ? ExactDir(r, dim) : ExactPerp(r, fe.N, dim);
            if (dir == default) dir = ExactDir(r, dim);
            if (r.Chance(0.3) && fe.N != default) dir += fe.N * (r.Sign() * r.Pow2(-50, -10));
            var origin = fe.X - dir * (r.Int(1, 8) * g);
            return (Ray(r, dim, origin, dir), spec);
        }

        /// <summary>
        /// Rays parallel to a face, boundary, side or thin target: on it (running along it), or offset along its normal by
        /// a grid step, by the pass-through tolerance's order (thin targets) or by nothing; a third nearly parallel
        /// (tilted by 2^[−60, −8]).
        /// </summary>
        private static (Spec, Spec) Parallel(Rng r, Kind kind, int dim, Precision p)
        {
            double g = GridUnit(r);
            var (spec, features) = ExactTarget(r, kind, dim, g);
            var fe = r.Pick(features.ToArray());
            Vector3D dir, offset = default;
            var core = Core.Of(spec.Build());
            switch (kind)
            {
                case Kind.Segment: case Kind.Line: case Kind.Ray:
                {
                    var along = kind == Kind.Segment ? core.Q - core.P : core.Q;
                    dir = along == default ? ExactDir(r, dim) : along * r.Sign();
                    var n = ExactPerp(r, along == default ? ExactDir(r, dim) : Sign(along), dim);
                    double m = Math.Max(MaxAbs(fe.X), g);
                    offset = n * r.Pick(0.0, g, m * Math.ScaleB(1, -40) * r.Range(0.5, 2), m * Math.ScaleB(1, r.Int(-52, -30)));
                    break;
                }
                case Kind.Triangle:
                {
                    // In the triangle's plane when it lies in an axis plane (exact), else along an edge.
                    var v = new[] { core.P, core.Q, core.H };
                    int i = r.Int(3);
                    dir = v[(i + 1) % 3] - v[i];
                    if (dim == 3 && core.P.Z == core.Q.Z && core.Q.Z == core.H.Z && r.Chance(0.6)) dir = new Vector3D(ExactDir(r, 2).X, ExactDir(r, 2).Y, 0);
                    if (dir == default) dir = ExactDir(r, dim);
                    if (r.Chance(0.3)) offset = (dim == 3 ? Vector3D.UnitZ : ExactPerp(r, Sign(dir), 2)) * (r.Sign() * g * r.Pick(1, 0.5, Math.ScaleB(1, -30)));
                    break;
                }
                default:
                {
                    var n = fe.N == default ? ExactDir(r, dim) : fe.N;
                    dir = ExactPerp(r, n, dim);
                    offset = n * (r.Int(-2, 2) * g * r.Pick(1, 0.5, 0.25));
                    break;
                }
            }
            if (r.Chance(0.3)) dir += ExactDir(r, dim) * r.Pow2(-60, -8);
            var origin = fe.X + offset - dir * (r.Int(-2, 8) * g);
            return (Ray(r, dim, origin, dir), spec);
        }

        private static Vector3D Sign(Vector3D v) => new Vector3D(Math.Sign(v.X), Math.Sign(v.Y), Math.Sign(v.Z));

        /// <summary>
        /// The origin exactly on the surface (a feature of an exact target), or nudged off it by 1–4 units in the last
        /// place of one coordinate (just inside or just outside), heading in, out, along or anywhere.
        /// </summary>
        private static (Spec, Spec) OnSurface(Rng r, Kind kind, int dim, Precision p)
        {
            var (spec, features) = ExactTarget(r, kind, dim, GridUnit(r));
            var fe = r.Pick(features.ToArray());
            var o = fe.X;
            if (r.Chance(0.5))
            {
                int i = r.Int(dim), k = r.Int(1, 4);
                double x = Get(o, i);
                for (int j = 0; j < k; j++) x = r.Chance(0.5) ? (p.Float ? MathF.BitIncrement((float)x) : Math.BitIncrement(x)) : (p.Float ? MathF.BitDecrement((float)x) : Math.BitDecrement(x));
                o = i == 0 ? new Vector3D(x, o.Y, o.Z) : i == 1 ? new Vector3D(o.X, x, o.Z) : new Vector3D(o.X, o.Y, x);
            }
            var dir = r.Int(4) switch
            {
                0 when fe.N != default => -fe.N,
                1 when fe.N != default => fe.N,
                2 => ExactPerp(r, fe.N, dim),
                _ => Dir(r, dim),
            };
            return (Ray(r, dim, o, dir), spec);
        }

        /// <summary>The origin strictly inside a solid (deep, or within 2^−40 of its size of the surface), or on a thin target.</summary>
        private static (Spec, Spec) Inside(Rng r, Kind kind, int dim, Precision p)
        {
            double s = r.Pow2(-4, 4);
            var target = r.Chance(0.5) ? RandomTarget(r, kind, dim, U3(r, 1, dim) * s, s) : ExactTarget(r, kind, dim, GridUnit(r) * s).Item1;
            var o = InnerPoint(r, target, s);
            return (Ray(r, dim, o, Dir(r, dim)), target);
        }

        /// <summary>
        /// Far away: the origin 2^[20, 50] of the target's size from it (1e6–1e15), aimed into it, at its surface or near it; or the whole
        /// configuration translated by up to 2^50 of its size.
        /// </summary>
        private static (Spec, Spec) Far(Rng r, Kind kind, int dim, Precision p)
        {
            double s = r.Pow2(-4, 4);
            var c = U3(r, 1, dim) * s;
            var target = RandomTarget(r, kind, dim, c, s);
            if (r.Chance(0.5))
            {
                var o = c + Dir(r, dim) * (s * r.Pow2(20, p.Float ? 30 : 50));
                var aim = r.Chance(0.5) ? InnerPoint(r, target, s) : SurfacePoint(r, target, s) + U3(r, r.Pick(0, 1e-6, 1), dim) * s;
                return (Ray(r, dim, o, aim - o), target);
            }
            var shift = Dir(r, dim) * (s * r.Pow2(20, p.Float ? 40 : 50));
            var o2 = c + U3(r, 3, dim) * s;
            var d = SurfacePoint(r, target, s) - o2;
            return (Ray(r, dim, o2 + shift, d), target.Translated(shift));
        }

        /// <summary>A random configuration at a log-uniform scale over the whole range (double 2^−1074…2^1020, subnormals included; float 2^±125).</summary>
        private static (Spec, Spec) Magnitudes(Rng r, Kind kind, int dim, Precision p)
        {
            double s = r.Chance(0.1) ? r.Pow2(p.SubMin + 4, p.SubMax) : r.Pow2(p.MinExp, p.MaxExp - 1);
            var c = U3(r, 1.5, dim) * s;
            var target = RandomTarget(r, kind, dim, c, s);
            var o = c + U3(r, 3, dim) * s;
            var d = r.Chance(0.6) ? SurfacePoint(r, target, s) - o : Dir(r, dim);
            return (Ray(r, dim, o, d), target);
        }

        /// <summary>A target 2^[4, 120] (float 2^[4, 60]) smaller than the origin's distance, or a large target with the origin that much closer to it than its size.</summary>
        private static (Spec, Spec) MixedScales(Rng r, Kind kind, int dim, Precision p)
        {
            double big = p.Float ? r.Pow2(-40, 40) : r.Pow2(-300, 300);
            double small = big * r.Pow2(-p.MixMax, -4);
            if (r.Chance(0.5))
            {
                var c = U3(r, 1, dim) * big;
                var target = RandomTarget(r, kind, dim, c, small);
                var o = c + Dir(r, dim) * big;
                return (Ray(r, dim, o, SurfacePoint(r, target, small) - o), target);
            }
            var host = RandomTarget(r, kind, dim, U3(r, 1, dim) * big, big);
            var at = SurfacePoint(r, host, big) + Dir(r, dim) * (small * r.Range(-2, 2));
            return (Ray(r, dim, at, Dir(r, dim)), host);
        }

        /// <summary>
        /// Degenerate targets: zero-radius spheres and capsules, zero-length capsules and segments, coincident and
        /// collinear triangles, boxes with zero extents; rays exactly through them (grid) or near them.
        /// </summary>
        private static (Spec, Spec) Degenerate(Rng r, Kind kind, int dim, Precision p)
        {
            double g = GridUnit(r);
            var a = Grid(r, 6, g, dim);
            var e = ExactDir(r, dim) * (r.Int(1, 4) * g);
            Spec target = kind switch
            {
                Kind.Sphere => Spec.Sphere(dim, a, 0),
                Kind.Capsule => r.Chance(0.5) ? Spec.Capsule(dim, a, a, r.Int(0, 2) * g) : Spec.Capsule(dim, a, a + e, 0),
                Kind.Segment => r.Chance(0.5) ? Spec.Segment(dim, a, a) : Spec.Segment(dim, a, a + e),
                Kind.Triangle => r.Int(3) switch
                {
                    0 => Spec.Triangle(dim, a, a, a),
                    1 => Spec.Triangle(dim, a, a, a + e),
                    _ => Spec.Triangle(dim, a, a + e, a + e * r.Pick(-1, 0.5, 2, 3)),
                },
                Kind.Aabb => Spec.Aabb(dim, a, a + new Vector3D(r.Chance(0.5) ? 0 : g, r.Chance(0.5) ? 0 : g, 0)),
                Kind.Obb => r.Chance(0.5)
                    ? (dim == 3 ? Spec.ObbQuaternion(a, 0, 0, 0, 1, new Vector3D(g, 0, 0)) : Spec.Obb2Axis(a, 1, 0, new Vector3D(0, g, 0)))
                    : (dim == 3 ? Spec.ObbQuaternion(a, r.Gauss(), r.Gauss(), r.Gauss(), r.Gauss(), default) : Spec.Obb2Angle(a, r.Range(0, 6.3), default)),
                _ => ExactTarget(r, kind, dim, g).Item1,
            };
            // Through a point of the degenerate target exactly (an exact direction from a grid origin), or near it.
            var x = r.Chance(0.5) ? a : a + e * (r.Int(0, 2) * 0.5);
            var dir = ExactDir(r, dim);
            var o = x - dir * (r.Int(-1, 6) * g);
            if (r.Chance(0.3)) dir = x + U3(r, g, dim) * r.Pow2(-40, 0) - o;
            return (Ray(r, dim, o, dir), target);
        }
    }
}
