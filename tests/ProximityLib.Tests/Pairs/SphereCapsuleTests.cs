using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SphereCapsuleTests
    {
        [Test]
        public void SeparatedOverlappingAndConcentric()
        {
            var c = new Capsule3(V(0, 0, 0), V(4, 0, 0), 2);
            var r = ClosestDistance.Between(new Sphere(V(2, 5, 0), 1), c);
            Result(r, 2, V(2, 4, 0), V(2, 2, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0.5));
            Result(ClosestDistance.Between(new Sphere(V(2, 3, 0), 2), c), -1, V(2, 1, 0), V(2, 2, 0));
            // The center on the axis: along AnyPerpendicular of the axis, (0, −1, 0).
            Result(ClosestDistance.Between(new Sphere(V(1, 0, 0), 1), c), -3, V(1, 1, 0), V(1, -2, 0));
            Result(ClosestDistance.Between(new Circle(V(7, 0), 1), new Capsule2(V(0, 0), V(4, 0), 1)), 1, V(6, 0), V(5, 0));
            Assert.That(ProximityQuery.Overlaps(new Circle(V(7, 0), 1), new Capsule2(V(0, 0), V(4, 0), 2)), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Circle(V(7.5, 0), 1), new Capsule2(V(0, 0), V(4, 0), 2)), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("sphere", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("sphere", "capsule");
    }
}
