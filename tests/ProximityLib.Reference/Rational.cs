using System;
using System.Numerics;

namespace ProximityReference
{
    /// <summary>An exact rational number over BigInteger, always reduced, denominator positive.</summary>
    public readonly struct Rational : IComparable<Rational>
    {
        public readonly BigInteger N, D;

        public Rational(BigInteger n, BigInteger d)
        {
            if (d.IsZero) throw new DivideByZeroException();
            if (d.Sign < 0) { n = -n; d = -d; }
            var g = BigInteger.GreatestCommonDivisor(n, d);
            if (!g.IsOne && !g.IsZero) { n /= g; d /= g; }
            N = n; D = n.IsZero ? BigInteger.One : d;
        }

        public static readonly Rational Zero = new Rational(0, 1);
        public static readonly Rational One = new Rational(1, 1);

        public int Sign => N.Sign;
        public bool IsZero => N.IsZero;

        /// <summary>The exact value of a finite double (every double is a dyadic rational).</summary>
        public static Rational FromDouble(double x)
        {
            if (!double.IsFinite(x)) throw new ArgumentException("not finite", nameof(x));
            if (x == 0) return Zero;
            long bits = BitConverter.DoubleToInt64Bits(x);
            bool negative = bits < 0;
            int exponent = (int)((bits >> 52) & 0x7FF);
            long mantissa = bits & 0xFFFFFFFFFFFFFL;
            if (exponent == 0) exponent = 1; else mantissa |= 1L << 52;
            exponent -= 1075;
            BigInteger n = negative ? -mantissa : mantissa;
            return exponent >= 0 ? new Rational(n << exponent, 1) : new Rational(n, BigInteger.One << -exponent);
        }

        public static implicit operator Rational(double x) => FromDouble(x);
        public static implicit operator Rational(int x) => new Rational(x, 1);

        public static Rational operator +(Rational a, Rational b) =>
            a.D == b.D ? new Rational(a.N + b.N, a.D) : new Rational(a.N * b.D + b.N * a.D, a.D * b.D);
        public static Rational operator -(Rational a, Rational b) =>
            a.D == b.D ? new Rational(a.N - b.N, a.D) : new Rational(a.N * b.D - b.N * a.D, a.D * b.D);
        public static Rational operator -(Rational a) => new Rational(-a.N, a.D);
        public static Rational operator *(Rational a, Rational b) => new Rational(a.N * b.N, a.D * b.D);
        public static Rational operator /(Rational a, Rational b) => new Rational(a.N * b.D, a.D * b.N);

        public int CompareTo(Rational other) => (N * other.D).CompareTo(other.N * D);
        public static bool operator <(Rational a, Rational b) => a.CompareTo(b) < 0;
        public static bool operator >(Rational a, Rational b) => a.CompareTo(b) > 0;
        public static bool operator <=(Rational a, Rational b) => a.CompareTo(b) <= 0;
        public static bool operator >=(Rational a, Rational b) => a.CompareTo(b) >= 0;
        public static Rational Abs(Rational a) => a.Sign < 0 ? -a : a;
        public static Rational Min(Rational a, Rational b) => a <= b ? a : b;
        public static Rational Max(Rational a, Rational b) => a >= b ? a : b;

        /// <summary>Nearest double (ties and the last bit are not guaranteed: used for reporting, not for E).</summary>
        public double ToDouble()
        {
            if (N.IsZero) return 0;
            // Shift so the quotient carries 64 significant bits, then let the double conversion round.
            long shift = (long)D.GetBitLength() - (long)BigInteger.Abs(N).GetBitLength() + 64;
            var q = shift >= 0 ? (N << (int)shift) / D : N / (D << (int)-shift);
            return Scale((double)q, -shift);
        }

        private static double Scale(double x, long exponent)
        {
            while (exponent > 1000) { x *= Math.Pow(2, 1000); exponent -= 1000; }
            while (exponent < -1000) { x *= Math.Pow(2, -1000); exponent += 1000; }
            return x * Math.Pow(2, exponent);
        }

        /// <summary>√q for q ≥ 0, to within a relative error of 2^-bits (an approximation with a rational value).</summary>
        public static Rational Sqrt(Rational q, int bits = 160)
        {
            if (q.Sign < 0) throw new ArgumentException("negative", nameof(q));
            if (q.IsZero) return Zero;
            // √(N/D) = √(N·D)/D; scale N·D by 4^k so the integer root has `bits` significant bits.
            var nd = q.N * q.D;
            int k = Math.Max(0, bits - (int)(nd.GetBitLength() / 2) + 2);
            var root = ISqrt(nd << (2 * k));
            return new Rational(root, q.D << k);
        }

        private static BigInteger ISqrt(BigInteger n)
        {
            if (n < 2) return n;
            var x = BigInteger.One << (int)((n.GetBitLength() + 1) / 2);
            while (true)
            {
                var y = (x + n / x) >> 1;
                if (y >= x) return x;
                x = y;
            }
        }

        public override string ToString() => ToDouble().ToString("R");
    }
}
