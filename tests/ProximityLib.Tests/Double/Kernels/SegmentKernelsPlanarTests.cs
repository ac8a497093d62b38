using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>
    /// The planar segment–segment kernel against the 3D kernel on lifted inputs, which the fuzz and the exact families
    /// check: every field bit for bit (so the planar one inherits their verdicts), on seeded pairs aimed at the branches.
    /// </summary>
    public class SegmentKernelsPlanarTests
    {
        /// <summary>
        /// Kinds: 0 general; 1 small-integer grid (exact zeros: touching, collinear, crossing at ends, shared and
        /// zero-length segments); 2 nearly parallel (1e-1 … 1e-15) at offsets 0 … 1e-3, shifted along; 3 nearly collinear
        /// and overlapping; 4 one segment of length 0 or tiny beside the other; 5 mixed magnitudes 2^-40 … 2^40 and a
        /// common translation up to 2^30; 6 the whole range, 2^-1070 … 2^1020 (subnormal, out-of-range and huge pairs).
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        [TestCase(6)]
        public void MatchesTheLiftedKernelBitForBit(int kind)
        {
            var r = new Random(7100 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            Vector2D P(double s) => new Vector2D(U(-s, s), U(-s, s));
            Vector2D Grid() => new Vector2D(r.Next(-3, 4), r.Next(-3, 4));
            for (int i = 0; i < 20000; i++)
            {
                Vector2D a0, a1, b0, b1;
                switch (kind)
                {
                    case 1: a0 = Grid(); a1 = Grid(); b0 = Grid(); b1 = Grid(); break;
                    case 2:
                    case 3:
                        {
                            double angle = U(0, 2 * Math.PI), theta = Math.Pow(10, -U(1, 15)) * (r.Next(2) * 2 - 1);
                            var da = new Vector2D(Math.Cos(angle), Math.Sin(angle));
                            var db = new Vector2D(Math.Cos(angle + theta), Math.Sin(angle + theta));
                            var normal = new Vector2D(-da.Y, da.X);
                            double h = kind == 3 ? 0 : r.Next(3) == 0 ? 0 : Math.Pow(10, -U(3, 16));
                            a0 = P(1);
                            a1 = a0 + da * U(0.1, 2);
                            b0 = a0 + da * U(-1, 1.5) + normal * h;
                            b1 = b0 + db * U(0.1, 2) * (r.Next(2) * 2 - 1);
                            break;
                        }
                    case 4:
                        a0 = P(1); a1 = a0 + P(r.Next(2) == 0 ? 0 : 1e-12); b0 = P(1); b1 = P(1);
                        if (r.Next(2) == 0) (a0, a1, b0, b1) = (b0, b1, a0, a1);
                        break;
                    case 5:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            a0 = t + P(Math.ScaleB(1, r.Next(-40, 41))); a1 = a0 + P(Math.ScaleB(1, r.Next(-40, 41)));
                            b0 = t + P(Math.ScaleB(1, r.Next(-40, 41))); b1 = b0 + P(Math.ScaleB(1, r.Next(-40, 41)));
                            break;
                        }
                    case 6:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            a0 = P(s); a1 = P(s); b0 = P(s); b1 = P(s);
                            break;
                        }
                    default: a0 = P(1); a1 = P(1); b0 = P(1); b1 = P(1); break;
                }
                string repro = $"kind {kind}, case {i}: ({R(a0)}, {R(a1)}) vs ({R(b0)}, {R(b1)})";
                var lifted = K.SegmentSegment(a0.To3(), a1.To3(), b0.To3(), b1.To3(), out bool liftedIn).To2();
                var planar = K.SegmentSegment2(a0, a1, b0, b1, out bool planarIn);
                Assert.That(planarIn, Is.EqualTo(liftedIn), repro);
                Assert.That(Bits(planar), Is.EqualTo(Bits(lifted)), repro + $": planar {planar}, lifted {lifted}");
                // The raw kernels (the planar triangle kernels take these): the same squared distance and range verdict,
                // parameters equal up to the sign of a zero.
                double r2Planar = K.SegmentSegmentFlat(a0.To3(), a1.To3(), b0.To3(), b1.To3(), out double sp, out double tp, out bool inPlanar);
                double r2Lifted = K.SegmentSegmentCore(a0.To3(), a1.To3(), b0.To3(), b1.To3(), out double sl, out double tl, out bool inLifted);
                Assert.That((BitConverter.DoubleToInt64Bits(r2Planar), inPlanar), Is.EqualTo((BitConverter.DoubleToInt64Bits(r2Lifted), inLifted)), repro);
                Assert.That(BitConverter.DoubleToInt64Bits(sp + 0), Is.EqualTo(BitConverter.DoubleToInt64Bits(sl + 0)), repro);
                Assert.That(BitConverter.DoubleToInt64Bits(tp + 0), Is.EqualTo(BitConverter.DoubleToInt64Bits(tl + 0)), repro);
                Assert.That(BitConverter.DoubleToInt64Bits(K.SegmentSegment2Distance(a0, a1, b0, b1)),
                    Is.EqualTo(BitConverter.DoubleToInt64Bits(K.SegmentSegmentDistance(a0.To3(), a1.To3(), b0.To3(), b1.To3()))), repro);
            }
        }

        private static long[] Bits(DistanceResult2 x) => new[]
        {
            BitConverter.DoubleToInt64Bits(x.Distance), BitConverter.DoubleToInt64Bits(x.DistanceSquared),
            BitConverter.DoubleToInt64Bits(x.PointA.X), BitConverter.DoubleToInt64Bits(x.PointA.Y),
            BitConverter.DoubleToInt64Bits(x.PointB.X), BitConverter.DoubleToInt64Bits(x.PointB.Y),
            BitConverter.DoubleToInt64Bits(x.ParameterA), BitConverter.DoubleToInt64Bits(x.ParameterB),
        };

        private static string R(Vector2D v) => $"new Vector2D({v.X:R}, {v.Y:R})";
    }
}
