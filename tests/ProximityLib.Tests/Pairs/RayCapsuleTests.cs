using System;
using NUnit.Framework;
using ProximityLib.Double;
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
    }
}
