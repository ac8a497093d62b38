using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Pairs.HalfSpaceBoxChecks;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class PointHalfSpaceTests
    {
        private static readonly HalfSpace Floor = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 2));

        [Test]
        public void AboveOnAndBelow()
        {
            Result(ClosestDistance.Between(V(3, 4, 5), Floor), 4, V(3, 4, 5), V(3, 4, 1), 0);
            Result(ClosestDistance.Between(V(3, 4, 1), Floor), 0, V(3, 4, 1), V(3, 4, 1), 0);
            // Inside: minus the depth; moving the point by PointB − PointA puts it on the boundary.
            Result(ClosestDistance.Between(V(1, 1, -2), Floor), -3, V(1, 1, -2), V(1, 1, 1), 0);
            Assert.That(ClosestDistance.Between(V(1, 1, -2), Floor).DistanceSquared, Is.EqualTo(0));
            Assert.That(ClosestDistance.Between(V(3, 4, 5), Floor).DistanceSquared, Is.EqualTo(16));
            Assert.That(ProximityQuery.Overlaps(V(3, 4, 5), Floor), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(3, 4, 1), Floor), Is.True);
            Assert.That(ProximityQuery.Overlaps(Floor, V(1, 1, -2)), Is.True);
        }

        [Test]
        public void TiltedAndTwoDimensional()
        {
            // Normal (1, 1, 0)/√2 through (1, 1, 0): the origin is √2 inside.
            var h = HalfSpace.FromPointNormal(V(1, 1, 0), V(1, 1, 0));
            Result(ClosestDistance.Between(V(0, 0, 7), h), -Math.Sqrt(2), V(0, 0, 7), V(1, 1, 7), 1e-15);
            var p = HalfPlane.FromPointNormal(V(1, 0), V(-2, 0)); // the solid x ≥ 1
            Result(ClosestDistance.Between(V(4, 7), p), -3, V(4, 7), V(1, 7), 0);
            Result(ClosestDistance.Between(V(-1, 7), p), 2, V(-1, 7), V(1, 7), 0);
            Assert.That(ProximityQuery.Overlaps(p, V(-1, 7)), Is.False);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 1), new Num.Vector3(0, 0, 2));
            var r = Flt.ClosestDistance.Between(new Num.Vector3(3, 4, 5), h);
            Assert.That(r.Distance, Is.EqualTo(4f));
            Assert.That(r.PointB, Is.EqualTo(new Num.Vector3(3, 4, 1)));
            Assert.That(Flt.ClosestDistance.Distance(h, new Num.Vector3(3, 4, -5)), Is.EqualTo(-6f));
            Assert.That(Flt.ProximityQuery.Overlaps(h, new Num.Vector3(3, 4, 1)), Is.True);
            var p = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 1), new Num.Vector2(0, 1));
            Assert.That(Flt.ClosestDistance.Between(new Num.Vector2(5, 3), p).Distance, Is.EqualTo(2f));
        }

        [Test]
        public void FarOffsetOnATiltedPlane()
        {
            // The boundary point and the query point 1e6 from the origin, 3 apart along the (0.6, 0.8, 0) normal: measured
            // from the stored point, not through the offset Normal·Point ≈ 1.4e6.
            var h = HalfSpace.FromPointNormal(V(1e6, 1e6, 1e6), V(3, 4, 0));
            var q = V(1e6 + 1.8, 1e6 + 2.4, 1e6 + 5);
            var r = Check(f => (q * f, HalfSpace.FromPointNormal(V(1e6, 1e6, 1e6) * f, V(3, 4, 0))));
            double e = E(r.D, ExactHeight(h.Normal, h.Point, new[] { q }), Scale(new[] { q, h.Point }));
            TestContext.Out.WriteLine($"far offset E = {e:F3}");
            Assert.That(e, Is.LessThanOrEqualTo(4));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(120, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var q = Rand.P(rng, dim); var n = Rand.Dir(rng, dim);
                return f => (Rand.Pt(dim, q * f), Rand.Hs(dim, p * f, n));
            }, (a, b, d) =>
            {
                var (n, p) = Plane(b);
                var q = a is Vector2D v ? V(v.X, v.Y, 0) : (Vector3D)a;
                return (ExactHeight(n, p, new[] { q }), Scale(new[] { q, p }));
            });
            TestContext.Out.WriteLine($"PointHalfSpace worst E = {worst:F3}");
        }

        internal static (Vector3D n, Vector3D p) Plane(object h) => h switch
        {
            HalfSpace s => (s.Normal, s.Point),
            HalfPlane s => (V(s.Normal.X, s.Normal.Y, 0), V(s.Point.X, s.Point.Y, 0)),
            _ => throw new ArgumentException(),
        };
    }
}
