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

        [Test]
        public void SharedSubnormalIntervalKeepsBothWitnessesInsideBothBoxes()
        {
            // x touches (depth 0, first on ties); y is shared at the single value 3ε: ½·3ε rounds to 2ε (ties to even),
            // so ½lo + ½hi = 4ε would leave both boxes. The witnesses' y must be 3ε.
            double e = double.Epsilon;
            var a = new Aabb3(V(0, 0, 0), V(1, 3 * e, 1));
            var b = new Aabb3(V(1, 3 * e, 0), V(2, 1, 1));
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.PointA.Y, Is.EqualTo(3 * e));
            Assert.That(r.PointB.Y, Is.EqualTo(3 * e));
            Assert.That(r.PointA.X, Is.EqualTo(1));
            Assert.That(r.PointB.X, Is.EqualTo(1));
            var swapped = ClosestDistance.Between(b, a);
            Assert.That(swapped.PointA, Is.EqualTo(r.PointB));
            Assert.That(swapped.PointB, Is.EqualTo(r.PointA));
        }

        [Test]
        public void DistanceAloneAgreesWithBetweenApartAndOverlapping()
        {
            var apart = new Aabb3(V(2, 3, 3), V(4, 4, 4));
            var overlapping = new Aabb3(V(0.25, -1, 0.75), V(0.5, 2, 3)); // least overlap: z, 1 − 0.75
            Assert.That(ClosestDistance.Distance(Unit, apart), Is.EqualTo(3));
            Assert.That(ClosestDistance.Distance(Unit, overlapping), Is.EqualTo(-0.25));
            Assert.That(ClosestDistance.Between(Unit, overlapping).Distance, Is.EqualTo(-0.25));
        }
    }
}
