using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class LineCapsuleTests
    {
        [Test]
        public void Separated3D() =>
            Result(ClosestDistance.Between(new Line3(V(0, 0, 0), V(1, 0, 0)), new Capsule3(V(2, 3, -1), V(2, 3, 1), 1)), 2, V(2, 0, 0), V(2, 2, 0));

        /// <summary>2D crossing: the capsule's start is 1 below the line, so the line moves 1 + radius 1 down: −2.</summary>
        [Test]
        public void Crossing2DAddsTheCrossingDepth()
        {
            var r = ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Capsule2(V(2, -1), V(2, 3), 1));
            Result(r, -2, V(2, 0), V(2, -2));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((2.0, 0.0)));
            // In 3D the same configuration is only r deep.
            Assert.That(ClosestDistance.Distance(new Line3(V(0, 0, 0), V(1, 0, 0)), new Capsule3(V(2, -1, 0), V(2, 3, 0), 1)), Is.EqualTo(-1));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "capsule");

        /// <summary>Distance and Overlaps against Between, bit for bit, across the near-touch band (<see cref="LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand"/>).</summary>
        [Test]
        public void OverlapsIsBetweenAcrossTheNearTouchBand() => LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand("line", 20261209);
    }
}
