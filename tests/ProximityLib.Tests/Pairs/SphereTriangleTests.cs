using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;

namespace ProximityTests.Pairs
{
    public class SphereTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void ApartTouchingAndOverlapping()
        {
            Result(ClosestDistance.Between(new Sphere(V(1, 1, 3), 1), T), 2, V(1, 1, 2), V(1, 1, 0));
            // Overlapping from below: pushed down along −N by 0.5.
            Result(ClosestDistance.Between(new Sphere(V(1, 1, -0.5), 1), T), -0.5, V(1, 1, 0.5), V(1, 1, 0));
            // Center on the triangle: pushed along N = (B − A) × (C − A) = +z by the radius.
            Result(ClosestDistance.Between(new Sphere(V(1, 1, 0), 2), T), -2, V(1, 1, -2), V(1, 1, 0));
            // Near vertex B.
            Result(ClosestDistance.Between(new Sphere(V(7, -4, 0), 1), T), 4, V(6.4, -3.2, 0), V(4, 0, 0));
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(1, 1, 3), 3), T), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(1, 1, 3), 2.5), T), Is.False);
            Result(ClosestDistance.Between(T, new Sphere(V(1, 1, 3), 1)), 2, V(1, 1, 0), V(1, 1, 2));
        }

        [Test]
        public void CircleAgainstTheSolidTriangle()
        {
            // Center inside, nearest edge the hypotenuse at 1/√2: depth 0.5 + 1/√2, pushed out through it.
            var r = ClosestDistance.Between(new Circle(V(1, 2), 0.5), T2);
            double h = Math.Sqrt(0.5);
            Result(r, -(0.5 + h), V(1 - 0.5 * h, 2 - 0.5 * h), V(1.5, 2.5));
            Result(ClosestDistance.Between(new Circle(V(5, 5), 1), T2), Math.Sqrt(18) - 1, V(5 - h, 5 - h), V(2, 2));
            Assert.That(ProximityQuery.Overlaps(new Circle(V(5, 5), 1), T2), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Circle(V(1, 2), 0.1), T2), Is.True);
            var f = ProximityLib.ClosestDistance.Between(new ProximityLib.Circle(new System.Numerics.Vector2(5, 5), 1), new ProximityLib.Triangle2(new System.Numerics.Vector2(0, 0), new System.Numerics.Vector2(4, 0), new System.Numerics.Vector2(0, 4)));
            Assert.That(f.Distance, Is.EqualTo((float)(Math.Sqrt(18) - 1)));
        }

        [Test]
        public void ScalingAndRandomFamilies()
        {
            CheckScaling(new Sphere(V(1, 1, 0.25), 1), T, "overlap", 1, 900, -900);
            CheckScaling(new Circle(V(1, 2), 0.5), T2, "inside", 1, 900, -900);
            var g = new Random(14);
            var w3 = new Worst("sphere–triangle 3D");
            var w2 = new Worst("circle–triangle 2D");
            for (int i = 0; i < 200; i++)
            {
                var t = Tri3(g, i);
                var s = new Sphere(Near(g, t), g.NextDouble() * Math.Pow(2, -g.Next(30)));
                string at = $"3D case {i}";
                w3.Add(Check(s, t, ref at), at);
                var t2 = Tri2(g, i);
                var c = new Circle(Near(g, t2), g.NextDouble() * Math.Pow(2, -g.Next(30)));
                at = $"2D case {i}";
                w2.Add(Check(c, t2, ref at), at);
                if (i % 25 == 0) { CheckScaling(s, t, at, 3, 900, -900); CheckScaling(c, t2, at, 3, 900, -900); }
            }
            w3.Report();
            w2.Report();
        }
    }
}
