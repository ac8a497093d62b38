using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;

namespace ProximityTests.Pairs
{
    public class PointTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void EveryRegionOfThePlaneTriangle()
        {
            Result(ClosestDistance.Between(V(1, 1, 3), T), 3, V(1, 1, 3), V(1, 1, 0));      // over the interior
            Result(ClosestDistance.Between(V(1, 1, -2), T), 2, V(1, 1, -2), V(1, 1, 0));    // two-sided
            Result(ClosestDistance.Between(V(5, -1, 0), T), Math.Sqrt(2), V(5, -1, 0), V(4, 0, 0)); // vertex B
            Result(ClosestDistance.Between(V(2, -3, 4), T), 5, V(2, -3, 4), V(2, 0, 0));    // edge AB
            Result(ClosestDistance.Between(V(3, 3, 0), T), Math.Sqrt(2), V(3, 3, 0), V(2, 2, 0)); // edge BC, in the plane
            Result(ClosestDistance.Between(V(1, 1, 0), T), 0, V(1, 1, 0), V(1, 1, 0));      // on it
            Assert.That(ProximityQuery.Overlaps(V(1, 1, 0), T), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(4, 0, 0), T), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(1, 1, 1e-300), T), Is.False);
            Result(ClosestDistance.Between(T, V(1, 1, 3)), 3, V(1, 1, 0), V(1, 1, 3));
        }

        [Test]
        public void DegenerateTrianglesAreTheirSegmentOrPoint()
        {
            var flat = new Triangle3(V(0, 0, 0), V(2, 0, 0), V(4, 0, 0));
            Result(ClosestDistance.Between(V(1, 3, 0), flat), 3, V(1, 3, 0), V(1, 0, 0));
            Result(ClosestDistance.Between(V(5, 0, 0), flat), 1, V(5, 0, 0), V(4, 0, 0));
            var point = new Triangle3(V(1, 1, 1), V(1, 1, 1), V(1, 1, 1));
            Result(ClosestDistance.Between(V(1, 1, 4), point), 3, V(1, 1, 4), V(1, 1, 1));
            Assert.That(ProximityQuery.Overlaps(V(1, 1, 1), point), Is.True);
            Result(ClosestDistance.Between(V(1, 3), new Triangle2(V(0, 0), V(2, 0), V(4, 0))), 3, V(1, 3), V(1, 0));
            // A point on a flat 2D triangle touches it: no interior, never negative.
            Result(ClosestDistance.Between(V(1, 0), new Triangle2(V(0, 0), V(4, 0), V(2, 0))), 0, V(1, 0), V(1, 0));
        }

        [Test]
        public void SolidTriangleIn2D()
        {
            // Inside: minus the distance to the nearest edge (AB and CA tie at 1: AB, the first, wins).
            Result(ClosestDistance.Between(V(1, 1), T2), -1, V(1, 1), V(1, 0));
            Result(ClosestDistance.Between(V(1, 2), T2), -Math.Sqrt(0.5), V(1, 2), V(1.5, 2.5));
            Result(ClosestDistance.Between(V(5, 5), T2), Math.Sqrt(18), V(5, 5), V(2, 2));
            Result(ClosestDistance.Between(V(2, 0), T2), 0, V(2, 0), V(2, 0));
            Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Between(V(2, 0), T2).Distance), Is.EqualTo(0L), "+0 on the boundary");
            Assert.That(ProximityQuery.Overlaps(V(1, 1), T2), Is.True);
            Assert.That(ProximityQuery.Overlaps(V(5, 5), T2), Is.False);
            // Clockwise vertices: the same solid.
            Result(ClosestDistance.Between(V(1, 2), new Triangle2(V(0, 0), V(0, 4), V(4, 0))), -Math.Sqrt(0.5), V(1, 2), V(1.5, 2.5));
        }

        [Test]
        public void FloatApiRoundsTheDoubleAnswer()
        {
            var f = ProximityLib.ClosestDistance.Between(new System.Numerics.Vector3(1, 1, 3), new ProximityLib.Triangle3(new System.Numerics.Vector3(0, 0, 0), new System.Numerics.Vector3(4, 0, 0), new System.Numerics.Vector3(0, 4, 0)));
            Assert.That(f.Distance, Is.EqualTo(3f));
            var f2 = ProximityLib.ClosestDistance.Between(new System.Numerics.Vector2(1, 2), new ProximityLib.Triangle2(new System.Numerics.Vector2(0, 0), new System.Numerics.Vector2(4, 0), new System.Numerics.Vector2(0, 4)));
            Assert.That(f2.Distance, Is.EqualTo((float)-Math.Sqrt(0.5)));
            Assert.That(ProximityLib.ProximityQuery.Overlaps(new System.Numerics.Vector2(1, 2), new ProximityLib.Triangle2(new System.Numerics.Vector2(0, 0), new System.Numerics.Vector2(4, 0), new System.Numerics.Vector2(0, 4))), Is.True);
        }

        [Test]
        public void ScalingByPowersOfTwoIsExact()
        {
            CheckScaling(V(1, 1, 3), T, "interior", 1, -7, 900, -900);
            CheckScaling(V(3, 3, 0.5), new Triangle3(V(0.1, 0.2, 0.3), V(4, 0, 0.5), V(0, 4, -0.5)), "edge", 1, 900, -900);
            CheckScaling(V(1, 2), T2, "inside 2D", 3, 900, -900);
            CheckScaling(V(5, 5), T2, "outside 2D", 900, -900);
            // Huge and tiny coordinates: finite answers.
            var r = ClosestDistance.Between(V(1e300, -1e300, 1e300), new Triangle3(V(-1e300, 0, 0), V(1e300, 1e300, 0), V(0, -1e300, 1e-300)));
            Assert.That(double.IsFinite(r.Distance) && r.Distance > 0, Is.True, r.ToString());
            Assert.That(ClosestDistance.Between(V(1e-310, 0, 5e-324), new Triangle3(V(0, 0, 0), V(1e-310, 0, 0), V(0, 1e-310, 0))).Distance, Is.EqualTo(5e-324));
        }

        [Test]
        public void RandomFamiliesAgainstTheExactReference()
        {
            var g = new Random(12);
            var w3 = new Worst("point–triangle 3D");
            var w2 = new Worst("point–triangle 2D");
            for (int i = 0; i < 300; i++)
            {
                var t = Tri3(g, i);
                string at = $"3D case {i}";
                w3.Add(Check(Near(g, t), t, ref at), at);
                var t2 = Tri2(g, i);
                at = $"2D case {i}";
                w2.Add(Check(Near(g, t2), t2, ref at), at);
                if (i % 25 == 0)
                {
                    CheckScaling(Near(g, t), t, $"3D case {i}", 5, 900, -900);
                    CheckScaling(Near(g, t2), t2, $"2D case {i}", 5, 900, -900);
                }
            }
            w3.Report();
            w2.Report();
        }
    }
}
