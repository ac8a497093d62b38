using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;

namespace ProximityTests.Pairs
{
    public class TriangleTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void CrossingCoplanarAndParallel()
        {
            var cross = new Triangle3(V(1, 1, -1), V(1, 1, 1), V(3, 3, 1));
            Assert.That(ClosestDistance.Between(T, cross).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(T, cross), Is.True);
            // Coplanar overlapping, touching at a vertex, disjoint.
            Assert.That(ClosestDistance.Between(T, new Triangle3(V(1, 1, 0), V(5, 1, 0), V(1, 5, 0))).Distance, Is.EqualTo(0));
            Result(ClosestDistance.Between(T, new Triangle3(V(4, 0, 0), V(6, 0, 0), V(5, 2, 0))), 0, V(4, 0, 0), V(4, 0, 0));
            Assert.That(ProximityQuery.Overlaps(T, new Triangle3(V(4, 0, 0), V(6, 0, 0), V(5, 2, 0))), Is.True);
            Result(ClosestDistance.Between(T, new Triangle3(V(5, 0, 0), V(7, 0, 0), V(6, 2, 0))), 1, V(4, 0, 0), V(5, 0, 0));
            Assert.That(ProximityQuery.Overlaps(T, new Triangle3(V(5, 0, 0), V(7, 0, 0), V(6, 2, 0))), Is.False);
            // Parallel planes: the canonically first triangle's first minimum, in either order.
            var up = new Triangle3(V(0, 0, 2), V(4, 0, 2), V(0, 4, 2));
            Result(ClosestDistance.Between(T, up), 2, V(0, 0, 0), V(0, 0, 2));
            Result(ClosestDistance.Between(up, T), 2, V(0, 0, 2), V(0, 0, 0));
        }

        [Test]
        public void SolidTrianglesIn2D()
        {
            // B is A moved by 3 along x: the least push of A is through its hypotenuse, by 1/√2, onto B's vertex (3, 0).
            var r = ClosestDistance.Between(T2, new Triangle2(V(3, 0), V(7, 0), V(3, 4)));
            Result(r, -Math.Sqrt(0.5), V(3.5, 0.5), V(3, 0), 1e-14);
            Result(ClosestDistance.Between(T2, new Triangle2(V(5, 0), V(7, 0), V(6, 2))), 1, V(4, 0), V(5, 0));
            Assert.That(ProximityQuery.Overlaps(T2, new Triangle2(V(1, 1), V(2, 1), V(1, 2))), Is.True);
            // B inside A: A clears it fastest through its hypotenuse, by (4 − 2)/√2 = √2.
            Assert.That(ClosestDistance.Between(T2, new Triangle2(V(1, 1), V(2, 1), V(1, 2))).Distance, Is.EqualTo(-Math.Sqrt(2)).Within(1e-15));
        }

        [Test]
        public void ScalingAndRandomFamilies()
        {
            CheckScaling(T, new Triangle3(V(1, 1, -1), V(1, 1, 1), V(3, 3, 1)), "crossing", 1, 900, -900);
            CheckScaling(T2, new Triangle2(V(3, 0), V(7, 0), V(3, 4)), "2D overlap", 1, 900, -900);
            var g = new Random(17);
            var w3 = new Worst("triangle–triangle 3D");
            var w2 = new Worst("triangle–triangle 2D");
            for (int i = 0; i < 150; i++)
            {
                var a = Tri3(g, i);
                var b = i % 4 == 0
                    ? new Triangle3(a.A + (a.B - a.A) * 0.5 + P3(g, 1e-12), Near(g, a), a.C + (a.B - a.C) * 0.25) // nearly coplanar
                    : new Triangle3(Near(g, a), Near(g, a), Tri3(g, i / 6).C);
                string at = $"3D case {i}";
                w3.Add(Check(a, b, ref at), at);
                var a2 = Tri2(g, i);
                var b2 = new Triangle2(Near(g, a2), Near(g, a2), Tri2(g, i / 6).C);
                at = $"2D case {i}";
                w2.Add(Check(a2, b2, ref at), at);
                if (i % 25 == 0) { CheckScaling(a, b, at, 3, 900, -900); CheckScaling(a2, b2, at, 3, 900, -900); }
            }
            w3.Report();
            w2.Report();
        }
    }
}
