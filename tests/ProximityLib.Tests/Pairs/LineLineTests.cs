using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class LineLineTests
    {
        [Test]
        public void SkewLines()
        {
            var a = new Line3(V(0, 0, 0), V(1, 0, 0));
            var b = new Line3(V(5, -7, 3), V(0, 1, 0));
            var r = ClosestDistance.Between(a, b);
            Result(r, 3, V(5, 0, 0), V(5, 0, 3));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((5.0, 7.0)));
            Assert.That(ProximityQuery.Overlaps(a, b), Is.False);
        }

        /// <summary>Parallel lines: the canonically first line's origin (lower x first) and its projection, in either order.</summary>
        [Test]
        public void ParallelLinesAnswerTheCanonicalOrigin()
        {
            var a = new Line3(V(0, 0, 0), V(1, 0, 0));
            var b = new Line3(V(1, 2, 0), V(-1, 0, 0));
            Result(ClosestDistance.Between(a, b), 2, V(0, 0, 0), V(0, 2, 0));
            Result(ClosestDistance.Between(b, a), 2, V(0, 2, 0), V(0, 0, 0));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(ClosestDistance.Between(a, b).Swapped()));
        }

        [Test]
        public void CrossingLines2DMeetAtOnePoint()
        {
            var r = ClosestDistance.Between(new Line2(V(0, 0), V(1, 1)), new Line2(V(4, 0), V(0, 1)));
            Result(r, 0, V(4, 4), V(4, 4), 1e-14);
            Assert.That(r.PointA, Is.EqualTo(r.PointB));
            Assert.That(r.ParameterB, Is.EqualTo(4).Within(1e-14));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 1)), new Line2(V(4, 0), V(0, 1))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 0)), new Line2(V(4, 1), V(-1, 0))), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "line"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "line");
    }
}
