using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SphereAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(0, 0, 0), V(2, 2, 2));

        [Test]
        public void Apart()
        {
            var r = ClosestDistance.Between(new Sphere(V(4, 1, 1), 1), Box);
            Result(r, 1, V(3, 1, 1), V(2, 1, 1));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(4, 1, 1), 1), Box), Is.False);
            Result(ClosestDistance.Between(new Circle(V(5, 6), 1), new Aabb2(V(0, 0), V(2, 2))), 4, V(4.4, 5.2), V(2, 2), 1e-15);
        }

        [Test]
        public void CenterOutsideButOverlapping()
        {
            var r = ClosestDistance.Between(new Sphere(V(2.5, 1, 1), 1), Box);
            Result(r, -0.5, V(1.5, 1, 1), V(2, 1, 1));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(2.5, 1, 1), 1), Box), Is.True);
        }

        [Test]
        public void CenterInsideAddsTheFaceDepth()
        {
            var r = ClosestDistance.Between(new Sphere(V(1.5, 1, 1), 1), Box);
            Result(r, -1.5, V(0.5, 1, 1), V(2, 1, 1));
        }

        [Test]
        public void TouchingACorner()
        {
            double c = 2 + 1 / System.Math.Sqrt(3);
            Assert.That(ClosestDistance.Between(new Sphere(V(c, c, c), 1), Box).Distance, Is.EqualTo(0).Within(1e-15));
        }
    }
}
