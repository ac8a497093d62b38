using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>
    /// The planar point–box kernels against the 3D ones on lifted inputs (a planar Box), which the fuzz and the exact
    /// families check: values equal bit for bit up to the sign of a zero, verdicts and inRange equal (for the contact,
    /// every field, the near-touch normal included, where the fast path answers).
    /// </summary>
    public class PointKernelsPlanarTests
    {
        /// <summary>
        /// Kinds: 0 general, inside and outside; 1 small-integer grid with integer extents (points on faces and corners,
        /// zero extents, a point-sized box); 2 points 1e-3 … 1e-15 off a face or a corner, either side; 3 mixed magnitudes
        /// 2^-40 … 2^40 and translations up to 2^30; 4 the whole range, 2^-1070 … 2^1020; 5 point-sized boxes with the
        /// point on them or a few subnormal steps off (an offset that vanishes in the rotation must not count as inside).
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void MatchesTheLiftedKernelBitForBit(int kind)
        {
            var r = new Random(7300 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            Vector2D P(double s) => new Vector2D(U(-s, s), U(-s, s));
            Vector2D Grid(int m) => new Vector2D(r.Next(-m, m + 1), r.Next(-m, m + 1));
            for (int i = 0; i < 20000; i++)
            {
                Vector2D p, centre, half;
                double angle = r.Next(4) == 0 ? 0 : U(0, 2 * Math.PI);
                switch (kind)
                {
                    case 1:
                        p = Grid(3); centre = Grid(1); half = new Vector2D(r.Next(0, 3), r.Next(0, 3));
                        angle = r.Next(2) == 0 ? 0 : Math.PI / 2 * r.Next(4);
                        break;
                    case 2:
                        {
                            centre = P(1); half = new Vector2D(U(0, 1), U(0, 1));
                            var dx = new Vector2D(Math.Cos(angle), Math.Sin(angle));
                            var dy = new Vector2D(-dx.Y, dx.X);
                            double off = Math.Pow(10, -U(3, 15)) * (r.Next(2) * 2 - 1);
                            p = r.Next(2) == 0
                                ? centre + dx * (half.X + off) + dy * U(-half.Y, half.Y)
                                : centre + dx * (half.X + off) + dy * (half.Y + off * U(-1, 1));
                            break;
                        }
                    case 3:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            double sb = Math.ScaleB(1, r.Next(-40, 41));
                            centre = t + P(sb); half = new Vector2D(U(0, sb), U(0, sb));
                            p = t + P(Math.ScaleB(1, r.Next(-40, 41)));
                            break;
                        }
                    case 4:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            centre = P(s); half = new Vector2D(U(0, s), U(0, s)); p = P(s);
                            break;
                        }
                    case 5:
                        {
                            centre = P(Math.ScaleB(1, r.Next(2) == 0 ? r.Next(-1070, -1015) : r.Next(-1070, 30))); half = default;
                            p = centre + (r.Next(3) == 0 ? default : new Vector2D(r.Next(-3, 4), r.Next(-3, 4)) * double.Epsilon);
                            break;
                        }
                    default:
                        centre = P(1); half = new Vector2D(U(0, 1), U(0, 1)); p = P(2);
                        break;
                }
                var obb = new Obb2(centre, new Vector2D(Math.Cos(angle), Math.Sin(angle)), half);
                string repro = $"kind {kind}, case {i}: point new Vector2D({p.X:R}, {p.Y:R}), OBB {obb}";

                Same(K.PointBoxDistanceSquared2(p, obb.ToBox2()), K.PointBoxDistanceSquared(p.To3(), obb.ToBox()), "squared distance " + repro);
                double planar = K.PointBoxDistance2(p, obb.ToBox2(), out bool planarIn);
                double lifted = K.PointBoxDistance(p.To3(), obb.ToBox(), out bool liftedIn);
                Same(planar, lifted, "distance " + repro);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "inRange " + repro);
                Assert.That(K.PointInBox2(p, obb.ToBox2()), Is.EqualTo(K.PointInBox(p.To3(), obb.ToBox())), "inside " + repro);

                var planarContact = K.PointBox2(p, obb.ToBox2(), out planarIn);
                var liftedContact = K.PointBox(p.To3(), obb.ToBox(), out liftedIn);
                Assert.That(planarIn, Is.EqualTo(liftedIn), "contact inRange " + repro);
                double[] x = { planarContact.Distance, planarContact.DistanceSquared, planarContact.Parameter, planarContact.Closest.X, planarContact.Closest.Y, planarContact.Closest.Z, planarContact.Normal.X, planarContact.Normal.Y, planarContact.Normal.Z };
                double[] y = { liftedContact.Distance, liftedContact.DistanceSquared, liftedContact.Parameter, liftedContact.Closest.X, liftedContact.Closest.Y, liftedContact.Closest.Z, liftedContact.Normal.X, liftedContact.Normal.Y, liftedContact.Normal.Z };
                // Outside the fast range the slow path answers and the contact is not read (the lifted normal's z can be
                // 0·∞ there); inRange must agree either way.
                if (liftedIn) for (int j = 0; j < x.Length; j++) Same(x[j], y[j], $"contact field {j} " + repro);
            }
        }

        private static void Same(double planar, double lifted, string repro)
        {
            if (BitConverter.DoubleToInt64Bits(planar) != BitConverter.DoubleToInt64Bits(lifted) && !(planar == 0 && lifted == 0))
                Assert.Fail($"{repro}: planar {planar:R}, lifted {lifted:R}");
        }
    }
}
