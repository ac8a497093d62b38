// Copied from src/ProximityLib/Num.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib
{
    internal static class Num
    {
        // Math.Clamp throws when lo > hi; queries must never throw, and callers guarantee lo <= hi anyway.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Clamp(double x, double lo, double hi) => Math.Min(Math.Max(x, lo), hi);

        // Max, Min and FastClamp are for operands that are never NaN and never two zeros of opposite sign (shapes store no
        // −0, and a difference of distinct values is not zero): there they equal Math.Max/Min bit for bit, which on .NET
        // spend three instructions each on NaN and zero-sign rules that the hardware's maxsd/minsd leave out.
#if NET
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Max(double x, double y) => double.MaxNative(x, y);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Min(double x, double y) => double.MinNative(x, y);
#else
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Max(double x, double y) => Math.Max(x, y);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Min(double x, double y) => Math.Min(x, y);
#endif

        /// <summary><see cref="Clamp"/> by <see cref="Max"/> and <see cref="Min"/> (the same operand rules).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double FastClamp(double x, double lo, double hi) => Min(Max(x, lo), hi);

        public static void Finite(double value, string name)
        {
            if (!double.IsFinite(value)) throw new ArgumentException($"{name} must be finite (got {value}).", name);
        }

        public static void NonNegative(double value, string name)
        {
            Finite(value, name);
            if (value < 0) throw new ArgumentException($"{name} must be non-negative (got {value}).", name);
        }

        /// <summary>
        /// x + 0, which is x except that −0 becomes 0. Shapes store no −0: where two shapes agree in a coordinate, their
        /// difference is then +0 in either argument order, so symmetric kernels give answers whose zero signs agree too.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double NoNegativeZero(double x) => x + 0.0;

        public static Double.Vector3D NoNegativeZero(Double.Vector3D v) => new Double.Vector3D(v.X + 0.0, v.Y + 0.0, v.Z + 0.0);
        public static Double.Vector2D NoNegativeZero(Double.Vector2D v) => new Double.Vector2D(v.X + 0.0, v.Y + 0.0);

        public static void Finite(Double.Vector3D v, string name)
        {
            if (!v.IsFinite) throw new ArgumentException($"{name} must have finite components (got {v}).", name);
        }

        public static void Finite(Double.Vector2D v, string name)
        {
            if (!v.IsFinite) throw new ArgumentException($"{name} must have finite components (got {v}).", name);
        }

        /// <summary>
        /// The power of two 2^−⌊log2 m⌋ for a positive finite m (clamped to the normal range, so a subnormal m gets 2^1022):
        /// it brings m into [2^−52, 4), where sums of a few squares neither overflow nor underflow, and multiplying by it
        /// is exact. Math.ScaleB/ILogB are not in netstandard2.1.
        /// </summary>
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.AggressiveInlining)]
        public static double InversePowerOfTwo(double m)
        {
            long exponent = ((BitConverter.DoubleToInt64Bits(m) >> 52) & 0x7FF) - 1023;
            exponent = Math.Min(1022, Math.Max(-1022, exponent));
            return BitConverter.Int64BitsToDouble((1023 - exponent) << 52);
        }

        /// <summary>
        /// The unit vector along a finite non-zero v: v·k (k a power of two, exact) divided by its length l, so |v|² neither
        /// overflows nor underflows for any finite v; |v| = l / k. Throws <see cref="ArgumentException"/> naming the
        /// parameter on a zero or non-finite v.
        /// </summary>
        public static Double.Vector3D Unit(Double.Vector3D v, string name, out double k, out double l)
        {
            Finite(v, name);
            double m = Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));
            if (m == 0) throw new ArgumentException($"{name} must be non-zero (got {v}).", name);
            k = InversePowerOfTwo(m);
            var u = v * k;
            l = u.Length;
            return NoNegativeZero(u / l);
        }

        public static Double.Vector2D Unit(Double.Vector2D v, string name, out double k, out double l)
        {
            Finite(v, name);
            double m = Math.Max(Math.Abs(v.X), Math.Abs(v.Y));
            if (m == 0) throw new ArgumentException($"{name} must be non-zero (got {v}).", name);
            k = InversePowerOfTwo(m);
            var u = v * k;
            l = u.Length;
            return NoNegativeZero(u / l);
        }
    }
}
