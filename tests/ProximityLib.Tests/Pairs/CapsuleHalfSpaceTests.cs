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
    public class CapsuleHalfSpaceTests
    {
        [Test]
        public void LowerCapWins()
        {
            var h = HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1));
            var r = ClosestDistance.Between(new Capsule3(V(0, 0, 5), V(4, 0, 3), 1), h);
            Result(r, 2, V(4, 0, 2), V(4, 0, 0), 0);
            Assert.That(r.ParameterA, Is.EqualTo(1));
            r = ClosestDistance.Between(new Capsule3(V(0, 0, 5), V(4, 0, 0.5), 1), h);
            Result(r, -0.5, V(4, 0, -0.5), V(4, 0, 0), 0);
            Assert.That(ProximityQuery.Overlaps(h, new Capsule3(V(0, 0, 5), V(4, 0, 0.5), 1)), Is.True);
            // Parallel axis: Start, and the radius below it.
            var p = ClosestDistance.Between(new Capsule2(V(-3, 2), V(3, 2), 1), HalfPlane.FromPointNormal(V(0, 0), V(0, 1)));
            Result(p, 1, V(-3, 1), V(-3, 0), 0);
            Assert.That(p.ParameterA, Is.EqualTo(0));
        }

        [Test]
        public void CapsNearlyTouching()
        {
            // The lower cap 2^-30 above the boundary, far from the origin on a tilted plane.
            var n = V(1, 2, 2); // |n| = 3
            var p = V(1e6, -1e6, 3e6);
            var end = p + n * ((1 + Math.Pow(2, -30)) / 3) ;
            var r = Check(f => (new Capsule3(end * f, (end + V(0, 0, 5)) * f, 1 * f), HalfSpace.FromPointNormal(p * f, n)));
            var h = HalfSpace.FromPointNormal(p, n);
            double e = E(r.D, ExactHeight(h.Normal, h.Point, new[] { end, end + V(0, 0, 5) }, 1), Scale(new[] { end, end + V(0, 0, 5), p }, 1));
            TestContext.Out.WriteLine($"CapsuleHalfSpace nearly touching E = {e:F3}");
            Assert.That(e, Is.LessThanOrEqualTo(8));
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 0), new Num.Vector3(0, 0, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Capsule3(new Num.Vector3(0, 0, 5), new Num.Vector3(0, 0, 3), 1), h), Is.EqualTo(2f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(420, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var a = Rand.P(rng, dim); var b = Rand.P(rng, dim); var n = Rand.Dir(rng, dim); double r = Rand.F(rng, 0, 1);
                return f => (Rand.Cap(dim, a * f, b * f, r * f), Rand.Hs(dim, p * f, n));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(y);
                var (ends, r) = x is Capsule3 c ? (new[] { c.Start, c.End }, c.Radius)
                    : (new[] { SegmentHalfSpaceTests.V3(((Capsule2)x).Start), SegmentHalfSpaceTests.V3(((Capsule2)x).End) }, ((Capsule2)x).Radius);
                return (ExactHeight(n, p, ends, r), Scale(ends.Append(p), r));
            });
            TestContext.Out.WriteLine($"CapsuleHalfSpace worst E = {worst:F3}");
        }
    }
}
