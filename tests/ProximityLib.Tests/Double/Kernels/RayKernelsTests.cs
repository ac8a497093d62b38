using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>The AABB ray kernel (the world frame shifted to min) against the box kernel on the AABB's Box form.</summary>
    public class RayKernelsTests
    {
        /// <summary>
        /// Kinds: 0 general (hits, misses, origins inside); 1 small-integer grid with unit and diagonal directions (origins
        /// on faces, edges and corners, rays along faces, flat and point-sized boxes); 2 origins 1e-3 … 1e-15 off a face;
        /// 3 mixed magnitudes 2^-40 … 2^40 and translations up to 2^30; 4 the whole range, 2^-1070 … 2^1020. Each case in
        /// 3D and in the plane: every field equal bit for bit up to the sign of a zero, and inRange equal.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        public void AabbMatchesTheBoxKernelBitForBit(int kind)
        {
            var r = new Random(7400 + kind);
            double U(double lo, double hi) => lo + (hi - lo) * r.NextDouble();
            Vector3D P(double s) => new Vector3D(U(-s, s), U(-s, s), U(-s, s));
            Vector3D Grid(int m) => new Vector3D(r.Next(-m, m + 1), r.Next(-m, m + 1), r.Next(-m, m + 1));
            for (int i = 0; i < 20000; i++)
            {
                Vector3D o, d, min, max;
                switch (kind)
                {
                    case 1:
                        o = Grid(3); min = Grid(2); max = min + new Vector3D(r.Next(0, 3), r.Next(0, 3), r.Next(0, 3));
                        d = new Vector3D(r.Next(-1, 2), r.Next(-1, 2), r.Next(-1, 2));
                        if (d == default) d = Vector3D.UnitX;
                        break;
                    case 2:
                        {
                            min = P(1); max = min + new Vector3D(U(0, 1), U(0, 1), U(0, 1));
                            double off = Math.Pow(10, -U(3, 15)) * (r.Next(2) * 2 - 1);
                            o = new Vector3D(U(min.X, max.X), U(min.Y, max.Y), U(min.Z, max.Z));
                            o = r.Next(3) switch { 0 => new Vector3D(max.X + off, o.Y, o.Z), 1 => new Vector3D(o.X, min.Y - off, o.Z), _ => new Vector3D(o.X, o.Y, max.Z + off) };
                            d = P(1);
                            break;
                        }
                    case 3:
                        {
                            var t = P(Math.ScaleB(1, r.Next(31)));
                            double sb = Math.ScaleB(1, r.Next(-40, 41));
                            min = t + P(sb); max = min + new Vector3D(U(0, sb), U(0, sb), U(0, sb));
                            o = t + P(Math.ScaleB(1, r.Next(-40, 41))); d = P(1);
                            break;
                        }
                    case 4:
                        {
                            double s = Math.ScaleB(1, r.Next(-1070, 1021));
                            min = P(s); max = min + new Vector3D(U(0, s), U(0, s), U(0, s)); o = P(s); d = P(1);
                            break;
                        }
                    default:
                        min = P(1); max = min + new Vector3D(U(0, 1), U(0, 1), U(0, 1)); o = P(2); d = P(1);
                        break;
                }
                if (d == default) d = Vector3D.UnitY;
                d = d / d.Length;
                string repro = $"kind {kind}, case {i}: ray ({R(o)}, {R(d)}), AABB ({R(min)}, {R(max)})";

                var box = K.RayBox(o, d, new Aabb3(min, max).ToBox(), out bool boxIn);
                var aabb = K.RayAabb(o, d, min, max, false, out bool aabbIn);
                Assert.That(aabbIn, Is.EqualTo(boxIn), "3D inRange " + repro);
                Same(aabb, box, "3D " + repro);

                var o2 = new Vector2D(o.X, o.Y);
                var d2 = new Vector2D(d.X, d.Y);
                if (d2 == default) continue;
                d2 = d2 / d2.Length;
                var min2 = new Vector2D(min.X, min.Y);
                var max2 = new Vector2D(max.X, max.Y);
                box = K.RayBox(o2.To3(), d2.To3(), new Aabb2(min2, max2).ToBox(), out boxIn);
                aabb = K.RayAabb(o2.To3(), d2.To3(), min2.To3(), max2.To3(), true, out aabbIn);
                Assert.That(aabbIn, Is.EqualTo(boxIn), "2D inRange " + repro);
                Same(aabb, box, "2D " + repro);
            }
        }

        private static void Same(RayHit3 x, RayHit3 y, string repro)
        {
            Assert.That((x.Hit, x.StartsInside), Is.EqualTo((y.Hit, y.StartsInside)), repro);
            double[] p = { x.T, x.Point.X, x.Point.Y, x.Point.Z, x.Normal.X, x.Normal.Y, x.Normal.Z };
            double[] q = { y.T, y.Point.X, y.Point.Y, y.Point.Z, y.Normal.X, y.Normal.Y, y.Normal.Z };
            for (int i = 0; i < p.Length; i++)
                if (BitConverter.DoubleToInt64Bits(p[i]) != BitConverter.DoubleToInt64Bits(q[i]) && !(p[i] == 0 && q[i] == 0))
                    Assert.Fail($"{repro}: field {i} AABB kernel {p[i]:R}, box kernel {q[i]:R}\n  AABB {x}\n  box {y}");
        }

        private static string R(Vector3D v) => $"new Vector3D({v.X:R}, {v.Y:R}, {v.Z:R})";
    }
}
