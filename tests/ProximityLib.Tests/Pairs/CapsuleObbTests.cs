using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using ProximityTests.Support;
using static ProximityTests.Pairs.HalfSpaceBoxChecks;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class CapsuleObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        private static Vector3D U(object l) { dynamic d = l; return d.Direction is Vector2D v ? SegmentHalfSpaceTests.V3(v) : (Vector3D)d.Direction; }

        [Test]
        public void AgainstADiamond()
        {
            var r = ClosestDistance.Between(new Capsule3(V(3, -1, 0), V(3, 1, 0), 0.5), Diamond);
            Result(r, 2.5 - Math.Sqrt(2), V(2.5, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(0.5).Within(1e-15));
            // Axis along z through the centre: depth 1 (sideways to a face) plus the radius.
            Assert.That(ClosestDistance.Between(new Capsule3(V(0, 0, -3), V(0, 0, 3), 0.5), Diamond).Distance, Is.EqualTo(-1.5).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(3, -1, 0), V(3, 1, 0), 1.6), Diamond), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(3, -1, 0), V(3, 1, 0), 1.5), Diamond), Is.False);
            var d2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            // 2D: an axis crossing the diamond is deeper than the radius: the 2D crossing depth √2 plus it.
            Assert.That(ClosestDistance.Between(new Capsule2(V(-5, 0), V(5, 0), 0.5), d2).Distance, Is.EqualTo(-Math.Sqrt(2) - 0.5).Within(1e-15));
            var f = new Flt.Obb2(new Num.Vector2(0, 0), new Num.Vector2(1, 0), new Num.Vector2(1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Capsule2(new Num.Vector2(0, 4), new Num.Vector2(3, 4), 1), f), Is.EqualTo(2f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(7400 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var o = Rand.P(rng, dim, 3); var u = Rand.P(rng, dim, 3);
                    double rad = Rand.F(rng, 0, 1);
                    bool permuted = rng.Next(2) == 0;
                    var axes = permuted ? ObbRotations.Permuted(rng, dim) : Rand.Axes(rng, dim);
                    var c = Rand.P(rng, dim);
                    var h = V(Rand.F(rng, 0, 1), Rand.F(rng, 0, 1), dim == 3 ? Rand.F(rng, 0, 1) : 0);
                    Func<double, object> shape = f => Rand.Cap(dim, o * f, u * f, rad * f);
                    var shape1 = shape(1);
                    worst = Math.Max(worst, ObbRotations.Measure(dim, shape, c, axes, h, (lo, hi) => ExactLineAabb(o, u - o, 0, 1, lo, hi, dim == 2) - (Rational)rad, new[] { o, u }, rad, permuted));
                }
            }
            TestContext.Out.WriteLine($"CapsuleObb worst E (permuted axes, exact) = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }

        /// <summary>
        /// Capsule axes 1e-9 … 1e-15 from a rotated box's or an AABB's edge (crossing it, or ending beside it) or vertex
        /// (passing it): the capsule moved by PointB − PointA must touch the box to within 64 u·S, checked exactly. The
        /// axis's box-frame coordinates carry u·S, so the rounded residual's direction is off by u·S/gap: it left up to
        /// 4e-4 of overlap. Modes: 0 OBB crossing, 1 OBB ending, 2 AABB crossing, 3 OBB vertex, 4 AABB vertex.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        public void AxesNearAnEdgePushOutToTouching(int mode)
        {
            var rnd = new Random(31 + mode);
            Vector3D U(Vector3D v) => v * (1 / v.Length);
            for (int i = 0; i < 70; i++)
            {
                double h = Math.Pow(10, -9 - i % 7);
                var c = new Vector3D(rnd.NextDouble() * 3, rnd.NextDouble() * 3, rnd.NextDouble() * 3);
                var half = new Vector3D(0.5, 0.4, 0.3);
                Vector3D ax = Vector3D.UnitX, ay = Vector3D.UnitY, az = Vector3D.UnitZ;
                object box;
                if (mode == 2 || mode == 4) box = new Aabb3(c - half, c + half);
                else
                {
                    var q = System.Numerics.Quaternion.Normalize(new System.Numerics.Quaternion((float)rnd.NextDouble(), (float)rnd.NextDouble(), (float)rnd.NextDouble(), 1f));
                    var obb = Obb3.FromQuaternion(c, q.X, q.Y, q.Z, q.W, half);
                    ax = obb.AxisX; ay = obb.AxisY; az = obb.AxisZ;
                    box = obb;
                }
                Capsule3 cap;
                if (mode >= 3)
                {
                    // Past the vertex at +half, off it along a direction inside its normal cone, the axis across that direction.
                    var vertex = c + ax * half.X + ay * half.Y + az * half.Z;
                    var out3 = U(ax * (0.3 + rnd.NextDouble()) + ay * (0.3 + rnd.NextDouble()) + az * (0.3 + rnd.NextDouble()));
                    var across = U(Vector3D.Cross(out3, new Vector3D(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5)));
                    cap = new Capsule3(vertex + out3 * h - across * 0.4, vertex + out3 * h + across * 0.5, 0.2);
                }
                else
                {
                    var onEdge = c + ax * half.X + ay * half.Y + az * 0.1;
                    var away = U(ax * (0.3 + rnd.NextDouble()) + ay * (0.3 + rnd.NextDouble()));
                    var start = onEdge + away * h;
                    var along = U(Vector3D.Cross(away, az) + az * 0.1);
                    cap = mode == 1 ? new Capsule3(start, start + U(away + az * 0.2) * 0.5, 0.2) : new Capsule3(start - along * 0.5, start + along * 0.5, 0.2);
                }
                var ra = RShape.FromAny(cap);
                var rb = RShape.FromAny(box);
                double tol = 64 * Exactly.U * Exact.Scale(ra, rb);
                foreach (var (x, y, rx, ry) in new[] { ((object)cap, box, ra, rb), (box, cap, rb, ra) })
                {
                    var r = Api.Between(x, y);
                    double after = Exact.SignedDistance(rx.Translated(RVec.From((Vector3D)r.PointB) - RVec.From((Vector3D)r.PointA)), ry).ToDouble();
                    Assert.That((double)r.Distance, Is.LessThan(0), $"case {i}: {x} vs {y}");
                    Assert.That(Math.Abs(after), Is.LessThanOrEqualTo(tol), $"case {i} (gap {h:G1}): {x} vs {y} moved by PointB − PointA is {after:R} from touching");
                }
            }
        }
    }
}
