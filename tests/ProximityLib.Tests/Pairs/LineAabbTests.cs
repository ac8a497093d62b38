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
    public class LineAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(-1, -1, -1), V(1, 1, 1));

        [Test]
        public void ApartGrazingAndThrough()
        {
            // Parallel to x above the top face edge: distance to the edge (y = 1, z = 1).
            // Parallel to z beside the face y = 1: every z in [−1, 1] is closest; one of that stretch, PointB beside it.
            var r = ClosestDistance.Between(new Line3(V(0, 4, 5), V(0, 0, 1)), Box);
            Assert.That(r.Distance, Is.EqualTo(3));
            Assert.That(r.PointA.Z, Is.InRange(-1.0, 1.0));
            Assert.That(r.PointA, Is.EqualTo(V(0, 4, r.PointA.Z)));
            Assert.That(r.PointB, Is.EqualTo(V(0, 1, r.PointA.Z)));
            Assert.That(r.ParameterA, Is.EqualTo(r.PointA.Z - 5).Within(1e-15));
            // Past an edge: the line x + y = 6 (z = 0) is 4/√2 from the edge x = y = 1.
            var skew = new Line3(V(3, 3, 0), V(1, -1, 0));
            Result(ClosestDistance.Between(skew, Box), 2 * Math.Sqrt(2), V(3, 3, 0), V(1, 1, 0), 1e-15);
            // Grazing an edge: touching.
            Assert.That(ClosestDistance.Between(new Line3(V(1, 1, 0), V(0, 0, 1)), Box).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Line3(V(1, 1, 0), V(0, 0, 1)), Box), Is.True);
            // Through the centre along z: the least sideways push clears it by 1 (x first).
            var t = ClosestDistance.Between(new Line3(V(0, 0, 7), V(0, 0, -1)), Box);
            Assert.That(t.Distance, Is.EqualTo(-1));
            Assert.That((t.PointB - t.PointA).Length, Is.EqualTo(1).Within(1e-15));
            Assert.That(Vector3D.Dot(t.PointB - t.PointA, V(0, 0, 1)), Is.EqualTo(0));
            // Diagonal through the centre: the depth across the hexagonal shadow, √(2/3)·√2 = 2/√3 ... along (1, −1, 0)/√2: √2.
            var d = ClosestDistance.Between(new Line3(V(0, 0, 0), V(1, 1, 1)), Box);
            Assert.That(d.Distance, Is.EqualTo(-Math.Sqrt(2)).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(Box, new Line3(V(0, 4, 5), V(0, 0, 1))), Is.False);
        }

        [Test]
        public void TwoDimensional()
        {
            var b = new Aabb2(V(0, 0), V(2, 1));
            var r = ClosestDistance.Between(new Line2(V(5, 3), V(-1, 0)), b);
            Assert.That(r.Distance, Is.EqualTo(2));
            Assert.That(r.PointA.X, Is.InRange(0.0, 2.0));
            Assert.That(r.PointB, Is.EqualTo(V(r.PointA.X, 1)));
            var through = ClosestDistance.Between(new Line2(V(1, 5), V(0, -1)), b);
            Assert.That(through.Distance, Is.EqualTo(-1));
        }

        [Test]
        public void Float()
        {
            var b = new Flt.Aabb3(new Num.Vector3(-1, -1, -1), new Num.Vector3(1, 1, 1));
            Assert.That(Flt.ClosestDistance.Distance(new Flt.Line3(new Num.Vector3(0, 4, 5), new Num.Vector3(0, 0, 1)), b), Is.EqualTo(3f));
            Assert.That(Flt.ProximityQuery.Overlaps(b, new Flt.Line3(new Num.Vector3(0, 0, 5), new Num.Vector3(0, 0, 1))), Is.True);
        }

        [Test]
        public void FarOriginsAndGrazingLines()
        {
            // Lines whose origin is 1e6 along them from the box, passing within 2^-30 of an edge or nearly parallel to a face.
            double worst = 0;
            var rng = new Random(5);
            for (int i = 0; i < 200; i++)
            {
                var lo = Rand.P(rng, 3, 1); var hi = lo + V(Rand.F(rng, 0.5, 2), Rand.F(rng, 0.5, 2), Rand.F(rng, 0.5, 2));
                var edgePoint = V(hi.X, hi.Y, Rand.F(rng, lo.Z, hi.Z)) + V(1, 1, 0) * (Math.Pow(2, -30) * (rng.Next(3) - 1));
                var u = V(Rand.F(rng, -1, 1), Rand.F(rng, -1, 1), 1);
                if (rng.Next(2) == 0) u = V(1, Math.Pow(2, -35), 0);
                var o = edgePoint + u * 1e6;
                worst = Math.Max(worst, Measure(3, o, u, lo, hi, false, rng));
            }
            TestContext.Out.WriteLine($"LineAabb far/grazing worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }

        /// <summary>Check on the configuration and E against the exact reference.</summary>
        internal static double Measure(int dim, Vector3D o, Vector3D u, Vector3D lo, Vector3D hi, bool ray, Random rng)
        {
            Func<double, (object, object)> make = f => (ray ? Rand.Ry(dim, o * f, u) : Rand.Ln(dim, o * f, u), Rand.Ab(dim, lo * f, hi * f));
            var r = Check(make);
            var (a, _) = make(1);
            dynamic l = a;
            Vector3D lu = l.Direction is Vector2D u2 ? SegmentHalfSpaceTests.V3(u2) : l.Direction;
            var exact = ExactLineAabb(o, lu, ray ? 0 : double.NegativeInfinity, double.PositiveInfinity, lo, hi, dim == 2);
            return E(r.D, exact, Scale(HalfSpaceAabbTests.Corners(lo, hi).Append(o)));
        }

        [Test]
        public void RandomInvariantsAndAccuracy()
        {
            double worst = 0;
            foreach (int dim in new[] { 2, 3 })
            {
                var rng = new Random(1100 + dim);
                for (int i = 0; i < 300; i++)
                {
                    var lo = Rand.P(rng, dim); var hi = lo + V(Rand.F(rng, 0, 2), Rand.F(rng, 0, 2), dim == 3 ? Rand.F(rng, 0, 2) : 0);
                    worst = Math.Max(worst, Measure(dim, Rand.P(rng, dim, 3), Rand.Dir(rng, dim), lo, hi, false, rng));
                }
            }
            TestContext.Out.WriteLine($"LineAabb worst E = {worst:F3}");
            Assert.That(worst, Is.LessThanOrEqualTo(32));
        }
    }
}
