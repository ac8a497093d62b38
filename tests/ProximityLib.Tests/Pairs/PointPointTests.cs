using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointPointTests
    {
        [Test]
        public void ThreeFourFive()
        {
            Result(ClosestDistance.Between(V(1, 2, 3), V(4, 6, 3)), 5, V(1, 2, 3), V(4, 6, 3));
            Result(ClosestDistance.Between(V(1, 1), V(4, 5)), 5, V(1, 1), V(4, 5));
            Assert.That(ClosestDistance.Between(V(1, 2, 3), V(4, 6, 3)).DistanceSquared, Is.EqualTo(25));
            Assert.That(ProximityQuery.Overlaps(V(1, 2, 3), V(4, 6, 3)), Is.False);
        }

        [Test]
        public void SamePointTouches()
        {
            Result(ClosestDistance.Between(V(7, -2, 0.5), V(7, -2, 0.5)), 0, V(7, -2, 0.5), V(7, -2, 0.5));
            Assert.That(ProximityQuery.Overlaps(V(7, -2, 0.5), V(7, -2, 0.5)), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(7, -2), V(7, -2)), Is.True);
        }

        [Test]
        public void FloatApiRoundsTheSameAnswer()
        {
            var r = ProximityLib.ClosestDistance.Between(new System.Numerics.Vector3(1, 2, 3), new System.Numerics.Vector3(4, 6, 3));
            Assert.That(r.Distance, Is.EqualTo(5f));
            Assert.That(r.PointB, Is.EqualTo(new System.Numerics.Vector3(4, 6, 3)));
        }
    }
}
