using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class AabbObbTests
    {
        private static readonly Aabb3 Cube = new Aabb3(V(-1, -1, -1), V(1, 1, 1));

        [Test]
        public void ApartEdgeToFace()
        {
            // A cube turned 45° about z at x = 3: its edge x = 3 − √2 faces the AABB's face x = 1.
            var diamond = new Obb3(V(3, 0, 0), System.Numerics.Quaternion.Identity, V(1, 1, 1));
            diamond = Obb3.FromQuaternion(V(3, 0, 0), 0, 0, Math.Sin(Math.PI / 8), Math.Cos(Math.PI / 8), V(1, 1, 1));
            var r = ClosestDistance.Between(Cube, diamond);
            Assert.That(r.Distance, Is.EqualTo(2 - Math.Sqrt(2)).Within(1e-15));
            Assert.That(r.PointA.X, Is.EqualTo(1).Within(1e-15));
            Assert.That(r.PointB.X, Is.EqualTo(3 - Math.Sqrt(2)).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(Cube, diamond), Is.False);
        }

        [Test]
        public void OverlapByTheVertex()
        {
            var box = new Obb2(V(2, 0), Math.PI / 4, V(1, 1));
            var r = ClosestDistance.Between(new Aabb2(V(-1, -1), V(1, 1)), box);
            Assert.That(r.Distance, Is.EqualTo(-(Math.Sqrt(2) - 1)).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(new Aabb2(V(-1, -1), V(1, 1)), box), Is.True);
        }

        [Test]
        public void TouchingWithASubRoundingOffsetScalesExactly()
        {
            // Fuzz seed 2041 (case 2000000028943): the boxes touch, and B's centre lies 2^-108 off the plane x = 0 (about
            // 2^-117 of the size). Scaled by 2^-446 that offset's square underflows, and the touching pair's candidates
            // were told apart by equal zeros: PointA.X came out 0 there instead of 3.08e-33 · 2^-446. 2^k scaling is exact.
            var a = new Aabb3(V(0, -128, 0), V(448, 0, 128));
            var b = Obb3.FromQuaternion(V(3.0814879110195774E-33, 96, -64), 1, -1, 1, 1, V(64, 0, 96));
            double k = Math.Pow(2, -446);
            var r = ClosestDistance.Between(a, b);
            var rs = ClosestDistance.Between(new Aabb3(a.Min * k, a.Max * k), Obb3.FromQuaternion(b.Center * k, 1, -1, 1, 1, b.HalfExtents * k));
            Assert.That(rs.Distance, Is.EqualTo(r.Distance * k));
            Assert.That(rs.PointA, Is.EqualTo(r.PointA * k));
            Assert.That(rs.PointB, Is.EqualTo(r.PointB * k));
        }
    }
}
