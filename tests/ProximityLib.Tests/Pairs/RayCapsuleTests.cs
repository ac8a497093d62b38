using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class RayCapsuleTests
    {
        [Test]
        public void CrossingAndBehind2D()
        {
            var c = new Capsule2(V(2, -1), V(2, 3), 1);
            Result(ClosestDistance.Between(new Ray2(V(0, 0), V(1, 0)), c), -2, V(2, 0), V(2, -2));
            Result(ClosestDistance.Between(new Ray2(V(4, 0), V(1, 0)), c), 1, V(4, 0), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(3, 0), V(1, 0)), c), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(3.5, 0), V(1, 0)), c), Is.False);
        }

        [Test]
        public void Separated3D()
        {
            var r = ClosestDistance.Between(new Ray3(V(0, 0, 0), V(1, 0, 0)), new Capsule3(V(-2, 3, 0), V(-2, 5, 0), 1));
            Result(r, Math.Sqrt(13) - 1, V(0, 0, 0), V(-2, 3, 0) * (1 - 1 / Math.Sqrt(13)) + V(0, 0, 0));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("ray", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("ray", "capsule");

        /// <summary>
        /// A 2D ray, line or segment lying along a capsule's axis (its start a rounded point of the axis, its direction the
        /// axis's, reversed or not, turned by 0 or a few u), so the axes' Minkowski difference is a sliver whose every depth
        /// is rounding: the witnesses stay on the shapes (the linear one's on it, checked exactly) and the push-out
        /// touches. Fuzz 7:3000000037270: a ray running back along the axis from inside it got the axis's far end, 0.99
        /// off the ray, as its witness (the face picked by rounding had its foot beyond the ray's origin).
        /// </summary>
        [TestCase("ray")]
        [TestCase("line")]
        [TestCase("segment")]
        public void AlongTheAxisKeepsWitnessesOnTheShapes2D(string kind)
        {
            var rnd = new Random(kind.Length * 7919);
            for (int i = 0; i < 300; i++)
            {
                Vector2D b0 = V(rnd.NextDouble() * 8 - 4, rnd.NextDouble() * 8 - 4), b1 = V(rnd.NextDouble() * 8 - 4, rnd.NextDouble() * 8 - 4);
                var cap = new Capsule2(b0, b1, 0.1 + rnd.NextDouble());
                var start = b0 + (b1 - b0) * (0.05 + 0.9 * rnd.NextDouble());
                var dir = (b1 - b0) * (i % 2 == 0 ? 1 : -1);
                double turn = (i / 2 % 3) * 1e-16;
                dir = V(dir.X - dir.Y * turn, dir.Y + dir.X * turn);
                object lin = kind == "ray" ? new Ray2(start, dir) : kind == "line" ? (object)new Line2(start, dir)
                    : new Segment2(start, start + dir * (0.1 + 2 * rnd.NextDouble()));
                var rl = RShape.FromAny(lin);
                var rc = RShape.FromAny(cap);
                double tol = 64 * Exactly.U * Exact.Scale(rl, rc);
                foreach (bool swap in new[] { false, true })
                {
                    var r = swap ? Api.Between(cap, lin) : Api.Between(lin, cap);
                    var onLinear = (Vector2D)(swap ? r.PointB : r.PointA);
                    Assert.That(double.IsFinite(onLinear.X) && double.IsFinite(onLinear.Y), $"case {i}, swap {swap}: {lin} vs {cap}: witness {onLinear}");
                    double off = Exact.SignedDistance(RShape.FromAny(onLinear), rl).ToDouble();
                    Assert.That(off, Is.LessThanOrEqualTo(tol), $"case {i}, swap {swap}: the {kind}'s witness {onLinear} is {off:R} off it");
                    var (rx, ry) = swap ? (rc, rl) : (rl, rc);
                    double after = Exact.SignedDistance(rx.Translated(RVec.From((Vector2D)r.PointB) - RVec.From((Vector2D)r.PointA)), ry).ToDouble();
                    Assert.That(Math.Abs(after), Is.LessThanOrEqualTo(tol), $"case {i}, swap {swap}: moved by PointB − PointA is {after:R} from touching");
                }
            }
        }

        /// <summary>Distance and Overlaps against Between, bit for bit, across the near-touch band (<see cref="LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand"/>).</summary>
        [Test]
        public void OverlapsIsBetweenAcrossTheNearTouchBand() => LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand("ray", 20261210);
    }
}
