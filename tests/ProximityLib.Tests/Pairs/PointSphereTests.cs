using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointSphereTests
    {
        private static readonly Sphere S = new Sphere(V(0, 0, 0), 3);

        [Test]
        public void OutsideIsTheGap()
        {
            var r = ClosestDistance.Between(V(0, 5, 0), S);
            Result(r, 2, V(0, 5, 0), V(0, 3, 0));
            Assert.That(r.DistanceSquared, Is.EqualTo(4));
            Result(ClosestDistance.Between(V(3, 4), new Circle(V(0, 0), 1)), 4, V(3, 4), V(0.6, 0.8));
            Assert.That(ProximityQuery.Overlaps(V(0, 5, 0), S), Is.False);
        }

        [Test]
        public void InsideIsNegativeDepthToTheSurface()
        {
            var r = ClosestDistance.Between(V(0, 1, 0), S);
            Result(r, -2, V(0, 1, 0), V(0, 3, 0));
            Assert.That(r.DistanceSquared, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(V(0, 1, 0), S), Is.True);
        }

        [Test]
        public void OnTheSurfaceTouches()
        {
            Assert.That(ClosestDistance.Between(V(0, 0, -3), S).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(V(0, 0, -3), S), Is.True);
        }

        [Test]
        public void AtTheCenterPushesOutAlongPlusX()
        {
            Result(ClosestDistance.Between(V(0, 0, 0), S), -3, V(0, 0, 0), V(3, 0, 0));
            Result(ClosestDistance.Between(V(1, 1), new Circle(V(1, 1), 2)), -2, V(1, 1), V(3, 1));
        }

        [Test]
        public void ZeroRadiusIsAPoint()
        {
            Result(ClosestDistance.Between(new Sphere(V(0, 0, 0), 0), V(0, 0, 2)), 2, V(0, 0, 0), V(0, 0, 2));
        }
    }
}
