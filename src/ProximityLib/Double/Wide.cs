using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// The fast path's range. Every kernel reports whether its answer can be trusted, from quantities it forms anyway:
    /// a squared length of the configuration (the squared gap, the segment's squared length, the sum of squared sizes)
    /// in [2^-960, 2^960] leaves every square and product far from underflow and overflow and puts whatever underflows
    /// far below the configuration's rounding; the box kernels check the largest magnitude of their relative
    /// coordinates and extents in [2^-450, 2^450] the same way. An OBB also records at construction whether every stored
    /// value is 0 or within [2^-400, 2^400] (the flag sits beside another, so the struct does not grow): between such
    /// values every non-zero difference lies in [2^-452, 2^401]. What fails a check takes the slow path,
    /// <see cref="Wide"/>. Each check is one or two predictable comparisons.
    /// </summary>
    internal static class Range
    {
        /// <summary>2^-400 and 2^400: the moderate magnitudes of an OBB's stored values.</summary>
        public const double Min = 3.8725919148493183e-121, Max = 2.5822498780869086e+120;
        /// <summary>2^-960 and 2^960: squared lengths in between are far from underflow and overflow.</summary>
        public const double Lo2 = 1.0261342003245941e-289, Hi2 = 9.7453140114e+288;
        /// <summary>2^-480: a length at least this large keeps its rounding far above the subnormal range.</summary>
        public const double Lo = 3.2033329522929615e-145;
        /// <summary>2^-450 and 2^450: the box kernels' relative magnitudes.</summary>
        public const double BoxMin = 3.4395525670743494e-136, BoxMax = 2.9073548971824276e+135;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Moderate(double x)
        {
            double m = Math.Abs(x);
            return m == 0 || (m >= Min && m <= Max);
        }

        public static bool Moderate(Vector3D v) => Moderate(v.X) && Moderate(v.Y) && Moderate(v.Z);
        public static bool Moderate(Vector2D v) => Moderate(v.X) && Moderate(v.Y);

        /// <summary>Whether a squared length x2 (≥ 0) lies in [2^-960, 2^960]: one subtraction and one unsigned compare of its bits; NaN and ∞ fail.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool In(double x2) => (ulong)(BitConverter.DoubleToInt64Bits(x2) - Lo2Bits) <= Span2Bits;

        /// <summary>
        /// Whether the larger of two squares (≥ 0) lies in [2^-960, 2^960]: one check where testing each would cost two,
        /// for verdicts x2 ≤ y2 that only need the larger one trusted. A NaN <paramref name="x2"/> fails: Num.Max returns it
        /// (maxsd returns its second operand when either is NaN; Math.Max returns NaN).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool LargerIn(double y2, double x2) => In(Num.Max(y2, x2));

        private const long Lo2Bits = (1023L - 960) << 52;
        private const ulong Span2Bits = 1920UL << 52;

        /// <summary>
        /// Whether a squared length v2 = |v|² can be trusted: in [2^-960, 2^960], or exactly 0 because v is. NaN (an
        /// overflowed difference) fails.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Length2(Vector3D v, double v2) => In(v2) || (v.X == 0 && v.Y == 0 && v.Z == 0);

        /// <summary><see cref="Length2(Vector3D, double)"/> of the vector (x, y, z), for kernels in plain doubles.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Length2(double x, double y, double z, double v2) => In(v2) || (x == 0 && y == 0 && z == 0);

        /// <summary>Whether the largest relative magnitude m of a box kernel lies in [2^-450, 2^450] or is 0 (everything coincides).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Box(double m) => (m >= BoxMin && m <= BoxMax) || m == 0;

        /// <summary>
        /// The largest magnitude of v's components, by the hardware max (<see cref="Num.Max"/>; Math.Max spends eight more
        /// instructions on NaN and zero-sign rules). Range checks take it, and the larger of several such values by
        /// Num.Max too, of differences of finite coordinates, extents and radii: never NaN (an overflowed difference is
        /// ∞, which the hardware max orders, so the check still fails) and never −0 (magnitudes), where both maxes agree.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double MaxAbs(Vector3D v) => Num.Max(Math.Abs(v.X), Num.Max(Math.Abs(v.Y), Math.Abs(v.Z)));

        /// <summary>The largest magnitude of v's components, as for 3D.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double MaxAbs(Vector2D v) => Num.Max(Math.Abs(v.X), Math.Abs(v.Y));

        /// <summary>The largest magnitude over three vectors' components (a range check's offsets and extents).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double MaxAbs(Vector3D a, Vector3D b, Vector3D c) => Num.Max(MaxAbs(a), Num.Max(MaxAbs(b), MaxAbs(c)));

        /// <summary>As for 3D.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double MaxAbs(Vector2D a, Vector2D b, Vector2D c) => Num.Max(MaxAbs(a), Num.Max(MaxAbs(b), MaxAbs(c)));

        /// <summary>The largest magnitude over four vectors' components.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double MaxAbs(Vector3D a, Vector3D b, Vector3D c, Vector3D d) => Num.Max(Num.Max(MaxAbs(a), MaxAbs(b)), Num.Max(MaxAbs(c), MaxAbs(d)));
    }

    /// <summary>A shape that the slow path can measure and rescale by a power of two.</summary>
    internal interface IScalable<T> where T : struct
    {
        /// <summary>Feeds every stored point and length to the rescaling.</summary>
        void Measure(ref Rescale s);

        /// <summary>The same shape in the rescaled frame.</summary>
        T Rescaled(in Rescale s);
    }

    /// <summary>
    /// Maps a configuration outside the fast path's range into it and the answer back. Normally a pure power-of-two
    /// scaling that brings the largest magnitude into [1, 2): it is exact (up to subnormal results), so the answer is
    /// bit for bit the fast path's on the scaled inputs, and 2^k-scaled inputs give 2^k-scaled answers across the
    /// boundary of the two paths. Only a configuration tiny against its own position (size below 2^-400 of its
    /// coordinates, which pure scaling would underflow) is first translated next to the origin; that translation
    /// rounds once per coordinate, at the configuration's scale.
    /// </summary>
    internal struct Rescale
    {
        private Vector3D _lo, _hi;                  // componentwise bounds of every point
        private bool _started, _translate;
        private double _abs, _len;                  // largest |coordinate|, largest length
        private double _down1, _down2, _up1, _up2;  // 2^-e and 2^e, each as two factors that stay in range

        public void Point(Vector3D p)
        {
            if (!_started) { _lo = _hi = p; _started = true; }
            _lo = new Vector3D(Math.Min(_lo.X, p.X), Math.Min(_lo.Y, p.Y), Math.Min(_lo.Z, p.Z));
            _hi = new Vector3D(Math.Max(_hi.X, p.X), Math.Max(_hi.Y, p.Y), Math.Max(_hi.Z, p.Z));
            _abs = Math.Max(_abs, Range.MaxAbs(p));
        }

        public void Point(Vector2D p) => Point(p.To3());

        public void Length(double r) => _len = Math.Max(_len, r);

        /// <summary>
        /// Chooses the frame once every shape is measured. It depends only on the set of values, not on which shape
        /// they came from, so both argument orders get the same frame. The translation origin is the componentwise
        /// minimum, within the configuration's size of every point.
        /// </summary>
        public void Decide()
        {
            double abs = Math.Max(_abs, _len);
            double rel = Math.Max(_len, Range.MaxAbs(_hi - _lo));
            _translate = rel < abs * Range.Min;
            double m = _translate ? rel : abs;
            int e = m > 0 ? Exponent(m) : 0;
            Split(-e, out _down1, out _down2);
            Split(e, out _up1, out _up2);
        }

        public Vector3D Apply(Vector3D p) => (_translate ? p - _lo : p) * _down1 * _down2;
        public Vector2D Apply(Vector2D p) => Vector2D.From3(Apply(p.To3()));
        public double Apply(double length) => length * _down1 * _down2;

        private Vector3D Back(Vector3D p) => _translate ? _lo + p * _up1 * _up2 : p * _up1 * _up2;

        /// <summary>
        /// A coordinate range of the original frame (the largest magnitude a witness may have) in the rescaled one: a
        /// point within it there maps back within <paramref name="range"/>. Exactly range·2^-e for a pure scaling; with
        /// the translation, what the translation origin leaves of it (never negative; a translated configuration lies
        /// far inside the range, so this only bounds unbounded shapes' points).
        /// </summary>
        public double ApplyRange(double range) =>
            (_translate ? Math.Max(0, range - Range.MaxAbs(_lo)) * (1 - 1.0 / (1L << 52)) : range) * _down1 * _down2;

        /// <summary>The answer in the original frame; a line's or ray's parameter (<paramref name="lengthA"/>, <paramref name="lengthB"/>) is a length and scales back too.</summary>
        public DistanceResult3 Back(in DistanceResult3 r, bool lengthA, bool lengthB) =>
            new DistanceResult3(r.Distance * _up1 * _up2, r.DistanceSquared * _up1 * _up1 * _up2 * _up2,
                Back(r.PointA), Back(r.PointB), lengthA ? r.ParameterA * _up1 * _up2 : r.ParameterA, lengthB ? r.ParameterB * _up1 * _up2 : r.ParameterB);

        /// <summary>As for 3D.</summary>
        public DistanceResult2 Back(in DistanceResult2 r, bool lengthA, bool lengthB) =>
            new DistanceResult2(r.Distance * _up1 * _up2, r.DistanceSquared * _up1 * _up1 * _up2 * _up2,
                Vector2D.From3(Back(r.PointA.To3())), Vector2D.From3(Back(r.PointB.To3())),
                lengthA ? r.ParameterA * _up1 * _up2 : r.ParameterA, lengthB ? r.ParameterB * _up1 * _up2 : r.ParameterB);

        /// <summary>A ray hit mapped back: T scales like a length, the normal is a direction and stays.</summary>
        public RayHit3 Back(in RayHit3 h) => h.Hit ? new RayHit3(h.T * _up1 * _up2, Back(h.Point), h.Normal, h.StartsInside) : h;

        public RayHit2 Back(in RayHit2 h) =>
            h.Hit ? new RayHit2(h.T * _up1 * _up2, Vector2D.From3(Back(h.Point.To3())), h.Normal, h.StartsInside) : h;


        /// <summary>floor(log2 m) for a finite m &gt; 0, subnormals included.</summary>
        private static int Exponent(double m)
        {
            int bias = 0;
            if (m < 1e-300) { m *= 1267650600228229401496703205376.0; bias = 100; } // 2^100 lifts subnormals to normal
            return (int)((BitConverter.DoubleToInt64Bits(m) >> 52) & 0x7FF) - 1023 - bias;
        }

        /// <summary>2^n as two normal factors (|n| ≤ 2046).</summary>
        private static void Split(int n, out double f1, out double f2)
        {
            int n1 = n / 2;
            f1 = Pow2(n1);
            f2 = Pow2(n - n1);
        }

        private static double Pow2(int n) => BitConverter.Int64BitsToDouble((long)(n + 1023) << 52);
    }

    /// <summary>
    /// The slow path: a configuration with a shape outside the moderate range, or a point pair whose squared distance
    /// left [2^-960, 2^960], is rescaled (<see cref="Rescale"/>), answered by the same kernel, and mapped back. Rare by
    /// construction (float inputs never need it beyond coincident points), so it is kept out of line.
    /// </summary>
    internal static class Wide
    {
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 Between<TA, TB>(TA a, TB b, Func<TA, TB, DistanceResult3> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(a, b);
            return s.Back(core(a.Rescaled(s), b.Rescaled(s)), LengthParameter<TA>(), LengthParameter<TB>());
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 Between<TA, TB>(TA a, TB b, Func<TA, TB, DistanceResult2> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(a, b);
            return s.Back(core(a.Rescaled(s), b.Rescaled(s)), LengthParameter<TA>(), LengthParameter<TB>());
        }

        /// <summary>
        /// <see cref="Between{TA, TB}(TA, TB, Func{TA, TB, DistanceResult3})"/> for a kernel told the range its witnesses
        /// must stay in (<paramref name="range"/> in the original frame, handed to it in the rescaled one), so the
        /// answer it maps back stays finite.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 Between<TA, TB>(TA a, TB b, double range, Func<TA, TB, double, DistanceResult3> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(a, b);
            return s.Back(core(a.Rescaled(s), b.Rescaled(s), s.ApplyRange(range)), LengthParameter<TA>(), LengthParameter<TB>());
        }

        /// <summary>As for 3D.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 Between<TA, TB>(TA a, TB b, double range, Func<TA, TB, double, DistanceResult2> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(a, b);
            return s.Back(core(a.Rescaled(s), b.Rescaled(s), s.ApplyRange(range)), LengthParameter<TA>(), LengthParameter<TB>());
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        public static bool Overlaps<TA, TB>(TA a, TB b, Func<TA, TB, bool> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(a, b);
            return core(a.Rescaled(s), b.Rescaled(s));
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        public static RayHit3 Cast<TA, TB>(TA ray, TB b, Func<TA, TB, RayHit3> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(ray, b);
            return s.Back(core(ray.Rescaled(s), b.Rescaled(s)));
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        public static RayHit2 Cast<TA, TB>(TA ray, TB b, Func<TA, TB, RayHit2> core)
            where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = Measure(ray, b);
            return s.Back(core(ray.Rescaled(s), b.Rescaled(s)));
        }

        /// <summary>Whether the shape's result parameter is a length (a line's or ray's t), which scales with the frame.</summary>
        private static bool LengthParameter<T>() =>
            typeof(T) == typeof(Line3) || typeof(T) == typeof(Ray3) || typeof(T) == typeof(Line2) || typeof(T) == typeof(Ray2);

        private static Rescale Measure<TA, TB>(TA a, TB b) where TA : struct, IScalable<TA> where TB : struct, IScalable<TB>
        {
            var s = default(Rescale);
            a.Measure(ref s);
            b.Measure(ref s);
            s.Decide();
            return s;
        }
    }
}
