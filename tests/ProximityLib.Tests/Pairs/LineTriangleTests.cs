using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class LineTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void CrossingGrazingAndApartIn3D()
        {
            // Along z through (1, 1): crossing, one common point, t = 1 from the origin below.
            var r = ClosestDistance.Between(new Line3(V(1, 1, -1), V(0, 0, 1)), T);
            Result(r, 0, V(1, 1, 0), V(1, 1, 0));
            Assert.That(r.ParameterA, Is.EqualTo(1));
            Assert.That(ProximityQuery.Overlaps(new Line3(V(1, 1, -1), V(0, 0, 1)), T), Is.True);
            // Through vertex B along −z: grazing, touching at B, 5 from the origin.
            var g = ClosestDistance.Between(new Line3(V(4, 0, 5), V(0, 0, -1)), T);
            Result(g, 0, V(4, 0, 0), V(4, 0, 0));
            Assert.That(g.ParameterA, Is.EqualTo(5));
            Assert.That(ProximityQuery.Overlaps(T, new Line3(V(4, 0, 5), V(0, 0, -1))), Is.True);
            // Beside vertex B along z: 1 from it.
            var b = ClosestDistance.Between(new Line3(V(5, 0, 5), V(0, 0, -1)), T);
            Result(b, 1, V(5, 0, 0), V(4, 0, 0));
            Assert.That(b.ParameterA, Is.EqualTo(5));
            Assert.That(ProximityQuery.Overlaps(new Line3(V(5, 0, 5), V(0, 0, -1)), T), Is.False);
            // Skew past edge BC (x + y = 4): the line x + y = 6 at z = 0 along z... (3, 3, z): √2 from (2, 2, 0).
            Result(ClosestDistance.Between(new Line3(V(3, 3, 7), V(0, 0, 1)), T), Math.Sqrt(2), V(3, 3, 0), V(2, 2, 0));
        }

        [Test]
        public void InThePlaneAndParallelToIt()
        {
            // In the plane across the triangle: 0 at a common point (on the line x = 1, inside the triangle).
            var r = ClosestDistance.Between(new Line3(V(1, -1, 0), V(0, 1, 0)), T);
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.PointA, Is.EqualTo(r.PointB));
            Assert.That(r.PointA.X, Is.EqualTo(1).Within(1e-15));
            Assert.That(r.PointA.Y, Is.InRange(-1e-15, 3 + 1e-15));
            Assert.That(r.ParameterA, Is.EqualTo(r.PointA.Y + 1).Within(1e-15));
            // In the plane, missing it: x = 5, nearest B.
            Result(ClosestDistance.Between(new Line3(V(5, -7, 0), V(0, 1, 0)), T), 1, V(5, 0, 0), V(4, 0, 0));
            // Parallel to the plane just above it: the height, over some point of the triangle.
            foreach (double h in new[] { 2, 1e-9, 1e-150 })
            {
                var p = ClosestDistance.Between(new Line3(V(-3, 1, h), V(1, 0, 0)), T);
                Assert.That(p.Distance, Is.EqualTo(h), p.ToString());
                Assert.That(p.PointB, Is.EqualTo(V(p.PointA.X, 1, 0)), p.ToString());
                Assert.That(p.PointA.X, Is.InRange(0.0, 3.0), p.ToString());
                Assert.That(p.ParameterA, Is.EqualTo(p.PointA.X + 3).Within(1e-15), p.ToString());
                Assert.That(ProximityQuery.Overlaps(new Line3(V(-3, 1, h), V(1, 0, 0)), T), Is.False);
            }
            // At 1e-300 the height is far below the configuration's rounding (u·S ≈ 4e-16 here): the answer may be 0 (the
            // witness then lies 1e-300 off the plane); only the bound E·u·S holds.
            var deep = ClosestDistance.Between(new Line3(V(-3, 1, 1e-300), V(1, 0, 0)), T);
            Assert.That(deep.Distance, Is.InRange(0.0, 1e-300 + 4 * 4 * Math.Pow(2, -53)), deep.ToString());
            Assert.That(deep.PointB.Z, Is.EqualTo(0).Within(1e-300), deep.ToString());
            // Parallel to edge BC beside it (the line x + y = 6 in the plane): √2, PointA − PointB = (1, 1, 0).
            var e = ClosestDistance.Between(new Line3(V(3, 3, 0), V(1, -1, 0)), T);
            Assert.That(e.Distance, Is.EqualTo(Math.Sqrt(2)).Within(1e-15));
            Near(e.PointA - e.PointB, V(1, 1, 0), 1e-15, "offset " + e);
        }

        [Test]
        public void NearlyParallelToThePlane()
        {
            // Falling 1e-4 per unit from height 1e-3: crosses z = 0 at (1, 1) after 10 units (to 1e-8).
            var d = V(1, 0, -1e-4);
            var r = ClosestDistance.Between(new Line3(V(-9, 1, 1e-3), d), T);
            Assert.That(r.Distance, Is.EqualTo(0));
            Near(r.PointA, V(1, 1, 0), 1e-13, "crossing " + r);
            Assert.That(r.ParameterA, Is.EqualTo(Math.Sqrt(100 + 1e-6)).Within(1e-12));
            // The same crossing 1e6 away along the line: still crossing (0 exactly), the point to the origin's rounding.
            var far = ClosestDistance.Between(new Line3(V(1, 1, 0) - d * 1e6, d), T);
            Assert.That(far.Distance, Is.EqualTo(0));
            Near(far.PointA, V(1, 1, 0), 1e-9, "far crossing " + far);
        }

        [Test]
        public void DegenerateTriangles()
        {
            var flat = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(2, 0, 0));
            Result(ClosestDistance.Between(new Line3(V(1, -1, 3), V(0, 1, 0)), flat), 3, V(1, 0, 3), V(1, 0, 0));
            Result(ClosestDistance.Between(new Line3(V(1, 5, 0), V(0, -1, 0)), flat), 0, V(1, 0, 0), V(1, 0, 0));
            var point = new Triangle3(V(1, 1, 1), V(1, 1, 1), V(1, 1, 1));
            var p = ClosestDistance.Between(new Line3(V(-2, 0, 0), V(1, 0, 0)), point);
            Result(p, Math.Sqrt(2), V(1, 0, 0), V(1, 1, 1));
            Assert.That(p.ParameterA, Is.EqualTo(3));
            // 2D: a flat triangle is a segment, so a crossing is 0, not negative.
            var f2 = new Triangle2(V(0, 0), V(4, 0), V(2, 0));
            Result(ClosestDistance.Between(new Line2(V(1, -1), V(0, 1)), f2), 0, V(1, 0), V(1, 0), 1e-15);
            Assert.That(ProximityQuery.Overlaps(new Line2(V(1, -1), V(0, 1)), f2), Is.True);
            // Parallel to it: 1, over some point of it.
            var par = ClosestDistance.Between(new Line2(V(-5, 1), V(1, 0)), f2);
            Assert.That(par.Distance, Is.EqualTo(1));
            Assert.That(par.PointB, Is.EqualTo(V(par.PointA.X, 0)), par.ToString());
            Assert.That(par.PointA.X, Is.InRange(0.0, 4.0), par.ToString());
            Assert.That(ProximityQuery.Overlaps(new Line2(V(-5, 1), V(1, 0)), f2), Is.False);
        }

        [Test]
        public void SolidTriangleIn2D()
        {
            // y = 1 across it: heights over the line −1, −1, 3: pushed down by 1 (onto AB).
            var r = ClosestDistance.Between(new Line2(V(-5, 1), V(1, 0)), T2);
            Assert.That(r.Distance, Is.EqualTo(-1));
            Near(new Vector3D(r.PointB.X - r.PointA.X, r.PointB.Y - r.PointA.Y, 0), V(0, -1, 0), 1e-15, "push " + r);
            Assert.That(r.PointA.Y, Is.EqualTo(1));
            Assert.That(r.PointA.X, Is.InRange(0.0, 4.0), r.ToString());
            Assert.That(r.ParameterA, Is.EqualTo(r.PointA.X + 5).Within(1e-15), r.ToString());
            Assert.That(ProximityQuery.Overlaps(new Line2(V(-5, 1), V(1, 0)), T2), Is.True);
            // x + y = 3.5, parallel to BC: B and C are 0.5/√2 above it, A 3.5/√2 below: pushed toward BC by √2/4.
            var h = ClosestDistance.Between(new Line2(V(0, 3.5), V(1, -1)), T2);
            Assert.That(h.Distance, Is.EqualTo(-Math.Sqrt(2) / 4).Within(1e-15));
            // The push's witnesses within 32·u·S (S = 5): a 1e-14 tolerance.
            Near(new Vector3D(h.PointB.X - h.PointA.X, h.PointB.Y - h.PointA.Y, 0), V(0.25, 0.25, 0), 1e-14, "push " + h);
            // A needle-thin sliver crossed across its length: the depth is the shorter way off it, 1 (not 0).
            var sliver = new Triangle2(V(0, 0), V(4, 0), V(2, 1e-9));
            Assert.That(ClosestDistance.Between(new Line2(V(1, -5), V(0, 1)), sliver).Distance, Is.EqualTo(-1).Within(1e-15));
            // Through vertex B only: touching, one point.
            var t = ClosestDistance.Between(new Line2(V(4, -1), V(0, 1)), T2);
            Assert.That(BitConverter.DoubleToInt64Bits(t.Distance), Is.EqualTo(0L), t.ToString());
            Result(t, 0, V(4, 0), V(4, 0));
            Assert.That(t.ParameterA, Is.EqualTo(1));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(4, -1), V(0, 1)), T2), Is.True);
            // Apart: x + y = 6 is √2 from BC; x = 5 is 1 from B.
            var a = ClosestDistance.Between(new Line2(V(3, 3), V(1, -1)), T2);
            Assert.That(a.Distance, Is.EqualTo(Math.Sqrt(2)).Within(1e-14)); // measured 1.2e-15 off (E ≈ 2 at S = 5)
            Near(new Vector3D(a.PointA.X - a.PointB.X, a.PointA.Y - a.PointB.Y, 0), V(1, 1, 0), 1e-14, "offset " + a); // 2.4e-15 measured
            var v = ClosestDistance.Between(new Line2(V(5, 7), V(0, -1)), T2);
            Result(v, 1, V(5, 0), V(4, 0));
            Assert.That(v.ParameterA, Is.EqualTo(7));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(5, 7), V(0, -1)), T2), Is.False);
        }

        [Test]
        public void FloatAndBothOrders()
        {
            var tri = new Flt.Triangle3(new Num.Vector3(0, 0, 0), new Num.Vector3(4, 0, 0), new Num.Vector3(0, 4, 0));
            var line = new Flt.Line3(new Num.Vector3(-3, 1, 2), new Num.Vector3(1, 0, 0));
            Assert.That(Flt.ClosestDistance.Distance(line, tri), Is.EqualTo(2f));
            Assert.That(Flt.ClosestDistance.Distance(tri, line), Is.EqualTo(2f));
            Assert.That(Flt.ProximityQuery.Overlaps(tri, new Flt.Line3(new Num.Vector3(1, 1, -1), new Num.Vector3(0, 0, 1))), Is.True);
            var tri2 = new Flt.Triangle2(new Num.Vector2(0, 0), new Num.Vector2(4, 0), new Num.Vector2(0, 4));
            var line2 = new Flt.Line2(new Num.Vector2(-5, 1), new Num.Vector2(1, 0));
            Assert.That(Flt.ClosestDistance.Distance(line2, tri2), Is.EqualTo(-1f));
            var sw = Flt.ClosestDistance.Between(tri2, line2);
            Assert.That(sw.PointA - sw.PointB, Is.EqualTo(new Num.Vector2(0, -1)));
            Assert.That(Flt.ProximityQuery.Overlaps(tri2, new Flt.Line2(new Num.Vector2(5, 7), new Num.Vector2(0, -1))), Is.False);
            Check(new Line3(V(1, 1, -1), V(0, 0, 1)), T, "crossing");
            Check(T2, new Line2(V(-5, 1), V(1, 0)), "2D, swapped");
        }

        [Test]
        public void Scaling()
        {
            CheckScaling(new Line3(V(1, 1, -1), V(0.5, 0, 1)), T, "crossing", 1, 900, -900);
            CheckScaling(new Line3(V(3, 3, -1), V(0.25, 0, 1)), T, "past an edge", 1, 900, -900);
            CheckScaling(new Line3(V(-3, 1, 0.5), V(1, 1e-9, 0)), T, "parallel above", 1, 900, -900);
            CheckScaling(new Line2(V(1, 1), V(2, 0.5)), T2, "across 2D", 1, 900, -900);
            CheckScaling(new Line2(V(3, 3), V(5, 1)), T2, "apart 2D", 1, 900, -900);
        }

        [Test]
        public void RandomFamiliesAgainstTheExactReference()
        {
            var g = new Random(17);
            var w3 = new Worst("line–triangle 3D");
            var w2 = new Worst("line–triangle 2D");
            for (int i = 0; i < 240; i++)
            {
                var t = Tri3(g, i);
                var p = Near(g, t);
                var d = LineDirection3(g, t, i);
                // Every fourth origin far along the line (1e6), every seventh configuration translated by 1e6.
                var o = i % 4 == 1 ? p - d * 1e6 : p;
                if (i % 7 == 3) { var s = V(1e6, -1e6, 1e6); o += s; t = new Triangle3(t.A + s, t.B + s, t.C + s); }
                string at = $"3D case {i}";
                w3.Add(Check(new Line3(o, d), t, ref at), at);
                var t2 = Tri2(g, i);
                var q = Near(g, t2);
                var d2 = LineDirection2(g, t2, i);
                var o2 = i % 4 == 1 ? q - d2 * 1e6 : q;
                if (i % 7 == 3) { var s = V(1e6, -1e6); o2 += s; t2 = new Triangle2(t2.A + s, t2.B + s, t2.C + s); }
                at = $"2D case {i}";
                w2.Add(Check(new Line2(o2, d2), t2, ref at), at);
                if (i % 20 == 0)
                {
                    CheckScaling(new Line3(o, d), t, $"3D case {i}", 5, 900, -900);
                    CheckScaling(new Line2(o2, d2), t2, at, 5, 900, -900);
                }
            }
            w3.Report();
            w2.Report();
        }

        /// <summary>Any direction, or nearly along an edge, or (nearly) in the triangle's plane.</summary>
        internal static Vector3D LineDirection3(Random g, Triangle3 t, int i)
        {
            var e1 = t.B - t.A;
            var e2 = t.C - t.A;
            Vector3D d = (i % 3) switch
            {
                1 => e1 + P3(g, 1e-9),
                2 => e1 * Next(g) + e2 * Next(g) + P3(g, g.Next(2) == 0 ? 0 : 1e-12),
                _ => P3(g),
            };
            return d.LengthSquared > 1e-30 ? d : V(1, 0, 0);
        }

        internal static Vector2D LineDirection2(Random g, Triangle2 t, int i)
        {
            var d = i % 3 == 1 ? t.B - t.A + P2(g, 1e-9) : P2(g);
            return d.LengthSquared > 1e-30 ? d : V(1, 0);
        }
    }
}
