using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using static ProximityTests.Pairs.HalfSpaceBoxChecks;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class TriangleHalfSpaceTests
    {
        [Test]
        public void LowestVertexFirstOnTies()
        {
            var h = HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1));
            Result(ClosestDistance.Between(new Triangle3(V(0, 0, 3), V(1, 0, 2), V(0, 1, 4)), h), 2, V(1, 0, 2), V(1, 0, 0), 0);
            // B and C equally low: B.
            Result(ClosestDistance.Between(h, new Triangle3(V(0, 0, 3), V(1, 0, -1), V(0, 1, -1))), -1, V(1, 0, 0), V(1, 0, -1), 0);
            // Lying in a parallel plane: A.
            Result(ClosestDistance.Between(new Triangle3(V(5, 0, 1), V(1, 0, 1), V(0, 1, 1)), h), 1, V(5, 0, 1), V(5, 0, 0), 0);
            var t2 = new Triangle2(V(0, 0), V(4, 0), V(0, 4));
            Result(ClosestDistance.Between(t2, HalfPlane.FromPointNormal(V(3, 3), V(-1, -1))), Math.Sqrt(2), V(4, 0), V(5, 1), 1e-15);
            Assert.That(ProximityQuery.Overlaps(t2, HalfPlane.FromPointNormal(V(1, 1), V(-1, -1))), Is.True);
            // Degenerate triangles are points or segments: the same rule.
            Result(ClosestDistance.Between(new Triangle3(V(2, 2, 2), V(2, 2, 2), V(2, 2, 2)), h), 2, V(2, 2, 2), V(2, 2, 0), 0);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 0), new Num.Vector3(0, 0, 1));
            var t = new Flt.Triangle3(new Num.Vector3(0, 0, 3), new Num.Vector3(1, 0, 2), new Num.Vector3(0, 1, 4));
            Assert.That(Flt.ClosestDistance.Between(t, h).PointA, Is.EqualTo(new Num.Vector3(1, 0, 2)));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(520, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var a = Rand.P(rng, dim); var b = Rand.P(rng, dim); var c = Rand.P(rng, dim); var n = Rand.Dir(rng, dim);
                return f => (Rand.Tri(dim, a * f, b * f, c * f), Rand.Hs(dim, p * f, n));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(y);
                var v = x is Triangle3 t ? new[] { t.A, t.B, t.C }
                    : new[] { SegmentHalfSpaceTests.V3(((Triangle2)x).A), SegmentHalfSpaceTests.V3(((Triangle2)x).B), SegmentHalfSpaceTests.V3(((Triangle2)x).C) };
                return (ExactHeight(n, p, v), Scale(v.Append(p)));
            });
            TestContext.Out.WriteLine($"TriangleHalfSpace worst E = {worst:F3}");
        }
    }
}
