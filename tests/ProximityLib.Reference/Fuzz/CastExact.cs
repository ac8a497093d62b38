using System;
using System.Numerics;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// An exact real (P + Q·√D)/R with R &gt; 0 and D ≥ 0: the parameter of a ray's first hit on a polytope (Q = 0) or on a
    /// ball, cylinder or capsule (the smaller root of a quadratic with dyadic coefficients). Every comparison is exact
    /// (signs of a + b·√c decided on squares); <see cref="ToDouble"/> and <see cref="Error"/> are for reports and E.
    /// </summary>
    public readonly struct Surd
    {
        public readonly Dy P, Q, D, R;

        public Surd(Dy p, Dy q, Dy d, Dy r)
        {
            if (r.Sign == 0) throw new ArgumentException("zero denominator", nameof(r));
            if (d.Sign < 0) throw new ArgumentException("negative radicand", nameof(d));
            if (r.Sign < 0) { p = -p; q = -q; r = -r; }
            if (d.IsZero) q = Dy.Zero;
            P = p; Q = q; D = d; R = r;
        }

        public static Surd Of(Dy x) => new Surd(x, Dy.Zero, Dy.Zero, Dy.From(1));
        public static Surd Ratio(Dy num, Dy den) => new Surd(num, Dy.Zero, Dy.Zero, den);
        public static readonly Surd Zero = Of(Dy.Zero);

        public bool IsRational => Q.IsZero;

        /// <summary>The sign of x + y·√d (d ≥ 0), exactly.</summary>
        public static int SignOf(Dy x, Dy y, Dy d)
        {
            int sx = x.Sign, sy = d.IsZero ? 0 : y.Sign;
            if (sy == 0) return sx;
            if (sx == 0 || sx == sy) return sy;
            // Opposite signs: compare x² with y²·d.
            int c = (x.Square() - y.Square() * d).Sign;
            return c == 0 ? 0 : c > 0 ? sx : sy;
        }

        /// <summary>The sign of x + y·√a + z·√b (a, b ≥ 0), exactly.</summary>
        public static int SignOf(Dy x, Dy y, Dy a, Dy z, Dy b)
        {
            int s1 = SignOf(x, y, a), s2 = b.IsZero ? 0 : z.Sign;
            if (s2 == 0) return s1;
            if (s1 == 0 || s1 == s2) return s2;
            // |x + y√a| against |z|√b: (x + y√a)² − z²b = x² + a·y² − z²b + 2xy·√a.
            int c = SignOf(x.Square() + a * y.Square() - z.Square() * b, Dy.From(2) * x * y, a);
            return c == 0 ? 0 : c > 0 ? s1 : s2;
        }

        /// <summary>sign(this − v).</summary>
        public int CompareTo(Dy v) => SignOf(P - v * R, Q, D);

        /// <summary>sign(this − num/den), den ≠ 0.</summary>
        public int CompareTo(Dy num, Dy den)
        {
            int s = den.Sign;
            // (P + Q√D)/R − num/den, times R·|den| > 0.
            return SignOf(P * den * s - num * R * s, Q * den * s, D);
        }

        /// <summary>sign(this − o).</summary>
        public int CompareTo(Surd o) => SignOf(P * o.R - o.P * R, Q * o.R, D, -(o.Q * R), o.D);

        public static Surd Min(Surd a, Surd b) => a.CompareTo(b) <= 0 ? a : b;

        /// <summary>The value as a double (for reports and for choosing parameters).</summary>
        public double ToDouble() => Dy.Ratio(P + Q * Roots.Sqrt(D, 80), R);

        /// <summary>|x − this|, approximately (the root to 200 bits; relative error far below anything reported).</summary>
        public Dy AbsDiff(Dy x, out Dy denominator)
        {
            denominator = R;
            return Dy.Abs(x * R - P - Q * Roots.Sqrt(D, 200));
        }

        /// <summary>|x − this| / unit as a double (E in units of unit).</summary>
        public double Error(Dy x, Dy unit)
        {
            var diff = AbsDiff(x, out var den);
            return Dy.Ratio(diff, den * unit);
        }

        public override string ToString() => ToDouble().ToString("R");
    }

    /// <summary>Square roots of dyadics to a given precision, and exact vector helpers the cast reference needs.</summary>
    public static class Roots
    {
        /// <summary>floor(√n) for n ≥ 0 (Newton's method on integers).</summary>
        public static BigInteger ISqrt(BigInteger n)
        {
            if (n.Sign < 0) throw new ArgumentException("negative", nameof(n));
            if (n < 2) return n;
            int bits = (int)((n.GetBitLength() + 1) / 2);
            var x = BigInteger.One << bits; // ≥ √n
            while (true)
            {
                var y = (x + n / x) >> 1;
                if (y >= x) return x;
                x = y;
            }
        }

        /// <summary>√q rounded down to about <paramref name="bits"/> significant bits (q ≥ 0).</summary>
        public static Dy Sqrt(Dy q, int bits)
        {
            if (q.Sign <= 0) return Dy.Zero;
            var m = q.M;
            int e = q.E;
            int shift = Math.Max(0, 2 * bits - (int)m.GetBitLength());
            if (((e - shift) & 1) != 0) shift++;
            return new Dy(ISqrt(m << shift), (e - shift) / 2);
        }

        /// <summary>A dyadic upper bound of √q within a relative 2^−60.</summary>
        public static Dy SqrtUpper(Dy q)
        {
            var s = Sqrt(q, 64);
            return s.IsZero ? s : new Dy(s.M + 1, s.E);
        }

        public static DyVec Cross(DyVec a, DyVec b) => new DyVec(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        public static Dy MaxAbs(DyVec v) => Dy.Max(Dy.Abs(v.X), Dy.Max(Dy.Abs(v.Y), Dy.Abs(v.Z)));

        /// <summary>Exact squared distance from x to the segment [a, b] (a point when a = b), as num/den with den &gt; 0.</summary>
        public static (Dy Num, Dy Den) SegmentDistance2(DyVec x, DyVec a, DyVec b)
        {
            var e = b - a;
            var w = x - a;
            var ee = e.LengthSquared;
            var we = DyVec.Dot(w, e);
            var one = Dy.From(1);
            if (ee.IsZero || we.Sign <= 0) return (w.LengthSquared, one);
            if (we >= ee) return ((x - b).LengthSquared, one);
            return (w.LengthSquared * ee - we.Square(), ee);
        }

        /// <summary>Is x within tol of the segment [a, b]? Exact.</summary>
        public static bool NearSegment(DyVec x, DyVec a, DyVec b, Dy tol)
        {
            if (tol.Sign < 0) return false;
            var (n, d) = SegmentDistance2(x, a, b);
            return n <= tol.Square() * d;
        }

        /// <summary>Is x within tol of the line through p along e (e ≠ 0), or of the ray (s ≥ 0) when <paramref name="half"/>? Exact.</summary>
        public static bool NearLinear(DyVec x, DyVec p, DyVec e, bool half, Dy tol)
        {
            if (tol.Sign < 0) return false;
            var w = x - p;
            var we = DyVec.Dot(w, e);
            if (half && we.Sign <= 0) return w.LengthSquared <= tol.Square();
            var ee = e.LengthSquared;
            return w.LengthSquared * ee - we.Square() <= tol.Square() * ee;
        }
    }
}
