using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentCapsuleTests
    {
        [Test]
        public void SeparatedAndMeetingAxes3D()
        {
            var c = new Capsule3(V(0, 0, 0), V(4, 0, 0), 1);
            var r = ClosestDistance.Between(new Segment3(V(2, 3, -1), V(2, 3, 1)), c);
            Result(r, 2, V(2, 3, 0), V(2, 1, 0));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((0.5, 0.5)));
            // Axes meet at (2, 0, 0): 3D depth is the radius, pushed along dA × dB = (0, 0, −8) normalised.
            var m = ClosestDistance.Between(new Segment3(V(2, -1, 0), V(2, 1, 0)), c);
            Result(m, -1, V(2, 0, 0), V(2, 0, 1));
        }

        /// <summary>2D crossing: the segment's end (2, −1) is 1 below the axis line, the least of the four endpoint–line distances (1, 3, 2, 2), so the depth is 1 + radius 1.</summary>
        [Test]
        public void CrossingAxes2DAddTheCrossingDepth()
        {
            var r = ClosestDistance.Between(new Segment2(V(2, -1), V(2, 3)), new Capsule2(V(0, 0), V(4, 0), 1));
            Result(r, -2, V(2, -1), V(2, 1));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((0.0, 0.5)));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(2, -1), V(2, 3)), new Capsule2(V(0, 0), V(4, 0), 1)), Is.True);
            // Touching from outside.
            Result(ClosestDistance.Between(new Segment2(V(2, 1), V(2, 3)), new Capsule2(V(0, 0), V(4, 0), 1)), 0, V(2, 1), V(2, 1));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("segment", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("segment", "capsule");

        /// <summary>
        /// The distance-only entry and Overlaps (in 3D the axes' distance less the radius from the inlined segment kernel; in
        /// 2D Overlaps without the crossing depth where the axes are within the radius or clear of each other) against
        /// Between, bit for bit, in both orders, 3D and 2D: a radius of the reach's size or of the gap's; a segment from
        /// 2^-60 to 2^-10 of its reach off the capsule's axis around the near-touch threshold, meeting it, crossing it,
        /// lying on it, a point segment, at scales 2^±300.
        /// </summary>
        [Test]
        public void DistanceOnlyIsBetweenAcrossTheNearTouchBand()
        {
            var rng = new Random(20261208);
            double U(double lo, double hi) => lo + (hi - lo) * rng.NextDouble();
            for (int i = 0; i < 20000; i++)
            {
                double scale = Math.ScaleB(1, rng.Next(3) switch { 0 => 0, 1 => -300, _ => 300 });
                var b0 = V(U(-1, 1), U(-1, 1), U(-1, 1));
                var b1 = V(U(-1, 1), U(-1, 1), U(-1, 1));
                double gap = rng.Next(5) == 0 ? 0 : Math.ScaleB(U(1, 2), -rng.Next(10, 61));
                var a0 = b0 + (b1 - b0) * U(-0.2, 1.2) + V(U(-1, 1), U(-1, 1), U(-1, 1)) * gap;
                var a1 = rng.Next(10) == 0 ? a0 : V(U(-1, 1), U(-1, 1), U(-1, 1));
                if (rng.Next(10) == 0) { a0 = b0; a1 = b1; }
                // A radius of the reach's size, or of the gap's (2^-70..2^-10): then the axes can be nearly touching beyond it.
                double rb = (rng.Next(2) == 0 ? U(0.01, 0.5) : Math.ScaleB(U(1, 2), -rng.Next(10, 71))) * scale;
                string at = $"case {i}: ({a0}, {a1}) vs ({b0}, {b1}, {rb:R}) x {scale}";
                var s3 = new Segment3(a0 * scale, a1 * scale);
                var c3 = new Capsule3(b0 * scale, b1 * scale, rb);
                var s2 = new Segment2(V(a0.X, a0.Y) * scale, V(a1.X, a1.Y) * scale);
                var c2 = new Capsule2(V(b0.X, b0.Y) * scale, V(b1.X, b1.Y) * scale, rb);
                double between = ClosestDistance.Between(s3, c3).Distance;
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(s3, c3)), Is.EqualTo(BitConverter.DoubleToInt64Bits(between)), "3D " + at);
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(c3, s3)), Is.EqualTo(BitConverter.DoubleToInt64Bits(ClosestDistance.Between(c3, s3).Distance)), "3D swapped, " + at);
                Assert.That(ProximityQuery.Overlaps(s3, c3), Is.EqualTo(between <= 0), "3D Overlaps, " + at);
                between = ClosestDistance.Between(s2, c2).Distance;
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(s2, c2)), Is.EqualTo(BitConverter.DoubleToInt64Bits(between)), "2D " + at);
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(c2, s2)), Is.EqualTo(BitConverter.DoubleToInt64Bits(ClosestDistance.Between(c2, s2).Distance)), "2D swapped, " + at);
                Assert.That(ProximityQuery.Overlaps(s2, c2), Is.EqualTo(between <= 0), "2D Overlaps, " + at);
            }
        }
    }
}
