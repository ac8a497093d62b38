using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class LineRayTests
    {
        [Test]
        public void PointingAwayAndCrossing()
        {
            var x = new Line3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(x, new Ray3(V(3, 2, 1), V(0, 1, 0)));
            Result(r, Math.Sqrt(5), V(3, 0, 0), V(3, 2, 1));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((3.0, 0.0)));
            var c = ClosestDistance.Between(x, new Ray3(V(3, 2, 1), V(0, -1, 0)));
            Result(c, 1, V(3, 0, 0), V(3, 0, 1));
            Assert.That(c.ParameterB, Is.EqualTo(2));
            Result(ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(0, -1))), 0, V(3, 0), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(0, 1))), Is.False);
        }

        [Test]
        public void ParallelRayAnswersItsOrigin() =>
            Result(ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(-1, 0))), 2, V(3, 0), V(3, 2));
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "ray"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "ray");
    }
}
