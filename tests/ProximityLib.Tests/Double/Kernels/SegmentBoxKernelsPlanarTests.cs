using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>
    /// The planar segment–box kernels against the 3D ones on lifted inputs (a planar Box), which the fuzz and the exact
    /// families check: every field equal bit for bit up to the sign of a zero, the verdicts and inRange equal, on seeded
    /// pairs aimed at the branches.
    /// </summary>
    public class SegmentBoxKernelsPlanarTests
    {
        /// <summary>
        /// Kinds: 0 general, apart and crossing; 1 small-integer grid with integer extents (exact zeros: segments along
        /// faces, through corners, ends on faces, axis-parallel segments, zero-length segments and zero extents);
        /// 2 ends near the box (1e-3 … 1e-15 off a face or a corner, either side); 3 segments inside or through the box
        /// (the push-out branch); 4 mixed magnitudes 2^-40 … 2^40 and translations up to 2^30; 5 the whole range,
        /// 2^-1070 … 2^1020.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void MatchesTheLiftedKernelBitForBit(int kind)
        {
            var r = new Random(7200 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            Vector2D P(double s) => new Vector2D(U(-s, s), U(-s, s));
            Vector2D Grid(int m) => new Vector2D(r.Next(-m, m + 1), r.Next(-m, m + 1));
            for (int i = 0; i < 12000; i++)
            {
                Vector2D a, b, centre, half;
                double angle = r.Next(4) == 0 ? 0 : U(0, 2 * Math.PI);
                switch (kind)
                {
                    case 1:
                        a = Grid(3); b = r.Next(5) == 0 ? a : Grid(3); centre = Grid(1); half = new Vector2D(r.Next(0, 3), r.Next(0, 3));
                        angle = r.Next(2) == 0 ? 0 : Math.PI / 2 * r.Next(4);
                        break;
                    case 2:
                        {
                            centre = P(1); half = new Vector2D(U(0, 1), U(0, 1));
                            var dx = new Vector2D(Math.Cos(angle), Math.Sin(angle));
                            var dy = new Vector2D(-dx.Y, dx.X);
                            double off = Math.Pow(10, -U(3, 15)) * (r.Next(2) * 2 - 1);
                            a = r.Next(2) == 0
                                ? centre + dx * (half.X + off) + dy * U(-half.Y, half.Y)
                                : centre + dx * (half.X + off) + dy * (half.Y + off * U(-1, 1));
                            b = r.Next(3) == 0 ? a + dy * U(-2, 2) : a + P(2);
                            break;
                        }
                    case 3:
                        centre = P(1); half = new Vector2D(U(0, 1), U(0, 1));
                        a = centre + P(0.7); b = r.Next(2) == 0 ? centre + P(0.7) : centre + P(3);
                        break;
                    case 4:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            double sb = Math.ScaleB(1, r.Next(-40, 41)), ss = Math.ScaleB(1, r.Next(-40, 41));
                            centre = t + P(sb); half = new Vector2D(U(0, sb), U(0, sb));
                            a = t + P(Math.ScaleB(1, r.Next(-40, 41))); b = a + P(ss);
                            break;
                        }
                    case 5:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            centre = P(s); half = new Vector2D(U(0, s), U(0, s)); a = P(s); b = P(s);
                            break;
                        }
                    default:
                        centre = P(1); half = new Vector2D(U(0, 1), U(0, 1)); a = P(2); b = P(2);
                        break;
                }
                var obb = new Obb2(centre, new Vector2D(Math.Cos(angle), Math.Sin(angle)), half);
                var min = centre - half;
                var max = centre + half;
                string repro = $"kind {kind}, case {i}: segment ({R(a)}, {R(b)}), OBB {obb}, AABB ({R(min)}, {R(max)})";

                var box = obb.ToBox();
                var lifted = K.SegmentInFrame(a.To3(), b.To3(), box.Origin, box.X, box.Y, box.Z, box.Lo, box.Hi, box.Planar, out bool liftedIn).To2();
                var planar = K.SegmentBox2(a, b, obb.ToBox2(), out bool planarIn);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "OBB " + repro);
                Same(planar, lifted, "OBB " + repro);
                Assert.That(K.SegmentBoxOverlaps2(a, b, obb.ToBox2(), out planarIn), Is.EqualTo(K.SegmentBoxOverlaps(a.To3(), b.To3(), obb.ToBox(), out liftedIn)), "OBB overlap " + repro);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "OBB overlap " + repro);

                lifted = K.SegmentAabb(a.To3(), b.To3(), min.To3(), max.To3(), true, out liftedIn).To2();
                planar = K.SegmentAabb2(a, b, min, max, out planarIn);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "AABB " + repro);
                Same(planar, lifted, "AABB " + repro);
                Assert.That(K.SegmentAabbOverlaps2(a, b, min, max, out planarIn), Is.EqualTo(K.SegmentAabbOverlaps(a.To3(), b.To3(), min.To3(), max.To3(), true, out liftedIn)), "AABB overlap " + repro);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "AABB overlap " + repro);
            }
        }

        /// <summary>Equal bits, or both zeros (of either sign).</summary>
        internal static void Same(DistanceResult2 x, DistanceResult2 y, string repro)
        {
            double[] p = { x.Distance, x.DistanceSquared, x.PointA.X, x.PointA.Y, x.PointB.X, x.PointB.Y, x.ParameterA, x.ParameterB };
            double[] q = { y.Distance, y.DistanceSquared, y.PointA.X, y.PointA.Y, y.PointB.X, y.PointB.Y, y.ParameterA, y.ParameterB };
            for (int i = 0; i < p.Length; i++)
                if (BitConverter.DoubleToInt64Bits(p[i]) != BitConverter.DoubleToInt64Bits(q[i]) && !(p[i] == 0 && q[i] == 0))
                    Assert.Fail($"{repro}: field {i} planar {p[i]:R}, lifted {q[i]:R}\n  planar {x}\n  lifted {y}");
        }

        private static string R(Vector2D v) => $"new Vector2D({v.X:R}, {v.Y:R})";
    }
}
