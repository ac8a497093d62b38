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
    public class RayHalfSpaceTests
    {
        private static readonly HalfSpace Floor = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));

        [Test]
        public void InwardIsUnbounded()
        {
            // From outside: the crossing point.
            var r = ClosestDistance.Between(new Ray3(V(2, 0, 5), V(1, 0, -1)), Floor);
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Near(r.PointA, V(6, 0, 1), 1e-14, "crossing");
            Assert.That(r.PointB, Is.EqualTo(r.PointA));
            // From inside: the origin.
            r = ClosestDistance.Between(new Ray3(V(2, 0, -5), V(1, 0, -1)), Floor);
            Assert.That(r.Distance, Is.EqualTo(double.NegativeInfinity));
            Assert.That(r.PointA, Is.EqualTo(V(2, 0, -5)));
            Assert.That(r.ParameterA, Is.EqualTo(0));
        }

        [Test]
        public void OutwardOrParallelIsTheOrigin()
        {
            var r = ClosestDistance.Between(new Ray3(V(2, 0, 5), V(1, 0, 1)), Floor);
            Result(r, 4, V(2, 0, 5), V(2, 0, 1), 0);
            // Starting inside heading out: finite depth; moving the ray up 6 puts its origin on the boundary.
            Result(ClosestDistance.Between(Floor, new Ray3(V(2, 0, -5), V(1, 0, 1))), -6, V(2, 0, 1), V(2, 0, -5), 0);
            Assert.That(ProximityQuery.Overlaps(new Ray3(V(2, 0, 5), V(1, 0, 1)), Floor), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Ray3(V(2, 0, 5), V(1, 0, -1)), Floor), Is.True);
            Result(ClosestDistance.Between(new Ray2(V(2, 3), V(-1, 0)), HalfPlane.FromPointNormal(V(0, 1), V(0, 1))), 2, V(2, 3), V(2, 1), 0);
        }

        [Test]
        public void Float()
        {
            var h = Flt.HalfPlane.FromPointNormal(new Num.Vector2(0, 1), new Num.Vector2(0, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Ray2(new Num.Vector2(0, 5), new Num.Vector2(1, -1)), h), Is.EqualTo(float.NegativeInfinity));
            Assert.That(Flt.ClosestDistance.Distance(h, new Flt.Ray2(new Num.Vector2(0, 5), new Num.Vector2(1, 1))), Is.EqualTo(4f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = RunRandom(720, 300, (rng, dim) =>
            {
                var p = Rand.P(rng, dim); var o = Rand.P(rng, dim); var n = Rand.Dir(rng, dim); var d = Rand.Dir(rng, dim);
                if (rng.Next(3) == 0) d = dim == 3 ? Vector3D.Cross(n, Rand.Dir(rng, 3)) : V(n.Y, -n.X, 0);
                if (d.LengthSquared == 0) d = V(n.Y, -n.X, 0) + V(0, 0, n.X);
                return f => (Rand.Ry(dim, o * f, d), Rand.Hs(dim, p * f, n));
            }, (x, y, dist) => LineHalfSpaceTests.Exact(x, y, dist, true));
            TestContext.Out.WriteLine($"RayHalfSpace worst E = {worst:F3}");
        }
    }
}
