using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SphereSphereTests
    {
        [Test]
        public void Apart()
        {
            var r = ClosestDistance.Between(new Sphere(V(0, 0, 0), 1), new Sphere(V(5, 0, 0), 2));
            Result(r, 2, V(1, 0, 0), V(3, 0, 0));
            Assert.That(r.DistanceSquared, Is.EqualTo(4));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1), new Sphere(V(5, 0, 0), 2)), Is.False);
            Result(ClosestDistance.Between(new Circle(V(0, 0), 1), new Circle(V(0, 4), 1)), 2, V(0, 1), V(0, 3));
        }

        [Test]
        public void OverlappingByDepth()
        {
            var r = ClosestDistance.Between(new Sphere(V(0, 0, 0), 2), new Sphere(V(3, 0, 0), 2));
            Result(r, -1, V(2, 0, 0), V(1, 0, 0));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 2), new Sphere(V(3, 0, 0), 2)), Is.True);
        }

        [Test]
        public void TouchingCounts()
        {
            Assert.That(ClosestDistance.Between(new Sphere(V(0, 0, 0), 1), new Sphere(V(0, 0, 3), 2)).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1), new Sphere(V(0, 0, 3), 2)), Is.True);
        }

        [Test]
        public void CoincidentCentersPushAlongPlusX()
        {
            Result(ClosestDistance.Between(new Sphere(V(1, 2, 3), 1), new Sphere(V(1, 2, 3), 2)), -3, V(0, 2, 3), V(3, 2, 3));
        }

        [Test]
        public void NearContactKeepsTheTinyGap()
        {
            double gap = System.Math.Pow(2, -40);
            var r = ClosestDistance.Between(new Sphere(V(0, 0, 0), 1), new Sphere(V(2 + gap, 0, 0), 1));
            Assert.That(r.Distance, Is.EqualTo(gap));
        }
    }
}
