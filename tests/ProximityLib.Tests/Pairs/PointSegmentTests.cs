using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointSegmentTests
    {
        private static readonly Segment3 X = new Segment3(V(-1, 0, 0), V(1, 0, 0));

        [Test]
        public void InteriorProjection()
        {
            var r = ClosestDistance.Between(V(0, 1, 0), X);
            Result(r, 1, V(0, 1, 0), V(0, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0.5));
            Assert.That(r.DistanceSquared, Is.EqualTo(1));
            Result(ClosestDistance.Between(V(2, 2), new Segment2(V(0, 0), V(4, 0))), 2, V(2, 2), V(2, 0));
        }

        [Test]
        public void BeyondTheEndsClampsToEndpoints()
        {
            var r = ClosestDistance.Between(V(3, 4, 0), X);
            Result(r, Math.Sqrt(20), V(3, 4, 0), V(1, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(1));
            r = ClosestDistance.Between(V(-4, 0, -3), X);
            Result(r, 3 * Math.Sqrt(2), V(-4, 0, -3), V(-1, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0));
        }

        [Test]
        public void PointFarAlongTheSegmentKeepsItsTinyDistance()
        {
            // The paper's Eq. 10 computes sqrt(|w|² − (w·v)²/|v|²) = sqrt(2^60 − 2^60) = 0 here.
            var s = new Segment3(V(0, 0, 0), V(Math.Pow(2, 31), 0, 0));
            var r = ClosestDistance.Between(V(Math.Pow(2, 30), Math.Pow(2, -20), 0), s);
            Assert.That(r.Distance, Is.EqualTo(Math.Pow(2, -20)));
            Assert.That(r.ParameterB, Is.EqualTo(0.5));
        }

        [Test]
        public void OnTheSegmentTouches()
        {
            Assert.That(ClosestDistance.Between(V(0.25, 0, 0), X).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(V(0.25, 0, 0), X), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(0.25, 1e-300, 0), X), Is.False);
            Assert.That(ProximityQuery.Overlaps(X, V(2, 0, 0)), Is.False);
        }

        [Test]
        public void ZeroLengthSegmentIsAPoint()
        {
            var r = ClosestDistance.Between(V(3, 4, 0), new Segment3(V(0, 0, 0), V(0, 0, 0)));
            Result(r, 5, V(3, 4, 0), V(0, 0, 0));
            Assert.That(r.ParameterB, Is.EqualTo(0));
        }

        [Test]
        public void SwappedOrderSwapsWitnessesAndParameters()
        {
            var r = ClosestDistance.Between(X, V(0.5, 2, 0));
            Result(r, 2, V(0.5, 0, 0), V(0.5, 2, 0));
            Assert.That(r.ParameterA, Is.EqualTo(0.75));
            Assert.That(r.ParameterB, Is.EqualTo(0));
        }
    }
}
