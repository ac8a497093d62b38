using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointCapsuleTests
    {
        [Test]
        public void OutsideInsideAndOnTheAxis()
        {
            var c = new Capsule3(V(0, 0, 0), V(4, 0, 0), 1);
            var r = ClosestDistance.Between(V(2, 3, 0), c);
            Result(r, 2, V(2, 3, 0), V(2, 1, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0.5));
            Result(ClosestDistance.Between(V(2, 0.5, 0), c), -0.5, V(2, 0.5, 0), V(2, 1, 0));
            // On the axis: pushed along AnyPerpendicular of the axis, (d.y, −d.x, 0) normalised = (0, −1, 0).
            Result(ClosestDistance.Between(V(2, 0, 0), c), -1, V(2, 0, 0), V(2, -1, 0));
            // Beyond the end cap.
            Result(ClosestDistance.Between(V(7, 0, 4), c), 4, V(7, 0, 4), V(4.6, 0, 0.8));
            Result(ClosestDistance.Between(V(-2, 0), new Capsule2(V(0, 0), V(0, 4), 1)), 1, V(-2, 0), V(-1, 0));
        }

        [Test]
        public void ZeroLengthAxisAndZeroRadius()
        {
            Result(ClosestDistance.Between(V(0, 0, 5), new Capsule3(V(0, 0, 1), V(0, 0, 1), 2)), 2, V(0, 0, 5), V(0, 0, 3));
            Result(ClosestDistance.Between(V(1, 1), new Capsule2(V(0, 0), V(2, 0), 0)), 1, V(1, 1), V(1, 0));
            Assert.That(ProximityQuery.Overlaps(V(1, 0), new Capsule2(V(0, 0), V(2, 0), 0)), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(1, 2), new Capsule2(V(0, 0), V(2, 0), 2)), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(1, 2.5), new Capsule2(V(0, 0), V(2, 0), 2)), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("point", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("point", "capsule");
    }
}
