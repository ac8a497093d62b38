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
    public class HalfSpaceObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);

        [Test]
        public void DiamondAgainstAFloor()
        {
            // A unit-half-extent box turned 45° about z, centre (0, 0, 5): its lowest points are the edge at z = 4.
            var box = new Obb3(V(0, 0, 5), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));
            Result(ClosestDistance.Between(HalfSpace.FromPointNormal(V(0, 0, 0), V(0, 0, 1)), box), 4, V(0, 0, 0), V(0, 0, 4), 1e-15);
            // A floor tilted like the box's face: that face's middle.
            var r = ClosestDistance.Between(box, HalfSpace.FromPointNormal(V(-S, -S, 0), V(1, 1, 0)));
            Result(r, 0, V(-S, -S, 5), V(-S, -S, 5), 1e-15);
            var d2 = new Obb2(V(0, 3), Math.PI / 4, V(1, 1));
            Result(ClosestDistance.Between(HalfPlane.FromPointNormal(V(0, 0), V(0, 1)), d2), 3 - Math.Sqrt(2), V(0, 0), V(0, 3 - Math.Sqrt(2)), 1e-15);
            Assert.That(ProximityQuery.Overlaps(d2, HalfPlane.FromPointNormal(V(0, 2), V(0, 1))), Is.True);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 0), new Num.Vector2(0, 1));
            var box = new Flt.Obb2(new Num.Vector2(0, 5), new Num.Vector2(1, 0), new Num.Vector2(1, 2));
            Assert.That(Flt.ClosestDistance.Distance(h, box), Is.EqualTo(3f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(1020, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var c = Rand.P(rng, dim); var n = Rand.Dir(rng, dim); var axes = Rand.Axes(rng, dim);
                if (rng.Next(3) == 0) p += V(1e6, 1e6, dim == 3 ? -1e6 : 0) ;
                if (rng.Next(3) == 0) n = axes[rng.Next(dim)]; // a face parallel to the boundary
                var c2 = p + c;
                var h = V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), dim == 3 ? Rand.F(rng, 0, 2) : 0);
                return f => (Rand.Hs(dim, p * f, n), Rand.Ob(dim, c2 * f, axes, h * f));
            }, (x, y, d) =>
            {
                var (n, p) = PointHalfSpaceTests.Plane(x);
                var (c, axes, h) = Rand.Frame(y);
                var pts = Corners(c, axes, h).ToArray();
                return (ExactHeight(n, p, pts), Scale(pts.Select(v => v.ToDouble()).Append(p)));
            });
            TestContext.Out.WriteLine($"HalfSpaceObb worst E = {worst:F3}");
        }
    }
}
