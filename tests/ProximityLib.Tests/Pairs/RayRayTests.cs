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
    }
}
