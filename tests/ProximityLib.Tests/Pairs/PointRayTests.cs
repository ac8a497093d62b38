using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointRayTests
    {
        [Test]
        public void BehindTheOriginAndAlongTheRay()
        {
            var ray = new Ray3(V(0, 0, 0), V(2, 0, 0));
            var r = ClosestDistance.Between(V(-3, 4, 0), ray);
            Result(r, 5, V(-3, 4, 0), V(0, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0));
            var q = ClosestDistance.Between(ray, V(3, 4, 0));
            Result(q, 4, V(3, 0, 0), V(3, 4, 0));
            Assert.That(q.ParameterA, Is.EqualTo(3));
            Result(ClosestDistance.Between(V(-1, 1), new Ray2(V(0, 0), V(0, 5))), 1, V(-1, 1), V(0, 1));
        }

        [Test]
        public void OverlapsOnlyOnTheRay()
        {
            var ray = new Ray2(V(1, 1), V(1, 0));
            Assert.That(ProximityQuery.Overlaps(V(4, 1), ray), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(0, 1), ray), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(1, 1), ray), Is.True);
            Assert.That(ClosestDistance.Distance(V(0, 1), ray), Is.EqualTo(1));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("point", "ray"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("point", "ray");
    }
}
