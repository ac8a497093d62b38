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
    public class LineObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        private static Vector3D U(object l) { dynamic d = l; return d.Direction is Vector2D v ? SegmentHalfSpaceTests.V3(v) : (Vector3D)d.Direction; }

        [Test]
        public void AgainstADiamond()
        {
            Result(ClosestDistance.Between(new Line3(V(3, 0, 0), V(0, 1, 0)), Diamond), 3 - Math.Sqrt(2), V(3, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            // Through the centre along z: the least sideways push reaches a face, 1 away.
            Assert.That(ClosestDistance.Between(new Line3(V(0, 0, 5), V(0, 0, 1)), Diamond).Distance, Is.EqualTo(-1).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(Diamond, new Line3(V(0, 0, 5), V(0, 0, 1))), Is.True);
            Assert.That(ProximityQuery.Overlaps(Diamond, new Line3(V(3, 0, 0), V(0, 1, 0))), Is.False);
            var d2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            // Along x through the centre: sideways to a vertex, √2.
            Assert.That(ClosestDistance.Between(new Line2(V(-5, 0), V(1, 0)), d2).Distance, Is.EqualTo(-Math.Sqrt(2)).Within(1e-15));
            var f = new Flt.Obb2(new Num.Vector2(0, 0), new Num.Vector2(1, 0), new Num.Vector2(1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Line2(new Num.Vector2(0, 3), new Num.Vector2(1, 0)), f), Is.EqualTo(2f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(4400 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var o = Rand.P(rng, dim, 3); var u = Rand.Dir(rng, dim);
                    double rad = Rand.F(rng, 0, 1);
                    bool permuted = rng.Next(2) == 0;
                    var axes = permuted ? ObbRotations.Permuted(rng, dim) : Rand.Axes(rng, dim);
                    var c = Rand.P(rng, dim);
                    var h = V(Rand.F(rng, 0, 1), Rand.F(rng, 0, 1), dim == 3 ? Rand.F(rng, 0, 1) : 0);
                    Func<double, object> shape = f => Rand.Ln(dim, o * f, u);
                    var shape1 = shape(1);
                    worst = Math.Max(worst, ObbRotations.Measure(dim, shape, c, axes, h, (lo, hi) => ExactLineAabb(o, U(shape1), double.NegativeInfinity, double.PositiveInfinity, lo, hi, dim == 2), new[] { o }, 0, permuted));
                }
            }
            TestContext.Out.WriteLine($"LineObb worst E (permuted axes, exact) = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }
    }
}
