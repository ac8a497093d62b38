using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentAabbTests
    {
        private static readonly Aabb3 Cube = new Aabb3(V(0, 0, 0), V(1, 1, 1));

        [Test]
        public void ApartAlongAnAxis()
        {
            var r = ClosestDistance.Between(new Segment3(V(2, 0.5, 0.5), V(3, 0.5, 0.5)), Cube);
            Result(r, 1, V(2, 0.5, 0.5), V(1, 0.5, 0.5));
            Assert.That(r.ParameterA, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(2, 0.5, 0.5), V(3, 0.5, 0.5)), Cube), Is.False);
            Result(ClosestDistance.Between(new Segment2(V(2, 0.5), V(3, 0.5)), new Aabb2(V(0, 0), V(1, 1))), 1, V(2, 0.5), V(1, 0.5));
        }

        [Test]
        public void ApartPassingAnEdgeDiagonally()
        {
            // The segment x + y = 3 (z = 0.5) passes the edge x = y = 1 at distance 1/√2 from it.
            var r = ClosestDistance.Between(new Segment3(V(3, 0, 0.5), V(0, 3, 0.5)), Cube);
            Result(r, System.Math.Sqrt(0.5), V(1.5, 1.5, 0.5), V(1, 1, 0.5));
            Assert.That(r.ParameterA, Is.EqualTo(0.5));
        }

        [Test]
        public void ThroughTheMiddleIsPushedOutSideways()
        {
            var seg = new Segment3(V(-1, 0.5, 0.5), V(2, 0.5, 0.5));
            var r = ClosestDistance.Between(seg, Cube);
            Assert.That(r.Distance, Is.EqualTo(-0.5));
            Near(r.PointB - r.PointA, V(0, -0.5, 0), 1e-15, "translation of the segment onto the y = 0 face");
            Assert.That(ProximityQuery.Overlaps(seg, Cube), Is.True);
        }

        [Test]
        public void AlongAFaceTouches()
        {
            var seg = new Segment3(V(-1, 1, 0.5), V(2, 1, 0.5));
            Assert.That(ClosestDistance.Between(seg, Cube).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(seg, Cube), Is.True);
        }

        [Test]
        public void CrossingAZeroThicknessBoxOverlaps()
        {
            var flat = new Aabb2(V(0, 1), V(2, 1));
            var seg = new Segment2(V(1, 0), V(1.25, 2));
            Assert.That(ProximityQuery.Overlaps(seg, flat), Is.True);
            Assert.That(ClosestDistance.Between(seg, flat).Distance, Is.LessThan(0));
        }
    }
}
