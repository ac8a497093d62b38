using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentSphereTests
    {
        private static readonly Sphere Unit = new Sphere(V(0, 0, 0), 1);

        [Test]
        public void Apart()
        {
            var r = ClosestDistance.Between(new Segment3(V(-2, 3, 0), V(2, 3, 0)), Unit);
            Result(r, 2, V(0, 3, 0), V(0, 1, 0));
            Assert.That(r.ParameterA, Is.EqualTo(0.5));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 3, 0), V(2, 3, 0)), Unit), Is.False);
            Result(ClosestDistance.Between(new Circle(V(0, 0), 1), new Segment2(V(3, -1), V(3, 1))), 2, V(1, 0), V(3, 0));
        }

        [Test]
        public void EnteringIsNegative()
        {
            var r = ClosestDistance.Between(new Segment3(V(-2, 0.5, 0), V(2, 0.5, 0)), Unit);
            Result(r, -0.5, V(0, 0.5, 0), V(0, 1, 0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 0.5, 0), V(2, 0.5, 0)), Unit), Is.True);
        }

        [Test]
        public void ThroughTheCenterPushesPerpendicular()
        {
            // The segment runs along x through the center: no direction is preferred, and the documented one is a
            // perpendicular of the segment, here moving it by +y onto the sphere's top.
            var r = ClosestDistance.Between(new Segment3(V(-2, 0, 0), V(2, 0, 0)), Unit);
            Result(r, -1, V(0, 0, 0), V(0, 1, 0));
        }

        [Test]
        public void TangentTouches()
        {
            Assert.That(ClosestDistance.Between(new Segment3(V(-2, 1, 0), V(2, 1, 0)), Unit).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 1, 0), V(2, 1, 0)), Unit), Is.True);
        }
    }
}
