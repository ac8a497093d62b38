using System;
using System.Collections.Generic;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// A shape exactly as the library stores it (double form, OBB axes as stored), for the fuzz's exact checks: exact
    /// membership, exact support functions, exact points built from parameters (so a candidate point is in the shape by
    /// construction), and a scaled local double copy (relative to an origin, sized ~1) in which candidate parameters
    /// are searched. A sphere is its center (its core) plus a radius, a capsule its axis plus a radius; the other shapes
    /// have radius 0. Lines, rays and half-spaces are unbounded: their support function is +∞ except along the
    /// directions where it is finite (<see cref="TrySupport"/>), and candidate directions are fitted to those exactly
    /// (<see cref="Fit"/>).
    /// </summary>
    public sealed class Core
    {
        public Kind Kind { get; }
        public bool Planar { get; }
        /// <summary>Point; segment/capsule start; sphere/OBB center; AABB min; line/ray origin; triangle A; half-space point.</summary>
        public Vector3D P { get; }
        /// <summary>Segment/capsule end; AABB max; line/ray direction (as stored); triangle B; half-space normal (as stored).</summary>
        public Vector3D Q { get; }
        public double R { get; }
        public Vector3D[] Axes { get; } = { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ };
        /// <summary>OBB half-extents; triangle C.</summary>
        public Vector3D H { get; }

        // Local double copy: (x − origin)·2^−shift (directions and normals are not lengths: kept as stored).
        private Vector3D _p, _q, _h;
        // A half-space's tangents, exactly perpendicular to its stored normal (2D: one), and their local doubles.
        private DyVec _t1, _t2;
        private Vector3D _lt1, _lt2;
        private readonly List<Vector3D> _vertices = new List<Vector3D>();
        private readonly List<(Vector3D, Vector3D)> _edges = new List<(Vector3D, Vector3D)>();

        private Core(Kind kind, bool planar, Vector3D p, Vector3D q, double r, Vector3D[]? axes, Vector3D h)
        {
            Kind = kind; Planar = planar; P = p; Q = q; R = r; H = h;
            if (axes != null) Axes = axes;
        }

        /// <summary>The double-API shape a shape of either API holds (what the float API computes on).</summary>
        public static object DoubleForm(object shape) => shape switch
        {
            Vector3D or Vector2D => shape,
            _ when shape.GetType().Namespace == "ProximityLib.Double" => shape,
            ProximityLib.Line3 x => (Dbl.Line3)x,
            ProximityLib.Line2 x => (Dbl.Line2)x,
            ProximityLib.Ray3 x => (Dbl.Ray3)x,
            ProximityLib.Ray2 x => (Dbl.Ray2)x,
            ProximityLib.Capsule3 x => (Dbl.Capsule3)x,
            ProximityLib.Capsule2 x => (Dbl.Capsule2)x,
            ProximityLib.Triangle3 x => (Dbl.Triangle3)x,
            ProximityLib.Triangle2 x => (Dbl.Triangle2)x,
            ProximityLib.HalfSpace x => (Dbl.HalfSpace)x,
            ProximityLib.HalfPlane x => (Dbl.HalfPlane)x,
            _ => Shapes.Widen(shape),
        };

        /// <summary>The core of a library shape of either API (float shapes are taken in the double form they hold).</summary>
        public static Core Of(object shape)
        {
            shape = DoubleForm(shape);
            static Vector3D V(Vector2D v) => new Vector3D(v.X, v.Y, 0);
            return shape switch
            {
                Vector3D p => new Core(Kind.Point, false, p, default, 0, null, default),
                Vector2D p => new Core(Kind.Point, true, V(p), default, 0, null, default),
                Dbl.Segment3 s => new Core(Kind.Segment, false, s.Start, s.End, 0, null, default),
                Dbl.Segment2 s => new Core(Kind.Segment, true, V(s.Start), V(s.End), 0, null, default),
                Dbl.Sphere s => new Core(Kind.Sphere, false, s.Center, default, s.Radius, null, default),
                Dbl.Circle c => new Core(Kind.Sphere, true, V(c.Center), default, c.Radius, null, default),
                Dbl.Aabb3 b => new Core(Kind.Aabb, false, b.Min, b.Max, 0, null, default),
                Dbl.Aabb2 b => new Core(Kind.Aabb, true, V(b.Min), V(b.Max), 0, null, default),
                Dbl.Obb3 b => new Core(Kind.Obb, false, b.Center, default, 0, new[] { b.AxisX, b.AxisY, b.AxisZ }, b.HalfExtents),
                Dbl.Obb2 b => new Core(Kind.Obb, true, V(b.Center), default, 0, new[] { V(b.AxisX), V(b.AxisY), Vector3D.UnitZ },
                    new Vector3D(b.HalfExtents.X, b.HalfExtents.Y, 0)),
                Dbl.Line3 l => new Core(Kind.Line, false, l.Origin, l.Direction, 0, null, default),
                Dbl.Line2 l => new Core(Kind.Line, true, V(l.Origin), V(l.Direction), 0, null, default),
                Dbl.Ray3 l => new Core(Kind.Ray, false, l.Origin, l.Direction, 0, null, default),
                Dbl.Ray2 l => new Core(Kind.Ray, true, V(l.Origin), V(l.Direction), 0, null, default),
                Dbl.Capsule3 c => new Core(Kind.Capsule, false, c.Start, c.End, c.Radius, null, default),
                Dbl.Capsule2 c => new Core(Kind.Capsule, true, V(c.Start), V(c.End), c.Radius, null, default),
                Dbl.Triangle3 t => new Core(Kind.Triangle, false, t.A, t.B, 0, null, t.C),
                Dbl.Triangle2 t => new Core(Kind.Triangle, true, V(t.A), V(t.B), 0, null, V(t.C)),
                Dbl.HalfSpace h => new Core(Kind.HalfSpace, false, h.Point, h.Normal, 0, null, default),
                Dbl.HalfPlane h => new Core(Kind.HalfSpace, true, V(h.Point), V(h.Normal), 0, null, default),
                _ => throw new ArgumentException(shape.GetType().FullName),
            };
        }

        /// <summary>Solids (docs/api.md): sphere/circle, capsule, the 2D triangle, half-space/half-plane, AABB, OBB.</summary>
        public bool IsSolid => Kind == Kind.Sphere || Kind == Kind.Aabb || Kind == Kind.Obb || Kind == Kind.Capsule
                               || Kind == Kind.HalfSpace || (Kind == Kind.Triangle && Planar);
        public bool IsBox => Kind == Kind.Aabb || Kind == Kind.Obb;
        /// <summary>Lines, rays and half-spaces: the support function is +∞ in most directions.</summary>
        public bool IsUnbounded => Kind == Kind.Line || Kind == Kind.Ray || Kind == Kind.HalfSpace;
        /// <summary>Shapes with a radius around their core (sphere: its center; capsule: its axis).</summary>
        public bool IsRounded => Kind == Kind.Sphere || Kind == Kind.Capsule;

        /// <summary>Bitwise identity of the stored shapes.</summary>
        public bool SameAs(Core o) =>
            Kind == o.Kind && Planar == o.Planar && Spec.Bits(P, o.P) && Spec.Bits(Q, o.Q) && Spec.Bits(R, o.R) && Spec.Bits(H, o.H)
            && Spec.Bits(Axes[0], o.Axes[0]) && Spec.Bits(Axes[1], o.Axes[1]) && Spec.Bits(Axes[2], o.Axes[2]);

        // ---- exact -------------------------------------------------------------------------------------------------

        private List<DyVec>? _defining;

        /// <summary>The defining points of the local scale S (as the reference's RShape: ends, center, vertices).</summary>
        public IReadOnlyList<DyVec> Defining() => _defining ??= new List<DyVec>(MakeDefining());

        private IEnumerable<DyVec> MakeDefining()
        {
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: case Kind.Line: case Kind.Ray: case Kind.HalfSpace: yield return DyVec.From(P); break;
                case Kind.Segment: case Kind.Capsule: yield return DyVec.From(P); yield return DyVec.From(Q); break;
                case Kind.Triangle: yield return DyVec.From(P); yield return DyVec.From(Q); yield return DyVec.From(H); break;
                case Kind.Aabb:
                    for (int m = 0; m < 8; m++)
                        yield return new DyVec((m & 1) != 0 ? Q.X : P.X, (m & 2) != 0 ? Q.Y : P.Y, (m & 4) != 0 ? Q.Z : P.Z);
                    break;
                default:
                    var c = DyVec.From(P);
                    var e = new[] { DyVec.From(Axes[0]) * H.X, DyVec.From(Axes[1]) * H.Y, DyVec.From(Axes[2]) * H.Z };
                    for (int m = 0; m < 8; m++)
                        yield return c + Signed(e[0], m & 1) + Signed(e[1], m & 2) + Signed(e[2], m & 4);
                    break;
            }
        }

        private static DyVec Signed(DyVec v, int bit) => bit != 0 ? v : new DyVec(-v.X, -v.Y, -v.Z);

        /// <summary>
        /// S: the largest coordinate difference between the defining points of both shapes, or the larger radius
        /// (docs/accuracy.md), exactly — no overflow at the ends of the range.
        /// </summary>
        public static Dy Scale(Core a, Core b)
        {
            var s = Dy.Max(a.R, b.R);
            var pts = new List<DyVec>(a.Defining());
            pts.AddRange(b.Defining());
            for (int j = 0; j < 3; j++)
            {
                Dy lo = pts[0][j], hi = pts[0][j];
                foreach (var p in pts) { lo = Dy.Min(lo, p[j]); hi = Dy.Max(hi, p[j]); }
                s = Dy.Max(s, hi - lo);
            }
            return s;
        }

        /// <summary>The largest coordinate magnitude of the defining points (witness coordinates are rounded at this scale).</summary>
        public Dy Magnitude()
        {
            var m = Dy.Zero;
            foreach (var p in Defining()) m = Dy.Max(m, Dy.Max(Dy.Abs(p.X), Dy.Max(Dy.Abs(p.Y), Dy.Abs(p.Z))));
            return IsRounded ? m + R : m;
        }

        /// <summary>Squared Euclidean distance from x to the shape (its core expanded by the radius is handled by the caller), exactly.</summary>
        public Dy ExcessSquared(DyVec x, double t)
        {
            switch (Kind)
            {
                case Kind.Point: return (x - DyVec.From(P)).LengthSquared;
                case Kind.Segment:
                    var a = DyVec.From(P);
                    var on = a + (DyVec.From(Q) - a) * t;
                    return (x - on).LengthSquared;
                case Kind.Sphere: return (x - DyVec.From(P)).LengthSquared;
                case Kind.Capsule:
                    var s0 = DyVec.From(P);
                    return (x - (s0 + (DyVec.From(Q) - s0) * t)).LengthSquared;
                case Kind.Line: case Kind.Ray: return (x - (DyVec.From(P) + DyVec.From(Q) * t)).LengthSquared;
                case Kind.Triangle: case Kind.HalfSpace: throw new InvalidOperationException("no exact squared distance for a " + Kind + "; use Contains or Excess");
                case Kind.Aabb:
                {
                    var sum = Dy.Zero;
                    for (int j = 0; j < 3; j++)
                    {
                        Dy lo = Get(P, j), hi = Get(Q, j), v = x[j];
                        var e = v < lo ? lo - v : (v > hi ? v - hi : Dy.Zero);
                        sum += e.Square();
                    }
                    return sum;
                }
                default:
                {
                    var w = x - DyVec.From(P);
                    var sum = Dy.Zero;
                    for (int i = 0; i < 3; i++)
                    {
                        var l = Dy.Abs(DyVec.Dot(w, DyVec.From(Axes[i])));
                        Dy h = Get(H, i);
                        if (l > h) sum += (l - h).Square();
                    }
                    return sum;
                }
            }
        }

        /// <summary>
        /// Is x within tol of the shape (for a segment or capsule: of its axis point at parameter t; for a line or ray: of
        /// Origin + t·Direction with the stored direction)? Exact.
        /// </summary>
        public bool Contains(DyVec x, double t, Dy tol)
        {
            if (Planar && !x.Z.IsZero) return false;
            if ((Kind == Kind.Segment || Kind == Kind.Capsule) && !(t >= 0 && t <= 1)) return false;
            if (Kind == Kind.Line && !double.IsFinite(t)) return false;
            if (Kind == Kind.Ray && !(t >= 0 && double.IsFinite(t))) return false;
            if (Kind == Kind.Triangle) return NearTriangle(x, DyVec.From(P), DyVec.From(Q), DyVec.From(H), tol);
            if (Kind == Kind.HalfSpace)
            {
                // n·(x − P) ≤ tol·|n| with the stored (unit to rounding) normal.
                var n = DyVec.From(Q);
                var g = DyVec.Dot(n, x - DyVec.From(P));
                return g.Sign <= 0 || (tol.Sign >= 0 && g.Square() <= tol.Square() * n.LengthSquared);
            }
            var e2 = ExcessSquared(x, t);
            return IsRounded ? DyMath.AtLeastRoot((Dy)R + tol, e2) : DyMath.AtLeastRoot(tol, e2);
        }

        /// <summary>How far x lies outside the shape (approximately; for messages), at the parameter t like <see cref="Contains"/>.</summary>
        public double Excess(DyVec x, double t)
        {
            switch (Kind)
            {
                case Kind.Triangle:
                {
                    DyVec a = DyVec.From(P), b = DyVec.From(Q), c = DyVec.From(H);
                    var n = Cross(b - a, c - a);
                    double best = Math.Min(SegmentGap(x, a, b), Math.Min(SegmentGap(x, b, c), SegmentGap(x, c, a)));
                    if (!n.LengthSquared.IsZero && InsidePrism(x, a, b, c, n))
                        best = Math.Min(best, Math.Abs(DyVec.Dot(x - a, n).ToDouble()) / DyMath.Sqrt(n.LengthSquared));
                    return best;
                }
                case Kind.HalfSpace:
                {
                    var n = DyVec.From(Q);
                    return Math.Max(0, DyVec.Dot(n, x - DyVec.From(P)).ToDouble() / DyMath.Sqrt(n.LengthSquared));
                }
                default:
                    return DyMath.Sqrt(ExcessSquared(x, t)) - (IsRounded ? R : 0);
            }
        }

        private static DyVec Cross(DyVec u, DyVec v) => new DyVec(u.Y * v.Z - u.Z * v.Y, u.Z * v.X - u.X * v.Z, u.X * v.Y - u.Y * v.X);

        /// <summary>Does x project into the triangle's prism (on the inner side of all three edges, n = (b − a) × (c − a) ≠ 0)? Exact.</summary>
        private static bool InsidePrism(DyVec x, DyVec a, DyVec b, DyVec c, DyVec n) =>
            DyVec.Dot(Cross(b - a, x - a), n).Sign >= 0 && DyVec.Dot(Cross(c - b, x - b), n).Sign >= 0 && DyVec.Dot(Cross(a - c, x - c), n).Sign >= 0;

        /// <summary>Is x within tol of the segment [a, b] (possibly a point)? Exact, no division.</summary>
        private static bool NearSegment(DyVec x, DyVec a, DyVec b, Dy tol)
        {
            var e = b - a;
            var w = x - a;
            var ee = e.LengthSquared;
            var we = DyVec.Dot(w, e);
            if (ee.IsZero || we.Sign <= 0) return DyMath.AtLeastRoot(tol, w.LengthSquared);
            if (we >= ee) return DyMath.AtLeastRoot(tol, (x - b).LengthSquared);
            // |w|² − (w·e)²/|e|² ≤ tol², times |e|².
            return tol.Sign >= 0 && w.LengthSquared * ee - we.Square() <= tol.Square() * ee;
        }

        private static double SegmentGap(DyVec x, DyVec a, DyVec b)
        {
            var e = b - a;
            var w = x - a;
            var ee = e.LengthSquared;
            var we = DyVec.Dot(w, e);
            if (ee.IsZero || we.Sign <= 0) return DyMath.Sqrt(w.LengthSquared);
            if (we >= ee) return DyMath.Sqrt((x - b).LengthSquared);
            return DyMath.Sqrt(w.LengthSquared - we.Square() * (Dy)(1 / ee.ToDouble()));
        }

        /// <summary>
        /// Is x within tol of the triangle abc (any degenerate one included)? A point whose projection falls inside is at
        /// |(x − a)·n|/|n| from the plane; otherwise the nearest point is on an edge. In 2D (z = 0) the inside test is
        /// the solid triangle's containment. Exact.
        /// </summary>
        public static bool NearTriangle(DyVec x, DyVec a, DyVec b, DyVec c, Dy tol)
        {
            var n = Cross(b - a, c - a);
            var nn = n.LengthSquared;
            if (!nn.IsZero && InsidePrism(x, a, b, c, n))
            {
                var h = DyVec.Dot(x - a, n);
                if (h.IsZero || (tol.Sign >= 0 && h.Square() <= tol.Square() * nn)) return true;
            }
            return NearSegment(x, a, b, tol) || NearSegment(x, b, c, tol) || NearSegment(x, c, a, tol);
        }

        /// <summary>max over the core of x·n, exactly (the radius is added by the caller); old kinds only (always finite).</summary>
        public Dy Support(DyVec n) =>
            TrySupport(n, out var s) ? s : throw new InvalidOperationException($"the support of a {Kind} along {n.ToDouble()} is +∞");

        /// <summary>
        /// max over the core of x·n, exactly, when it is finite: a line's only along directions exactly perpendicular to
        /// it, a ray's where n·Direction ≤ 0, a half-space's only along positive multiples of its normal.
        /// </summary>
        public bool TrySupport(DyVec n, out Dy s)
        {
            var p = DyVec.From(P);
            switch (Kind)
            {
                case Kind.Line:
                {
                    s = DyVec.Dot(p, n);
                    return DyVec.Dot(DyVec.From(Q), n).IsZero;
                }
                case Kind.Ray:
                {
                    s = DyVec.Dot(p, n);
                    return DyVec.Dot(DyVec.From(Q), n).Sign <= 0;
                }
                case Kind.HalfSpace:
                {
                    var normal = DyVec.From(Q);
                    s = DyVec.Dot(p, n);
                    var c = Cross(n, normal);
                    return c.X.IsZero && c.Y.IsZero && c.Z.IsZero && DyVec.Dot(n, normal).Sign > 0;
                }
                case Kind.Triangle:
                    s = Dy.Max(DyVec.Dot(p, n), Dy.Max(DyVec.Dot(DyVec.From(Q), n), DyVec.Dot(DyVec.From(H), n)));
                    return true;
                case Kind.Capsule:
                    s = Dy.Max(DyVec.Dot(p, n), DyVec.Dot(DyVec.From(Q), n));
                    return true;
                default:
                    s = OldSupport(n);
                    return true;
            }
        }

        /// <summary>
        /// Fits a direction n so that this shape's support along sign·n can be finite: a half-space replaces it by its
        /// normal (times sign), a line projects it exactly onto the plane perpendicular to it, a ray does so only when
        /// sign·n points along it. Bounded shapes leave n alone. The result is exact (no rounding), possibly zero.
        /// </summary>
        public DyVec Fit(DyVec n, int sign)
        {
            var d = DyVec.From(Q);
            switch (Kind)
            {
                case Kind.HalfSpace: return sign > 0 ? d : -d;
                case Kind.Line: return Perpendicular(n, d);
                case Kind.Ray: return (DyVec.Dot(n, d) * sign).Sign > 0 ? Perpendicular(n, d) : n;
                default: return n;
            }
        }

        /// <summary>n − d·(n·d)/(d·d), times d·d: exactly perpendicular to d.</summary>
        private static DyVec Perpendicular(DyVec n, DyVec d) => n * d.LengthSquared - d * DyVec.Dot(n, d);

        private Dy OldSupport(DyVec n)
        {
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: return DyVec.Dot(DyVec.From(P), n);
                case Kind.Segment: return Dy.Max(DyVec.Dot(DyVec.From(P), n), DyVec.Dot(DyVec.From(Q), n));
                case Kind.Aabb:
                {
                    var s = Dy.Zero;
                    for (int j = 0; j < 3; j++) s += n[j] * (n[j].Sign >= 0 ? Get(Q, j) : Get(P, j));
                    return s;
                }
                default:
                {
                    var s = DyVec.Dot(DyVec.From(P), n);
                    for (int i = 0; i < 3; i++) s += Dy.Abs(DyVec.Dot(DyVec.From(Axes[i]), n)) * Get(H, i);
                    return s;
                }
            }
        }

        private static Dy Get(Vector3D v, int i) => i == 0 ? v.X : (i == 1 ? v.Y : v.Z);
        private static double D(Vector3D v, int i) => i == 0 ? v.X : (i == 1 ? v.Y : v.Z);

        /// <summary>The exact point of the shape at a local parameter (clamped into the shape, so it is in it exactly).</summary>
        public DyVec ExactPoint(Vector3D param, Frame f)
        {
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: return DyVec.From(P);
                case Kind.Segment: case Kind.Capsule:
                    double t = Math.Min(Math.Max(param.X, 0), 1);
                    var a = DyVec.From(P);
                    return a + (DyVec.From(Q) - a) * t;
                case Kind.Line: case Kind.Ray:
                {
                    double lt = Kind == Kind.Ray ? Math.Max(param.X, 0) : param.X;
                    return DyVec.From(P) + DyVec.From(Q) * Dy.From(lt).Times2(f.Shift);
                }
                case Kind.Triangle:
                {
                    // Barycentric (u, v) clamped exactly into u, v ≥ 0, u + v ≤ 1.
                    Dy u = Dy.Max(Dy.From(param.X), Dy.Zero), v = Dy.Max(Dy.From(param.Y), Dy.Zero), one = Dy.From(1);
                    if (u > one) { u = one; v = Dy.Zero; }
                    else if (u + v > one) v = one - u;
                    var a0 = DyVec.From(P);
                    return a0 + (DyVec.From(Q) - a0) * u + (DyVec.From(H) - a0) * v;
                }
                case Kind.HalfSpace:
                {
                    // P + u·T1 + v·T2 − w·N with T1, T2 exactly perpendicular to N and w ≥ 0: in the half-space exactly.
                    var w = Dy.Max(Dy.From(param.Z), Dy.Zero);
                    var local = _t1 * Dy.From(param.X) + _t2 * Dy.From(param.Y) - DyVec.From(Q) * w;
                    return DyVec.From(P) + local.Times2(f.Shift);
                }
                case Kind.Aabb:
                {
                    var g = f.ToGlobal(param);
                    Dy C(int j) => Dy.Min(Dy.Max(g[j], Get(P, j)), Get(Q, j));
                    return new DyVec(C(0), C(1), Planar ? Dy.Zero : C(2));
                }
                default:
                {
                    var x = DyVec.From(P);
                    for (int i = 0; i < (Planar ? 2 : 3); i++)
                    {
                        Dy l = Dy.From(D(param, i)).Times2(f.Shift);
                        Dy h = Get(H, i);
                        l = Dy.Min(Dy.Max(l, -h), h);
                        x += DyVec.From(Axes[i]) * l;
                    }
                    return x;
                }
            }
        }

        // ---- local double copy --------------------------------------------------------------------------------------

        /// <summary>Builds the local copy in frame f (call once per frame).</summary>
        public void Localize(Frame f)
        {
            _vertices.Clear();
            _edges.Clear();
            _p = f.ToLocal(DyVec.From(P));
            _q = Kind == Kind.Segment || Kind == Kind.Aabb || Kind == Kind.Capsule || Kind == Kind.Triangle ? f.ToLocal(DyVec.From(Q))
                : Kinds.IsLinear(Kind) || Kind == Kind.HalfSpace ? Q : default;
            _h = Kind == Kind.Triangle ? f.ToLocal(DyVec.From(H)) : f.LengthToLocal(H);
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: _vertices.Add(_p); _edges.Add((_p, _p)); break;
                case Kind.Segment: case Kind.Capsule: _vertices.Add(_p); _vertices.Add(_q); _edges.Add((_p, _q)); break;
                case Kind.Line: case Kind.Ray:
                    // A long stretch of the line (the configuration is ~1 in local units) for the edge–edge candidates.
                    _vertices.Add(_p);
                    _edges.Add((Kind == Kind.Ray ? _p : _p - _q * Reach, _p + _q * Reach));
                    break;
                case Kind.Triangle:
                    _vertices.Add(_p); _vertices.Add(_q); _vertices.Add(_h);
                    _edges.Add((_p, _q)); _edges.Add((_q, _h)); _edges.Add((_h, _p));
                    break;
                case Kind.HalfSpace:
                {
                    var normal = DyVec.From(Q);
                    if (Planar) { _t1 = new DyVec(-normal.Y, normal.X, Dy.Zero); _t2 = default; }
                    else
                    {
                        // The axis least aligned with n gives a well-conditioned first tangent.
                        var e = Math.Abs(Q.X) <= Math.Abs(Q.Y) && Math.Abs(Q.X) <= Math.Abs(Q.Z) ? Vector3D.UnitX
                            : Math.Abs(Q.Y) <= Math.Abs(Q.Z) ? Vector3D.UnitY : Vector3D.UnitZ;
                        _t1 = Cross(normal, DyVec.From(e));
                        _t2 = Cross(normal, _t1);
                    }
                    _lt1 = _t1.ToDouble();
                    _lt2 = _t2.ToDouble();
                    _vertices.Add(_p);
                    _edges.Add((_p - _lt1 * Reach, _p + _lt1 * Reach));
                    if (!Planar) _edges.Add((_p - _lt2 * Reach, _p + _lt2 * Reach));
                    break;
                }
                default:
                    int n = Planar ? 2 : 3;
                    for (int m = 0; m < (1 << n); m++) _vertices.Add(LocalPoint(Corner(m)));
                    for (int i = 0; i < n; i++)
                        for (int m = 0; m < (1 << n); m++)
                            if ((m & (1 << i)) == 0) _edges.Add((_vertices[m], _vertices[m | (1 << i)]));
                    break;
            }
        }

        private Vector3D Corner(int m)
        {
            var lo = Kind == Kind.Aabb ? _p : -_h;
            var hi = Kind == Kind.Aabb ? _q : _h;
            return new Vector3D((m & 1) != 0 ? hi.X : lo.X, (m & 2) != 0 ? hi.Y : lo.Y, (m & 4) != 0 ? hi.Z : lo.Z);
        }

        /// <summary>How far (local units) the line, ray and half-space stand-in edges reach from the origin or point.</summary>
        private const double Reach = 16;

        public IReadOnlyList<Vector3D> LocalVertices => _vertices;
        public IReadOnlyList<(Vector3D A, Vector3D B)> LocalEdges => _edges;

        /// <summary>
        /// Local point of a parameter (segment, capsule: t; line, ray: t in local units; triangle: barycentric (u, v);
        /// half-space: tangent coordinates and depth (u, v, w); AABB: the local point; OBB: box-frame coordinates).
        /// </summary>
        public Vector3D LocalPoint(Vector3D param) => Kind switch
        {
            Kind.Point or Kind.Sphere => _p,
            Kind.Segment or Kind.Capsule => _p + (_q - _p) * Math.Min(Math.Max(param.X, 0), 1),
            Kind.Line => _p + _q * param.X,
            Kind.Ray => _p + _q * Math.Max(param.X, 0),
            Kind.Triangle => TrianglePoint(param),
            Kind.HalfSpace => _p + _lt1 * param.X + _lt2 * param.Y - _q * Math.Max(param.Z, 0),
            Kind.Aabb => param,
            _ => _p + Axes[0] * param.X + Axes[1] * param.Y + Axes[2] * param.Z,
        };

        /// <summary>The parameter of the shape's nearest point to a local point (textbook clamps).</summary>
        public Vector3D Project(Vector3D y)
        {
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: return default;
                case Kind.Line: case Kind.Ray:
                {
                    double lt = Vector3D.Dot(y - _p, _q) / _q.LengthSquared;
                    if (!double.IsFinite(lt)) lt = 0;
                    return new Vector3D(Kind == Kind.Ray ? Math.Max(lt, 0) : lt, 0, 0);
                }
                case Kind.Triangle: return ProjectTriangle(y);
                case Kind.HalfSpace:
                {
                    var w0 = y - _p;
                    double depth = -Vector3D.Dot(w0, _q) / _q.LengthSquared;
                    double u = Vector3D.Dot(w0, _lt1) / _lt1.LengthSquared;
                    double v = Planar ? 0 : Vector3D.Dot(w0, _lt2) / _lt2.LengthSquared;
                    static double F(double x) => double.IsFinite(x) ? x : 0;
                    return new Vector3D(F(u), F(v), F(Math.Max(depth, 0)));
                }
                case Kind.Segment: case Kind.Capsule:
                    var d = _q - _p;
                    double dd = d.LengthSquared;
                    double t = dd > 0 ? Vector3D.Dot(y - _p, d) / dd : 0;
                    return new Vector3D(double.IsFinite(t) ? Math.Min(Math.Max(t, 0), 1) : 0, 0, 0);
                case Kind.Aabb:
                    return new Vector3D(Math.Min(Math.Max(y.X, _p.X), _q.X), Math.Min(Math.Max(y.Y, _p.Y), _q.Y), Math.Min(Math.Max(y.Z, _p.Z), _q.Z));
                default:
                    var w = y - _p;
                    return new Vector3D(Math.Min(Math.Max(Vector3D.Dot(w, Axes[0]), -_h.X), _h.X),
                        Math.Min(Math.Max(Vector3D.Dot(w, Axes[1]), -_h.Y), _h.Y),
                        Math.Min(Math.Max(Vector3D.Dot(w, Axes[2]), -_h.Z), _h.Z));
            }
        }

        private Vector3D TrianglePoint(Vector3D param)
        {
            double u = Math.Max(param.X, 0), v = Math.Max(param.Y, 0);
            if (u + v > 1) { double s = u + v; u /= s; v /= s; }
            return _p + (_q - _p) * u + (_h - _p) * v;
        }

        /// <summary>Barycentric (u, v) of the local triangle's point nearest y: the plane projection when inside, else the best edge point.</summary>
        private Vector3D ProjectTriangle(Vector3D y)
        {
            Vector3D e0 = _q - _p, e1 = _h - _p, w = y - _p;
            double d00 = Vector3D.Dot(e0, e0), d01 = Vector3D.Dot(e0, e1), d11 = Vector3D.Dot(e1, e1);
            double d20 = Vector3D.Dot(w, e0), d21 = Vector3D.Dot(w, e1), den = d00 * d11 - d01 * d01;
            if (den > 1e-30 * d00 * d11)
            {
                double u = (d11 * d20 - d01 * d21) / den, v = (d00 * d21 - d01 * d20) / den;
                if (u >= 0 && v >= 0 && u + v <= 1) return new Vector3D(u, v, 0);
            }
            static double T(Vector3D a, Vector3D b, Vector3D x)
            {
                var e = b - a;
                double t = Vector3D.Dot(x - a, e) / e.LengthSquared;
                return double.IsFinite(t) ? Math.Min(Math.Max(t, 0), 1) : 0;
            }
            double tab = T(_p, _q, y), tac = T(_p, _h, y), tbc = T(_q, _h, y);
            var best = new Vector3D(tab, 0, 0);
            double bd = (y - (_p + e0 * tab)).LengthSquared;
            double dac = (y - (_p + e1 * tac)).LengthSquared;
            if (dac < bd) { bd = dac; best = new Vector3D(0, tac, 0); }
            if ((y - (_q + (_h - _q) * tbc)).LengthSquared < bd) best = new Vector3D(1 - tbc, tbc, 0);
            return best;
        }

        /// <summary>A random parameter of the shape.</summary>
        public Vector3D RandomParam(Rng rng)
        {
            switch (Kind)
            {
                case Kind.Segment: return new Vector3D(rng.Unit(), 0, 0);
                case Kind.Capsule: return new Vector3D(rng.Unit(), 0, 0);
                case Kind.Line: return new Vector3D(rng.Range(-2, 2), 0, 0);
                case Kind.Ray: return new Vector3D(rng.Range(0, 3), 0, 0);
                case Kind.Triangle: { double u = rng.Unit(); return new Vector3D(u, rng.Unit() * (1 - u), 0); }
                case Kind.HalfSpace: return new Vector3D(rng.Range(-2, 2), rng.Range(-2, 2), rng.Range(0, 1));
                case Kind.Aabb: return new Vector3D(rng.Range(_p.X, _q.X), rng.Range(_p.Y, _q.Y), rng.Range(_p.Z, _q.Z));
                case Kind.Obb: return new Vector3D(rng.Range(-_h.X, _h.X), rng.Range(-_h.Y, _h.Y), rng.Range(-_h.Z, _h.Z));
                default: return default;
            }
        }

        /// <summary>
        /// Edge directions, exactly: the segment's (capsule axis's) end − start, a line's or ray's direction, a triangle's
        /// edges and (3D) its normal, the box axes with non-zero extent. A half-space has none (its normal is imposed by
        /// <see cref="Fit"/>).
        /// </summary>
        public IEnumerable<DyVec> Directions()
        {
            if (Kind == Kind.Segment || Kind == Kind.Capsule)
            {
                var d = DyVec.From(Q) - DyVec.From(P);
                if (!d.LengthSquared.IsZero) yield return d;
            }
            if (Kinds.IsLinear(Kind)) yield return DyVec.From(Q);
            if (Kind == Kind.Triangle)
            {
                DyVec a = DyVec.From(P), b = DyVec.From(Q), c = DyVec.From(H);
                foreach (var e in new[] { b - a, c - b, a - c })
                    if (!e.LengthSquared.IsZero) yield return e;
                var n = Cross(b - a, c - a);
                if (!Planar && !n.LengthSquared.IsZero) yield return n;
            }
            if (IsBox)
                for (int i = 0; i < (Planar ? 2 : 3); i++)
                    if (Kind == Kind.Obb ? Get(H, i).Sign > 0 : Get(Q, i) > Get(P, i)) yield return DyVec.From(Axes[i]);
        }

        /// <summary>max over the core of x·n in the local copy (approximate; for ranking directions).</summary>
        public double LocalSupport(Vector3D n)
        {
            switch (Kind)
            {
                // Unbounded shapes: the direction is fitted (Fit), so the support is at the origin or boundary point.
                case Kind.Point: case Kind.Sphere: case Kind.Line: case Kind.Ray: case Kind.HalfSpace: return Vector3D.Dot(_p, n);
                case Kind.Segment: case Kind.Capsule: return Math.Max(Vector3D.Dot(_p, n), Vector3D.Dot(_q, n));
                case Kind.Triangle: return Math.Max(Vector3D.Dot(_p, n), Math.Max(Vector3D.Dot(_q, n), Vector3D.Dot(_h, n)));
                case Kind.Aabb:
                    return (n.X >= 0 ? _q.X : _p.X) * n.X + (n.Y >= 0 ? _q.Y : _p.Y) * n.Y + (n.Z >= 0 ? _q.Z : _p.Z) * n.Z;
                default:
                    return Vector3D.Dot(_p, n) + _h.X * Math.Abs(Vector3D.Dot(Axes[0], n)) + _h.Y * Math.Abs(Vector3D.Dot(Axes[1], n))
                           + _h.Z * Math.Abs(Vector3D.Dot(Axes[2], n));
            }
        }

        public double LocalRadius(Frame f) => f.LengthToLocal(new Vector3D(R, 0, 0)).X;
    }

    /// <summary>A local frame: x ↦ (x − origin)·2^−Shift, exactly up to the final rounding to double.</summary>
    public sealed class Frame
    {
        public DyVec Origin { get; }
        public int Shift { get; }

        public Frame(DyVec origin, Dy scale)
        {
            Origin = origin;
            Shift = scale.IsZero ? 0 : scale.Log2;
        }

        public Vector3D ToLocal(DyVec x) => (x - Origin).Times2(-Shift).ToDouble();
        public Vector3D LengthToLocal(Vector3D v) => DyVec.From(v).Times2(-Shift).ToDouble();
        public DyVec ToGlobal(Vector3D local) => Origin + DyVec.From(local).Times2(Shift);
    }
}
