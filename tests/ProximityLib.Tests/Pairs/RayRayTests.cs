using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class RayRayTests
    {
        [Test]
        public void InteriorAndOriginCandidates()
        {
            var a = new Ray3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(a, new Ray3(V(2, -3, 1), V(0, 1, 0)));
            Result(r, 1, V(2, 0, 0), V(2, 0, 1));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((2.0, 3.0)));
            var b = ClosestDistance.Between(a, new Ray3(V(2, -3, 1), V(0, -1, 0)));
            Result(b, Math.Sqrt(10), V(2, 0, 0), V(2, -3, 1));
        }

        /// <summary>Parallel overlapping rays: B's origin against A (1) beats A's origin against B (√2), in either order.</summary>
        [Test]
        public void ParallelRaysInEitherOrder()
        {
            var a = new Ray2(V(0, 0), V(1, 0));
            var b = new Ray2(V(1, 1), V(1, 0));
            Result(ClosestDistance.Between(a, b), 1, V(1, 0), V(1, 1));
            Result(ClosestDistance.Between(b, a), 1, V(1, 1), V(1, 0));
            // Collinear, same origin: the canonical first ray's origin, a common point.
            var c = ClosestDistance.Between(new Ray2(V(0, 0), V(1, 0)), new Ray2(V(0, 0), V(-1, 0)));
            Result(c, 0, V(0, 0), V(0, 0));
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(0, 0), V(1, 0)), new Ray2(V(2, 1), V(0, -1))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(0, 0), V(1, 0)), new Ray2(V(2, 1), V(0, 1))), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("ray", "ray"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("ray", "ray");

        /// <summary>
        /// 2D rays from origins near 1e306 that meet about 2e308 away, past double's range (fuzz 2032:1000000153338):
        /// Distance 0, and since no point of both is representable, the witnesses of parallel rays (an origin and its
        /// nearest point on the other ray), finite, with parameters ≥ 0. They once came back infinite.
        /// </summary>
        [Test]
        public void RaysMeetingBeyondTheRangeAnswerFiniteWitnesses()
        {
            var a = new Ray2(V(1.223834989498221E+306, -3.115081451145701E+306), V(-0.22979570366995586, 26.894910260239726));
            var b = new Ray2(V(-5.591456511307941E+305, 6.494607442838078E+305), V(0.0, 0.006258878828571157));
            foreach (var r in new[] { ClosestDistance.Between(a, b), ClosestDistance.Between(b, a).Swapped() })
            {
                Assert.That(r.Distance, Is.EqualTo(0));
                Assert.That(double.IsFinite(r.PointA.X) && double.IsFinite(r.PointA.Y) && double.IsFinite(r.PointB.X) && double.IsFinite(r.PointB.Y), Is.True, r.ToString());
                Assert.That(r.ParameterA >= 0 && r.ParameterB >= 0 && double.IsFinite(r.ParameterA) && double.IsFinite(r.ParameterB), Is.True, r.ToString());
                // B points straight up from x = -5.6e305; A reaches that x only at y ≈ 2e308: B's origin and its foot on A.
                Assert.That(r.PointB, Is.EqualTo(b.Origin));
                Assert.That(r.ParameterB, Is.EqualTo(0));
                Assert.That(r.ParameterA, Is.EqualTo(Vector2D.Dot(b.Origin - a.Origin, a.Direction)).Within(1e-12).Percent);
            }
        }
    }
}
