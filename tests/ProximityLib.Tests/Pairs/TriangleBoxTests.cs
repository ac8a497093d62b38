using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;
using Api = ProximityReference.Api;

namespace ProximityTests.Pairs
{
    /// <summary>Triangle–AABB and triangle–OBB.</summary>
    public class TriangleBoxTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void HandWorked()
        {
            // Box over the triangle: the triangle's edge BC meets its bottom at (2, 2, 1), the first minimum.
            Result(ClosestDistance.Between(T, new Aabb3(V(1, 1, 1), V(2, 2, 2))), 1, V(2, 2, 0), V(2, 2, 1));
            // The triangle slices the box: the least push is up by 0.25 (the box's z axis first among equals).
            var r = ClosestDistance.Between(T, new Aabb3(V(1, 1, -1), V(2, 2, 0.25)));
            Assert.That(r.Distance, Is.EqualTo(-0.25));
            Near(r.PointB - r.PointA, V(0, 0, 0.25), 1e-15, "push " + r);
            Assert.That(ProximityQuery.Overlaps(T, new Aabb3(V(1, 1, -1), V(2, 2, 0.25))), Is.True);
            Assert.That(ProximityQuery.Overlaps(T, new Aabb3(V(1, 1, 1), V(2, 2, 2))), Is.False);
            // Touching at an edge.
            Assert.That(ClosestDistance.Between(T, new Aabb3(V(4, -1, -1), V(5, 1, 1))).Distance, Is.EqualTo(0));
            // 2D: the box inside the solid triangle; the least push is through the hypotenuse, by √2, onto corner (1, 1).
            var r2 = ClosestDistance.Between(T2, new Aabb2(V(1, 1), V(2, 2)));
            Result(r2, -Math.Sqrt(2), V(2, 2), V(1, 1), 1e-14);
            var o = new Obb2(V(1.5, 1.5), 0.0, V(0.5, 0.5));
            Assert.That(ClosestDistance.Between(T2, o).Distance, Is.EqualTo(-Math.Sqrt(2)).Within(1e-14));
            var box = Obb3.FromQuaternion(V(1.5, 1.5, 1.5), 0, 0, 0, 1, V(0.5, 0.5, 0.5));
            Result(ClosestDistance.Between(T, box), 1, V(2, 2, 0), V(2, 2, 1), 1e-15);
        }

        /// <summary>
        /// Where the classic triangle–box separating-axis test (Akenine-Möller 2001) is fragile: a triangle lying in a face's
        /// plane (the plane axis separates nothing; only the edge axes decide) and a degenerate triangle (its normal is zero,
        /// so the plane axis proves nothing either way). Each case in both argument orders, AABB and the same box as an OBB,
        /// against the exact reference.
        /// </summary>
        [Test]
        public void FacePlaneAndDegenerateTriangles()
        {
            var box = new Aabb3(V(0, 0, 0), V(1, 1, 1));
            var obb = Obb3.FromQuaternion(V(0.5, 0.5, 0.5), 0, 0, 0, 1, V(0.5, 0.5, 0.5));
            var cases = new (Triangle3 T, bool Meet, string Name)[]
            {
                (new Triangle3(V(0.5, 0.5, 1), V(3, 0.5, 1), V(0.5, 3, 1)), true, "in the top face's plane, a corner on the face"),
                (new Triangle3(V(1, 1, 1), V(3, 1, 1), V(1, 3, 1)), true, "in the top face's plane, touching at the box's corner"),
                (new Triangle3(V(1.5, 1.5, 1), V(3, 1.5, 1), V(1.5, 3, 1)), false, "in the top face's plane, beside the face"),
                (new Triangle3(V(3, -0.5, 1), V(-0.5, 3, 1), V(3, 3, 1)), false, "in the top face's plane, its edge 0.25·√2 past the corner"),
                (new Triangle3(V(-1, 0.5, 0.5), V(2, 0.5, 0.5), V(0.5, 0.5, 0.5)), true, "collinear, through the box"),
                (new Triangle3(V(-1, 1, 1), V(2, 1, 1), V(0, 1, 1)), true, "collinear, along the top edge"),
                (new Triangle3(V(-1, 3.5, 1), V(3.5, -1, 1), V(0, 2.5, 1)), false, "collinear, missing the top corner by 0.25·√2"),
                (new Triangle3(V(1.25, 1, 2), V(1.25, 1, 2), V(1.25, 1, 2)), false, "all three vertices one point off the box"),
            };
            foreach (var (t, meet, name) in cases)
            {
                foreach (object b in new object[] { box, obb })
                {
                    string at = $"{name}: {t} | {b}";
                    Assert.That((bool)Api.Overlaps(t, b), Is.EqualTo(meet), at);
                    Assert.That((bool)Api.Overlaps(b, t), Is.EqualTo(meet), at);
                    Assert.That(Check(t, b, ref at), Is.LessThanOrEqualTo(32), at);
                }
            }
        }

        [Test]
        public void ScalingAndRandomFamilies()
        {
            CheckScaling(T, new Aabb3(V(1, 1, -1), V(2, 2, 0.25)), "slice", 1, 900, -900);
            CheckScaling(T2, new Aabb2(V(1, 1), V(2, 2)), "2D inside", 1, 900, -900);
            var g = new Random(18);
            var wa = new Worst("triangle–AABB 3D");
            var wo = new Worst("triangle–OBB 3D");
            var w2 = new Worst("triangle–AABB/OBB 2D");
            for (int i = 0; i < 120; i++)
            {
                var t = Tri3(g, i);
                var c = Near(g, t);
                var h = new Vector3D(Math.Abs(Next(g)), Math.Abs(Next(g)), Math.Abs(Next(g))) * 0.5;
                string at = $"AABB case {i}";
                wa.Add(Check(t, new Aabb3(c - h, c + h), ref at), at);
                var q = Obb3.FromQuaternion(c, Next(g), Next(g), Next(g), 0.5 + g.NextDouble(), h);
                at = $"OBB case {i}";
                wo.Add(Check(t, q, ref at), at);
                var t2 = Tri2(g, i);
                var c2 = Near(g, t2);
                var h2 = new Vector2D(Math.Abs(Next(g)), Math.Abs(Next(g))) * 0.5;
                at = $"2D case {i}";
                w2.Add(Check(t2, new Aabb2(c2 - h2, c2 + h2), ref at), at);
                at = $"2D OBB case {i}";
                w2.Add(Check(t2, new Obb2(c2, g.NextDouble() * 6, h2), ref at), at);
                if (i % 20 == 0) CheckScaling(t, new Aabb3(c - h, c + h), at, 3, 900, -900);
            }
            wa.Report();
            wo.Report();
            w2.Report();
        }
    }
}
