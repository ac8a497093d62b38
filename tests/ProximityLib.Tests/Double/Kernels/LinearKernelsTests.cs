using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    public class LinearKernelsTests
    {
        /// <summary>
        /// The capsule kernel's inline common case against the general <c>LinearCapsule</c> it stands for (which the fuzz
        /// and the exact families check), every field and inRange bit for bit, 3D and planar. Kinds: 0 general, apart
        /// and overlapping; 1 small-integer grid (parallel, collinear, crossing, shared ends, zero-length axes); 2 axes
        /// 2^-18 … 2^-34 of their size apart (either side of the 2^-26 switch); 3 nearly parallel 1e-2 … 1e-15; 4 mixed
        /// magnitudes 2^-40 … 2^40 with translations up to 2^30; 5 the whole range 2^-1070 … 2^1020.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void CapsuleCapsuleMatchesLinearCapsuleBitForBit(int kind)
        {
            var r = new Random(7300 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            for (int i = 0; i < 12000; i++)
            {
                bool planar = i % 2 == 1;
                Vector3D P(double s) => new Vector3D(U(-s, s), U(-s, s), planar ? 0 : U(-s, s));
                Vector3D Grid() => new Vector3D(r.Next(-3, 4), r.Next(-3, 4), planar ? 0 : r.Next(-3, 4));
                Vector3D a0, a1, b0, b1;
                double ra = r.Next(4) == 0 ? 0 : U(0, 1), rb = U(0, 1);
                switch (kind)
                {
                    case 1:
                        a0 = Grid(); a1 = r.Next(6) == 0 ? a0 : Grid(); b0 = Grid(); b1 = r.Next(6) == 0 ? b0 : Grid();
                        ra = r.Next(3); rb = r.Next(3);
                        break;
                    case 2:
                    case 3:
                        {
                            a0 = P(1); a1 = a0 + P(1);
                            var dA = a1 - a0;
                            var q = P(1);
                            q -= dA * (Vector3D.Dot(q, dA) / dA.LengthSquared);
                            q *= 1 / q.Length;
                            double gap = kind == 2 ? Math.ScaleB(1, -r.Next(18, 35)) : U(0, 1e-3);
                            var p = a0 + dA * U(-0.2, 1.2) + q * gap;
                            var dB = kind == 3 ? dA * U(-1.5, 1.5) + P(Math.Pow(10, -U(2, 15))) : P(1);
                            if (!planar && kind == 2) dB -= q * (Vector3D.Dot(dB, q));
                            b0 = p - dB * U(0, 1); b1 = p + dB * U(0, 1);
                            break;
                        }
                    case 4:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            a0 = t + P(Math.ScaleB(1, r.Next(-40, 41))); a1 = a0 + P(Math.ScaleB(1, r.Next(-40, 41)));
                            b0 = t + P(Math.ScaleB(1, r.Next(-40, 41))); b1 = b0 + P(Math.ScaleB(1, r.Next(-40, 41)));
                            ra *= Math.ScaleB(1, r.Next(-40, 41)); rb *= Math.ScaleB(1, r.Next(-40, 41));
                            break;
                        }
                    case 5:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            a0 = P(s); a1 = P(s); b0 = P(s); b1 = P(s); ra *= s; rb *= s;
                            break;
                        }
                    default: a0 = P(1); a1 = P(1); b0 = P(1); b1 = P(1); break;
                }
                string repro = $"kind {kind}, case {i}, planar {planar}: ({a0}, {a1}, {ra:R}) vs ({b0}, {b1}, {rb:R})";
                var fast = K.CapsuleCapsule(a0, a1, ra, b0, b1, rb, planar, out bool fastIn);
                var general = K.LinearCapsule(Linear.Segment(a0, a1), ra, b0, b1, rb, planar, true, out bool generalIn);
                Assert.That(fastIn, Is.EqualTo(generalIn), repro);
                Assert.That(Bits(fast), Is.EqualTo(Bits(general)), $"{repro}\n  fast    {fast}\n  general {general}");
            }
        }

        private static long[] Bits(DistanceResult3 x) => new[]
        {
            BitConverter.DoubleToInt64Bits(x.Distance), BitConverter.DoubleToInt64Bits(x.DistanceSquared),
            BitConverter.DoubleToInt64Bits(x.PointA.X), BitConverter.DoubleToInt64Bits(x.PointA.Y), BitConverter.DoubleToInt64Bits(x.PointA.Z),
            BitConverter.DoubleToInt64Bits(x.PointB.X), BitConverter.DoubleToInt64Bits(x.PointB.Y), BitConverter.DoubleToInt64Bits(x.PointB.Z),
            BitConverter.DoubleToInt64Bits(x.ParameterA), BitConverter.DoubleToInt64Bits(x.ParameterB),
        };
    }
}
