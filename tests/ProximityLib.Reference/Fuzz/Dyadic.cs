using System;
using System.Numerics;
using ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// An exact dyadic number M·2^E. Every double is one, and sums, differences and products of dyadics are dyadics, so
    /// the fuzz's per-case checks (membership, |PB − PA|², support functions, tolerances) are exact over the whole double
    /// range without the GCD reductions that make <see cref="Rational"/> slow. No division.
    /// </summary>
    public readonly struct Dy : IComparable<Dy>
    {
        public readonly BigInteger M;
        public readonly int E;

        public Dy(BigInteger m, int e) { M = m; E = m.IsZero ? 0 : e; }

        public static readonly Dy Zero = default;
        public int Sign => M.Sign;
        public bool IsZero => M.IsZero;

        /// <summary>The exact value of a finite double.</summary>
        public static Dy From(double x)
        {
            if (!double.IsFinite(x)) throw new ArgumentException($"not finite: {x}", nameof(x));
            if (x == 0) return Zero;
            long bits = BitConverter.DoubleToInt64Bits(x);
            int exponent = (int)((bits >> 52) & 0x7FF);
            long mantissa = bits & 0xFFFFFFFFFFFFFL;
            if (exponent == 0) exponent = 1; else mantissa |= 1L << 52;
            return new Dy(bits < 0 ? -mantissa : mantissa, exponent - 1075);
        }

        public static implicit operator Dy(double x) => From(x);

        /// <summary>2^k exactly.</summary>
        public static Dy Pow2(int k) => new Dy(BigInteger.One, k);

        public static Dy operator +(Dy a, Dy b)
        {
            if (a.M.IsZero) return b;
            if (b.M.IsZero) return a;
            int e = Math.Min(a.E, b.E);
            return new Dy((a.M << (a.E - e)) + (b.M << (b.E - e)), e);
        }

        public static Dy operator -(Dy a) => new Dy(-a.M, a.E);
        public static Dy operator -(Dy a, Dy b) => a + (-b);
        public static Dy operator *(Dy a, Dy b) => new Dy(a.M * b.M, a.E + b.E);
        public Dy Times2(int k) => new Dy(M, E + k);
        public Dy Square() => this * this;
        public static Dy Abs(Dy a) => a.M.Sign < 0 ? -a : a;
        public static Dy Max(Dy a, Dy b) => a.CompareTo(b) >= 0 ? a : b;
        public static Dy Min(Dy a, Dy b) => a.CompareTo(b) <= 0 ? a : b;

        public int CompareTo(Dy other) => (this - other).Sign;
        public static bool operator <(Dy a, Dy b) => a.CompareTo(b) < 0;
        public static bool operator >(Dy a, Dy b) => a.CompareTo(b) > 0;
        public static bool operator <=(Dy a, Dy b) => a.CompareTo(b) <= 0;
        public static bool operator >=(Dy a, Dy b) => a.CompareTo(b) >= 0;
        public static bool operator ==(Dy a, Dy b) => a.CompareTo(b) == 0;
        public static bool operator !=(Dy a, Dy b) => a.CompareTo(b) != 0;
        public override bool Equals(object? obj) => obj is Dy d && this == d;
        public override int GetHashCode() => ToDouble().GetHashCode();

        public Rational ToRational() =>
            E >= 0 ? new Rational(M << E, BigInteger.One) : new Rational(M, BigInteger.One << -E);

        /// <summary>log2 |x| rounded down (the exponent of the leading bit); int.MinValue for 0.</summary>
        public int Log2 => M.IsZero ? int.MinValue : (int)BigInteger.Abs(M).GetBitLength() - 1 + E;

        /// <summary>The nearest double, or ±∞ beyond the range (for reporting and for choosing parameters).</summary>
        public double ToDouble()
        {
            if (M.IsZero) return 0;
            var m = M;
            int e = E;
            long len = (long)BigInteger.Abs(m).GetBitLength();
            if (len > 64) { m >>= (int)(len - 64); e += (int)(len - 64); }
            return Scale((double)m, e);
        }

        private static double Scale(double x, long e)
        {
            while (e > 1000 && x != 0 && !double.IsInfinity(x)) { x *= Math.Pow(2, 1000); e -= 1000; }
            while (e < -1000 && x != 0) { x *= Math.Pow(2, -1000); e += 1000; }
            return x * Math.Pow(2, e);
        }

        /// <summary>a / b as a double (for reporting error ratios; no overflow for any operands).</summary>
        public static double Ratio(Dy a, Dy b)
        {
            if (a.IsZero) return 0;
            if (b.IsZero) return double.PositiveInfinity;
            int ea = a.Log2, eb = b.Log2;
            return a.Times2(-ea).ToDouble() / b.Times2(-eb).ToDouble() * Math.Pow(2, Math.Max(-1074, Math.Min(1023, ea - eb)));
        }

        public override string ToString() => ToDouble().ToString("R");
    }

    /// <summary>An exact dyadic 3-vector (2D shapes have z = 0).</summary>
    public readonly struct DyVec
    {
        public readonly Dy X, Y, Z;
        public DyVec(Dy x, Dy y, Dy z) { X = x; Y = y; Z = z; }
        public static DyVec From(Vector3D v) => new DyVec(v.X, v.Y, v.Z);
        public static DyVec operator +(DyVec a, DyVec b) => new DyVec(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static DyVec operator -(DyVec a, DyVec b) => new DyVec(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static DyVec operator -(DyVec a) => new DyVec(-a.X, -a.Y, -a.Z);
        public static DyVec operator *(DyVec a, Dy s) => new DyVec(a.X * s, a.Y * s, a.Z * s);
        public static Dy Dot(DyVec a, DyVec b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public Dy LengthSquared => Dot(this, this);
        public Dy this[int i] => i == 0 ? X : (i == 1 ? Y : Z);
        public RVec ToRVec() => new RVec(X.ToRational(), Y.ToRational(), Z.ToRational());
        public Vector3D ToDouble() => new Vector3D(X.ToDouble(), Y.ToDouble(), Z.ToDouble());
        public DyVec Times2(int k) => new DyVec(X.Times2(k), Y.Times2(k), Z.Times2(k));
    }

    /// <summary>
    /// Exact comparisons involving square roots: is a ≤ √q? (q ≥ 0). Used for distances (|x − y| = √(|x − y|²)) and for
    /// gaps along unnormalised directions (gap/|n|).
    /// </summary>
    public static class DyMath
    {
        /// <summary>a ≤ √q, exactly.</summary>
        public static bool AtMostRoot(Dy a, Dy q) => a.Sign <= 0 || a.Square() <= q;

        /// <summary>a ≥ √q, exactly.</summary>
        public static bool AtLeastRoot(Dy a, Dy q) => a.Sign >= 0 && a.Square() >= q;

        /// <summary>√q as a double (for reports; no under- or overflow in the intermediate square).</summary>
        public static double Sqrt(Dy q)
        {
            if (q.Sign <= 0) return 0;
            int e = q.Log2 & ~1;
            return Math.Sqrt(q.Times2(-e).ToDouble()) * Math.Pow(2, e / 2);
        }

        /// <summary>a·√n2 ≥ g, exactly (n2 ≥ 0).</summary>
        public static bool TimesRootAtLeast(Dy a, Dy n2, Dy g)
        {
            if (a.Sign >= 0) return g.Sign <= 0 || a.Square() * n2 >= g.Square();
            return g.Sign < 0 && a.Square() * n2 <= g.Square();
        }
    }
}
