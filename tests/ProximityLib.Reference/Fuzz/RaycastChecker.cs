using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;
using Flt = ProximityLib;

namespace ProximityReference.Fuzz
{
    /// <summary>A ray-cast answer of either API and dimension, widened exactly to doubles (2D: z = 0).</summary>
    public readonly struct HitRes
    {
        public readonly bool Hit, Inside;
        public readonly double T;
        public readonly Vector3D Point, Normal;

        public HitRes(bool hit, double t, Vector3D point, Vector3D normal, bool inside) { Hit = hit; T = t; Point = point; Normal = normal; Inside = inside; }

        private static Vector3D V(double x, double y) => new Vector3D(x, y, 0);

        public static HitRes From(object r) => r switch
        {
            Dbl.RayHit3 x => new HitRes(x.Hit, x.T, x.Point, x.Normal, x.StartsInside),
            Dbl.RayHit2 x => new HitRes(x.Hit, x.T, V(x.Point.X, x.Point.Y), V(x.Normal.X, x.Normal.Y), x.StartsInside),
            Flt.RayHit3 x => new HitRes(x.Hit, x.T, new Vector3D(x.Point.X, x.Point.Y, x.Point.Z), new Vector3D(x.Normal.X, x.Normal.Y, x.Normal.Z), x.StartsInside),
            Flt.RayHit2 x => new HitRes(x.Hit, x.T, V(x.Point.X, x.Point.Y), V(x.Normal.X, x.Normal.Y), x.StartsInside),
            _ => throw new InvalidOperationException(r?.GetType().Name),
        };

        /// <summary>The float API's answer for a double answer: T, Point and Normal rounded; a hit past float's range is a miss.</summary>
        public HitRes RoundedToFloat() => Hit && !PastFloat
            ? new HitRes(true, (float)T, F(Point), F(Normal), Inside)
            : new HitRes(false, float.PositiveInfinity, default, default, false);

        /// <summary>A hit whose T or Point lies past float's range (the float API answers it with a miss).</summary>
        public bool PastFloat => Hit && (T > float.MaxValue || !F(Point).IsFinite);

        private static Vector3D F(Vector3D v) => new Vector3D((float)v.X, (float)v.Y, (float)v.Z);

        public static HitRes Miss(bool isFloat) => new HitRes(false, double.PositiveInfinity, default, default, false);

        public bool SameBits(HitRes o) => Hit == o.Hit && Inside == o.Inside && Spec.Bits(T, o.T) && Spec.Bits(Point, o.Point) && Spec.Bits(Normal, o.Normal);

        public string Show(bool isFloat, int dim) =>
            $"Hit = {Hit}, T = {Res.N(T, isFloat)}, Point = {Res.P(Point, isFloat, dim)}, Normal = {Res.P(Normal, isFloat, dim)}, StartsInside = {Inside}";
    }

    /// <summary>One violated invariant of a ray-cast case, with what a C# repro needs.</summary>
    public sealed class CastFailure
    {
        public CastCase Case { get; }
        public string Invariant { get; }
        public string Message { get; }
        /// <summary>C# statements after <c>var ray = …; var target = …;</c>.</summary>
        public IReadOnlyList<string> Code { get; }
        public bool Batch { get; }

        public CastFailure(CastCase c, string invariant, string message, IReadOnlyList<string> code, bool batch = false)
        {
            Case = c; Invariant = invariant; Message = message; Code = code; Batch = batch;
        }

        /// <summary>A self-contained C# repro (top-level statements) that rebuilds the ray and the target bit for bit and makes the call.</summary>
        public string Repro()
        {
            var c = Case;
            var sb = new StringBuilder();
            sb.AppendLine($"// ray cast on a {c.TargetName} ({c.PrecisionName}), generator \"{c.Generator}\": invariant {Invariant}");
            foreach (var line in Message.Split('\n')) sb.AppendLine("// " + line);
            sb.AppendLine($"// replay: dotnet run --project tests/ProximityLib.Accuracy -c Release -- --fuzz-casts-replay {c.Seed}:{c.Index}");
            sb.AppendLine(Spec.Usings(c.Float));
            if (Batch) sb.AppendLine("using ProximityLib.Batch;");
            sb.AppendLine($"var ray = {c.Ray.ToCSharp()};");
            sb.AppendLine($"var target = {c.Target.ToCSharp()};");
            foreach (var line in Code) sb.AppendLine(line);
            return sb.ToString();
        }
    }

    /// <summary>
    /// Checks one ray-cast case against every invariant; every comparison is exact (dyadic arithmetic). Units: U = u·S + η
    /// (u = 2^−53 double, 2^−24 float; S = the local scale: the largest coordinate difference between the ray's origin and
    /// the target's defining points, the radius, and the exact first hit's t when that is larger — a hit far along an
    /// unbounded target is rounded at that distance; η the smallest subnormal). The bounds:
    /// <list type="bullet">
    /// <item>(c) first hit: the answer is the exact first hit of the target perturbed by δ = B·U (<see cref="CastRef"/>), with
    /// T's own rounding ρ = 2u·T on top. B = 32 in double: a first-order rounding analysis of the kernels (every rounding of
    /// the offsets from the origin, the dot and cross products, the square root and the final division at its maximum, in
    /// the same direction) gives at most about 20·u·S for the sphere's and the capsule's quadratic and less for the slab,
    /// plane and edge-function tests; 32 is the pair queries' bound (docs/api.md). B = 2 in float: the float API rounds
    /// the double answer once. At an incidence cosine c the interval is t* ± B·U/c: forward error where the hit is
    /// well-conditioned, the backward form at a graze.</item>
    /// <item>E = |T − t*|/U, measured where the hit is well-conditioned (condition number ≤ 2: the perturbed first hits
    /// lie within 4·B·U of each other, i.e. c ≥ 1/2 on every face that can decide it); the check (c) bounds it by
    /// 2·B + 2·T/S·(u's rounding), so at most 2·B + 4.</item>
    /// <item>(d) Point: on the target within δ_P = 2·δ + 8·u·M (M the largest coordinate magnitude: Point is formed at
    /// its position), and on the ray within δ_P of the stretch the interval allows (a 3D triangle's barycentric Point:
    /// within F·δ/cos, its crossing's conditioning, see <see cref="TriangleRef"/>).</item>
    /// <item>(e) Normal: unit (|n|² within 2^−40, float 2^−20), outward: a supporting plane of a solid at Point (n·Point ≥
    /// max over the solid of n·x − δ_P − α·S) and n·d ≤ α for T &gt; 0 (the ray enters), with the normal's angle
    /// tolerance α = 2^−20, plus 2·√(δ_P/R) on a sphere or capsule (a graze's normal is uncertain by √(2δ_P/R); a radius
    /// below the point's rounding leaves it undetermined); exactly −Direction for zero-thickness 3D targets; a
    /// half-space's exactly; a wall's perpendicular to it and against the ray; a 3D triangle's parallel to its normal.</item>
    /// <item>(g) 2^k scaling: bit for bit (every field, k up to ±900 within the range); (h) translation by an exact grid
    /// offset: T passes (c) again, and within 2·δ + 2ρ of the untranslated T when well-conditioned; (f) float: the
    /// double API's answer on the same (widened) inputs rounded once, bit for bit; (k) the batch casts: each lane equals
    /// the set-of-one lane bit for bit and passes (c) with B = 32 in float units against the ray with its direction
    /// rounded to float (the batch's), StartsInside unknown (0).</item>
    /// </list>
    /// </summary>
    public sealed class CastChecker
    {
        public const double DoubleBound = 32, FloatBound = 2, BatchBound = 32;

        private readonly CastCase _c;
        private readonly List<CastFailure> _fails = new List<CastFailure>();
        private readonly bool _float;
        private readonly Dy _u, _eta;
        private readonly double _bound;
        private object _ray = null!, _target = null!;
        private Dbl.Ray3 _inner3;
        private Dbl.Ray2 _inner2;
        private Vector3D _o, _d;
        private Core _core = null!;
        private CastRef _ref = null!;
        private Dy _unit, _delta, _s;
        private HashSet<string> _ran = new HashSet<string>();

        /// <summary>E measured on this case: (precision label, E).</summary>
        public List<(string Precision, double E)> Errors { get; } = new List<(string, double)>();

        private CastChecker(CastCase c)
        {
            _c = c;
            _float = c.Float;
            _u = Dy.Pow2(_float ? -24 : -53);
            _eta = Dy.Pow2(_float ? -149 : -1074);
            _bound = _float ? FloatBound : DoubleBound;
        }

        public static List<CastFailure> Run(CastCase c, HashSet<string> ran, List<(string, double)> errors)
        {
            var k = new CastChecker(c) { _ran = ran };
            k.RunAll();
            errors.AddRange(k.Errors);
            return k._fails;
        }

        public static List<CastFailure> Run(CastCase c) => Run(c, new HashSet<string>(), new List<(string, double)>());

        private void Fail(string invariant, string message, IReadOnlyList<string> code, bool batch = false) =>
            _fails.Add(new CastFailure(_c, invariant, message, code, batch));

        private string N(double x) => Res.N(x, _float);
        private string Show(HitRes h) => h.Show(_float, _c.Dim);
        private string Lit(double x) => Spec.Literal(x, _float);

        // ---- calls ---------------------------------------------------------------------------------------------------

        private HitRes Cast(object ray, object target) => HitRes.From(_float
            ? (object)Flt.Raycast.Cast((dynamic)ray, (dynamic)target)
            : (object)Dbl.Raycast.Cast((dynamic)ray, (dynamic)target));

        private HitRes Cast(object ray, object target, double max) => HitRes.From(_float
            ? (object)Flt.Raycast.Cast((dynamic)ray, (dynamic)target, (float)max)
            : (object)Dbl.Raycast.Cast((dynamic)ray, (dynamic)target, max));

        private static HitRes CastDouble(object ray, object target, double max) =>
            HitRes.From((object)Dbl.Raycast.Cast((dynamic)Core.DoubleForm(ray), (dynamic)Core.DoubleForm(target), max));

        private string Call(double? max) => max.HasValue ? $"var h = Raycast.Cast(ray, target, {Lit(max.Value)});" : "var h = Raycast.Cast(ray, target);";

        // ---- the run -------------------------------------------------------------------------------------------------

        private void RunAll()
        {
            try
            {
                _ray = _c.Ray.Build();
                _target = _c.Target.Build();
            }
            catch (ArgumentException e)
            {
                Fail("generator", $"the generator made an invalid shape: {e.Message}", Array.Empty<string>());
                return;
            }
            var dr = Core.DoubleForm(_ray);
            if (dr is Dbl.Ray3 r3) { _inner3 = r3; _o = r3.Origin; _d = r3.Direction; }
            else { _inner2 = (Dbl.Ray2)dr; _o = new Vector3D(_inner2.Origin.X, _inner2.Origin.Y, 0); _d = new Vector3D(_inner2.Direction.X, _inner2.Direction.Y, 0); }
            _core = Core.Of(_target);

            HitRes h;
            try { h = Cast(_ray, _target); }
            catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException))
            {
                Fail("a no exception", $"Raycast.Cast threw {e.GetType().Name}: {e.Message}", new[] { Call(null) });
                return;
            }
            var code = new List<string> { Call(null), $"// got {Show(h)}" };
            bool fine = CheckForm(h, "Cast(ray, target)", code, _o);

            // The exact reference and the local scale.
            var o = DyVec.From(_o);
            var d = DyVec.From(_d);
            _ref = CastRef.For(_target, o, d, _u * _bound);
            _s = Scale(_core, _o);
            var nominal = _ref.Nominal;
            if (nominal.HasValue)
            {
                var tn = Dy.From(Math.Abs(nominal.Value.ToDouble()));
                if (tn > _s) _s = tn;
            }
            _unit = _s * _u + _eta;
            _delta = _unit * _bound;

            if (_float) CheckFloat(h, code);
            if (fine)
            {
                CheckFirstHit(h, code, _delta, "c first hit");
                CheckPointAndNormal(h, code);
                MeasureE(h);
                CheckScaling(h);
                CheckTranslation(h);
                CheckBatch();
            }
            CheckMaxDistance(h, nominal);
        }

        /// <summary>S: the largest coordinate difference between the origin and the target's defining points, or its radius.</summary>
        private static Dy Scale(Core target, Vector3D origin) =>
            Core.Scale(Core.Of(target.Planar ? (object)new Vector2D(origin.X, origin.Y) : origin), target);

        /// <summary>(a) the shape of an answer: no NaN; a miss is T = +∞ with zero Point and Normal; a hit finite; StartsInside only for a solid, with T = 0, Point = Origin, zero Normal; otherwise a unit Normal.</summary>
        private bool CheckForm(HitRes h, string call, List<string> code, Vector3D origin)
        {
            var problems = new List<string>();
            if (double.IsNaN(h.T) || !NotNaN(h.Point) || !NotNaN(h.Normal)) problems.Add("NaN in the answer");
            if (!h.Hit)
            {
                if (!double.IsPositiveInfinity(h.T) || h.Point != default || h.Normal != default || h.Inside)
                    problems.Add("a miss must have T = +∞, zero Point and Normal, StartsInside false");
            }
            else
            {
                if (!(h.T >= 0) || !double.IsFinite(h.T)) problems.Add($"a hit with T = {N(h.T)} (must be finite and ≥ 0)");
                if (!h.Point.IsFinite) problems.Add("a hit with a non-finite Point");
                if (h.Inside)
                {
                    if (!_core.IsSolid) problems.Add($"StartsInside on a {_c.Target.KindName}, which is not a solid");
                    if (h.T != 0 || !Spec.Bits(h.Point, Widened(origin)) || h.Normal != default) problems.Add("StartsInside needs T = 0, Point = Origin and a zero Normal");
                }
                else
                {
                    double nn = h.Normal.LengthSquared, tol = _float ? Math.ScaleB(1, -20) : Math.ScaleB(1, -40);
                    if (!(Math.Abs(nn - 1) <= tol)) problems.Add($"|Normal|² = {nn:R} (must be 1 within {tol:G3})");
                }
            }
            if (problems.Count > 0) Fail("a form", $"{call}: {string.Join("; ", problems)}", code);
            // Usable for the other checks: no NaN, and a hit's T and Point finite.
            return !double.IsNaN(h.T) && NotNaN(h.Point) && NotNaN(h.Normal) && (!h.Hit || double.IsFinite(h.T) && h.Point.IsFinite);
        }

        private static bool NotNaN(Vector3D v) => !double.IsNaN(v.X) && !double.IsNaN(v.Y) && !double.IsNaN(v.Z);

        /// <summary>A vector as the API reports it: float components in the float API, z = +0 in 2D.</summary>
        private Vector3D Widened(Vector3D v)
        {
            if (_c.Dim == 2) v = new Vector3D(v.X, v.Y, 0);
            return _float ? new Vector3D((float)v.X, (float)v.Y, (float)v.Z) : v;
        }

        private Vector3D Flat(Vector3D v) => _c.Dim == 2 ? new Vector3D(v.X, v.Y, 0) : v;

        /// <summary>T's own rounding: 2u·T.</summary>
        private Dy Rho(double t) => Dy.From(t) * _u * Dy.From(2);

        // ---- (c) the first hit against the exact reference ----------------------------------------------------------

        private void CheckFirstHit(HitRes h, List<string> code, Dy delta, string invariant)
        {
            if (!h.Hit && _float && CastDouble(_ray, _target, double.PositiveInfinity).PastFloat) return; // a miss by the float range: (f) checks it
            var problems = new List<string>();
            var t = h.Hit ? Dy.From(h.T) : Dy.Zero;
            _ref.CheckT(h.Hit, t, h.Inside, delta, Rho(h.Hit ? h.T : 0), problems);
            if (problems.Count > 0)
                Fail(invariant, $"{string.Join("; ", problems)}\nreference: {_ref.Describe(delta)}; U = {_unit.ToDouble():G4} (S = {_s.ToDouble():G4})", code);
        }

        private void MeasureE(HitRes h)
        {
            if (!h.Hit || h.Inside) return;
            var wc = _ref.WellConditioned(_delta);
            if (!wc.HasValue) return;
            Errors.Add((_c.PrecisionName, wc.Value.Error(Dy.From(h.T), _unit)));
        }

        // ---- (d), (e) the point and the normal -------------------------------------------------------------------

        private void CheckPointAndNormal(HitRes h, List<string> code)
        {
            if (!h.Hit || h.Inside) return;
            var p = DyVec.From(h.Point);
            var o = DyVec.From(_o);
            var d = DyVec.From(_d);
            var dd = d.LengthSquared;
            var mag = Dy.Max(Dy.Max(_core.Magnitude(), Roots.MaxAbs(o)), Roots.MaxAbs(p));
            var deltaP = _delta * Dy.From(2) + _u * mag * Dy.From(8);
            var rho = Rho(h.T);
            var thin = _ref is PassRef pass ? pass.TolMax * Dy.From(1.5) : Dy.Zero;
            string tolText = $"δ_P = 2·δ + 8·u·M = {deltaP.ToDouble():G4} (δ = {_delta.ToDouble():G4}, M = {mag.ToDouble():G4})";

            // (d) on the target (a solid: its boundary) and on the ray.
            var onTol = _ref is TriangleRef tri ? tri.Reach(deltaP) : deltaP + thin;
            if (!_ref.OnTarget(p, onTol))
                Fail("d point", $"Point is not on the target within {tolText}{(thin.IsZero ? "" : $" + 1.5·tol")}\nreference: {_ref.Describe(_delta)}", code);
            var w = p - o;
            var wd = DyVec.Dot(w, d);
            var perp2 = w.LengthSquared * dd - wd.Square(); // |perp|²·|d|²
            // A 3D triangle's Point is its barycentric point, exact on the triangle but off the ray by the crossing's own
            // conditioning (F/cos per δ: a graze or a sliver), and by the edge-on path's tolerance.
            var reach = deltaP + thin + (_ref is TriangleRef tr ? tr.Reach(Dy.Zero) + _delta * Dy.From(Math.Min(tr.Conditioning, Math.ScaleB(1, 60))) : Dy.Zero);
            if (perp2 > reach.Square() * dd)
                Fail("d point", $"Point is {DyMath.Sqrt(perp2) / DyMath.Sqrt(dd):G4} from the ray's line, more than {reach.ToDouble():G4} ({tolText})", code);
            else
            {
                // Along the ray: Point's parameter within the stretch the answer may have come from.
                var wc = _ref.WellConditioned(_delta);
                if (wc.HasValue)
                {
                    var slack = deltaP + thin + _delta * Dy.From(4) + rho;
                    var tP = wd; // times |d|²
                    var tt = Dy.From(h.T);
                    if (Dy.Abs(tP - tt * dd) > slack * dd)
                        Fail("d point", $"Point lies at t = {Dy.Ratio(tP, dd):R} along the ray but T = {N(h.T)} (a well-conditioned hit): more than δ_P + 4·δ + ρ = {slack.ToDouble():G4} apart", code);
                }
            }

            // (e) the normal.
            var n = DyVec.From(h.Normal);
            var minusD = Widened(-_d);
            string? wrong = null;
            var nd = DyVec.Dot(n, d);
            var small = Dy.Pow2(-20);
            switch (_ref)
            {
                case PassRef _:
                    if (!Spec.Bits(h.Normal, minusD)) wrong = "must be −Direction exactly (a zero-thickness target)";
                    break;
                case WallRef wall:
                {
                    if (Spec.Bits(h.Normal, minusD)) break;
                    var e = wall.Direction;
                    var ne = DyVec.Dot(n, e);
                    if (ne.Square() > small.Square() * e.LengthSquared) wrong = "must be perpendicular to the wall (or −Direction along it)";
                    else if (nd > small) wrong = "must face the side the ray comes from (Normal·Direction ≤ 0)";
                    break;
                }
                case TriangleRef triangle:
                {
                    if (Spec.Bits(h.Normal, minusD)) break;
                    var nn = triangle.Normal;
                    var c = Roots.Cross(n, nn);
                    if (c.LengthSquared > small.Square() * nn.LengthSquared) wrong = "must be the triangle's unit normal (or −Direction edge-on)";
                    else if (h.T > 0 && nd > small) wrong = "must face the side the ray comes from (Normal·Direction ≤ 0)";
                    break;
                }
                default:
                {
                    if (_core.Kind == Kind.HalfSpace)
                    {
                        if (!Spec.Bits(h.Normal, Widened(_core.Q))) wrong = "must be the half-space's stored normal exactly";
                        break;
                    }
                    // A zero radius with the origin on the axis (or at the centre): −Direction (docs/pairs.md).
                    if (h.T == 0 && _core.R == 0 && Spec.Bits(h.Normal, minusD)) break;
                    // The normal's angle is uncertain by 2^−20, and on a curved surface by what the point's uncertainty δ_P
                    // turns it: δ_P/R head-on, √(2·δ_P/R) at a graze (below rounding when R is tiny against the distance).
                    double angle = Math.Pow(2, -20) + (_core.R > 0 ? 2 * Math.Sqrt(deltaP.ToDouble() / _core.R) : 0);
                    if (h.T > 0 && nd > Dy.From(angle))
                        wrong = $"must point against the ray at a hit with T > 0 (Normal·Direction = {nd.ToDouble():G4} > {angle:G3})";
                    else if (_core.TrySupport(n, out var sup))
                    {
                        // A supporting plane at Point: n·Point ≥ max over the solid of n·x − tol (the radius at |n| ≈ 1), the
                        // normal's angle tolerance times the solid's extent on top.
                        var r = Dy.From(_core.R);
                        var gap = sup + r - DyVec.Dot(n, p);
                        var allowed = deltaP * Dy.From(1 + 1e-6) + r * Dy.Pow2(-30) + Dy.From(Math.Min(angle, 2)) * (_s + r);
                        if (gap > allowed)
                            wrong = $"is not outward at Point: the solid reaches {gap.ToDouble():G4} beyond Point along it, more than {allowed.ToDouble():G4} ({tolText}, angle {angle:G3})";
                    }
                    break;
                }
            }
            if (wrong != null) Fail("e normal", $"Normal {Res.P(h.Normal, _float, _c.Dim)} {wrong}", code);
        }

        // ---- (b) maxDistance --------------------------------------------------------------------------------------

        /// <summary>
        /// (b) Cast(ray, target, M) is the unlimited answer when its T ≤ M, else a miss, bit for bit; M drawn around the
        /// answer's T (one unit in the last place below, at, above), around the exact t*, 0, +∞ or random; a negative or NaN
        /// M throws ArgumentException.
        /// </summary>
        private void CheckMaxDistance(HitRes h, Surd? nominal)
        {
            var rng = _c.Rng;
            int pick = rng.Int(10);
            if (pick < 4 && rng.Int(16) != 0) return;
            double m;
            double tn = nominal.HasValue ? nominal.Value.ToDouble() : _s.ToDouble();
            double t = h.Hit ? h.T : tn;
            switch (pick)
            {
                case 4: m = double.PositiveInfinity; break;
                case 5: m = t; break;
                case 6: m = _float ? MathF.BitDecrement((float)t) : Math.BitDecrement(t); break;
                case 7: m = _float ? MathF.BitIncrement((float)t) : Math.BitIncrement(t); break;
                case 8: m = tn * (1 + rng.Sign() * Math.ScaleB(1, -rng.Int(1, _float ? 24 : 53))); break;
                case 9: m = rng.Chance(0.2) ? 0 : rng.Unit() * 2 * _s.ToDouble(); break;
                default: m = rng.Chance(0.5) ? -rng.Unit() : double.NaN; break;
            }
            if (_float) m = (float)m;
            if (!(m >= 0) || double.IsNaN(m))
            {
                _ran.Add("b maxDistance < 0 or NaN");
                try
                {
                    Cast(_ray, _target, m);
                    Fail("b maxDistance", $"Cast(ray, target, {N(m)}) did not throw (a negative or NaN maxDistance must throw ArgumentException)", new[] { Call(m) });
                }
                catch (ArgumentException e) when (e.ParamName == "maxDistance") { }
                catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException))
                {
                    Fail("b maxDistance", $"Cast(ray, target, {N(m)}) threw {e.GetType().Name} ({e.Message}), not ArgumentException naming maxDistance", new[] { Call(m) });
                }
                return;
            }
            if (double.IsNaN(t) || double.IsInfinity(m) && pick != 4) return;
            _ran.Add("b maxDistance");
            HitRes hm;
            try { hm = Cast(_ray, _target, m); }
            catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException))
            {
                Fail("a no exception", $"Cast(ray, target, {N(m)}) threw {e.GetType().Name}: {e.Message}", new[] { Call(m) });
                return;
            }
            // The float API decides in double (docs: computed in double, rounded once): its T can round down onto maxDistance.
            double decided = _float && h.Hit ? CastDouble(_ray, _target, double.PositiveInfinity).T : h.T;
            bool within = h.Hit && decided <= m;
            if (h.Hit && !within && h.T <= m) _ran.Add("note: float T ≤ maxDistance but a miss (the double T is above it)");
            var want = within ? h : HitRes.Miss(_float);
            if (!hm.SameBits(want))
                Fail("b maxDistance", $"Cast(ray, target, {N(m)}) is not the unlimited answer {(within ? "(T ≤ maxDistance)" : "turned into a miss (T > maxDistance)")}",
                    new[] { Call(null), Call(m).Replace("var h =", "var hm ="), $"// got h: {Show(h)}", $"//     hm: {Show(hm)}" });
        }

        // ---- (f) float = the double answer rounded ---------------------------------------------------------------

        private void CheckFloat(HitRes h, List<string> code)
        {
            var want = CastDouble(_ray, _target, double.PositiveInfinity).RoundedToFloat();
            if (!h.SameBits(want))
                Fail("f float = rounded double", $"the float answer is not the double API's answer on the same inputs rounded once: expected {want.Show(true, _c.Dim)}", code);
        }

        // ---- (g) 2^k scaling --------------------------------------------------------------------------------------

        private void CheckScaling(HitRes h)
        {
            int lo = _float ? -126 : -900, hi = _float ? 126 : 900;
            var mags = _c.Ray.Lengths().Concat(_c.Target.Lengths()).Where(x => x != 0).Select(x => Math.ILogB(x)).ToArray();
            if (mags.Length == 0) return;
            int mn = mags.Min(), mx = mags.Max();
            if (mn < lo || mx >= hi) return;
            int kLo = lo - mn, kHi = hi - 1 - mx;
            if (kLo > kHi) return;
            var rng = _c.Rng;
            int k = rng.Int(4) switch { 0 => kLo, 1 => kHi, _ => rng.Int(kLo, kHi) };
            if (k == 0) k = kHi > 0 ? 1 : -1;
            if (k < kLo || k > kHi) return;
            _ran.Add("g 2^k scaling");
            var rs = _c.Ray.ScaledBy2(k);
            var ts = _c.Target.ScaledBy2(k);
            HitRes h2;
            var code = new List<string> { $"var rays = {rs.ToCSharp()};", $"var targets = {ts.ToCSharp()};",
                "var h = Raycast.Cast(ray, target);", "var hs = Raycast.Cast(rays, targets);" };
            try { h2 = Cast(rs.Build(), ts.Build()); }
            catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException))
            {
                Fail("g 2^k scaling", $"the scaled cast threw {e.GetType().Name}: {e.Message}", code);
                return;
            }
            code.Add($"// got h:  {Show(h)}");
            code.Add($"//     hs: {Show(h2)}");
            var diffs = new List<string>();
            // In float, a hit the scaling moves past float's range is a miss (the double answer says so).
            if (_float && h.Hit != h2.Hit && CastDouble(h.Hit ? rs.Build() : _ray, h.Hit ? ts.Build() : _target, double.PositiveInfinity).PastFloat) return;
            if (h.Hit != h2.Hit || h.Inside != h2.Inside) diffs.Add($"Hit/StartsInside {h2.Hit}/{h2.Inside} instead of {h.Hit}/{h.Inside}");
            else if (h.Hit)
            {
                void Same(string name, double x, double y)
                {
                    double want = Math.ScaleB(x, k);
                    if (x == 0 && y != 0) { if (Normal(Math.ScaleB(y, -k))) diffs.Add($"{name}: {N(y)} instead of 0"); return; }
                    if (y == 0 && x != 0) { if (Normal(want)) diffs.Add($"{name}: 0 instead of {N(want)}"); return; }
                    if (!Normal(x) || !Normal(want)) return;
                    if (!Spec.Bits(want, y)) diffs.Add($"{name}: {N(y)} instead of {N(want)}");
                }
                Same("T", h.T, h2.T);
                Same("Point.X", h.Point.X, h2.Point.X); Same("Point.Y", h.Point.Y, h2.Point.Y); Same("Point.Z", h.Point.Z, h2.Point.Z);
                if (!Spec.Bits(h.Normal, h2.Normal)) diffs.Add($"Normal {Res.P(h2.Normal, _float, _c.Dim)} instead of {Res.P(h.Normal, _float, _c.Dim)}");
            }
            if (diffs.Count > 0) Fail("g 2^k scaling", $"scaling the ray's origin and the target by 2^{k} is not exact: {string.Join("; ", diffs)}", code);
        }

        private bool Normal(double x) => x == 0 || (double.IsFinite(x) && Math.Abs(x) >= (_float ? Math.ScaleB(1, -126) : Math.ScaleB(1, -1022))
                                                     && Math.Abs(x) <= (_float ? float.MaxValue : double.MaxValue));

        // ---- (h) translation ------------------------------------------------------------------------------------

        /// <summary>A translation keeping every position sum exact (as the pair fuzz's): per axis a multiple of the coordinates' lowest set bit within the significand's reach.</summary>
        private Vector3D? ExactTranslation()
        {
            var rng = _c.Rng;
            int p = _float ? 24 : 53, top = _float ? 127 : 1023;
            var positions = _c.Ray.Positions().Concat(_c.Target.Positions()).ToArray();
            var t = new double[3];
            for (int j = 0; j < _c.Dim; j++)
            {
                var xs = positions.Select(v => j == 0 ? v.X : j == 1 ? v.Y : v.Z).ToArray();
                var nonzero = xs.Where(x => x != 0).ToArray();
                if (nonzero.Length == 0) { t[j] = rng.Sign() * Math.ScaleB(1, rng.Int(_float ? -100 : -900, _float ? 100 : 900)); continue; }
                int q = nonzero.Min(x => LowestBit(x));
                double limit = Math.ScaleB(1, Math.Min(q + p, top));
                double tmin = -limit - xs.Min(), tmax = limit - xs.Max();
                double span = Math.Max(Math.Abs(tmin), Math.Abs(tmax));
                double grain = Math.ScaleB(1, q);
                if (!(span > grain)) continue;
                double m = rng.Chance(0.5) ? rng.Range(tmin, tmax) : rng.Sign() * Math.Pow(2, rng.Range(q, Math.Log2(span)));
                m = Math.Max(tmin, Math.Min(tmax, m));
                t[j] = Math.Truncate(m / grain) * grain;
            }
            var tv = new Vector3D(t[0], t[1], t[2]);
            if (tv == default) return null;
            foreach (var x in positions)
                for (int j = 0; j < _c.Dim; j++)
                {
                    double xj = j == 0 ? x.X : j == 1 ? x.Y : x.Z, tj = t[j], s = xj + tj;
                    if (!double.IsFinite(s) || (Dy)s != (Dy)xj + (Dy)tj || (_float && (float)s != s)) return null;
                }
            return tv;
        }

        private static int LowestBit(double x)
        {
            var d = (Dy)x;
            var m = System.Numerics.BigInteger.Abs(d.M);
            int k = 0;
            while (m.IsEven) { m >>= 1; k++; }
            return d.E + k;
        }

        private void CheckTranslation(HitRes h)
        {
            var tv = ExactTranslation();
            if (tv == null) return;
            var rt = _c.Ray.Translated(tv.Value);
            var tt = _c.Target.Translated(tv.Value);
            object ray2, target2;
            try { ray2 = rt.Build(); target2 = tt.Build(); }
            catch (ArgumentException) { return; }
            _ran.Add("h translation");
            var code = new List<string> { $"var rayt = {rt.ToCSharp()};", $"var targett = {tt.ToCSharp()};",
                "var h = Raycast.Cast(ray, target);", "var ht = Raycast.Cast(rayt, targett);" };
            HitRes h2;
            try { h2 = Cast(ray2, target2); }
            catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException))
            {
                Fail("h translation", $"the translated cast threw {e.GetType().Name}: {e.Message}", code);
                return;
            }
            code.Add($"// got h:  {Show(h)}");
            code.Add($"//     ht: {Show(h2)}");
            string what = $"translating the ray and the target by {Res.P(tv.Value, _float, _c.Dim)} (exact)";
            if (!CheckForm(h2, "Cast(rayt, targett)", code, _o + Flat(tv.Value))) return;
            if (!h2.Hit && _float && CastDouble(ray2, target2, double.PositiveInfinity).PastFloat) return;
            var problems = new List<string>();
            _ref.CheckT(h2.Hit, h2.Hit ? Dy.From(h2.T) : Dy.Zero, h2.Inside, _delta, Rho(h2.Hit ? h2.T : 0), problems);
            if (problems.Count > 0)
                Fail("h translation", $"{what}: the translated answer fails the first-hit check: {string.Join("; ", problems)}\nreference: {_ref.Describe(_delta)}", code);
            else if (h.Hit && h2.Hit && !h.Inside && !h2.Inside && _ref.WellConditioned(_delta).HasValue)
            {
                var diff = Dy.Abs(Dy.From(h2.T) - Dy.From(h.T));
                var allowed = _delta * Dy.From(2) + Rho(h.T) + Rho(h2.T);
                if (diff > allowed)
                    Fail("h translation", $"{what} changed T from {N(h.T)} to {N(h2.T)} at a well-conditioned hit: {Dy.Ratio(diff, _unit):G4} U > 2·B + 2ρ", code);
            }
        }

        // ---- (k) the batch casts ----------------------------------------------------------------------------------

        private void CheckBatch()
        {
            if (!_float || _c.Dim != 3) return;
            var kind = _c.Target.Kind;
            if (kind != Kind.Sphere && kind != Kind.Aabb && kind != Kind.Triangle) return;
            if (_s < Dy.Pow2(-28) || _s > Dy.Pow2(28)) return;
            _ran.Add("k batch");
            var rng = _c.Rng;
            int n = rng.Int(1, 19), j = rng.Int(0, n - 1);
            double max = rng.Chance(0.25) ? rng.Unit() * 2 * _s.ToDouble() : double.PositiveInfinity;
            float fmax = (float)max;
            double size = Math.Max(_s.ToDouble(), 1e-6);
            var fill = new Spec[n];
            for (int i = 0; i < n; i++)
                fill[i] = i == j ? _c.Target : Generators.RandomShape(rng, kind, 3, _c.Target.P + new Vector3D(rng.Range(-1, 1), rng.Range(-1, 1), rng.Range(-1, 1)) * size, size).ToFloat();
            var ray = (Flt.Ray3)_ray;
            float[] one = new float[1], many = new float[n], oneMax = new float[1];
            string set = kind == Kind.Sphere ? "SphereSet" : kind == Kind.Aabb ? "AabbSet" : "TriangleSet";
            string type = kind == Kind.Sphere ? "Sphere" : kind == Kind.Aabb ? "Aabb3" : "Triangle3";
            void Run(Spec[] shapes, float[] result, float m)
            {
                switch (kind)
                {
                    case Kind.Sphere: Flt.Batch.BatchQuery.Raycasts(ray, new Flt.Batch.SphereSet(shapes.Select(s => (Flt.Sphere)s.Build()).ToArray()), result, m); break;
                    case Kind.Aabb: Flt.Batch.BatchQuery.Raycasts(ray, new Flt.Batch.AabbSet(shapes.Select(s => (Flt.Aabb3)s.Build()).ToArray()), result, m); break;
                    default: Flt.Batch.BatchQuery.Raycasts(ray, new Flt.Batch.TriangleSet(shapes.Select(s => (Flt.Triangle3)s.Build()).ToArray()), result, m); break;
                }
            }
            string callOne = $"var t = new float[1]; BatchQuery.Raycasts(ray, new {set}(new[] {{ target }}), t);";
            try
            {
                Run(new[] { _c.Target }, one, float.PositiveInfinity);
                Run(fill, many, float.PositiveInfinity);
                Run(new[] { _c.Target }, oneMax, fmax);
            }
            catch (Exception e)
            {
                Fail("k batch", $"BatchQuery.Raycasts threw {e.GetType().Name}: {e.Message}", new[] { callOne }, true);
                return;
            }
            float v = one[0];
            if (!Spec.Bits(v, many[j]))
                Fail("k batch lane", $"lane {j} of a set of {n} gives {N(many[j])}, a set of one {N(v)}",
                    new[] { $"var shapes = new {type}[] {{ {string.Join(", ", fill.Select((s, i) => i == j ? "target" : s.ToCSharp()))} }};",
                            $"var t = new float[{n}]; BatchQuery.Raycasts(ray, new {set}(shapes), t);", callOne, $"// got t[{j}] = {N(many[j])}, t1[0] = {N(v)}" }, true);
            float wantMax = v <= fmax ? v : float.PositiveInfinity;
            if (!Spec.Bits(oneMax[0], wantMax))
                Fail("k batch lane", $"with maxDistance {N(fmax)} the lane is {N(oneMax[0])}, not {N(wantMax)} (the unlimited {N(v)})",
                    new[] { callOne, $"var tm = new float[1]; BatchQuery.Raycasts(ray, new {set}(new[] {{ target }}), tm, {Lit(fmax)});" }, true);
            var code = new List<string> { callOne, $"// got t[0] = {N(v)}; scalar float cast: {Show(Cast(_ray, _target))}" };
            if (float.IsNaN(v) || float.IsNegative(v)) { Fail("k batch vs exact", $"the lane is {N(v)}", code, true); return; }
            // The batch casts the ray with its direction rounded to float.
            var df = new Vector3D(ray.Direction.X, ray.Direction.Y, ray.Direction.Z);
            var rb = CastRef.For(_target, DyVec.From(_o), DyVec.From(df), _u * BatchBound);
            var s = _s;
            var unit = s * _u + _eta;
            var delta = unit * BatchBound;
            bool hit = !float.IsPositiveInfinity(v);
            var t = hit ? Dy.From(v) : Dy.Zero;
            var problems = new List<string>();
            bool edgeOn = rb is PassRef || rb is TriangleRef tr && tr.InPlane;
            if (edgeOn)
            {
                // A ray in a triangle's plane, or a degenerate triangle: the batch answers as the scalar cast (edge-on, a
                // hit or a miss by the pass-through tolerance): only a hit must be near.
                if (hit && !rb.OnTarget(DyVec.From(_o) + DyVec.From(df) * t, delta + Rho(v) * Dy.From(2)))
                    problems.Add($"hit at T = {N(v)} on an edge-on or degenerate triangle, farther than δ from it");
            }
            else rb.CheckT(hit, t, false, delta, Rho(hit ? v : 0), problems, insideUnknown: true);
            if (problems.Count > 0)
                Fail("k batch vs exact", $"{string.Join("; ", problems)}\nreference (direction rounded to float): {rb.Describe(delta)}; B = {BatchBound}, U = {unit.ToDouble():G4}", code, true);
            if (hit && v > 0 && !edgeOn)
            {
                var wc = rb.WellConditioned(delta);
                if (wc.HasValue) Errors.Add(("batch", wc.Value.Error(t, unit)));
            }
        }
    }
}
