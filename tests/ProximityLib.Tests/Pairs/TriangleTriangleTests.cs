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

        /// <summary>
        /// Inputs on which published triangle–triangle overlap tests gave the wrong verdict (issue threads, data only):
        /// coplanar pairs that a Guigue–Devillers implementation missed (LokiResearch/fast-triangle-triangle-intersection
        /// #3 and #4), coplanar triangles sharing a vertex that failed in 6 of 36 corner orders (llnl/axom #152), and
        /// disjoint coplanar triangles reported as intersecting (benardp/contours #1). Every corner order of both triangles,
        /// both argument orders, double and float: the known verdict, and every invariant against the exact reference.
        /// </summary>
        [TestCase(-1, 0, 0, 2, 0, -2, 2, 0, 2, 0.551, 0, -0.796, 1.224, 0, 0.326, 3.469, 0, 1.000, true, TestName = "Coplanar, a vertex inside (LokiResearch #3)")]
        [TestCase(0, 0, 0, 0, 0, 8, 8, 0, 0, 2, 0, 2, 1, 0, 4, 9, 0, 0, true, TestName = "Coplanar, crossing edges (LokiResearch #4)")]
        [TestCase(76.648, 54.6752, 15.0012, 76.648, 54.6752, 14.5542, 76.582, 54.6752, 14.7879,
                  76.6252, 54.6752, 14.892, 76.582, 54.6752, 14.7879, 76.5617, 54.6752, 14.7929, true, TestName = "Coplanar, sharing a vertex (axom #152)")]
        [TestCase(12.3015, -0.253368, 5.49101, 18.6765, -2.55337, 4.91756, 12.3015, -2.55337, 4.91756,
                  -11.9885, -0.253368, 5.49101, 1.61448, -0.253368, 5.49101, 1.61448, -2.55337, 4.91756, false, TestName = "Coplanar, disjoint (contours #1)")]
        public void PublishedFailureCases(double ax, double ay, double az, double bx, double by, double bz, double cx, double cy, double cz,
            double dx, double dy, double dz, double ex, double ey, double ez, double fx, double fy, double fz, bool meet)
        {
            var p = new[] { V(ax, ay, az), V(bx, by, bz), V(cx, cy, cz) };
            var q = new[] { V(dx, dy, dz), V(ex, ey, ez), V(fx, fy, fz) };
            var orders = new[] { new[] { 0, 1, 2 }, new[] { 0, 2, 1 }, new[] { 1, 0, 2 }, new[] { 1, 2, 0 }, new[] { 2, 0, 1 }, new[] { 2, 1, 0 } };
            foreach (var i in orders)
                foreach (var j in orders)
                {
                    var a = new Triangle3(p[i[0]], p[i[1]], p[i[2]]);
                    var b = new Triangle3(q[j[0]], q[j[1]], q[j[2]]);
                    string at = $"{a} | {b}";
                    Assert.That(ProximityQuery.Overlaps(a, b), Is.EqualTo(meet), at);
                    Assert.That(ProximityQuery.Overlaps(b, a), Is.EqualTo(meet), at);
                    Assert.That(ClosestDistance.Between(a, b).Distance == 0, Is.EqualTo(meet), at);
                    Assert.That(Check(a, b, ref at), Is.LessThanOrEqualTo(32), at);
                    var fa = new System.Numerics.Vector3[] { F(a.A), F(a.B), F(a.C) };
                    var fb = new System.Numerics.Vector3[] { F(b.A), F(b.B), F(b.C) };
                    var ta = new ProximityLib.Triangle3(fa[0], fa[1], fa[2]);
                    var tb = new ProximityLib.Triangle3(fb[0], fb[1], fb[2]);
                    Assert.That(ProximityLib.ProximityQuery.Overlaps(ta, tb), Is.EqualTo(meet), "float " + at);
                    Assert.That(ProximityLib.ProximityQuery.Overlaps(tb, ta), Is.EqualTo(meet), "float " + at);
                }
        }

        private static System.Numerics.Vector3 F(Vector3D v) => new System.Numerics.Vector3((float)v.X, (float)v.Y, (float)v.Z);

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
