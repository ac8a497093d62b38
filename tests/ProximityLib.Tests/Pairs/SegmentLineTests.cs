using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentLineTests
    {
        [Test]
        public void SkewEndpointAndCrossing()
        {
            var x = new Line3(V(-4, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(new Segment3(V(3, -1, 2), V(3, 1, 2)), x);
            Result(r, 2, V(3, 0, 2), V(3, 0, 0));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((0.5, 7.0)));
            Result(ClosestDistance.Between(new Segment3(V(0, 2, 1), V(0, 2, 5)), x), Math.Sqrt(5), V(0, 2, 1), V(0, 0, 0));
            var c = ClosestDistance.Between(new Segment2(V(1, 1), V(3, -1)), new Line2(V(0, 0), V(1, 0)));
            Result(c, 0, V(2, 0), V(2, 0));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(1, 1), V(3, -1)), new Line2(V(0, 0), V(1, 0))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(1, 1), V(3, 0.5)), new Line2(V(0, 0), V(1, 0))), Is.False);
        }

        /// <summary>A segment parallel to the line: every segment point is 2 away; the documented pick is the segment's start.</summary>
        [Test]
        public void ParallelSegmentAnswersItsStart()
        {
            var r = ClosestDistance.Between(new Segment2(V(1, 2), V(5, 2)), new Line2(V(0, 0), V(1, 0)));
            Result(r, 2, V(1, 2), V(1, 0));
            var q = ClosestDistance.Between(new Line3(V(0, 0, 0), V(-1, 0, 0)), new Segment3(V(1, 2, 0), V(5, 2, 0)));
            Result(q, 2, V(1, 0, 0), V(1, 2, 0));
            Assert.That(q.ParameterA, Is.EqualTo(-1));
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("segment", "line"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("segment", "line");
    }
}
