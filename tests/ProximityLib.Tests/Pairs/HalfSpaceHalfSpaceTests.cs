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
        /// <summary>
        /// Boundaries 1e300 apart, turned 1e-10, meet near x = −1e310, past double's range, and neither stored point lies
        /// in the other half-plane: the common point falls back to the midpoint of the stored points (0, 5e299). The
        /// rescaled slow path once found its meeting point within range in its own frame and mapped it back to −∞.
        /// </summary>
        [Test]
        public void MeetingBeyondTheRangeOnTheSlowPathAnswersTheMidpoint()
        {
            var r = ClosestDistance.Between(HalfPlane.FromPointNormal(V(0, 0), V(0, 1)), HalfPlane.FromPointNormal(V(0, 1e300), V(1e-10, -1)));
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(r.PointA, Is.EqualTo(V(0, 5e299)));
            Assert.That(r.PointB, Is.EqualTo(r.PointA));
        }

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
    

        /// <summary>
        /// Float half-planes ~2e37 from the origin with nearly opposite normals, each stored point outside the other:
        /// their boundaries meet beyond float's range (found by the long fuzz, seed 2028), where the float result turned
        /// the meeting point into ±∞ witnesses. The float API now answers −∞ with the midpoint of the stored points,
        /// finite, in both argument orders; the double API keeps the meeting point (finite in double).
        /// </summary>
        [Test]
        public void FloatMeetingPointBeyondFloatRangeFallsBackToTheMidpoint()
        {
            var pa = new Num.Vector2(2.293306E+37f, 2.3358516E+37f);
            var pb = new Num.Vector2(-5.835599E+35f, 2.4765464E+37f);
            var a = Flt.HalfPlane.FromPointNormal(pa, new Num.Vector2(-0.03906698f, -0.013954299f));
            var b = Flt.HalfPlane.FromPointNormal(pb, new Num.Vector2(0.39249292f, 0.13384941f));
            var mid = new Num.Vector2((float)(pa.X * 0.5 + pb.X * 0.5), (float)(pa.Y * 0.5 + pb.Y * 0.5));
            foreach (var r in new[] { Flt.ClosestDistance.Between(a, b), Flt.ClosestDistance.Between(b, a) })
            {
                Assert.That(r.Distance, Is.EqualTo(float.NegativeInfinity));
                Assert.That(r.PointA, Is.EqualTo(mid));
                Assert.That(r.PointB, Is.EqualTo(mid));
            }
            var d = ClosestDistance.Between(a.Inner, b.Inner);
            Assert.That(double.IsNegativeInfinity(d.Distance) && d.PointA.IsFinite && d.PointA == d.PointB, Is.True, d.ToString());
            Assert.That(Math.Max(Math.Abs(d.PointA.X), Math.Abs(d.PointA.Y)), Is.GreaterThan(float.MaxValue), "the double API's meeting point lies beyond float's range");
        }
    }
}
