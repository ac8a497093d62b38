using System;
using ProximityLib.Batch;
using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>One case measured: error of the double and float APIs against the exact answer, and the overlap verdicts.</summary>
    public readonly struct Measurement
    {
        public string Family { get; init; }
        public string Pair { get; init; }
        public double ErrorDouble { get; init; }
        public double ErrorFloat { get; init; }
        public double ErrorDoubleSwapped { get; init; }
        /// <summary>True when the exact margin is outside the band and the boolean disagrees with the exact verdict.</summary>
        public bool WrongOverlapDouble { get; init; }
        public bool WrongOverlapFloat { get; init; }
        public bool FloatMeasured { get; init; }
        /// <summary>E of the SIMD batch query on the float inputs, where the pair has one (NaN otherwise).</summary>
        public double ErrorBatch { get; init; }
        public double Exact { get; init; }
        public double Scale { get; init; }
        public string Case { get; init; }
        /// <summary>The paper's formula for this pair, when it has one: its E (distances) or whether it was wrong (booleans).</summary>
        public string? Baseline { get; init; }
        public double BaselineError { get; init; }
        public bool BaselineWrong { get; init; }
    }

    public static class Measure
    {
        private static (string?, double, bool) RunBaseline(Case c, Rational exact, double scale, bool decided)
        {
            double E(double d) => Exact.Error(d, exact, UDouble, scale);
            switch (c.A, c.B)
            {
                case (Vector3D p, Segment3 s): return ("paper Eq. 9–11", E(PaperFormulas.PointSegment(p, s.Start, s.End)), false);
                case (Segment3 s, Vector3D p): return ("paper Eq. 9–11", E(PaperFormulas.PointSegment(p, s.Start, s.End)), false);
                case (Vector2D p, Segment2 s):
                    return ("paper Eq. 9–11", E(PaperFormulas.PointSegment(new Vector3D(p.X, p.Y, 0), new Vector3D(s.Start.X, s.Start.Y, 0), new Vector3D(s.End.X, s.End.Y, 0))), false);
                case (Segment3 a, Segment3 b): return ("paper Eq. 13 (normal equations)", E(PaperFormulas.SegmentSegment(a.Start, a.End, b.Start, b.End)), false);
                case (Segment2 a, Segment2 b): return ("paper Eq. 14–15", E(PaperFormulas.SegmentSegment2(a.Start, a.End, b.Start, b.End)), false);
                case (Obb3 a, Obb3 b): return ("SAT without ε (Eq. 19–20)", 0, decided && PaperFormulas.ObbObbOverlaps(a, b) != (exact.Sign <= 0));
                default: return (null, 0, false);
            }
        }

        public const double UDouble = 1.0 / (1L << 53);
        public const double UFloat = 1.0 / (1 << 24);
        /// <summary>Booleans may answer either way when the exact signed distance is within this many u·S of zero.</summary>
        public const double Band = 32;

        /// <summary>The batch queries' safe range for the configuration's scale S: 2^±28.</summary>
        public const double BatchMinScale = 1.0 / (1 << 28), BatchMaxScale = 1 << 28;

        /// <summary>
        /// The promised bound on E for a pair (docs/api.md): 16 for the one-step kernels (point–point, point–AABB,
        /// point–segment, and a circle/sphere against a point, a segment, a circle/sphere or an AABB), else 32.
        /// </summary>
        public static double Bound(string pairKey)
        {
            string pair = pairKey.Substring(pairKey.IndexOf(' ') + 1);
            return pair.Contains("OBB") || pair == "segment–segment" || pair == "AABB–AABB" || pair == "segment–AABB" ? 32 : 16;
        }

        /// <summary>The batch query's distance for one pair, through sets of one, when the batch API covers the pair.</summary>
        private static float? Batch(object a, object b)
        {
            var d = new float[1];
            switch (a, b)
            {
                case (ProximityLib.Sphere x, ProximityLib.Sphere y): BatchQuery.Distances(new SphereSet(new[] { x }), new SphereSet(new[] { y }), d); return d[0];
                case (System.Numerics.Vector3 x, ProximityLib.Aabb3 y): BatchQuery.Distances(new PointSet(new[] { x }), new AabbSet(new[] { y }), d); return d[0];
                case (ProximityLib.Sphere x, ProximityLib.Aabb3 y): BatchQuery.Distances(new SphereSet(new[] { x }), new AabbSet(new[] { y }), d); return d[0];
                case (ProximityLib.Sphere x, ProximityLib.Obb3 y): BatchQuery.Distances(new SphereSet(new[] { x }), new ObbSet(new[] { y }), d); return d[0];
                case (ProximityLib.Segment3 x, ProximityLib.Segment3 y): BatchQuery.Distances(new SegmentSet(new[] { x }), new SegmentSet(new[] { y }), d); return d[0];
                case (ProximityLib.Segment2 x, ProximityLib.Segment2 y): BatchQuery.Distances(new SegmentSet(new[] { Flat(x) }), new SegmentSet(new[] { Flat(y) }), d); return d[0];
                default: return null;
            }
        }

        /// <summary>A 2D segment as the batch API takes it: a 3D segment in the z = 0 plane.</summary>
        public static ProximityLib.Segment3 Flat(ProximityLib.Segment2 s) =>
            new ProximityLib.Segment3(new System.Numerics.Vector3(s.Start, 0), new System.Numerics.Vector3(s.End, 0));

        public static Measurement Run(Case c)
        {
            var ra = RShape.FromAny(c.A);
            var rb = RShape.FromAny(c.B);
            var exact = Exact.SignedDistance(ra, rb);
            double scale = Exact.Scale(ra, rb);
            double d = Api.BetweenDistance(c.A, c.B);
            double ds = Api.BetweenDistance(c.B, c.A);
            bool overlaps = Api.Overlaps(c.A, c.B);
            bool decided = Math.Abs(exact.ToDouble()) > Band * UDouble * scale;

            // The float API on the same inputs rounded to float, against the exact answer for those rounded inputs.
            double ef = 0, eb = double.NaN;
            bool wrongF = false, floatMeasured = false;
            object? fa = null, fb = null;
            try { fa = Shapes.ToFloat(c.A); fb = Shapes.ToFloat(c.B); }
            catch (ArgumentException) { /* inputs outside the float range: not a float case */ }
            if (fa != null && fb != null)
            {
                var fra = RShape.FromAny(Shapes.Widen(fa));
                var frb = RShape.FromAny(Shapes.Widen(fb));
                var fexact = Exact.SignedDistance(fra, frb);
                double fscale = Exact.Scale(fra, frb);
                float df = (float)Api.BetweenDistance(fa, fb);
                if (fscale > 0 && double.IsFinite(fscale) && fscale < 1e30)
                {
                    floatMeasured = true;
                    ef = Exact.Error(df, fexact, UFloat, fscale);
                    bool fo = Api.Overlaps(fa, fb);
                    // The batch runs in float lanes: inside its documented safe range only (squares of the configuration's
                    // size must stay normal floats).
                    float? db = fscale >= BatchMinScale && fscale <= BatchMaxScale ? Batch(fa, fb) ?? Batch(fb, fa) : null;
                    if (db.HasValue) eb = Exact.Error(db.Value, fexact, UFloat, fscale);
                    wrongF = Math.Abs(fexact.ToDouble()) > Band * UFloat * fscale && fo != (fexact.Sign <= 0);
                }
            }

            var (baseline, baselineError, baselineWrong) = RunBaseline(c, exact, scale, decided);
            return new Measurement
            {
                Baseline = baseline,
                BaselineError = baselineError,
                BaselineWrong = baselineWrong,
                Family = c.Family,
                Pair = Shapes.PairKey(c.A, c.B),
                ErrorDouble = Exact.Error(d, exact, UDouble, scale),
                ErrorDoubleSwapped = Exact.Error(ds, exact, UDouble, scale),
                ErrorFloat = ef,
                ErrorBatch = eb,
                FloatMeasured = floatMeasured,
                WrongOverlapDouble = decided && overlaps != (exact.Sign <= 0),
                WrongOverlapFloat = wrongF,
                Exact = exact.ToDouble(),
                Scale = scale,
                Case = c.ToString(),
            };
        }
    }
}
