using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class AabbAabbTests
    {
        private static readonly Aabb3 Unit = new Aabb3(V(0, 0, 0), V(1, 1, 1));

        [Test]
        public void ApartAlongOneAxisWitnessesInTheSharedMiddle()
        {
            var r = ClosestDistance.Between(Unit, new Aabb3(V(2, 0.5, -1), V(3, 2, 0.5)));
            Result(r, 1, V(1, 0.75, 0.25), V(2, 0.75, 0.25));
            Assert.That(ProximityQuery.Overlaps(Unit, new Aabb3(V(2, 0.5, -1), V(3, 2, 0.5))), Is.False);
        }

        [Test]
        public void ApartAcrossACorner()
        {
            var r = ClosestDistance.Between(Unit, new Aabb3(V(2, 3, 3), V(4, 4, 4)));
            Result(r, 3, V(1, 1, 1), V(2, 3, 3));
            Assert.That(r.DistanceSquared, Is.EqualTo(9));
        }

        [Test]
        public void OverlapUsesTheLeastOverlappingAxis()
        {
            var a = new Aabb3(V(0, 0, 0), V(2, 2, 2));
            var b = new Aabb3(V(1.5, 0.5, 0), V(3, 1, 2));
            var r = ClosestDistance.Between(a, b);
            Result(r, -0.5, V(2, 0.75, 1), V(1.5, 0.75, 1));
            Assert.That(ProximityQuery.Overlaps(a, b), Is.True);
            Result(ClosestDistance.Between(new Aabb2(V(0, 0), V(2, 2)), new Aabb2(V(0.5, 1.75), V(1, 3))), -0.25, V(0.75, 2), V(0.75, 1.75));
        }

        [Test]
        public void FaceContactTouches()
        {
            var b = new Aabb3(V(1, 0, 0), V(2, 1, 1));
            Assert.That(ClosestDistance.Between(Unit, b).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(Unit, b), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Aabb2(V(0, 0), V(1, 1)), new Aabb2(V(1, 1), V(2, 2))), Is.True);
        }
    }
}
