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
        /// Distance and Overlaps (in 3D the axes' distance less the radius; 2D Overlaps without the crossing depth where the
        /// axes lie within the radius or clear of each other) against Between, bit for bit, across the near-touch band
        /// (<see cref="LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand"/>).
        /// </summary>
        [Test]
        public void DistanceOnlyIsBetweenAcrossTheNearTouchBand() => LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand("segment", 20261208);
    }
}
