using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointLineTests
    {
        [Test]
        public void ProjectionOntoTheLine()
        {
            var r = ClosestDistance.Between(V(0, 3, 4), new Line3(V(10, 0, 0), V(2, 0, 0)));
            Result(r, 5, V(0, 3, 4), V(0, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(-10));
            Assert.That(r.DistanceSquared, Is.EqualTo(25));
            var q = ClosestDistance.Between(V(1, 2), new Line2(V(5, 0), V(-1, 0)));
            Result(q, 2, V(1, 2), V(1, 0));
            Assert.That(q.ParameterB, Is.EqualTo(4));
        }

        [Test]
        public void PointOnTheLineOverlaps()
        {
            var l = new Line3(V(1, 1, 1), V(0, 0, 3));
            Assert.That(ClosestDistance.Distance(V(1, 1, -7), l), Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(V(1, 1, -7), l), Is.True);
            Assert.That(ProximityQuery.Overlaps(l, V(1, 1.5, -7)), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(3, 0), new Line2(V(0, 0), V(1, 0))), Is.True);
        }

        [Test]
        public void FloatMatchesDouble()
        {
            var r = ProximityLib.ClosestDistance.Between(new System.Numerics.Vector3(0, 3, 4), new ProximityLib.Line3(new System.Numerics.Vector3(10, 0, 0), new System.Numerics.Vector3(2, 0, 0)));
            Assert.That(r.Distance, Is.EqualTo(5f));
            Assert.That(r.ParameterB, Is.EqualTo(-10f));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("point", "line"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("point", "line");
    }
}
