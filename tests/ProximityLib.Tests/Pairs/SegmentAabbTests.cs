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
        public void EnteringThroughAFaceIsPushedBackAtItsDeepestEnd()
        {
            // Start lies 0.1 below the y = 1 face; every other push is at least 0.5: the push is +0.1·y, and the pushed
            // segment touches the face at Start alone (the face's touching point, without a second minimisation).
            var seg = new Segment3(V(0.5, 0.9, 0.5), V(0.6, 3, 0.5));
            var r = ClosestDistance.Between(seg, Cube);
            Result(r, -0.1, V(0.5, 0.9, 0.5), V(0.5, 1, 0.5), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(0));
            // The other way round the deepest end is End.
            r = ClosestDistance.Between(new Segment3(V(0.6, 3, 0.5), V(0.5, 0.9, 0.5)), Cube);
            Result(r, -0.1, V(0.5, 0.9, 0.5), V(0.5, 1, 0.5), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(1));
            var r2 = ClosestDistance.Between(new Segment2(V(0.5, 0.9), V(0.6, 3)), new Aabb2(V(0, 0), V(1, 1)));
            Result(r2, -0.1, V(0.5, 0.9), V(0.5, 1), 1e-15);
            Assert.That(r2.ParameterA, Is.EqualTo(0));
        }

        [Test]
        public void CuttingAnEdgeIsPushedOffWhereItCrossesIt()
        {
            // x + y = 1.9 (z = 0.5) cuts the edge x = y = 1 at depth 0.1/√2; the faces need at least 0.4. Pushed along
            // (1, 1, 0)/√2 the segment touches the edge at its middle, (0.95, 0.95, 0.5), t = 1/2.
            var seg = new Segment3(V(0.6, 1.3, 0.5), V(1.3, 0.6, 0.5));
            var r = ClosestDistance.Between(seg, Cube);
            double depth = 0.1 / System.Math.Sqrt(2);
            Result(r, -depth, V(0.95, 0.95, 0.5), V(1, 1, 0.5), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(0.5).Within(1e-15));
            // The same through the edge x = 1, z = 1 (along y), and in the plane through the corner (1, 1).
            r = ClosestDistance.Between(new Segment3(V(0.6, 0.25, 1.3), V(1.3, 0.25, 0.6)), Cube);
            Result(r, -depth, V(0.95, 0.25, 0.95), V(1, 0.25, 1), 1e-15);
            var r2 = ClosestDistance.Between(new Segment2(V(0.6, 1.3), V(1.3, 0.6)), new Aabb2(V(0, 0), V(1, 1)));
            Result(r2, -depth, V(0.95, 0.95), V(1, 1), 1e-15);
        }

        [Test]
        public void LyingInsideParallelToAFaceIsPushedOutThroughIt()
        {
            // Parallel to the y = 1 face, 0.1 below it, and longer than the box: the face's push touches it along the
            // whole stretch over the face, so the face names no single point and the minimisation picks one of them.
            var r = ClosestDistance.Between(new Segment3(V(-1, 0.9, 0.5), V(2, 0.9, 0.5)), Cube);
            Assert.That(r.Distance, Is.EqualTo(-0.1).Within(1e-15));
            Near(r.PointB - r.PointA, V(0, 0.1, 0), 1e-15, "the push through the y = 1 face");
            Assert.That(r.PointA.X, Is.InRange(0.0, 1.0), "a point of the stretch over the face");
            Near(r.PointA, V(-1 + 3 * r.ParameterA, 0.9, 0.5), 1e-15, "PointA at ParameterA");
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
