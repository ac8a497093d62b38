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
    public class HalfSpaceAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(1, 2, 3), V(3, 6, 4));

        [Test]
        public void LowestCornerOrMiddleOfTheLowestFace()
        {
            // Level along x and y: the middle of the bottom face.
            Result(ClosestDistance.Between(HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1)), Box), 2, V(2, 4, 1), V(2, 4, 3), 0);
            // Tilted (1, 1, 0): the lowest edge (x = 1, y = 2), its middle in z.
            var r = ClosestDistance.Between(HalfSpace.FromPointNormal(V(0, 0, 0), V(1, 1, 0)), Box);
            Result(r, 3 / Math.Sqrt(2), V(-0.5, 0.5, 3.5), V(1, 2, 3.5), 1e-15);
            // Through a vertex: touching; deeper: minus the depth of the lowest corner, witnessed at it.
            Result(ClosestDistance.Between(Box, HalfSpace.FromPointNormal(V(1, 2, 3), V(1, 1, 1))), 0, V(1, 2, 3), V(1, 2, 3), 1e-15);
            Result(ClosestDistance.Between(HalfSpace.FromPointNormal(V(0, 0, 2), V(0, 0, -1)), Box), -2, V(2, 4, 2), V(2, 4, 4), 0);
            Assert.That(ProximityQuery.Overlaps(Box, HalfSpace.FromPointNormal(V(1, 2, 3), V(1, 1, 1))), Is.True);
            Assert.That(ProximityQuery.Overlaps(Box, HalfSpace.FromPointNormal(V(1, 2, 2.5), V(0, 0, 1))), Is.False);
            var b2 = new Aabb2(V(1, 2), V(3, 6));
            Result(ClosestDistance.Between(HalfPlane.FromPointNormal(V(0, 0), V(-1, 0)), b2), -3, V(0, 4), V(3, 4), 0);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfSpace.FromPointNormal(new Num.Vector3(0, 0, 1), new Num.Vector3(0, 0, 1));
            var r = Flt.ClosestDistance.Between(new Flt.Aabb3(new Num.Vector3(1, 2, 3), new Num.Vector3(3, 6, 4)), h);
            Assert.That(r.Distance, Is.EqualTo(2f));
            Assert.That(r.PointA, Is.EqualTo(new Num.Vector3(2, 4, 3)));
        }

        [Test]
        public void PlanesThroughEdgesAndVerticesFarFromTheOrigin()
        {
            // Boxes 1e6 from the origin, planes through one of their corners or edge midpoints, tilted: touching to rounding.
            double worst = 0;
            var rng = new Random(11);
            for (int i = 0; i < 300; i++)
            {
                var lo = Rand.P(rng, 3, 1) + V(1e6, -1e6, 1e6);
                var hi = lo + V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), Rand.F(rng, 0, 2));
                var corner = V(rng.Next(2) == 0 ? lo.X : hi.X, rng.Next(2) == 0 ? lo.Y : hi.Y, rng.Next(2) == 0 ? lo.Z : hi.Z);
                if (rng.Next(2) == 0) corner = V(0.5 * lo.X + 0.5 * hi.X, corner.Y, corner.Z);
                var n = Rand.Dir(rng, 3);
                var r = Check(f => (HalfSpace.FromPointNormal(corner * f, n), new Aabb3(lo * f, hi * f)));
                var h = HalfSpace.FromPointNormal(corner, n);
                var pts = Corners(lo, hi);
                worst = Math.Max(worst, E(r.D, ExactHeight(h.Normal, h.Point, pts), Scale(pts.Append(corner))));
            }
            TestContext.Out.WriteLine($"HalfSpaceAabb through edges/vertices worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(8));
        }

        internal static Vector3D[] Corners(Vector3D lo, Vector3D hi) =>
            Enumerable.Range(0, 8).Select(c => V((c & 1) != 0 ? hi.X : lo.X, (c & 2) != 0 ? hi.Y : lo.Y, (c & 4) != 0 ? hi.Z : lo.Z)).ToArray();

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(920, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var lo = Rand.P(rng, dim); var n = Rand.Dir(rng, dim);
                var hi = lo + V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), dim == 3 ? Rand.F(rng, 0, 2) : 0);
                return f => (Rand.Hs(dim, p * f, n), Rand.Ab(dim, lo * f, hi * f));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(x);
                var pts = y is Aabb3 b ? Corners(b.Min, b.Max) : Corners(SegmentHalfSpaceTests.V3(((Aabb2)y).Min), SegmentHalfSpaceTests.V3(((Aabb2)y).Max));
                return (ExactHeight(n, p, pts), Scale(pts.Append(p)));
            });
            TestContext.Out.WriteLine($"HalfSpaceAabb worst E = {worst:F3}");
        }
    }
}
