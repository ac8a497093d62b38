using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentRayTests
    {
        [Test]
        public void BehindInFrontAndCrossing()
        {
            var ray = new Ray3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(new Segment3(V(-2, -1, 0), V(-2, 1, 0)), ray);
            Result(r, 2, V(-2, 0, 0), V(0, 0, 0));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((0.5, 0.0)));
            var f = ClosestDistance.Between(new Segment3(V(3, -1, 2), V(3, 1, 2)), ray);
            Result(f, 2, V(3, 0, 2), V(3, 0, 0));
            Assert.That(f.ParameterB, Is.EqualTo(3));
            var c = ClosestDistance.Between(new Segment2(V(3, -1), V(3, 1)), new Ray2(V(0, 0), V(1, 0)));
            Result(c, 0, V(3, 0), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(3, -1), V(3, 1)), new Ray2(V(0, 0), V(1, 0))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(-3, -1), V(-3, 1)), new Ray2(V(0, 0), V(1, 0))), Is.False);
        }

        [Test]
        public void CollinearPartlyBehind()
        {
            var r = ClosestDistance.Between(new Segment2(V(-3, 0), V(2, 0)), new Ray2(V(0, 0), V(1, 0)));
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.PointA, Is.EqualTo(r.PointB));
            Assert.That(r.ParameterB, Is.GreaterThanOrEqualTo(0));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("segment", "ray"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("segment", "ray");
    }
}
