using System;
using System.Collections.Generic;
using System.Linq;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// The exact reference of a ray cast (docs/pairs.md, "Ray casts"): the ray as stored (origin o, the normalised and
    /// rounded direction d, taken as exact; a parameter t is the point o + t·d, so t is the distance to within
    /// |1 − |d|| ≤ 2^−52) against the target as stored. Every decision is exact dyadic arithmetic (roots compared on
    /// squares, <see cref="Surd"/>). The accuracy contract checked against it is backward-stable: the answer must be the
    /// exact answer for the target perturbed by at most δ (and T by its own rounding ρ), where the caller picks
    /// δ = B·U. How that reads per kind of target:
    /// <list type="bullet">
    /// <item>Solids (sphere/circle, capsule, box, half-space, the 2D triangle): X_δ is the solid grown (δ &gt; 0) or shrunk
    /// (δ &lt; 0) by |δ| (boxes, half-spaces and triangles per face, a triangle also within its bounding box grown by δ).
    /// A hit needs t*(X_δ) ≤ T ≤ t*(X_−δ) (no solid material skipped, no hit before the ray comes within δ) and
    /// o + T·d in X_δ; a miss needs the ray to miss X_−δ; StartsInside must be true when o is in X_−δ and false when
    /// o is outside X_δ. At a well-conditioned hit the interval is t* ± δ/cos (cos the incidence cosine); at a graze
    /// it is one-sided, and what remains is the backward form.</item>
    /// <item>Zero-thickness 3D targets (point, segment, line, ray; a degenerate 3D triangle's edges; the 2D point): hit
    /// when the ray passes within tol = 2^−40·m (<c>PassThroughTolerance</c>, m the documented local scale) of the
    /// documented candidates (the origin on the target, an endpoint or a target ray's origin on the ray, the lines'
    /// closest approach); the reference evaluates each candidate exactly with tol·(1 ∓ 2^−10) (certain / possible, a
    /// band far wider than the rounding of m and of the residuals). A certain candidate forces a hit no later than it;
    /// a hit needs a possible candidate no later than T and o + T·d within √2·tol of the target. Nearly parallel
    /// closest approaches (sin² &lt; 2^−20), whose crossing point the rounding moves far along, are checked by the
    /// backward form only.</item>
    /// <item>2D segments, lines and rays (walls) and the 3D triangle (two-sided, zero thickness): a crossing whose
    /// endpoints or edges are farther than δ from it, with the origin farther than δ from the wall or plane, must be
    /// hit with |T − t*| ≤ δ/sin (sin the crossing angle; a 3D triangle: F·δ/cos, F the tilt factor of its plane when
    /// its vertices move by δ, large for slivers; a graze also up to 2·tol/cos early, edge-on); a ray exactly along a
    /// wall or in the triangle's plane is answered as the in-plane solid (the 3D triangle) or the first point along the
    /// wall; any hit needs o + T·d within δ of the target (3D triangle: plus the edge-on path's tolerance and, for a
    /// sliver, min(B·u·m·F/cos, its altitude): its barycentric weights' rounding over its area).</item>
    /// </list>
    /// </summary>
    public abstract class CastRef
    {
        protected readonly DyVec O, D;
        protected readonly Dy DD;

        protected CastRef(DyVec o, DyVec d) { O = o; D = d; DD = d.LengthSquared; }

        /// <summary>Whether the target is a solid (the ray can start inside it).</summary>
        public abstract bool IsSolid { get; }

        /// <summary>The exact first hit of the unperturbed target (null: a miss, or unknown for a band case).</summary>
        public abstract Surd? Nominal { get; }

        /// <summary>
        /// The problems of an answer (hit, T, StartsInside) at perturbation δ and T rounding ρ (both ≥ 0), as text; empty
        /// when it is acceptable. <paramref name="insideUnknown"/>: the answer cannot say StartsInside (the batch API's 0).
        /// </summary>
        public abstract void CheckT(bool hit, Dy t, bool startsInside, Dy delta, Dy rho, List<string> problems, bool insideUnknown = false);

        /// <summary>The exact t* to measure E against when the hit is well-conditioned at δ (condition number ≤ 2), else null.</summary>
        public abstract Surd? WellConditioned(Dy delta);

        /// <summary>Is x on the target within tol (a solid: within tol of its boundary, from either side)?</summary>
        public abstract bool OnTarget(DyVec x, Dy tol);

        /// <summary>The exact facts, for messages.</summary>
        public abstract string Describe(Dy delta);

        protected DyVec At(Dy t) => O + D * t;

        protected static string Show(Surd? s) => s.HasValue ? s.Value.ToDouble().ToString("R") : "none";

        /// <summary>
        /// The reference of a library target (either API's shape; float shapes in the double form they hold).
        /// <paramref name="relative"/>: a half-space's perturbation also grows by this much per unit of distance from the
        /// origin (B·u: its stored normal and the ray's direction are rounded, which tilts the boundary relative to the
        /// ray by that angle, so a far graze may move or vanish).
        /// </summary>
        public static CastRef For(object target, DyVec o, DyVec d, Dy relative = default)
        {
            var core = Core.Of(target);
            DyVec P = DyVec.From(core.P), Q = DyVec.From(core.Q), H = DyVec.From(core.H);
            switch (core.Kind)
            {
                case Kind.Point: return new PassRef(o, d, new[] { PassRef.Piece.Point(P) });
                case Kind.Segment:
                    if (!core.Planar) return new PassRef(o, d, new[] { PassRef.Piece.Segment(P, Q) });
                    return core.P == core.Q ? new PassRef(o, d, new[] { PassRef.Piece.Point(P) }) : new WallRef(o, d, P, Q - P, Kind.Segment);
                case Kind.Line: case Kind.Ray:
                    if (!core.Planar) return new PassRef(o, d, new[] { PassRef.Piece.Linear(P, Q, core.Kind == Kind.Ray) });
                    return new WallRef(o, d, P, Q, core.Kind);
                case Kind.Sphere: return new SolidRef(o, d, new Rounded(P, P, core.R), core);
                case Kind.Capsule: return new SolidRef(o, d, new Rounded(P, Q, core.R), core);
                case Kind.HalfSpace:
                {
                    var poly = new Polytope(o, relative);
                    poly.Add(Q, DyVec.Dot(Q, P), grows: true);
                    return new SolidRef(o, d, poly, core);
                }
                case Kind.Aabb:
                {
                    var poly = new Polytope();
                    for (int i = 0; i < (core.Planar ? 2 : 3); i++)
                    {
                        var a = Axis(i);
                        poly.Add(a, Q[i]);
                        poly.Add(-a, -P[i]);
                    }
                    return new SolidRef(o, d, poly, core);
                }
                case Kind.Obb:
                {
                    var poly = new Polytope();
                    for (int i = 0; i < (core.Planar ? 2 : 3); i++)
                    {
                        var a = DyVec.From(core.Axes[i]);
                        var c = DyVec.Dot(a, P);
                        poly.Add(a, c + H[i]);
                        poly.Add(-a, -c + H[i]);
                    }
                    return new SolidRef(o, d, poly, core);
                }
                default:
                {
                    var n = Roots.Cross(Q - P, H - P);
                    if (core.Planar)
                    {
                        if (!n.Z.IsZero) return new SolidRef(o, d, Polytope.Triangle(P, Q, H, n), core);
                        // Collinear or coincident: the segment between the two vertices farthest apart, or the point.
                        var pairs = new[] { (P, Q), (Q, H), (H, P) };
                        var (x, y) = pairs.OrderByDescending(p => (p.Item2 - p.Item1).LengthSquared).First();
                        return (y - x).LengthSquared.IsZero ? new PassRef(o, d, new[] { PassRef.Piece.Point(x) }) : new WallRef(o, d, x, y - x, Kind.Segment);
                    }
                    if (n.LengthSquared.IsZero)
                        return new PassRef(o, d, new[] { PassRef.Piece.Segment(P, Q), PassRef.Piece.Segment(Q, H), PassRef.Piece.Segment(H, P) });
                    return new TriangleRef(o, d, P, Q, H, relative);
                }
            }
        }

        private static DyVec Axis(int i) => i == 0 ? new DyVec(1, 0, 0) : i == 1 ? new DyVec(0, 1, 0) : new DyVec(0, 0, 1);

    }

    // ---- solids ------------------------------------------------------------------------------------------------------

    /// <summary>A closed convex solid with a signed perturbation δ: X_δ.</summary>
    public abstract class Solid
    {
        public abstract bool Contains(DyVec x, Dy delta);

        /// <summary>The first t ≥ 0 with o + t·d in X_δ (0 when o is in it); null when the ray misses it.</summary>
        public abstract Surd? FirstHit(DyVec o, DyVec d, Dy delta);
    }

    /// <summary>
    /// An intersection of half-spaces a·x ≤ b; X_δ moves each plane by δ·L, L ≥ |a| (within 2^−60); a plane added with
    /// grows moves by sign(δ)·relative·|x − o|·L more (a tilt by the angle relative about the origin o, bounded).
    /// </summary>
    public sealed class Polytope : Solid
    {
        private readonly List<(DyVec A, Dy B, Dy L, bool Grows)> _planes = new List<(DyVec, Dy, Dy, bool)>();
        private readonly DyVec _o;
        private readonly Dy _relative;

        public Polytope(DyVec o = default, Dy relative = default) { _o = o; _relative = relative; }

        public void Add(DyVec a, Dy b, bool grows = false) => _planes.Add((a, b, Roots.SqrtUpper(a.LengthSquared), grows));

        private Dy Offset(Dy delta, Dy l, bool grows, Dy distance) =>
            delta * l + (grows && !_relative.IsZero ? Dy.From(delta.Sign) * _relative * distance * l : Dy.Zero);

        /// <summary>
        /// A solid triangle (2D, or the in-plane triangle of a 3D one with normal n): its three edges' inner sides, and its
        /// bounding box, so that a grown sliver does not reach past its corners by more than δ per axis.
        /// </summary>
        public static Polytope Triangle(DyVec a, DyVec b, DyVec c, DyVec n)
        {
            var poly = new Polytope();
            foreach (var (p, q) in new[] { (a, b), (b, c), (c, a) })
            {
                // Inside: (e × (x − p))·n = (x − p)·(n × e) ≥ 0, i.e. α·x ≤ α·p with α = e × n (|α| = |e|·|n|).
                var alpha = Roots.Cross(q - p, n);
                poly.Add(alpha, DyVec.Dot(alpha, p));
            }
            for (int j = 0; j < 3; j++)
            {
                Dy lo = Dy.Min(a[j], Dy.Min(b[j], c[j])), hi = Dy.Max(a[j], Dy.Max(b[j], c[j]));
                var e = j == 0 ? new DyVec(1, 0, 0) : j == 1 ? new DyVec(0, 1, 0) : new DyVec(0, 0, 1);
                if (j == 2 && lo.IsZero && hi.IsZero && n.X.IsZero && n.Y.IsZero) continue; // a 2D triangle: no z faces
                poly.Add(e, hi);
                poly.Add(-e, -lo);
            }
            return poly;
        }

        public override bool Contains(DyVec x, Dy delta)
        {
            var distance = _relative.IsZero ? Dy.Zero : Roots.SqrtUpper((x - _o).LengthSquared);
            return _planes.All(p => DyVec.Dot(p.A, x) <= p.B + Offset(delta, p.L, p.Grows, distance));
        }

        public override Surd? FirstHit(DyVec o, DyVec d, Dy delta)
        {
            Dy enterN = Dy.Zero, enterD = Dy.From(1);
            Dy exitN = Dy.Zero, exitD = Dy.Zero; // exitD = 0: +∞
            var speed = _relative.IsZero ? Dy.Zero : Roots.SqrtUpper(d.LengthSquared);
            foreach (var (a, b, l, grows) in _planes)
            {
                // Along the ray |x − o| = t·|d| (o is the ray's origin here), so a growing plane changes the rate.
                var g0 = DyVec.Dot(a, o) - b - delta * l;
                var rate = DyVec.Dot(a, d) - Offset(delta, l, grows, speed) + delta * l;
                if (rate.IsZero)
                {
                    if (g0.Sign > 0) return null;
                    continue;
                }
                // g0 + rate·t ≤ 0: t ≥ −g0/rate when rate < 0, t ≤ −g0/rate when rate > 0.
                Dy n = -g0, den = rate;
                if (den.Sign < 0) { n = -n; den = -den; }
                if (rate.Sign < 0) { if (n * enterD > enterN * den) { enterN = n; enterD = den; } }
                else if (exitD.IsZero || n * exitD < exitN * den) { exitN = n; exitD = den; }
            }
            if (!exitD.IsZero && enterN * exitD > exitN * enterD) return null;
            return Surd.Ratio(enterN, enterD);
        }
    }

    /// <summary>A capsule (a ball when the axis ends coincide): the points within R of [A, B]; X_δ has radius R + δ (empty below 0).</summary>
    public sealed class Rounded : Solid
    {
        private readonly DyVec _a, _b;
        private readonly Dy _r;

        public Rounded(DyVec a, DyVec b, Dy r) { _a = a; _b = b; _r = r; }

        public override bool Contains(DyVec x, Dy delta)
        {
            var rho = _r + delta;
            if (rho.Sign < 0) return false;
            var (n, den) = Roots.SegmentDistance2(x, _a, _b);
            return n <= rho.Square() * den;
        }

        public override Surd? FirstHit(DyVec o, DyVec d, Dy delta)
        {
            var rho = _r + delta;
            if (rho.Sign < 0) return null;
            if (Contains(o, delta)) return Surd.Zero;
            Surd? best = Ball(o, d, _a, rho);
            var other = Ball(o, d, _b, rho);
            if (other.HasValue && (!best.HasValue || other.Value.CompareTo(best.Value) < 0)) best = other;
            var side = Side(o, d, rho);
            if (side.HasValue && (!best.HasValue || side.Value.CompareTo(best.Value) < 0)) best = side;
            return best;
        }

        /// <summary>The entry into the ball (c, ρ) from outside: (−b − √(b² − a·c))/a.</summary>
        private static Surd? Ball(DyVec o, DyVec d, DyVec center, Dy rho)
        {
            var w = o - center;
            var a = d.LengthSquared;
            var b = DyVec.Dot(w, d);
            var c = w.LengthSquared - rho.Square();
            if (b.Sign >= 0 || c.Sign <= 0) return null;
            var disc = b.Square() - a * c;
            if (disc.Sign < 0) return null;
            return new Surd(-b, Dy.From(-1), disc, a);
        }

        /// <summary>
        /// The entry into the infinite cylinder around the axis, kept when its axis parameter lies in [0, 1]: the same
        /// quadratic on the components across the axis, scaled by |e|² so they stay dyadic.
        /// </summary>
        private Surd? Side(DyVec o, DyVec d, Dy rho)
        {
            var e = _b - _a;
            var ee = e.LengthSquared;
            if (ee.IsZero) return null;
            var w = o - _a;
            Dy we = DyVec.Dot(w, e), de = DyVec.Dot(d, e);
            var W = w * ee - e * we;
            var V = d * ee - e * de;
            var a = V.LengthSquared;
            var b = DyVec.Dot(W, V);
            var c = W.LengthSquared - rho.Square() * ee.Square();
            if (a.IsZero || b.Sign >= 0 || c.Sign <= 0) return null;
            var disc = b.Square() - a * c;
            if (disc.Sign < 0) return null;
            // u = (we + t·de)/ee with t = (−b − √disc)/a: a·we − b·de − de·√disc in [0, a·ee].
            var x = a * we - b * de;
            if (Surd.SignOf(x, -de, disc) < 0 || Surd.SignOf(x - a * ee, -de, disc) > 0) return null;
            return new Surd(-b, Dy.From(-1), disc, a);
        }
    }

    /// <summary>The reference of a solid target.</summary>
    public sealed class SolidRef : CastRef
    {
        private readonly Solid _s;
        public Core Core { get; }
        private readonly Surd? _nominal;
        private readonly Dictionary<Dy, (Surd? Lo, Surd? Hi)> _cache = new Dictionary<Dy, (Surd?, Surd?)>();

        public SolidRef(DyVec o, DyVec d, Solid s, Core core) : base(o, d)
        {
            _s = s; Core = core;
            _nominal = s.FirstHit(o, d, Dy.Zero);
        }

        public Solid Shape => _s;
        public override bool IsSolid => true;
        public override Surd? Nominal => _nominal;

        /// <summary>The first hits of the grown and of the shrunk solid.</summary>
        public (Surd? Lo, Surd? Hi) Interval(Dy delta)
        {
            if (!_cache.TryGetValue(delta, out var v))
                _cache[delta] = v = (_s.FirstHit(O, D, delta), _s.FirstHit(O, D, -delta));
            return v;
        }

        public override void CheckT(bool hit, Dy t, bool startsInside, Dy delta, Dy rho, List<string> problems, bool insideUnknown = false)
        {
            var (lo, hi) = Interval(delta);
            bool inGrown = _s.Contains(O, delta), inShrunk = _s.Contains(O, -delta);
            if (!insideUnknown)
            {
                if (startsInside && !inGrown) problems.Add($"StartsInside, but the origin is outside the target grown by δ = {delta.ToDouble():G4}");
                if (!startsInside && inShrunk) problems.Add($"StartsInside false, but the origin lies inside the target shrunk by δ = {delta.ToDouble():G4}");
            }
            if (startsInside) return;
            if (hit)
            {
                if (!lo.HasValue) problems.Add($"hit at T = {t.ToDouble():R}, but the ray misses the target grown by δ = {delta.ToDouble():G4}");
                else if (lo.Value.CompareTo(t + rho) > 0)
                    problems.Add($"T = {t.ToDouble():R} is before the first hit {Show(lo)} of the target grown by δ = {delta.ToDouble():G4} (ρ = {rho.ToDouble():G4})");
                if (hi.HasValue && hi.Value.CompareTo(t - rho) < 0)
                    problems.Add($"T = {t.ToDouble():R} is after the first hit {Show(hi)} of the target shrunk by δ = {delta.ToDouble():G4}: the ray went through the solid (ρ = {rho.ToDouble():G4})");
                if (!_s.Contains(At(t), delta + rho * Roots.SqrtUpper(DD)))
                    problems.Add($"o + T·d is outside the target grown by δ + ρ = {(delta + rho).ToDouble():G4}");
            }
            else if (hi.HasValue)
                problems.Add($"a miss, but the ray enters the target shrunk by δ = {delta.ToDouble():G4} at t = {Show(hi)}");
        }

        public override Surd? WellConditioned(Dy delta)
        {
            var (lo, hi) = Interval(delta);
            if (!_nominal.HasValue || !lo.HasValue || !hi.HasValue || delta.IsZero) return null;
            // Condition number (t_hi − t_lo)/(2δ) ≤ 2.
            double width = Difference(hi.Value, lo.Value, delta);
            return width <= 4 ? _nominal : null;
        }

        /// <summary>(a − b)/unit, approximately.</summary>
        public static double Difference(Surd a, Surd b, Dy unit)
        {
            var x = (a.P + a.Q * Roots.Sqrt(a.D, 200)) * b.R - (b.P + b.Q * Roots.Sqrt(b.D, 200)) * a.R;
            return Dy.Ratio(x, a.R * b.R * unit);
        }

        public override bool OnTarget(DyVec x, Dy tol) => _s.Contains(x, tol) && !_s.Contains(x, -tol);

        public bool Contains(DyVec x, Dy delta) => _s.Contains(x, delta);

        public override string Describe(Dy delta)
        {
            var (lo, hi) = Interval(delta);
            return $"exact first hit {Show(_nominal)}; grown by δ = {delta.ToDouble():G4}: {Show(lo)}, shrunk: {Show(hi)}; origin {(_s.Contains(O, -delta) ? "inside" : _s.Contains(O, delta) ? "within δ of the boundary" : "outside")}";
        }
    }

    // ---- zero-thickness targets with the pass-through tolerance -----------------------------------------------------

    /// <summary>Points, 3D segments, lines and rays: the library's documented candidates, each evaluated exactly.</summary>
    public sealed class PassRef : CastRef
    {
        /// <summary>2^−40: <c>PassThroughTolerance</c>.</summary>
        public static readonly Dy Tolerance = Dy.Pow2(-40);
        /// <summary>The band around tol: 2^−10 relative.</summary>
        public static readonly double Band = 1.0 / 1024;

        public sealed class Piece
        {
            public Kind Kind;
            public DyVec A, B; // point; segment ends; linear origin and direction
            public bool Half;  // a ray target
            public static Piece Point(DyVec p) => new Piece { Kind = Kind.Point, A = p };
            public static Piece Segment(DyVec a, DyVec b) => new Piece { Kind = Kind.Segment, A = a, B = b };
            public static Piece Linear(DyVec p, DyVec e, bool half) => new Piece { Kind = half ? Kind.Ray : Kind.Line, A = p, B = e, Half = half };
        }

        private readonly struct Candidate
        {
            public readonly Surd T;
            public readonly bool Certain, Possible;
            public readonly string What;
            /// <summary>How far a δ perturbation moves it along the ray, per δ: 1, or 1/sin θ for the closest approach of two lines at angle θ.</summary>
            public readonly double Kappa;
            public Candidate(Surd t, bool certain, bool possible, string what, double kappa = 1)
            {
                T = t; Certain = certain; Possible = possible; What = what; Kappa = kappa;
            }
        }

        private readonly Piece[] _pieces;
        private readonly List<Candidate> _candidates = new List<Candidate>();
        /// <summary>A closest approach too close to parallel for its rounding (only the backward checks apply).</summary>
        private bool _ill;
        /// <summary>The largest tolerance of any piece (its upper band), for the backward checks.</summary>
        private Dy _tolMax = Dy.Zero;

        public PassRef(DyVec o, DyVec d, Piece[] pieces) : base(o, d)
        {
            _pieces = pieces;
            foreach (var p in pieces) Evaluate(p);
        }

        public override bool IsSolid => false;

        public override Surd? Nominal
        {
            get
            {
                Surd? best = null;
                foreach (var c in _candidates)
                    if (c.Possible && (!best.HasValue || c.T.CompareTo(best.Value) < 0)) best = c.T;
                return best;
            }
        }

        private static double MaxAbsD(DyVec v) => Roots.MaxAbs(v).ToDouble();

        private (Dy Lo, Dy Hi) Tol(double m)
        {
            var tol = Tolerance * Dy.From(m);
            var lo = tol * Dy.From(1 - Band);
            var hi = tol * Dy.From(1 + Band);
            if (hi > _tolMax) _tolMax = hi;
            return (lo, hi);
        }

        /// <summary>A point x = X/s (s &gt; 0) on the target as a candidate: t = (x − o)·d/|d|² clamped at 0, within tol of the ray's line and t ≥ −tol.</summary>
        private void PointCandidate(DyVec X, Dy s, Dy lo, Dy hi, string what, double kappa = 1)
        {
            var w = X - O * s;
            var wd = DyVec.Dot(w, D);
            var res = w.LengthSquared * DD - wd.Square(); // residual² · |d|² · s²
            bool Pass(Dy tol) => wd >= -(tol * s * DD) && res <= tol.Square() * DD * s.Square();
            bool possible = Pass(hi);
            if (!possible) return;
            var t = wd.Sign > 0 ? Surd.Ratio(wd, s * DD) : Surd.Zero;
            _candidates.Add(new Candidate(t, Pass(lo), true, what, kappa));
        }

        /// <summary>1/sin θ of two directions (|e|·|d|/|e × d|), for the closest approach's sensitivity.</summary>
        private double Kappa(DyVec e, Dy den) => Math.Min(Math.Sqrt(Dy.Ratio(e.LengthSquared * DD, den)), Math.ScaleB(1, 60));

        private void Evaluate(Piece p)
        {
            var one = Dy.From(1);
            switch (p.Kind)
            {
                case Kind.Point:
                {
                    var (lo, hi) = Tol(MaxAbsD(p.A - O));
                    PointCandidate(p.A, one, lo, hi, "the point");
                    break;
                }
                case Kind.Segment:
                {
                    var (lo, hi) = Tol(Math.Max(MaxAbsD(p.A - O), MaxAbsD(p.B - O)));
                    if (Roots.NearSegment(O, p.A, p.B, hi))
                        _candidates.Add(new Candidate(Surd.Zero, Roots.NearSegment(O, p.A, p.B, lo), true, "the origin on the segment"));
                    PointCandidate(p.A, one, lo, hi, "the segment's start");
                    PointCandidate(p.B, one, lo, hi, "the segment's end");
                    var e = p.B - p.A;
                    var ed = Roots.Cross(e, D);
                    var den = ed.LengthSquared;
                    if (den.IsZero) break;
                    if (den < Dy.Pow2(-20) * e.LengthSquared * DD) { _ill = true; break; }
                    var num = -DyVec.Dot(Roots.Cross(p.A - O, D), ed);
                    // s = num/den strictly inside (0, 1) for the library; certain only away from the ends.
                    if (num.Sign <= 0 || num >= den) break;
                    var X = p.A * den + e * num;
                    var margin = den * Dy.Pow2(-30);
                    int before = _candidates.Count;
                    PointCandidate(X, den, lo, hi, "the closest approach", Kappa(e, den));
                    if (_candidates.Count > before && (num < margin || num > den - margin))
                    {
                        var c = _candidates[before];
                        _candidates[before] = new Candidate(c.T, false, true, c.What, c.Kappa);
                    }
                    break;
                }
                default:
                {
                    var w = p.A - O;
                    var e = p.B;
                    var ed = Roots.Cross(e, D);
                    var den = ed.LengthSquared;
                    var ends = e.LengthSquared * DD;
                    // The library takes directions with |e × d|² below 2^−90 (rounded) as parallel: no crossing, and a local
                    // scale of |p − o| alone. Below 2^−94 it surely does, above 2^−86 surely not; in between either.
                    bool parallel = den < Dy.Pow2(-94) * ends, maybeParallel = den < Dy.Pow2(-86) * ends;
                    double mw = MaxAbsD(w), m = mw;
                    Dy num = Dy.Zero;
                    bool skew = !den.IsZero && !parallel;
                    if (skew)
                    {
                        if (den < Dy.Pow2(-20) * ends) _ill = true;
                        num = -DyVec.Dot(Roots.Cross(w, D), ed);
                        if (p.Half && num.Sign < 0) num = Dy.Zero;
                        m = Math.Max(m, Dy.Ratio(Roots.MaxAbs(w * den + e * num), den));
                    }
                    var (lo, hi) = Tol(m);
                    if (maybeParallel) lo = Tol(mw).Lo; // the library's scale may be |p − o| alone
                    if (Roots.NearLinear(O, p.A, e, p.Half, hi))
                        _candidates.Add(new Candidate(Surd.Zero, Roots.NearLinear(O, p.A, e, p.Half, lo), true, "the origin on the target"));
                    if (skew)
                    {
                        int before = _candidates.Count;
                        PointCandidate(p.A * den + e * num, den, lo, hi, "the closest approach", Kappa(e, den));
                        // Nearly parallel: the library's rounded approach can lie anywhere along the overlap, so it forces nothing.
                        if (_ill && _candidates.Count > before)
                        {
                            var c = _candidates[before];
                            _candidates[before] = new Candidate(c.T, false, true, c.What, c.Kappa);
                        }
                    }
                    if (p.Half && maybeParallel)
                    {
                        int before = _candidates.Count;
                        PointCandidate(p.A, one, lo, hi, "the target ray's origin");
                        if (!parallel && _candidates.Count > before)
                        {
                            var c = _candidates[before];
                            _candidates[before] = new Candidate(c.T, false, true, c.What, c.Kappa);
                        }
                    }
                    break;
                }
            }
        }

        public override void CheckT(bool hit, Dy t, bool startsInside, Dy delta, Dy rho, List<string> problems, bool insideUnknown = false)
        {
            Surd? certain = null, possible = null;
            string certainWhat = "";
            double certainKappa = 1, possibleKappa = 1;
            foreach (var c in _candidates)
            {
                if (c.Certain && (!certain.HasValue || c.T.CompareTo(certain.Value) < 0)) { certain = c.T; certainWhat = c.What; certainKappa = c.Kappa; }
                if (c.Possible && (!possible.HasValue || c.T.CompareTo(possible.Value) < 0)) { possible = c.T; possibleKappa = c.Kappa; }
            }
            if (!hit)
            {
                if (certain.HasValue) problems.Add($"a miss, but {certainWhat} passes within tol·(1 − 2^−10) at t = {Show(certain)}");
                return;
            }
            var lateBy = delta * Dy.From(certainKappa) + rho;
            if (certain.HasValue && certain.Value.CompareTo(t - lateBy) < 0)
                problems.Add($"T = {t.ToDouble():R} is after {certainWhat}, within tol·(1 − 2^−10) at t = {Show(certain)} (allowed κ·δ + ρ = {lateBy.ToDouble():G4})");
            if (!_ill)
            {
                if (!possible.HasValue) problems.Add($"hit at T = {t.ToDouble():R}, but no documented candidate passes within tol·(1 + 2^−10)");
                else if (possible.Value.CompareTo(t + delta * Dy.From(possibleKappa) + rho) > 0)
                    problems.Add($"T = {t.ToDouble():R} is before every candidate within tol·(1 + 2^−10) (the first at {Show(possible)})");
            }
            var reach = _tolMax * Dy.From(1.4142135623730951 * (1 + Band)) + delta + rho;
            if (!OnTarget(At(t), reach)) problems.Add($"o + T·d is farther than √2·tol + δ + ρ = {reach.ToDouble():G4} from the target");
        }

        public override Surd? WellConditioned(Dy delta)
        {
            if (_ill || _candidates.Count == 0 || _candidates.Any(c => !c.Certain || c.Kappa > 2)) return null;
            return Nominal;
        }

        /// <summary>Whether the ray's closest approach is too close to parallel for the candidate checks.</summary>
        public bool Ill => _ill;

        /// <summary>The largest tolerance (upper band) of the pieces.</summary>
        public Dy TolMax => _tolMax;

        public override bool OnTarget(DyVec x, Dy tol)
        {
            foreach (var p in _pieces)
            {
                bool near = p.Kind switch
                {
                    Kind.Point => (x - p.A).LengthSquared <= tol.Square(),
                    Kind.Segment => Roots.NearSegment(x, p.A, p.B, tol),
                    _ => Roots.NearLinear(x, p.A, p.B, p.Half, tol),
                };
                if (near) return true;
            }
            return false;
        }

        public override string Describe(Dy delta) =>
            $"tol ≤ {_tolMax.ToDouble():G4}; candidates: " + (_candidates.Count == 0 ? "none" :
                string.Join(", ", _candidates.Select(c => $"{c.What} at {c.T.ToDouble():R} ({(c.Certain ? "certain" : "in the band")})")))
            + (_ill ? "; nearly parallel (backward checks only)" : "");
    }

    // ---- 2D walls ----------------------------------------------------------------------------------------------------

    /// <summary>A 2D segment [p, p + e], line or ray (p, e) that the ray crosses.</summary>
    public sealed class WallRef : CastRef
    {
        private readonly DyVec _p, _e;
        private readonly Kind _kind;
        private readonly Dy _ee, _fe, _fp;
        private readonly Surd? _nominal;

        public WallRef(DyVec o, DyVec d, DyVec p, DyVec e, Kind kind) : base(o, d)
        {
            _p = p; _e = e; _kind = kind;
            _ee = e.LengthSquared;
            _fe = Cross2(d, e);
            _fp = Cross2(d, p - o);
            _nominal = Crossing();
        }

        private static Dy Cross2(DyVec a, DyVec b) => a.X * b.Y - a.Y * b.X;

        public override bool IsSolid => false;
        public override Surd? Nominal => _nominal;

        /// <summary>Where o + t·d meets the wall first (exact): the crossing, or along the wall its first point.</summary>
        private Surd? Crossing()
        {
            if (!_fe.IsZero)
            {
                // s = −fp/fe on the wall, t = ((p − o) × e)/fe on the ray.
                var sNum = -_fp;
                bool ahead = (sNum * _fe).Sign >= 0;
                if (_kind == Kind.Segment && (!ahead || Dy.Abs(sNum) > Dy.Abs(_fe))) return null;
                if (_kind == Kind.Ray && !ahead) return null;
                var t = Surd.Ratio(Cross2(_p - O, _e), _fe);
                return t.CompareTo(Dy.Zero) >= 0 ? t : (Surd?)null;
            }
            if (!_fp.IsZero) return null;
            // Along the wall: the origin on it gives 0, else the first point ahead.
            var gp = DyVec.Dot(D, _p - O);
            switch (_kind)
            {
                case Kind.Line: return Surd.Zero;
                case Kind.Ray:
                    if (DyVec.Dot(O - _p, _e).Sign >= 0) return Surd.Zero;
                    return gp.Sign > 0 ? Surd.Ratio(gp, DD) : (Surd?)null;
                default:
                    var gq = DyVec.Dot(D, _p + _e - O);
                    if (gp.Sign <= 0 && gq.Sign >= 0 || gp.Sign >= 0 && gq.Sign <= 0) return Surd.Zero;
                    if (gp.Sign < 0) return null;
                    return Surd.Ratio(Dy.Min(gp, gq), DD);
            }
        }

        /// <summary>Is the crossing robust at δ (the wall's ends and the origin farther than δ from it, the angle not below 2^−30)?</summary>
        private bool Robust(Dy delta)
        {
            if (!_nominal.HasValue || _fe.IsZero) return false;
            if (_fe.Square() < Dy.Pow2(-60) * _ee * DD) return false;
            if (Cross2(_e, _p - O).Square() <= delta.Square() * _ee) return false;
            var d2 = delta.Square() * DD;
            switch (_kind)
            {
                case Kind.Segment:
                    var fq = Cross2(D, _p + _e - O);
                    return _fp.Square() > d2 && fq.Square() > d2;
                case Kind.Ray:
                    // The target's origin farther than δ from the ray's line (the crossing then lies δ/sin or more along it).
                    return _fp.Square() > d2;
                default:
                    return true;
            }
        }

        /// <summary>Along the wall with a stretch longer than δ ahead of the origin (then the first point is forced).</summary>
        private bool RobustAlong(Dy delta)
        {
            if (!_fe.IsZero || !_fp.IsZero || !_nominal.HasValue) return false;
            var gp = DyVec.Dot(D, _p - O);
            var reach = delta * Roots.SqrtUpper(DD);
            switch (_kind)
            {
                case Kind.Line: return true;
                case Kind.Ray:
                    // The origin well inside the target ray, or the target's origin well ahead and the target pointing ahead.
                    return DyVec.Dot(O - _p, _e).Sign > 0 && (O - _p).LengthSquared > delta.Square()
                           || gp > reach && DyVec.Dot(D, _e).Sign > 0;
                default:
                    var gq = DyVec.Dot(D, _p + _e - O);
                    return Dy.Max(gp, gq) > reach && (Dy.Min(gp, gq) > reach || Dy.Min(gp, gq) < -reach);
            }
        }

        public override void CheckT(bool hit, Dy t, bool startsInside, Dy delta, Dy rho, List<string> problems, bool insideUnknown = false)
        {
            if (Robust(delta))
            {
                var num = Cross2(_p - O, _e);
                if (!hit) problems.Add($"a miss, but the ray crosses the wall at t = {Show(_nominal)} with its ends and the origin farther than δ = {delta.ToDouble():G4}");
                // |T − t*| ≤ δ·|e|/|fe| + ρ: a wall moved by δ moves the crossing by δ/sin.
                else if (!CloseEnough(t, num, delta, rho))
                    problems.Add($"T = {t.ToDouble():R} but the robust crossing is at {Show(_nominal)}: more than (δ + ρ)/sin (δ = {delta.ToDouble():G4}, sin = {Dy.Ratio(Dy.Abs(_fe), Roots.SqrtUpper(_ee * DD)):G4})");
            }
            else if (RobustAlong(delta))
            {
                if (!hit) problems.Add($"a miss, but the ray runs along the wall from t = {Show(_nominal)}");
                else if (!NearValue(_nominal!.Value, t, delta + rho))
                    problems.Add($"T = {t.ToDouble():R} but the ray runs along the wall from {Show(_nominal)} (allowed δ + ρ = {(delta + rho).ToDouble():G4})");
            }
            if (hit && !OnTarget(At(t), delta + rho * Roots.SqrtUpper(DD) * Dy.From(2)))
                problems.Add($"o + T·d is farther than δ + 2ρ = {(delta + rho * Dy.From(2)).ToDouble():G4} from the wall");
        }

        /// <summary>|T·fe − num| ≤ δ·|e| + ρ·|fe| (|e| by its upper root).</summary>
        private bool CloseEnough(Dy t, Dy num, Dy delta, Dy rho) =>
            Dy.Abs(t * _fe - num) <= delta * Roots.SqrtUpper(_ee) + rho * Dy.Abs(_fe);

        private static bool NearValue(Surd s, Dy t, Dy tol) => s.CompareTo(t - tol) >= 0 && s.CompareTo(t + tol) <= 0;

        public override Surd? WellConditioned(Dy delta)
        {
            if (Robust(delta) && _fe.Square() * Dy.From(4) >= _ee * DD) return _nominal;
            return RobustAlong(delta) ? _nominal : null;
        }

        public override bool OnTarget(DyVec x, Dy tol) => _kind switch
        {
            Kind.Segment => Roots.NearSegment(x, _p, _p + _e, tol),
            _ => Roots.NearLinear(x, _p, _e, _kind == Kind.Ray, tol),
        };

        /// <summary>The wall's direction (for the normal check).</summary>
        public DyVec Direction => _e;

        public override string Describe(Dy delta) =>
            $"exact crossing {Show(_nominal)}; {(Robust(delta) ? "robust" : RobustAlong(delta) ? "along the wall" : "not robust at δ")} (δ = {delta.ToDouble():G4})";
    }

    // ---- the 3D triangle -------------------------------------------------------------------------------------------

    /// <summary>A non-degenerate two-sided 3D triangle.</summary>
    public sealed class TriangleRef : CastRef
    {
        private readonly DyVec _a, _b, _c, _n;
        private readonly Dy _nn, _nd, _h0, _tolEdge;
        private readonly Polytope? _plane; // the in-plane solid when the ray lies in the plane
        private readonly Surd? _nominal;
        /// <summary>
        /// How far moving the vertices by δ moves the plane at the crossing x*, per δ: the plane shifts by δ and tilts by
        /// up to 2δ(|B − A| + |C − A|)/|n| about a vertex, so F = 1 + 2·max|x* − V|·(|B − A| + |C − A|)/|n| (large for slivers).
        /// </summary>
        private readonly double _tilt = 1;
        private readonly double _cos;
        /// <summary>B·u, the largest vertex offset m from the origin, and the smallest altitude (see the sliver allowance in CheckT).</summary>
        private readonly Dy _relative, _m, _altitude;

        public TriangleRef(DyVec o, DyVec d, DyVec a, DyVec b, DyVec c, Dy relative = default) : base(o, d)
        {
            _relative = relative;
            _a = a; _b = b; _c = c;
            _n = Roots.Cross(b - a, c - a);
            _nn = _n.LengthSquared;
            _nd = DyVec.Dot(_n, d);
            _h0 = DyVec.Dot(_n, a - o);
            // The edge-on path measures the ray against the edges with the pass-through tolerance of their offsets.
            double m = Math.Max(Roots.MaxAbs(a - o).ToDouble(), Math.Max(Roots.MaxAbs(b - o).ToDouble(), Roots.MaxAbs(c - o).ToDouble()));
            _tolEdge = PassRef.Tolerance * Dy.From(m * (1 + PassRef.Band));
            if (_nd.IsZero && _h0.IsZero) _plane = Polytope.Triangle(a, b, c, _n);
            _nominal = First();
            _cos = _nn.IsZero ? 0 : Math.Abs(Dy.Ratio(_nd, Roots.SqrtUpper(_nn * DD)));
            _m = Dy.Max(Roots.MaxAbs(a - o), Dy.Max(Roots.MaxAbs(b - o), Roots.MaxAbs(c - o)));
            var longest = new[] { b - a, c - b, a - c }.Select(v => v.LengthSquared).Aggregate(Dy.Max);
            _altitude = longest.IsZero ? Dy.Zero : Dy.From(Math.Sqrt(Dy.Ratio(_nn, longest)));
            if (_nominal.HasValue && _plane == null)
            {
                // In dyadics (any magnitude), to 30 bits: a tolerance, not a decision.
                var x = o + d * Dy.From(_nominal.Value.ToDouble());
                var reach2 = new[] { a, b, c }.Select(v => (x - v).LengthSquared).Aggregate(Dy.Max);
                var arms = Roots.Sqrt((b - a).LengthSquared, 30) + Roots.Sqrt((c - a).LengthSquared, 30);
                double f = 1 + 2 * Dy.Ratio(Roots.Sqrt(reach2, 30) * arms, Roots.Sqrt(_nn, 30));
                _tilt = double.IsFinite(f) ? Math.Min(f, Math.ScaleB(1, 60)) : Math.ScaleB(1, 60);
            }
        }

        public override bool IsSolid => false;
        public override Surd? Nominal => _nominal;

        private Surd? First()
        {
            if (_plane != null) return _plane.FirstHit(O, D, Dy.Zero);
            if (_nd.IsZero || (_h0 * _nd).Sign < 0) return null;
            var X = O * _nd + D * _h0;
            foreach (var (p, q) in Edges())
                if ((DyVec.Dot(Roots.Cross(q - p, X - p * _nd), _n) * _nd).Sign < 0) return null;
            return Surd.Ratio(_h0, _nd);
        }

        private IEnumerable<(DyVec, DyVec)> Edges() { yield return (_a, _b); yield return (_b, _c); yield return (_c, _a); }

        /// <summary>δ plus the edge-on path's tolerance: how far a hit may lie from the triangle.</summary>
        public Dy Reach(Dy delta) => delta + _tolEdge * Dy.From(2);

        /// <summary>
        /// A crossing with the origin farther than δ_w + F·δ from the plane and every edge farther than δ_w + F·δ/cos from it
        /// (the tilt moves it that far), at an angle not below 2^−30.
        /// </summary>
        private bool Robust(Dy dw, Dy delta)
        {
            if (_plane != null || _nd.IsZero || !_nominal.HasValue) return false;
            if (_nd.Square() < Dy.Pow2(-60) * _nn * DD) return false;
            if (_h0.Square() <= (dw + delta * Dy.From(_tilt)).Square() * _nn) return false;
            dw += delta * Dy.From(_tilt / _cos);
            var X = O * _nd + D * _h0;
            foreach (var (p, q) in Edges())
            {
                var lambda = DyVec.Dot(Roots.Cross(q - p, X - p * _nd), _n);
                if (lambda.Square() < dw.Square() * (q - p).LengthSquared * _nn * _nd.Square()) return false;
            }
            return true;
        }

        public override void CheckT(bool hit, Dy t, bool startsInside, Dy delta, Dy rho, List<string> problems, bool insideUnknown = false)
        {
            var dw = Reach(delta);
            if (Robust(dw, delta))
            {
                if (!hit) problems.Add($"a miss, but the ray crosses the triangle at t = {Show(_nominal)} farther than δ_w = {dw.ToDouble():G4} from its edges and the origin");
                else
                {
                    // The plane moved by δ moves the crossing by δ/cos (the edges are farther than δ_w: they do not decide
                    // it). A grazing ray (cos < 2^−10) may be answered edge-on, at the first edge within the pass-through
                    // tolerance, up to 2·tol/cos before the crossing.
                    var diff = t * _nd - _h0; // (T − t*)·nd
                    var late = diff * Dy.From(_nd.Sign);
                    var slack = delta * Dy.From(_tilt) * Roots.SqrtUpper(_nn) + rho * Dy.Abs(_nd);
                    bool grazing = _nd.Square() < Dy.Pow2(-20) * _nn * DD;
                    var early = grazing ? slack + _tolEdge * Dy.From(2) * Roots.SqrtUpper(_nn) : slack;
                    if (late > slack || -late > early)
                        problems.Add($"T = {t.ToDouble():R} but the robust crossing is at {Show(_nominal)}: more than F·δ/cos + ρ (δ = {delta.ToDouble():G4}, F = {_tilt:G4}, cos = {_cos:G4}{(grazing ? ", edge-on tolerance allowed before it" : "")})");
                }
            }
            else if (_plane != null)
            {
                var lo = _plane.FirstHit(O, D, dw);
                var hi = _plane.FirstHit(O, D, -dw);
                if (!hit && hi.HasValue) problems.Add($"a miss, but the ray lies in the triangle's plane and enters the triangle shrunk by δ_w = {dw.ToDouble():G4} at t = {Show(hi)}");
                if (hit && hi.HasValue && hi.Value.CompareTo(t - rho) < 0)
                    problems.Add($"T = {t.ToDouble():R} is after the in-plane entry {Show(hi)} into the triangle shrunk by δ_w = {dw.ToDouble():G4}");
                if (hit && lo.HasValue && lo.Value.CompareTo(t + rho) > 0)
                    problems.Add($"T = {t.ToDouble():R} is before the in-plane entry {Show(lo)} into the triangle grown by δ_w = {dw.ToDouble():G4}");
            }
            else if (_nd.IsZero && _h0.Square() > dw.Square() * _nn && hit)
                problems.Add($"hit at T = {t.ToDouble():R}, but the ray is parallel to the plane and farther than δ_w = {dw.ToDouble():G4} from it");
            // At a glancing angle T carries about u·m/cos (the plane's rounding, seen along the ray), which moves o + T·d
            // along the ray, off the triangle by up to that; a δ-perturbed triangle stays within its altitude of it: the
            // allowance is the smaller. (Slivers get no more: their T comes from the exact plane.)
            var glancing = _cos > 0 ? Dy.Min(_relative * _m * Dy.From(Math.Min(1 / _cos, Math.ScaleB(1, 60))), _altitude) : Dy.Zero;
            var near = dw + rho * Roots.SqrtUpper(DD) * Dy.From(2) + glancing;
            if (hit && !OnTarget(At(t), near))
                problems.Add($"o + T·d is farther than δ_w + 2ρ + min(B·u·m/cos, altitude) = {near.ToDouble():G4} from the triangle");
        }

        public override Surd? WellConditioned(Dy delta) =>
            Robust(Reach(delta), delta) && _cos >= 0.5 && _tilt <= 8 ? _nominal : null;

        /// <summary>F/cos: how far a δ move of the vertices can move the hit along the ray, per δ (for the point's check).</summary>
        public double Conditioning => _cos > 0 ? _tilt / _cos : double.PositiveInfinity;

        public override bool OnTarget(DyVec x, Dy tol) => Core.NearTriangle(x, _a, _b, _c, tol);

        /// <summary>Whether the ray lies in the triangle's plane (exactly).</summary>
        public bool InPlane => _plane != null;

        /// <summary>The triangle's normal (B − A) × (C − A), exactly.</summary>
        public DyVec Normal => _n;

        public override string Describe(Dy delta) =>
            $"exact crossing {Show(_nominal)}; {(_plane != null ? "the ray lies in the plane" : Robust(Reach(delta), delta) ? "robust" : "not robust")} at δ_w = {Reach(delta).ToDouble():G4}; n·d = {_nd.ToDouble():G4}, cos = {_cos:G4}, tilt factor F = {_tilt:G4}";
    }
}
