using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using Api = ProximityReference.Api;

namespace ProximityTests.Double
{
    /// <summary>
    /// Argument order must not matter, exactly (issue 10, item 4): Between(b, a) is Between(a, b) with the witnesses and
    /// parameters swapped, bit for bit, and Overlaps(b, a) == Overlaps(a, b), for same-type pairs too, in both APIs.
    /// The one exception is documented: bit-identical solids (depth &gt; 0 needs PointA ≠ PointB).
    /// </summary>
    public class OrderTests
    {
        [Test]
        public void ConcentricSpheres() => AssertSymmetric(new Sphere(V(1, 2, 3), 0.5), new Sphere(V(1, 2, 3), 0.25));

        [Test]
        public void ConcentricCirclesWithSignedZeros() => AssertSymmetric(new Circle(V(-0.0, 0), 0.5), new Circle(V(0, -0.0), 0.25));

        [Test]
        public void NestedAabbs()
        {
            AssertSymmetric(new Aabb3(V(-1, -1, -1), V(1, 1, 1)), new Aabb3(V(-0.5, -0.5, -0.5), V(0.5, 0.5, 0.5)));
            AssertSymmetric(new Aabb2(V(-1, -2), V(1, 2)), new Aabb2(V(-0.5, -0.25), V(0.5, 0.25)));
        }

        [Test]
        public void OverlappingObbs()
        {
            var a = Obb3.FromQuaternion(V(0, 0, 0), 0.1, 0.2, 0.3, 0.9, V(1, 0.5, 0.25));
            AssertSymmetric(a, Obb3.FromQuaternion(V(0.3, 0.1, 0), -0.2, 0.1, 0.4, 0.8, V(0.5, 0.5, 0.5)));
            AssertSymmetric(a, Obb3.FromQuaternion(V(0, 0, 0), 0.1, 0.2, 0.3, 0.9, V(0.5, 0.25, 0.125)));
            AssertSymmetric(new Obb2(V(0, 0), 0.3, V(1, 0.5)), new Obb2(V(0.25, 0.5), 1.1, V(0.5, 0.5)));
        }

        [Test]
        public void TouchingObbsAndSegments()
        {
            // Face to face, exactly touching; a T-junction; crossing and end-to-end segments.
            AssertSymmetric(new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1)), new Obb3(V(2, 0.5, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1)));
            AssertSymmetric(new Obb2(V(0, 0), 0.0, V(1, 1)), new Obb2(V(2, 2), 0.0, V(1, 1)));
            AssertSymmetric(new Segment3(V(0, 0, 0), V(2, 0, 0)), new Segment3(V(1, 0, 0), V(1, 3, 0)));
            AssertSymmetric(new Segment2(V(0, 0), V(2, 2)), new Segment2(V(0, 2), V(2, 0)));
            AssertSymmetric(new Segment2(V(0, 0), V(1, 0)), new Segment2(V(3, 0), V(1, 0)));
            AssertSymmetric(new Segment3(V(0, 0, 0), V(2, 0, 0)), new Segment3(V(1, 0, 0), V(3, 0, 0)));
        }

        [Test]
        public void IdenticalNonSolidsGiveOnePoint()
        {
            foreach (var s in new object[] { new Segment3(V(0, 1, 2), V(3, -1, 0.5)), new Segment2(V(0, 1), V(3, -1)), V(1, 2, 3), V(1, 2) })
            {
                dynamic r = Api.Between(s, s);
                Assert.That((object)r.PointA, Is.EqualTo((object)r.PointB), s.ToString());
                Assert.That((double)r.ParameterA, Is.EqualTo((double)r.ParameterB), s.ToString());
                Assert.That((double)r.Distance, Is.EqualTo(0), s.ToString());
            }
        }

        /// <summary>
        /// Seeded same-type pairs, half on a coarse grid (shared coordinates, exact ties, exact touching, signed zeros),
        /// half random; 2D and 3D; both APIs.
        /// </summary>
        [Test]
        public void RandomSameTypePairs()
        {
            var rng = new Random(2640);
            for (int i = 0; i < 3000; i++)
            {
                bool grid = i % 2 == 0;
                double C() => grid ? Math.Round((rng.NextDouble() * 2 - 1) * 4) / 4 * (rng.Next(2) == 0 ? 1 : -1) : rng.NextDouble() * 2 - 1;
                double H() => grid ? Math.Round(rng.NextDouble() * 4) / 4 : rng.NextDouble();
                Vector3D P3() => V(C(), C(), C());
                Vector2D P2() => V(C(), C());
                var share = rng.Next(3) == 0;
                var s3 = new Segment3(P3(), P3());
                var s2 = new Segment2(P2(), P2());
                var sp = new Sphere(P3(), H());
                var ci = new Circle(P2(), H());
                var a3 = Aabb3.FromCenter(P3(), V(H(), H(), H()));
                var a2 = Aabb2.FromCenter(P2(), V(H(), H()));
                var o3 = Obb3.FromQuaternion(P3(), C(), C(), C(), 1, V(H(), H(), H()));
                var o2 = new Obb2(P2(), C() * 3, V(H(), H()));
                var pairs = new List<(object, object)>
                {
                    (P3(), P3()), (P2(), P2()),
                    (s3, share ? new Segment3(s3.End, P3()) : new Segment3(P3(), P3())),
                    (s2, share ? new Segment2(s2.End, P2()) : new Segment2(P2(), P2())),
                    (sp, new Sphere(share ? sp.Center : P3(), H())),
                    (ci, new Circle(share ? ci.Center : P2(), H())),
                    (a3, Aabb3.FromCenter(share ? a3.Center : P3(), V(H(), H(), H()))),
                    (a2, Aabb2.FromCenter(share ? a2.Center : P2(), V(H(), H()))),
                    (o3, Obb3.FromQuaternion(share ? o3.Center : P3(), C(), C(), C(), 1, V(H(), H(), H()))),
                    (o2, new Obb2(share ? o2.Center : P2(), C() * 3, V(H(), H()))),
                };
                foreach (var (a, b) in pairs)
                    if (!a.Equals(b) || !IsSolid(a)) AssertSymmetric(a, b);
            }
        }

        private static bool IsSolid(object s) => s is Sphere || s is Circle || s is Aabb3 || s is Aabb2 || s is Obb3 || s is Obb2;

        private static void AssertSymmetric(object a, object b)
        {
            string what = $"{Describe(a)} vs {Describe(b)}";
            dynamic ab = Api.Between(a, b), ba = Api.Between(b, a);
            Assert.That(Bits(ab.Distance), Is.EqualTo(Bits(ba.Distance)), "Distance, " + what);
            Assert.That(Bits(ab.DistanceSquared), Is.EqualTo(Bits(ba.DistanceSquared)), "DistanceSquared, " + what);
            Assert.That(Bits(ab.PointA), Is.EqualTo(Bits(ba.PointB)), "PointA, " + what);
            Assert.That(Bits(ab.PointB), Is.EqualTo(Bits(ba.PointA)), "PointB, " + what);
            Assert.That(Bits(ab.ParameterA), Is.EqualTo(Bits(ba.ParameterB)), "ParameterA, " + what);
            Assert.That(Bits(ab.ParameterB), Is.EqualTo(Bits(ba.ParameterA)), "ParameterB, " + what);
            Assert.That((bool)Api.Overlaps(b, a), Is.EqualTo((bool)Api.Overlaps(a, b)), "Overlaps, " + what);

            var fa = ToFloat(a);
            var fb = ToFloat(b);
            if (fa == null || fb == null) return;
            dynamic fab = Api.Between(fa, fb), fba = Api.Between(fb, fa);
            Assert.That(Bits((double)fab.Distance), Is.EqualTo(Bits((double)fba.Distance)), "float Distance, " + what);
            Assert.That(fab.PointA.ToString(), Is.EqualTo(fba.PointB.ToString()), "float PointA, " + what);
            Assert.That(fab.PointB.ToString(), Is.EqualTo(fba.PointA.ToString()), "float PointB, " + what);
            Assert.That((bool)Api.Overlaps(fb, fa), Is.EqualTo((bool)Api.Overlaps(fa, fb)), "float Overlaps, " + what);
        }

        /// <summary>The float shape with the same values, when every value is a float (grid inputs are).</summary>
        private static object? ToFloat(object s)
        {
            static bool F(double x) => (double)(float)x == x;
            static bool F3(Vector3D v) => F(v.X) && F(v.Y) && F(v.Z);
            static bool F2(Vector2D v) => F(v.X) && F(v.Y);
            static System.Numerics.Vector3 N3(Vector3D v) => (System.Numerics.Vector3)v;
            static System.Numerics.Vector2 N2(Vector2D v) => (System.Numerics.Vector2)v;
            switch (s)
            {
                case Vector3D p when F3(p): return N3(p);
                case Vector2D p when F2(p): return N2(p);
                case Segment3 x when F3(x.Start) && F3(x.End): return new ProximityLib.Segment3(N3(x.Start), N3(x.End));
                case Segment2 x when F2(x.Start) && F2(x.End): return new ProximityLib.Segment2(N2(x.Start), N2(x.End));
                case Sphere x when F3(x.Center) && F(x.Radius): return new ProximityLib.Sphere(N3(x.Center), (float)x.Radius);
                case Circle x when F2(x.Center) && F(x.Radius): return new ProximityLib.Circle(N2(x.Center), (float)x.Radius);
                case Aabb3 x when F3(x.Min) && F3(x.Max): return new ProximityLib.Aabb3(N3(x.Min), N3(x.Max));
                case Aabb2 x when F2(x.Min) && F2(x.Max): return new ProximityLib.Aabb2(N2(x.Min), N2(x.Max));
                default: return null;
            }
        }

        private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);
        private static string Bits(Vector3D v) => $"{Bits(v.X):X} {Bits(v.Y):X} {Bits(v.Z):X}";
        private static string Bits(Vector2D v) => $"{Bits(v.X):X} {Bits(v.Y):X}";

        private static string Describe(object s) => s switch
        {
            Segment3 x => $"Segment3({x.Start}, {x.End})",
            Segment2 x => $"Segment2({x.Start}, {x.End})",
            Sphere x => $"Sphere({x.Center}, {x.Radius:R})",
            Circle x => $"Circle({x.Center}, {x.Radius:R})",
            Aabb3 x => $"Aabb3({x.Min}, {x.Max})",
            Aabb2 x => $"Aabb2({x.Min}, {x.Max})",
            Obb3 x => $"Obb3({x.Center}, {x.AxisX}, {x.AxisY}, {x.AxisZ}, {x.HalfExtents})",
            Obb2 x => $"Obb2({x.Center}, {x.AxisX}, {x.HalfExtents})",
            _ => s.ToString() ?? "",
        };
    }
}
