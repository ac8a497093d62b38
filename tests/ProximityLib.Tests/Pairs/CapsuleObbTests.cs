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
    public class CapsuleObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        private static Vector3D U(object l) { dynamic d = l; return d.Direction is Vector2D v ? SegmentHalfSpaceTests.V3(v) : (Vector3D)d.Direction; }

        [Test]
        public void AgainstADiamond()
        {
            var r = ClosestDistance.Between(new Capsule3(V(3, -1, 0), V(3, 1, 0), 0.5), Diamond);
            Result(r, 2.5 - Math.Sqrt(2), V(2.5, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(0.5).Within(1e-15));
            // Axis along z through the centre: depth 1 (sideways to a face) plus the radius.
            Assert.That(ClosestDistance.Between(new Capsule3(V(0, 0, -3), V(0, 0, 3), 0.5), Diamond).Distance, Is.EqualTo(-1.5).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(3, -1, 0), V(3, 1, 0), 1.6), Diamond), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(3, -1, 0), V(3, 1, 0), 1.5), Diamond), Is.False);
            var d2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            // 2D: an axis crossing the diamond is deeper than the radius: the 2D crossing depth √2 plus it.
            Assert.That(ClosestDistance.Between(new Capsule2(V(-5, 0), V(5, 0), 0.5), d2).Distance, Is.EqualTo(-Math.Sqrt(2) - 0.5).Within(1e-15));
            var f = new Flt.Obb2(new Num.Vector2(0, 0), new Num.Vector2(1, 0), new Num.Vector2(1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Capsule2(new Num.Vector2(0, 4), new Num.Vector2(3, 4), 1), f), Is.EqualTo(2f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(7400 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var o = Rand.P(rng, dim, 3); var u = Rand.P(rng, dim, 3);
                    double rad = Rand.F(rng, 0, 1);
                    bool permuted = rng.Next(2) == 0;
                    var axes = permuted ? ObbRotations.Permuted(rng, dim) : Rand.Axes(rng, dim);
                    var c = Rand.P(rng, dim);
                    var h = V(Rand.F(rng, 0, 1), Rand.F(rng, 0, 1), dim == 3 ? Rand.F(rng, 0, 1) : 0);
                    Func<double, object> shape = f => Rand.Cap(dim, o * f, u * f, rad * f);
                    var shape1 = shape(1);
                    worst = Math.Max(worst, ObbRotations.Measure(dim, shape, c, axes, h, (lo, hi) => ExactLineAabb(o, u - o, 0, 1, lo, hi, dim == 2) - (Rational)rad, new[] { o, u }, rad, permuted));
                }
            }
            TestContext.Out.WriteLine($"CapsuleObb worst E (permuted axes, exact) = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }
    }
}
