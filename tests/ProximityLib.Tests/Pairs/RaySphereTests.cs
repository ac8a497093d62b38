using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class RaySphereTests
    {
        [Test]
        public void BehindAndAhead()
        {
            var ray = new Ray3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(ray, new Sphere(V(-3, 4, 0), 1));
            Result(r, 4, V(0, 0, 0), V(-2.4, 3.2, 0));
            Assert.That(r.ParameterA, Is.EqualTo(0));
            Result(ClosestDistance.Between(ray, new Sphere(V(3, 4, 0), 5)), -1, V(3, 0, 0), V(3, -1, 0));
            Result(ClosestDistance.Between(new Ray2(V(0, 0), V(0, 1)), new Circle(V(2, 5), 1)), 1, V(0, 5), V(1, 5));
            Assert.That(ProximityQuery.Overlaps(ray, new Sphere(V(-3, 4, 0), 5)), Is.True);
            Assert.That(ProximityQuery.Overlaps(ray, new Sphere(V(-3, 4, 0), 4.5)), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("ray", "sphere"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("ray", "sphere");
    }
}
