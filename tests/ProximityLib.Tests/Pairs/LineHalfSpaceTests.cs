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
    public class LineHalfSpaceTests
    {
        private static readonly HalfSpace Floor = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));

        /// <summary>
        /// A crossing past the precision's range answers the origin (t = 0): in float a line descending 1e-38 per unit
        /// from 1e10 crosses at 1e48; in double one from 1e300 descending 1e-10 per unit crosses at 1e310 (the rescaled
        /// slow path, which once mapped its crossing back to infinity). Rays likewise.
        /// </summary>
        [Test]
        public void CrossingBeyondTheRangeAnswersTheOrigin()
        {
            var floor = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 0), new Num.Vector3(0, 1, 0));
            var origin = new Num.Vector3(0, 1e10f, 0);
            foreach (var r in new[] { Flt.ClosestDistance.Between(new Flt.Line3(origin, new Num.Vector3(1, -1e-38f, 0)), floor),
                                      Flt.ClosestDistance.Between(new Flt.Ray3(origin, new Num.Vector3(1, -1e-38f, 0)), floor) })
            {
                Assert.That(r.Distance, Is.EqualTo(float.NegativeInfinity));
                Assert.That((r.PointA, r.PointB, r.ParameterA), Is.EqualTo((origin, origin, 0f)));
            }
            var o = V(0, 1e300, 0);
            var ground = HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 1, 0));
            foreach (var r in new[] { ClosestDistance.Between(new Line3(o, V(1, -1e-10, 0)), ground), ClosestDistance.Between(new Ray3(o, V(1, -1e-10, 0)), ground) })
            {
                Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
                Assert.That((r.PointA, r.PointB, r.ParameterA), Is.EqualTo((o, o, 0.0)));
            }
            // Within the range the crossing stands: from 1e296, descending 1e-10 per unit, the line crosses at 1e306.
            var near = ClosestDistance.Between(new Line3(V(0, 1e296, 0), V(1, -1e-10, 0)), ground);
            Assert.That(near.PointA.X, Is.EqualTo(1e306).Within(1e-12).Percent);
        }

        [Test]
        public void CrossingIsUnboundedAtTheCrossingPoint()
        {
            var r = ClosestDistance.Between(new Line3(V(2, 0, 5), V(1, 0, -1)), Floor);
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(r.DistanceSquared, Is.EqualTo(0));
            Near(r.PointA, V(6, 0, 1), 1e-14, "crossing");
            Assert.That(r.PointB, Is.EqualTo(r.PointA));
            Assert.That(r.ParameterA, Is.EqualTo(4 * Math.Sqrt(2)).Within(1e-14));
            Assert.That(ClosestDistance.Distance(Floor, new Line3(V(2, 0, 5), V(1, 0, -1))), Is.EqualTo(double.NegativeInfinity));
            Assert.That(ProximityQuery.Overlaps(Floor, new Line3(V(2, 0, 5), V(1, 0, 1))), Is.True);
            // Origin on the boundary: t = +0.
            var o = ClosestDistance.Between(new Line2(V(3, 1), V(1, 1)), HalfPlane.FromPointNormal(V(0, 1), V(0, 1)));
            Assert.That(o.ParameterA, Is.EqualTo(0));
            Assert.That(BitConverter.DoubleToInt64Bits(o.ParameterA), Is.EqualTo(0));
            Assert.That(o.PointA, Is.EqualTo(V(3, 1)));
        }

        [Test]
        public void ParallelIsFinite()
        {
            Result(ClosestDistance.Between(new Line3(V(2, 3, 5), V(1, 1, 0)), Floor), 4, V(2, 3, 5), V(2, 3, 1), 0);
            Result(ClosestDistance.Between(new Line3(V(2, 3, -5), V(1, 1, 0)), Floor), -6, V(2, 3, -5), V(2, 3, 1), 0);
            Assert.That(ProximityQuery.Overlaps(new Line3(V(2, 3, 5), V(1, 1, 0)), Floor), Is.False);
            Result(ClosestDistance.Between(new Line2(V(2, 3), V(-1, 0)), HalfPlane.FromPointNormal(V(0, 1), V(0, -1))), -2, V(2, 3), V(2, 1), 0);
        }

        [Test]
        public void CrossingBeyondTheDoubleRangeFallsBackToTheOrigin()
        {
            // Normal·Direction is about 1e-300: the crossing lies near 1e300 · 1e10, beyond the range.
            var line = new Line3(V(0, 0, 1e10), V(1, 0, -1e-300));
            var r = ClosestDistance.Between(line, HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1)));
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(r.PointA, Is.EqualTo(V(0, 0, 1e10)));
            Assert.That(r.ParameterA, Is.EqualTo(0));
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 1), new Num.Vector3(0, 0, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Line3(new Num.Vector3(0, 0, 5), new Num.Vector3(1, 0, 1)), h), Is.EqualTo(float.NegativeInfinity));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Line3(new Num.Vector3(0, 0, 5), new Num.Vector3(1, 0, 0)), h), Is.EqualTo(4f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(620, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var o = Rand.P(rng, dim); var n = Rand.Dir(rng, dim); var d = Rand.Dir(rng, dim);
                if (rng.Next(3) == 0) d = dim == 3 ? Vector3D.Cross(n, Rand.Dir(rng, 3)) : V(n.Y, -n.X, 0); // parallel (to rounding)
                if (d.LengthSquared == 0) d = V(n.Y, -n.X, 0) + V(0, 0, n.X);
                return f => (Rand.Ln(dim, o * f, d), Rand.Hs(dim, p * f, n));
            }, (x, y, dist) => Exact(x, y, dist, false));
            TestContext.Out.WriteLine($"LineHalfSpace worst E = {worst:F3}");
        }

        /// <summary>Unbounded cases: verified here exactly (the sign of Normal·Direction); finite: the origin's exact height.</summary>
        internal static (Rational?, double) Exact(object x, object y, double dist, bool ray)
        {
            var (n, p) = PointHalfSpaceTests.Plane(y);
            dynamic l = x;
            Vector3D o = l.Origin is Vector2D o2 ? SegmentHalfSpaceTests.V3(o2) : l.Origin, u = l.Direction is Vector2D u2 ? SegmentHalfSpaceTests.V3(u2) : l.Direction;
            var k = RVec.Dot(RVec.From(n), RVec.From(u));
            var h = ExactHeight(n, p, new[] { o });
            bool unbounded = ray ? k.Sign < 0 : !k.IsZero;
            // Within rounding of parallel (|n·u| at most a few ulps) the computed verdict may go either way.
            if (Math.Abs(k.ToDouble()) > 1e-15)
                Assert.That(double.IsNegativeInfinity(dist), Is.EqualTo(unbounded), $"{x} {y}: D={dist:R} n·u={k.ToDouble():R}");
            return double.IsNegativeInfinity(dist) ? ((Rational?)null, 0) : (h, Scale(new[] { o, p }));
        }
    }
}
