using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SphereObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        [Test]
        public void ApartFromTheNearestEdge()
        {
            var r = ClosestDistance.Between(new Sphere(V(3, 0, 0), 1), Diamond);
            Result(r, 2 - Math.Sqrt(2), V(2, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(3, 0, 0), 1), Diamond), Is.False);
        }

        [Test]
        public void OverlappingFace()
        {
            // The face x' = 1 has outward normal (√½, √½, 0); a sphere centred 0.5 beyond it with radius 1.
            var c = V(S, S, 0) * 1.5;
            var r = ClosestDistance.Between(new Sphere(c, 1), Diamond);
            Assert.That(r.Distance, Is.EqualTo(-0.5).Within(1e-15));
            Near(r.PointB, V(S, S, 0), 1e-15, "PointB");
            Assert.That(ProximityQuery.Overlaps(new Sphere(c, 1), Diamond), Is.True);
            var box2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            Assert.That(ClosestDistance.Between(new Circle(V(S * 1.5, S * 1.5), 1), box2).Distance, Is.EqualTo(-0.5).Within(1e-15));
        }
    }
}
