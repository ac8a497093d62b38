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
    public class SphereHalfSpaceTests
    {
        [Test]
        public void ApartTouchingOverlapping()
        {
            var h = HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1));
            Result(ClosestDistance.Between(new Sphere(V(1, 2, 5), 2), h), 3, V(1, 2, 3), V(1, 2, 0), 0);
            Result(ClosestDistance.Between(new Sphere(V(1, 2, 2), 2), h), 0, V(1, 2, 0), V(1, 2, 0), 0);
            // Centre inside: depth = radius + the centre's depth; moving the sphere by PointB − PointA (up 3) just touches.
            Result(ClosestDistance.Between(h, new Sphere(V(1, 2, -1), 2)), -3, V(1, 2, 0), V(1, 2, -3), 0);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(1, 2, 2), 2), h), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(1, 2, 2.5), 2), h), Is.False);
            var c = ClosestDistance.Between(new Circle(V(3, 4), 1), HalfPlane.FromPointNormal(V(0, 0), V(3, 4)));
            Result(c, 4, V(2.4, 3.2), V(0, 0), 1e-15);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 0), new Num.Vector3(0, 0, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Sphere(new Num.Vector3(0, 0, 5), 2), h), Is.EqualTo(3f));
            Assert.That(Flt.ProximityQuery.Overlaps(h, new Flt.Sphere(new Num.Vector3(0, 0, 5), 5)), Is.True);
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(320, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var c = Rand.P(rng, dim); var n = Rand.Dir(rng, dim); double r = Rand.F(rng, 0, 2);
                return f => (Rand.Sph(dim, c * f, r * f), Rand.Hs(dim, p * f, n));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(y);
                var (c, r) = x is Sphere s ? (s.Center, s.Radius) : (SegmentHalfSpaceTests.V3(((Circle)x).Center), ((Circle)x).Radius);
                return (ExactHeight(n, p, new[] { c }, r), Scale(new[] { c, p }, r));
            });
            TestContext.Out.WriteLine($"SphereHalfSpace worst E = {worst:F3}");
        }
    }
}
