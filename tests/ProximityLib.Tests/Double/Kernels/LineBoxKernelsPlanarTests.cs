using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>
    /// The planar line/ray–box kernel against the 3D one on lifted inputs (a planar Box), which the fuzz and the exact
    /// families check: every field equal bit for bit up to the sign of a zero, the verdicts and inRange equal.
    /// </summary>
    public class LineBoxKernelsPlanarTests
    {
        /// <summary>
        /// Kinds: 0 general, apart and crossing; 1 small-integer grid with integer extents and axis directions (lines along
        /// faces, through corners, origins on faces, zero extents); 2 lines 1e-3 … 1e-15 off a face or corner, either side;
        /// 3 origins inside the box (a ray's push back past the face it leaves through); 4 mixed magnitudes 2^-40 … 2^40
        /// and translations up to 2^30; 5 the whole range, 2^-1070 … 2^1020.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        [TestCase(5)]
        public void MatchesTheLiftedKernelBitForBit(int kind)
        {
            var r = new Random(7400 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            Vector2D P(double s) => new Vector2D(U(-s, s), U(-s, s));
            for (int i = 0; i < 12000; i++)
            {
                Vector2D o, dir, centre, half;
                double angle = r.Next(4) == 0 ? 0 : U(0, 2 * Math.PI);
                switch (kind)
                {
                    case 1:
                        o = new Vector2D(r.Next(-3, 4), r.Next(-3, 4)); centre = new Vector2D(r.Next(-1, 2), r.Next(-1, 2));
                        half = new Vector2D(r.Next(0, 3), r.Next(0, 3));
                        dir = r.Next(3) == 0 ? new Vector2D(r.Next(-2, 3), r.Next(-2, 3)) : new Vector2D(r.Next(2) * 2 - 1, 0);
                        if (dir == default) dir = new Vector2D(0, 1);
                        if (r.Next(2) == 0) dir = new Vector2D(dir.Y, dir.X);
                        angle = r.Next(2) == 0 ? 0 : Math.PI / 2 * r.Next(4);
                        break;
                    case 2:
                        {
                            centre = P(1); half = new Vector2D(U(0, 1), U(0, 1));
                            var dx = new Vector2D(Math.Cos(angle), Math.Sin(angle));
                            var dy = new Vector2D(-dx.Y, dx.X);
                            double off = Math.Pow(10, -U(3, 15)) * (r.Next(2) * 2 - 1);
                            o = centre + dx * (half.X + off) + dy * (r.Next(2) == 0 ? U(-half.Y, half.Y) : half.Y + off);
                            dir = r.Next(2) == 0 ? dy : P(1);
                            o -= dir * U(-2, 2);
                            break;
                        }
                    case 3:
                        centre = P(1); half = new Vector2D(U(0, 1), U(0, 1)); o = centre + P(0.7); dir = P(1);
                        break;
                    case 4:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            double sb = Math.ScaleB(1, r.Next(-40, 41));
                            centre = t + P(sb); half = new Vector2D(U(0, sb), U(0, sb));
                            o = t + P(Math.ScaleB(1, r.Next(-40, 41))); dir = P(1);
                            break;
                        }
                    case 5:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            centre = P(s); half = new Vector2D(U(0, s), U(0, s)); o = P(s); dir = P(1);
                            break;
                        }
                    default:
                        centre = P(1); half = new Vector2D(U(0, 1), U(0, 1)); o = P(3); dir = P(1);
                        break;
                }
                if (dir == default) dir = new Vector2D(1, 0);
                var u = new Line2(o, dir).Direction; // the unit direction the pair files pass
                var obb = new Obb2(centre, new Vector2D(Math.Cos(angle), Math.Sin(angle)), half);
                var aabb = new Aabb2(centre - half, centre + half);
                foreach (bool ray in new[] { false, true })
                {
                    string repro = $"kind {kind}, case {i}, ray {ray}: origin ({o.X:R}, {o.Y:R}), direction ({u.X:R}, {u.Y:R}), OBB {obb}, AABB {aabb}";
                    foreach (var (planarBox, liftedBox, name) in new[] { (obb.ToBox2(), obb.ToBox(), "OBB"), (aabb.ToBox2(), aabb.ToBox(), "AABB") })
                    {
                        var lifted = K.LineBox(o.To3(), u.To3(), ray, liftedBox, out bool liftedIn).To2();
                        var planar = K.LineBox2(o, u, ray, planarBox, out bool planarIn);
                        Assert.That(planarIn, Is.EqualTo(liftedIn), name + " " + repro);
                        SegmentBoxKernelsPlanarTests.Same(planar, lifted, name + " " + repro);
                        Assert.That(K.LineBoxOverlaps2(o, u, ray, planarBox, out planarIn), Is.EqualTo(K.LineBoxOverlaps(o.To3(), u.To3(), ray, liftedBox, out liftedIn)), name + " overlap " + repro);
                        Assert.That(planarIn, Is.EqualTo(liftedIn), name + " overlap " + repro);
                    }
                }
            }
        }
    }
}
