using System;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// SplitMix64: a small, fully specified generator, so a case drawn from (seed, index) is the same on every runtime
    /// and machine (System.Random's seeded algorithm is an implementation detail).
    /// </summary>
    public sealed class Rng
    {
        private ulong _state;

        public Rng(ulong seed) { _state = seed; }

        /// <summary>The generator of case <paramref name="index"/> of run <paramref name="seed"/>.</summary>
        public static Rng ForCase(long seed, long index) => new Rng(Mix((ulong)seed * 0x9E3779B97F4A7C15UL) ^ Mix((ulong)index + 0x632BE59BD9B4E019UL));

        public static ulong Mix(ulong z)
        {
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
            return z ^ (z >> 31);
        }

        public ulong Next() => Mix(_state += 0x9E3779B97F4A7C15UL);

        /// <summary>Uniform in [0, 1).</summary>
        public double Unit() => (Next() >> 11) * (1.0 / (1UL << 53));

        public double Range(double lo, double hi) => lo + (hi - lo) * Unit();

        /// <summary>Uniform integer in [0, n).</summary>
        public int Int(int n) => (int)(Next() % (ulong)n);

        /// <summary>Uniform integer in [lo, hi].</summary>
        public int Int(int lo, int hi) => lo + Int(hi - lo + 1);

        public bool Chance(double p) => Unit() < p;

        public double Sign() => (Next() & 1) == 0 ? 1 : -1;

        public T Pick<T>(params T[] items) => items[Int(items.Length)];

        public double Gauss() => Math.Sqrt(-2 * Math.Log(1 - Unit())) * Math.Cos(2 * Math.PI * Unit());

        /// <summary>2^x with x uniform in [lo, hi] (log-uniform magnitudes).</summary>
        public double Pow2(double lo, double hi) => Math.Pow(2, Range(lo, hi));

        /// <summary>10^−x with x uniform in [lo, hi].</summary>
        public double Pow10Neg(double lo, double hi) => Math.Pow(10, -Range(lo, hi));
    }
}
