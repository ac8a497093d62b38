using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentSegmentTests
    {
        [Test]
        public void SkewInteriorPoints()
        {
            var r = ClosestDistance.Between(new Segment3(V(-1, 0, 0), V(1, 0, 0)), new Segment3(V(0, -1, 2), V(0, 1, 2)));
            Result(r, 2, V(0, 0, 0), V(0, 0, 2));
            Assert.That(r.ParameterA, Is.EqualTo(0.5));
            Assert.That(r.ParameterB, Is.EqualTo(0.5));
            Assert.That(r.DistanceSquared, Is.EqualTo(4));
        }

        [Test]
        public void EndpointToEndpoint()
        {
            var r = ClosestDistance.Between(new Segment3(V(0, 0, 0), V(1, 0, 0)), new Segment3(V(2, 1, 0), V(3, 1, 0)));
            Result(r, Math.Sqrt(2), V(1, 0, 0), V(2, 1, 0));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((1.0, 0.0)));
        }

        [Test]
        public void ParallelOverlapReturnsTheFirstEndpointCandidate()
        {
            var r = ClosestDistance.Between(new Segment3(V(0, 0, 0), V(2, 0, 0)), new Segment3(V(1, 1, 0), V(3, 1, 0)));
            Result(r, 1, V(2, 0, 0), V(2, 1, 0));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((1.0, 0.5)));
        }

        [Test]
        public void CollinearOverlapAndCrossingTouch()
        {
            var a = new Segment3(V(0, 0, 0), V(2, 0, 0));
            Assert.That(ClosestDistance.Between(a, new Segment3(V(1, 0, 0), V(3, 0, 0))).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(a, new Segment3(V(1, 0, 0), V(3, 0, 0))), Is.True);
            var x = ClosestDistance.Between(new Segment2(V(0, 0), V(2, 2)), new Segment2(V(0, 2), V(2, 0)));
            Result(x, 0, V(1, 1), V(1, 1));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(0, 0), V(2, 2)), new Segment2(V(0, 2), V(2, 0))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(0, 0), V(2, 2)), new Segment2(V(0, 2), V(0.5, 1.75))), Is.False);
        }

        [Test]
        public void AntiparallelTouchingEndToEnd()
        {
            var r = ClosestDistance.Between(new Segment2(V(0, 0), V(1, 0)), new Segment2(V(3, 0), V(1, 0)));
            Result(r, 0, V(1, 0), V(1, 0));
        }

        [Test]
        public void ZeroLengthSegments()
        {
            var p = new Segment3(V(0, 3, 0), V(0, 3, 0));
            Result(ClosestDistance.Between(p, new Segment3(V(-1, 0, 0), V(1, 0, 0))), 3, V(0, 3, 0), V(0, 0, 0));
            Result(ClosestDistance.Between(p, new Segment3(V(4, 3, 0), V(4, 3, 0))), 4, V(0, 3, 0), V(4, 3, 0));
        }

        [Test]
        public void NearlyParallelSegmentsKeepTheirSeparation()
        {
            // Two unit-scale segments 2^-30 apart in z, turned 2^-40 rad against each other: the distance is the
            // z-gap, which the cancelling |d0|²|d1|² − (d0·d1)² determinant cannot resolve.
            double e = Math.Pow(2, -40), gap = Math.Pow(2, -30);
            var a = new Segment3(V(0, 0, 0), V(1, 0, 0));
            var b = new Segment3(V(0, -e / 2, gap), V(1, e / 2, gap));
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(gap).Within(gap * 1e-12));
            Assert.That(Math.Abs(r.PointA.Y - r.PointB.Y), Is.LessThanOrEqualTo(e));
        }
    }
}
