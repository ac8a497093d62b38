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
    public class RayAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(-1, -1, -1), V(1, 1, 1));

        [Test]
        public void PointingAwayIsTheOrigin()
        {
            var r = ClosestDistance.Between(new Ray3(V(0, 0, 5), V(0, 0, 1)), Box);
            Result(r, 4, V(0, 0, 5), V(0, 0, 1), 0);
            Assert.That(r.ParameterA, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Ray3(V(0, 0, 5), V(0, 0, 1)), Box), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Ray3(V(0, 0, 5), V(0, 0, -1)), Box), Is.True);
            // Passing beside: as the line.
            var b = ClosestDistance.Between(new Ray3(V(0, 4, 5), V(0, 0, -1)), Box);
            Assert.That(b.Distance, Is.EqualTo(3));
            Assert.That(b.PointA.Z, Is.InRange(-1.0, 1.0));
            Assert.That(b.PointB, Is.EqualTo(V(0, 1, b.PointA.Z)));
        }

        [Test]
        public void StartingInsideCanBePushedBack()
        {
            // From (0, 0, 0.5) heading +z: moving it up 0.5 puts its origin on the top face.
            var r = ClosestDistance.Between(new Ray3(V(0, 0, 0.5), V(0, 0, 1)), Box);
            Result(r, -0.5, V(0, 0, 0.5), V(0, 0, 1), 1e-15);
            // Entering from above at the centre: sideways by 1 (a line would need the same).
            Assert.That(ClosestDistance.Between(new Ray3(V(0, 0, 5), V(0, 0, -1)), Box).Distance, Is.EqualTo(-1));
            var r2 = ClosestDistance.Between(new Ray2(V(0.5, 0), V(1, 0)), new Aabb2(V(-1, -1), V(1, 1)));
            Result(r2, -0.5, V(0.5, 0), V(1, 0), 1e-15);
        }

        [Test]
        public void Float()
        {
            var b = new Flt.Aabb2(new Num.Vector2(-1, -1), new Num.Vector2(1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Ray2(new Num.Vector2(0, 5), new Num.Vector2(0, 1)), b), Is.EqualTo(4f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(1200 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var lo = Rand.P(rng, dim); var hi = lo + V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), dim == 3 ? Rand.F(rng, 0, 2) : 0);
                    worst = Math.Max(worst, LineAabbTests.Measure(dim, Rand.P(rng, dim, 3), Rand.Dir(rng, dim), lo, hi, true, rng));
                }
            }
            TestContext.Out.WriteLine($"RayAabb worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }
    }
}
