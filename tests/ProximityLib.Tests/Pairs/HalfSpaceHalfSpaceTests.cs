using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using static ProximityTests.Pairs.HalfSpaceBoxChecks;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class HalfSpaceHalfSpaceTests
    {
        [Test]
        public void OppositeNormalsGiveTheGap()
        {
            var below = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));   // z ≤ 1
            var above = HalfSpace.FromPointNormal(V(4, 0, 3), V(0, 0, -1));  // z ≥ 3
            // Witnesses: the feet of the stored points' midpoint (2, 0, 2) on each boundary.
            Result(ClosestDistance.Between(below, above), 2, V(2, 0, 1), V(2, 0, 3), 0);
            Result(ClosestDistance.Between(above, below), 2, V(2, 0, 3), V(2, 0, 1), 0);
            var over = HalfSpace.FromPointNormal(V(4, 0, -1), V(0, 0, -1));  // z ≥ −1
            Result(ClosestDistance.Between(below, over), -2, V(2, 0, 1), V(2, 0, -1), 0);
            Assert.That(ProximityQuery.Overlaps(below, above), Is.False);
            Assert.That(ProximityQuery.Overlaps(over, below), Is.True);
        }

        [Test]
        public void OtherNormalsAreUnbounded()
        {
            var a = HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1));
            // Each stored point inside the other: their midpoint.
            var r = ClosestDistance.Between(a, HalfSpace.FromPointNormal(V(2, 0, -2), V(1, 0, 0)));
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(r.PointA, Is.EqualTo(V(1, 0, -1)));
            Assert.That(r.PointB, Is.EqualTo(r.PointA));
            // Neither inside the other: the meeting point of the boundaries nearest the midpoint.
            r = ClosestDistance.Between(a, HalfSpace.FromPointNormal(V(-2, 0, 2), V(1, 0, 0)));
            Assert.That(r.PointA, Is.EqualTo(V(-2, 0, 0)));
            // Only b's point inside a: it.
            r = ClosestDistance.Between(a, HalfSpace.FromPointNormal(V(2, 0, -2), V(-1, 0, 0)));
            Assert.That(r.PointA, Is.EqualTo(V(2, 0, -2)));
            // Same normal: one contains the other.
            Assert.That(ClosestDistance.Distance(a, HalfSpace.FromPointNormal(V(5, 5, 5), V(0, 0, 3))), Is.EqualTo(double.NegativeInfinity));
            Assert.That(ProximityQuery.Overlaps(a, HalfSpace.FromPointNormal(V(5, 5, 5), V(0, 0, 3))), Is.True);
            var p = ClosestDistance.Between(HalfPlane.FromPointNormal(V(0, 0), V(0, 1)), HalfPlane.FromPointNormal(V(3, 3), V(1, -1)));
            Assert.That(p.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(p.PointA, Is.EqualTo(V(0, 0)));
        }

        [Test]
        public void Float()
        {
            var a = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 0), new Num.Vector2(0, 1));
            var b = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 3), new Num.Vector2(0, -1));
            Assert.That(Flt.ClosestDistance.Distance(a, b), Is.EqualTo(3f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(820, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var q = Rand.P(rng, dim); var n = Rand.Dir(rng, dim);
                var m = rng.Next(2) == 0 ? -n : Rand.Dir(rng, dim);
                return f => (Rand.Hs(dim, p * f, n), Rand.Hs(dim, q * f, m));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(x);
                var (m, q) = PointHalfSpaceTests.Plane(y);
                bool opposite = n == -m;
                Assert.That(double.IsNegativeInfinity(d), Is.EqualTo(!opposite));
                return opposite ? (ExactHeight(n, p, new[] { q }), Scale(new[] { p, q })) : ((Rational?)null, 0);
            });
            TestContext.Out.WriteLine($"HalfSpaceHalfSpace worst E = {worst:F3}");
        }
    }
}
