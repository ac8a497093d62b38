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
    /// are searched. A sphere is its center (its core) plus a radius; the other shapes have radius 0.
    /// </summary>
    public sealed class Core
    {
        public Kind Kind { get; }
        public bool Planar { get; }
        /// <summary>Point; segment start; sphere/OBB center; AABB min.</summary>
        public Vector3D P { get; }
        /// <summary>Segment end; AABB max.</summary>
        public Vector3D Q { get; }
        public double R { get; }
        public Vector3D[] Axes { get; } = { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ };
        public Vector3D H { get; }

        // Local double copy: (x − origin)·2^−shift.
        private Vector3D _p, _q, _h;
        private readonly List<Vector3D> _vertices = new List<Vector3D>();
        private readonly List<(Vector3D, Vector3D)> _edges = new List<(Vector3D, Vector3D)>();

        private Core(Kind kind, bool planar, Vector3D p, Vector3D q, double r, Vector3D[]? axes, Vector3D h)
        {
            Kind = kind; Planar = planar; P = p; Q = q; R = r; H = h;
            if (axes != null) Axes = axes;
        }

        /// <summary>The core of a library shape of either API (float shapes are taken in the double form they hold).</summary>
        public static Core Of(object shape)
        {
            if (!(shape is Vector3D || shape is Vector2D || shape.GetType().Namespace == "ProximityLib.Double")) shape = Shapes.Widen(shape);
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
                _ => throw new ArgumentException(shape.GetType().FullName),
            };
        }

        public bool IsSolid => Kind == Kind.Sphere || Kind == Kind.Aabb || Kind == Kind.Obb;
        public bool IsBox => Kind == Kind.Aabb || Kind == Kind.Obb;

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
                case Kind.Point: case Kind.Sphere: yield return DyVec.From(P); break;
                case Kind.Segment: yield return DyVec.From(P); yield return DyVec.From(Q); break;
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
            return Kind == Kind.Sphere ? m + R : m;
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

        /// <summary>Is x within tol of the shape (for a segment: of its point at parameter t)? Exact.</summary>
        public bool Contains(DyVec x, double t, Dy tol)
        {
            if (Planar && !x.Z.IsZero) return false;
            if (Kind == Kind.Segment && !(t >= 0 && t <= 1)) return false;
            var e2 = ExcessSquared(x, t);
            return Kind == Kind.Sphere ? DyMath.AtLeastRoot((Dy)R + tol, e2) : DyMath.AtLeastRoot(tol, e2);
        }

        /// <summary>max over the core of x·n, exactly (the radius is added by the caller).</summary>
        public Dy Support(DyVec n)
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
                case Kind.Segment:
                    double t = Math.Min(Math.Max(param.X, 0), 1);
                    var a = DyVec.From(P);
                    return a + (DyVec.From(Q) - a) * t;
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
            _q = Kind == Kind.Segment || Kind == Kind.Aabb ? f.ToLocal(DyVec.From(Q)) : default;
            _h = f.LengthToLocal(H);
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: _vertices.Add(_p); _edges.Add((_p, _p)); break;
                case Kind.Segment: _vertices.Add(_p); _vertices.Add(_q); _edges.Add((_p, _q)); break;
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

        public IReadOnlyList<Vector3D> LocalVertices => _vertices;
        public IReadOnlyList<(Vector3D A, Vector3D B)> LocalEdges => _edges;

        /// <summary>Local point of a parameter (segment: t; AABB: the local point; OBB: box-frame coordinates).</summary>
        public Vector3D LocalPoint(Vector3D param) => Kind switch
        {
            Kind.Point or Kind.Sphere => _p,
            Kind.Segment => _p + (_q - _p) * Math.Min(Math.Max(param.X, 0), 1),
            Kind.Aabb => param,
            _ => _p + Axes[0] * param.X + Axes[1] * param.Y + Axes[2] * param.Z,
        };

        /// <summary>The parameter of the shape's nearest point to a local point (textbook clamps).</summary>
        public Vector3D Project(Vector3D y)
        {
            switch (Kind)
            {
                case Kind.Point: case Kind.Sphere: return default;
                case Kind.Segment:
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

        /// <summary>A random parameter of the shape.</summary>
        public Vector3D RandomParam(Rng rng)
        {
            switch (Kind)
            {
                case Kind.Segment: return new Vector3D(rng.Unit(), 0, 0);
                case Kind.Aabb: return new Vector3D(rng.Range(_p.X, _q.X), rng.Range(_p.Y, _q.Y), rng.Range(_p.Z, _q.Z));
                case Kind.Obb: return new Vector3D(rng.Range(-_h.X, _h.X), rng.Range(-_h.Y, _h.Y), rng.Range(-_h.Z, _h.Z));
                default: return default;
            }
        }

        /// <summary>Edge directions, exactly: the segment's end − start, the box axes with non-zero extent.</summary>
        public IEnumerable<DyVec> Directions()
        {
            if (Kind == Kind.Segment)
            {
                var d = DyVec.From(Q) - DyVec.From(P);
                if (!d.LengthSquared.IsZero) yield return d;
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
                case Kind.Point: case Kind.Sphere: return Vector3D.Dot(_p, n);
                case Kind.Segment: return Math.Max(Vector3D.Dot(_p, n), Vector3D.Dot(_q, n));
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
