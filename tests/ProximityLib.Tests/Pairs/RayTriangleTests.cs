using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class RayTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void TowardAwayAndOnIn3D()
        {
            // Down onto (1, 1) from height 2: crossing after 2.
            var r = ClosestDistance.Between(new Ray3(V(1, 1, 2), V(0, 0, -1)), T);
            Result(r, 0, V(1, 1, 0), V(1, 1, 0));
            Assert.That(r.ParameterA, Is.EqualTo(2));
            Assert.That(ProximityQuery.Overlaps(new Ray3(V(1, 1, 2), V(0, 0, -1)), T), Is.True);
            // Pointing away: the origin, 2 above (1, 1).
            var away = ClosestDistance.Between(new Ray3(V(1, 1, 2), V(0, 0, 1)), T);
            Result(away, 2, V(1, 1, 2), V(1, 1, 0));
            Assert.That(away.ParameterA, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(T, new Ray3(V(1, 1, 2), V(0, 0, 1))), Is.False);
            // Starting on the triangle, pointing away, and starting in it along its plane: 0 at the origin.
            var on = ClosestDistance.Between(new Ray3(V(1, 1, 0), V(0, 0, 1)), T);
            Result(on, 0, V(1, 1, 0), V(1, 1, 0));
            Assert.That(on.ParameterA, Is.EqualTo(0));
            var along = ClosestDistance.Between(new Ray3(V(1, 1, 0), V(1, 0, 0)), T);
            Assert.That(along.Distance, Is.EqualTo(0));
            Assert.That(along.PointA, Is.EqualTo(along.PointB));
            // In the plane beyond BC, heading away: the origin, 3√2 from (2, 2, 0).
            Result(ClosestDistance.Between(new Ray3(V(5, 5, 0), V(1, 0, 0)), T), 3 * Math.Sqrt(2), V(5, 5, 0), V(2, 2, 0), 1e-15);
            // Past vertex B (grazing) from below: touching at B.
            Result(ClosestDistance.Between(new Ray3(V(4, 0, -3), V(0, 0, 1)), T), 0, V(4, 0, 0), V(4, 0, 0));
            // Stopping short: the ray (1, 1, z ≥ −1) heading down misses; 1 from (1, 1, 0).
            Result(ClosestDistance.Between(new Ray3(V(1, 1, -1), V(0, 0, -1)), T), 1, V(1, 1, -1), V(1, 1, 0));
        }

        [Test]
        public void SolidTriangleIn2D()
        {
            // From (1, 1) along +x: sideways 1 (down) or back through AB by 1 (its origin 1 above AB); down by 1.
            var r = ClosestDistance.Between(new Ray2(V(1, 1), V(1, 0)), T2);
            Assert.That(r.Distance, Is.EqualTo(-1).Within(1e-15));
            Near(new Vector3D(r.PointB.X - r.PointA.X, r.PointB.Y - r.PointA.Y, 0), V(0, -1, 0), 1e-15, "push " + r);
            Assert.That(r.PointA.Y, Is.EqualTo(1));
            Assert.That(r.PointA.X, Is.InRange(1.0, 4.0), r.ToString());
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(1, 1), V(1, 0)), T2), Is.True);
            // From (1.5, 2) toward BC (direction (1, 1)): back through BC by 0.5/√2 = √2/4 beats every sideways push
            // (3.5/√2); pushed so, the ray touches BC at its origin (1.75, 2.25).
            var b = ClosestDistance.Between(new Ray2(V(1.5, 2), V(1, 1)), T2);
            Assert.That(b.Distance, Is.EqualTo(-Math.Sqrt(2) / 4).Within(1e-15));
            Result(b, b.Distance, V(1.5, 2), V(1.75, 2.25), 1e-15);
            Assert.That(b.ParameterA, Is.EqualTo(0));
            // Entering from outside at height 1 (heading −x): sideways 1 (down).
            var e = ClosestDistance.Between(new Ray2(V(5, 1), V(-1, 0)), T2);
            Assert.That(e.Distance, Is.EqualTo(-1).Within(1e-15));
            Near(new Vector3D(e.PointB.X - e.PointA.X, e.PointB.Y - e.PointA.Y, 0), V(0, -1, 0), 1e-15, "push " + e);
            // Along edge AB toward the triangle: touching.
            var t = ClosestDistance.Between(new Ray2(V(5, 0), V(-1, 0)), T2);
            Assert.That(BitConverter.DoubleToInt64Bits(t.Distance), Is.EqualTo(0L), t.ToString());
            Assert.That(t.PointA, Is.EqualTo(t.PointB));
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(5, 0), V(-1, 0)), T2), Is.True);
            // Pointing away: the origin. (5, 0) is 1 from B; (1, 5) heading up is √2 from C.
            Result(ClosestDistance.Between(new Ray2(V(5, 0), V(1, 0)), T2), 1, V(5, 0), V(4, 0));
            var up = ClosestDistance.Between(new Ray2(V(1, 5), V(0, 1)), T2);
            Result(up, Math.Sqrt(2), V(1, 5), V(0, 4));
            Assert.That(up.ParameterA, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(1, 5), V(0, 1)), T2), Is.False);
            // A flat triangle is the segment it is: a ray crossing it touches (0), never negative.
            var flat = new Triangle2(V(0, 0), V(4, 0), V(2, 0));
            Result(ClosestDistance.Between(new Ray2(V(1, 3), V(0, -1)), flat), 0, V(1, 0), V(1, 0), 1e-15);
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(1, 3), V(0, -1)), flat), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Ray2(V(1, 3), V(0, 1)), flat), Is.False);
        }

        [Test]
        public void FloatAndBothOrders()
        {
            var tri = new Flt.Triangle3(new Num.Vector3(0, 0, 0), new Num.Vector3(4, 0, 0), new Num.Vector3(0, 4, 0));
            var ray = new Flt.Ray3(new Num.Vector3(1, 1, 2), new Num.Vector3(0, 0, 1));
            Assert.That(Flt.ClosestDistance.Distance(ray, tri), Is.EqualTo(2f));
            Assert.That(Flt.ClosestDistance.Between(tri, ray).PointB, Is.EqualTo(new Num.Vector3(1, 1, 2)));
            Assert.That(Flt.ProximityQuery.Overlaps(tri, new Flt.Ray3(new Num.Vector3(1, 1, 2), new Num.Vector3(0, 0, -1))), Is.True);
            var tri2 = new Flt.Triangle2(new Num.Vector2(0, 0), new Num.Vector2(4, 0), new Num.Vector2(0, 4));
            Assert.That(Flt.ClosestDistance.Distance(tri2, new Flt.Ray2(new Num.Vector2(1, 1), new Num.Vector2(1, 0))), Is.EqualTo(-1f));
            Assert.That(Flt.ProximityQuery.Overlaps(new Flt.Ray2(new Num.Vector2(5, 0), new Num.Vector2(1, 0)), tri2), Is.False);
            Check(T, new Ray3(V(1, 1, 2), V(0, 0, -1)), "3D, swapped");
            Check(new Ray2(V(1.5, 2), V(1, 1)), T2, "back through BC");
        }

        [Test]
        public void Scaling()
        {
            CheckScaling(new Ray3(V(1, 1, 2), V(0.5, 0, -1)), T, "crossing", 1, 900, -900);
            CheckScaling(new Ray3(V(1, 1, 2), V(0.5, 0, 1)), T, "away", 1, 900, -900);
            CheckScaling(new Ray2(V(1.5, 2), V(1, 1)), T2, "inside 2D", 1, 900, -900);
            CheckScaling(new Ray2(V(5, 1), V(-1, 0.25)), T2, "entering 2D", 1, 900, -900);
        }

        [Test]
        public void RandomFamiliesAgainstTheExactReference()
        {
            var g = new Random(19);
            var w3 = new Worst("ray–triangle 3D");
            var w2 = new Worst("ray–triangle 2D");
            for (int i = 0; i < 240; i++)
            {
                var t = Tri3(g, i);
                var p = Near(g, t);
                var d = LineTriangleTests.LineDirection3(g, t, i);
                if (g.Next(2) == 0) d = -d;
                // Every fourth origin far back along the ray (1e6), every seventh configuration translated by 1e6.
                var o = i % 4 == 1 ? p - d * 1e6 : p;
                if (i % 7 == 3) { var s = V(-1e6, 1e6, 1e6); o += s; t = new Triangle3(t.A + s, t.B + s, t.C + s); }
                string at = $"3D case {i}";
                w3.Add(Check(new Ray3(o, d), t, ref at), at);
                var t2 = Tri2(g, i);
                var q = Near(g, t2);
                var d2 = LineTriangleTests.LineDirection2(g, t2, i);
                if (g.Next(2) == 0) d2 = -d2;
                var o2 = i % 4 == 1 ? q - d2 * 1e6 : q;
                if (i % 7 == 3) { var s = V(-1e6, 1e6); o2 += s; t2 = new Triangle2(t2.A + s, t2.B + s, t2.C + s); }
                at = $"2D case {i}";
                w2.Add(Check(new Ray2(o2, d2), t2, ref at), at);
                if (i % 20 == 0)
                {
                    CheckScaling(new Ray3(o, d), t, $"3D case {i}", 5, 900, -900);
                    CheckScaling(new Ray2(o2, d2), t2, at, 5, 900, -900);
                }
            }
            w3.Report();
            w2.Report();
        }
    }
}
