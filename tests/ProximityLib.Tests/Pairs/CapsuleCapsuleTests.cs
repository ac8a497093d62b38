using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class CapsuleCapsuleTests
    {
        [Test]
        public void Separated3DAndSymmetric()
        {
            var a = new Capsule3(V(0, 0, 0), V(4, 0, 0), 1);
            var b = new Capsule3(V(2, -1, 3), V(2, 1, 3), 0.5);
            var r = ClosestDistance.Between(a, b);
            Result(r, 1.5, V(2, 0, 1), V(2, 0, 2.5));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(r.Swapped()));
        }

        /// <summary>2D crossing: the second axis's start is 1 below the first axis's line: depth 1 + 1 + 0.5.</summary>
        [Test]
        public void Crossing2DAddsTheCrossingDepth()
        {
            var a = new Capsule2(V(0, 0), V(4, 0), 1);
            var b = new Capsule2(V(2, -1), V(2, 3), 0.5);
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(-2.5));
            Assert.That(Vector2D.Distance(r.PointA, r.PointB), Is.EqualTo(2.5));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(r.Swapped()));
            // Identical axes, different radii: the same answer in either order; 3D meeting axes push by the radii.
            var c = new Capsule3(V(0, 0, 0), V(2, 0, 0), 1);
            var d = new Capsule3(V(0, 0, 0), V(2, 0, 0), 0.25);
            Assert.That(ClosestDistance.Between(c, d).Distance, Is.EqualTo(-1.25));
            Assert.That(ClosestDistance.Between(d, c), Is.EqualTo(ClosestDistance.Between(c, d).Swapped()));
        }

        [Test]
        public void PointSizedCapsulesAreSpheres() =>
            Result(ClosestDistance.Between(new Capsule2(V(0, 0), V(0, 0), 1), new Capsule2(V(5, 0), V(5, 0), 2)), 2, V(1, 0), V(3, 0));
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("capsule", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("capsule", "capsule");
    }
}
