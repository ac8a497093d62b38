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
    public class CapsuleAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(-1, -1, -1), V(1, 1, 1));

        [Test]
        public void ApartTouchingOverlapping()
        {
            var r = ClosestDistance.Between(new Capsule3(V(0, 0, 4), V(0, 0, 6), 1), Box);
            Result(r, 2, V(0, 0, 3), V(0, 0, 1), 0);
            Assert.That(r.ParameterA, Is.EqualTo(0));
            // Axis touching the top face: the depth is the radius, the witness the radius below (the face's outward normal).
            Result(ClosestDistance.Between(new Capsule3(V(0, 0, 1), V(0, 0, 6), 0.5), Box), -0.5, V(0, 0, 0.5), V(0, 0, 1), 0);
            // Axis entering 0.25: depth 0.25 + radius, pushed up.
            Result(ClosestDistance.Between(Box, new Capsule3(V(0, 0, 0.75), V(0, 0, 6), 0.5)), -0.75, V(0, 0, 1), V(0, 0, 0.25), 1e-15);
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(0, 0, 2), V(0, 0, 6), 1), Box), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(0, 0, 2.5), V(0, 0, 6), 1), Box), Is.False);
            // 2D: a stadium beside a corner.
            var c = ClosestDistance.Between(new Capsule2(V(4, 5), V(10, 5), 1), new Aabb2(V(0, 0), V(1, 1)));
            Result(c, 4, V(4 - 0.6, 5 - 0.8), V(1, 1), 1e-15);
        }

        [Test]
        public void CapsNearlyTouching()
        {
            double worst = 0;
            var rng = new Random(3);
            for (int i = 0; i < 200; i++)
            {
                var lo = Rand.P(rng, 3, 1) + V(1e6, 0, -1e6); var hi = lo + V(Rand.F(rng, 0.5, 2), Rand.F(rng, 0.5, 2), Rand.F(rng, 0.5, 2));
                double r = Rand.F(rng, 0.25, 1);
                var dir = Rand.Dir(rng, 3); dir = dir * (1 / dir.Length);
                var corner = V(hi.X, hi.Y, hi.Z);
                var start = corner + V(Math.Abs(dir.X), Math.Abs(dir.Y), Math.Abs(dir.Z)) * (r + Math.Pow(2, -30) * (rng.Next(3) - 1));
                var end = start + Rand.P(rng, 3, 2).Abs3();
                worst = Math.Max(worst, Measure(3, start, end, r, lo, hi));
            }
            TestContext.Out.WriteLine($"CapsuleAabb nearly touching worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }

        internal static double Measure(int dim, Vector3D a, Vector3D b, double r, Vector3D lo, Vector3D hi)
        {
            var res = Check(f => (Rand.Cap(dim, a * f, b * f, r * f), Rand.Ab(dim, lo * f, hi * f)));
            var exact = ExactLineAabb(a, b - a, 0, 1, lo, hi, dim == 2) - (Rational)r;
            return E(res.D, exact, Scale(HalfSpaceAabbTests.Corners(lo, hi).Append(a).Append(b), r));
        }

        [Test]
        public void Float()
        {
            var b = new Flt.Aabb3(new Num.Vector3(-1, -1, -1), new Num.Vector3(1, 1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Capsule3(new Num.Vector3(0, 0, 4), new Num.Vector3(0, 0, 6), 1), b), Is.EqualTo(2f));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(1300 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var lo = Rand.P(rng, dim); var hi = lo + V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), dim == 3 ? Rand.F(rng, 0, 2) : 0);
                    var a = Rand.P(rng, dim, 3); var b = rng.Next(4) == 0 ? a : Rand.P(rng, dim, 3);
                    worst = Math.Max(worst, Measure(dim, a, b, Rand.F(rng, 0, 1), lo, hi));
                }
            }
            TestContext.Out.WriteLine($"CapsuleAabb worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }
    }

    internal static class VecExt
    {
        public static Vector3D Abs3(this Vector3D v) => new Vector3D(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));
    }
}
