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
    public class SegmentHalfSpaceTests
    {
        private static readonly HalfSpace Floor = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));

        [Test]
        public void LowerEndWins()
        {
            var r = ClosestDistance.Between(new Segment3(V(0, 0, 5), V(2, 0, 3)), Floor);
            Result(r, 2, V(2, 0, 3), V(2, 0, 1), 0);
            Assert.That(r.ParameterA, Is.EqualTo(1));
            // Entering: minus the depth of the deepest end.
            r = ClosestDistance.Between(new Segment3(V(0, 0, -3), V(2, 0, 3)), Floor);
            Result(r, -4, V(0, 0, -3), V(0, 0, 1), 0);
            Assert.That(r.ParameterA, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(Floor, new Segment3(V(0, 0, -3), V(2, 0, 3))), Is.True);
            Assert.That(ProximityQuery.Overlaps(Floor, new Segment3(V(0, 0, 1.5), V(2, 0, 3))), Is.False);
        }

        [Test]
        public void ParallelIsWitnessedAtStart()
        {
            var r = ClosestDistance.Between(new Segment3(V(4, 0, 3), V(-4, 0, 3)), Floor);
            Result(r, 2, V(4, 0, 3), V(4, 0, 1), 0);
            Assert.That(r.ParameterA, Is.EqualTo(0));
            var s = ClosestDistance.Between(new Segment2(V(4, -1), V(-4, -1)), HalfPlane.FromPointNormal(V(0, 0), V(0, 1)));
            Result(s, -1, V(4, -1), V(4, 0), 0);
            Assert.That(s.ParameterA, Is.EqualTo(0));
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 1), new Num.Vector2(0, 1));
            var r = Flt.ClosestDistance.Between(h, new Flt.Segment2(new Num.Vector2(0, 4), new Num.Vector2(3, 2)));
            Assert.That(r.Distance, Is.EqualTo(1f));
            Assert.That(r.PointB, Is.EqualTo(new Num.Vector2(3, 2)));
            Assert.That(r.ParameterB, Is.EqualTo(1f));
        }

        [Test]
        public void NearlyParallelSegments()
        {
            // A long segment tilted by 2^-40 over a plane with a far boundary point: the lower end wins, accurately.
            double worst = 0;
            var rng = new Random(7);
            for (int i = 0; i < 200; i++)
            {
                var n = Rand.Dir(rng, 3);
                var p = Rand.P(rng, 3, 1e6);
                var u = Vector3D.Cross(n, Rand.Dir(rng, 3));
                if (u.LengthSquared == 0) continue;
                var a = p + Rand.P(rng, 3, 1) - u * 1000;
                var b = a + u * 2000 + n * Math.Pow(2, -40) * (rng.Next(2) * 2 - 1);
                var r = Check(f => (new Segment3(a * f, b * f), HalfSpace.FromPointNormal(p * f, n)));
                var h = HalfSpace.FromPointNormal(p, n);
                worst = Math.Max(worst, E(r.D, ExactHeight(h.Normal, h.Point, new[] { a, b }), Scale(new[] { a, b, p })));
            }
            TestContext.Out.WriteLine($"SegmentHalfSpace nearly parallel worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(8));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(220, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var a = Rand.P(rng, dim); var b = Rand.P(rng, dim); var n = Rand.Dir(rng, dim);
                if (rng.Next(4) == 0) b = a; // a point-like segment
                return f => (Rand.Seg(dim, a * f, b * f), Rand.Hs(dim, p * f, n));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(y);
                var ends = x is Segment3 s ? new[] { s.Start, s.End } : new[] { V3(((Segment2)x).Start), V3(((Segment2)x).End) };
                return (ExactHeight(n, p, ends), Scale(ends.Append(p)));
            });
            TestContext.Out.WriteLine($"SegmentHalfSpace worst E = {worst:F3}");
        }

        internal static Vector3D V3(Vector2D v) => V(v.X, v.Y, 0);
    }
}
