using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using static ProximityTests.Pairs.TriangleTesting;

namespace ProximityTests.Pairs
{
    public class SegmentTriangleTests
    {
        private static readonly Triangle3 T = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
        private static readonly Triangle2 T2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));

        [Test]
        public void CrossingTouchingAndApartIn3D()
        {
            var r = ClosestDistance.Between(new Segment3(V(1, 1, -1), V(1, 1, 3)), T);
            Result(r, 0, V(1, 1, 0), V(1, 1, 0));
            Assert.That(r.ParameterA, Is.EqualTo(0.25));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(1, 1, -1), V(1, 1, 3)), T), Is.True);
            // Over the interior, not reaching it.
            Result(ClosestDistance.Between(new Segment3(V(1, 1, 1), V(1, 1, 3)), T), 1, V(1, 1, 1), V(1, 1, 0));
            // Past an edge: the segment's closest point to edge BC.
            Result(ClosestDistance.Between(new Segment3(V(3, 3, -1), V(3, 3, 1)), T), Math.Sqrt(2), V(3, 3, 0), V(2, 2, 0));
            // Touching at an endpoint.
            Result(ClosestDistance.Between(new Segment3(V(1, 1, 0), V(1, 1, 3)), T), 0, V(1, 1, 0), V(1, 1, 0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(1, 1, 1e-100), V(1, 1, 3)), T), Is.False);
        }

        [Test]
        public void ParallelAndCoplanarSegments()
        {
            // Parallel to edge AB at offset (y −1, z 2): every point of [1, 3] on it is as close; End, the first minimum, wins.
            var r = ClosestDistance.Between(new Segment3(V(-1, -1, 2), V(3, -1, 2)), T);
            Result(r, Math.Sqrt(5), V(3, -1, 2), V(3, 0, 0));
            Assert.That(r.ParameterA, Is.EqualTo(1));
            // In the plane, across the triangle.
            Result(ClosestDistance.Between(new Segment3(V(1, -1, 0), V(1, 5, 0)), T), 0, V(1, 0, 0), V(1, 0, 0));
            // In the plane, outside it.
            Result(ClosestDistance.Between(new Segment3(V(5, 0, 0), V(5, 4, 0)), T), 1, V(5, 0, 0), V(4, 0, 0));
            // Parallel to the plane over it: Start, the first minimum.
            Result(ClosestDistance.Between(new Segment3(V(1, 1, 2), V(2, 1, 2)), T), 2, V(1, 1, 2), V(1, 1, 0));
        }

        [Test]
        public void DegenerateTriangleAndSegment()
        {
            var flat = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(2, 0, 0));
            Result(ClosestDistance.Between(new Segment3(V(1, -1, 3), V(1, 1, 3)), flat), 3, V(1, 0, 3), V(1, 0, 0));
            Result(ClosestDistance.Between(new Segment3(V(1, -1, 0), V(1, 1, 0)), flat), 0, V(1, 0, 0), V(1, 0, 0));
            Result(ClosestDistance.Between(new Segment3(V(1, 1, 2), V(1, 1, 2)), T), 2, V(1, 1, 2), V(1, 1, 0));
            // 2D: a flat triangle is a segment, so a crossing is 0, not negative.
            Result(ClosestDistance.Between(new Segment2(V(1, -1), V(1, 1)), new Triangle2(V(0, 0), V(4, 0), V(2, 0))), 0, V(1, 0), V(1, 0));
        }

        [Test]
        public void SolidTriangleIn2D()
        {
            // Inside: the least push is down through AB, by 1.
            var r = ClosestDistance.Between(new Segment2(V(1, 1), V(2, 1)), T2);
            Assert.That(r.Distance, Is.EqualTo(-1).Within(1e-15));
            Near(TestShape3(r.PointB - r.PointA), V(0, -1, 0), 1e-15, "push");
            Assert.That(r.PointA.Y, Is.EqualTo(1).Within(1e-15));
            // Through it: down by 1 again.
            Assert.That(ClosestDistance.Between(new Segment2(V(-1, 1), V(5, 1)), T2).Distance, Is.EqualTo(-1).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(-1, 1), V(5, 1)), T2), Is.True);
            // Apart.
            Result(ClosestDistance.Between(new Segment2(V(3, 3), V(3, 5)), T2), Math.Sqrt(2), V(3, 3), V(2, 2));
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(3, 3), V(5, 1)), T2), Is.False);
            // Touching at a vertex: +0.
            var touch = ClosestDistance.Between(new Segment2(V(4, 0), V(6, -2)), T2);
            Assert.That(BitConverter.DoubleToInt64Bits(touch.Distance), Is.EqualTo(0L), touch.ToString());
            Assert.That(ProximityQuery.Overlaps(new Segment2(V(4, 0), V(6, -2)), T2), Is.True);
        }

        private static Vector3D TestShape3(Vector2D v) => new Vector3D(v.X, v.Y, 0);

        [Test]
        public void FloatAndScaling()
        {
            var f = ProximityLib.ClosestDistance.Between(new ProximityLib.Segment3(new System.Numerics.Vector3(1, 1, 1), new System.Numerics.Vector3(1, 1, 3)),
                new ProximityLib.Triangle3(new System.Numerics.Vector3(0, 0, 0), new System.Numerics.Vector3(4, 0, 0), new System.Numerics.Vector3(0, 4, 0)));
            Assert.That(f.Distance, Is.EqualTo(1f));
            CheckScaling(new Segment3(V(1, 1, -1), V(1, 1, 3)), T, "crossing", 1, 900, -900);
            CheckScaling(new Segment3(V(3, 3, -1), V(3.5, 3, 1)), T, "edge", 1, 900, -900);
            CheckScaling(new Segment2(V(1, 1), V(2, 1.5)), T2, "inside 2D", 1, 900, -900);
            CheckScaling(new Segment2(V(3, 3), V(5, 1)), T2, "apart 2D", 1, 900, -900);
        }

        [Test]
        public void RandomFamiliesAgainstTheExactReference()
        {
            var g = new Random(13);
            var w3 = new Worst("segment–triangle 3D");
            var w2 = new Worst("segment–triangle 2D");
            for (int i = 0; i < 240; i++)
            {
                var t = Tri3(g, i);
                var p0 = Near(g, t);
                // Every third: nearly parallel to an edge or the plane.
                var p1 = i % 3 == 0 ? p0 + (t.B - t.A) * g.NextDouble() + P3(g, 1e-9) : Near(g, t);
                string at = $"3D case {i}";
                w3.Add(Check(new Segment3(p0, p1), t, ref at), at);
                var t2 = Tri2(g, i);
                var q0 = Near(g, t2);
                var q1 = i % 3 == 0 ? q0 + (t2.B - t2.A) * g.NextDouble() + P2(g, 1e-9) : Near(g, t2);
                at = $"2D case {i}";
                w2.Add(Check(new Segment2(q0, q1), t2, ref at), at);
                if (i % 20 == 0)
                {
                    CheckScaling(new Segment3(p0, p1), t, at, 5, 900, -900);
                    CheckScaling(new Segment2(q0, q1), t2, at, 5, 900, -900);
                }
            }
            w3.Report();
            w2.Report();
        }
    }
}
