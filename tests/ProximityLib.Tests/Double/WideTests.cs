using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;
using Api = ProximityReference.Api;

namespace ProximityTests.Double
{
    /// <summary>
    /// The whole double range (issue 10, item 6): for any finite valid input no NaN, no ∞ where the answer is finite,
    /// no wrong verdict outside the band, and the error bounds for configuration scales 2^-1000 … 2^1000; shapes outside
    /// the moderate range take the rescaling slow path (src/ProximityLib/Double/Wide.cs).
    /// </summary>
    public class WideTests
    {
        [Test]
        public void TinySpheresApartDoNotOverlap()
        {
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e-200), new Sphere(V(3e-200, 0, 0), 1e-200)), Is.False);
            Assert.That(ClosestDistance.Between(new Sphere(V(0, 0, 0), 1e-200), new Sphere(V(3e-200, 0, 0), 1e-200)).Distance, Is.EqualTo(1e-200).Within(1e-215));
        }

        /// <summary>
        /// Ball verdicts d² ≤ r² trust the fast comparison only when r² is in range (<c>Kernels.WithinRadius</c>; a line's
        /// residual is checked too, <c>Kernels.LinearInBall</c>). Each case here has one or both squares outside [2^-960, 2^960], and the expected verdict
        /// follows from the inputs by hand: points 1e-170 apart are apart, however small their squared gap rounds. Every
        /// configuration is at one scale, so the tolerance band (relative to that scale) cannot excuse a wrong verdict.
        /// </summary>
        [Test]
        public void BallVerdictsWhereASquareLeavesTheRange()
        {
            // Both squares underflow to 0: the bare comparison would say "touching".
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 0), new Sphere(V(1e-170, 0, 0), 0)), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(1e-170, 0, 0), new Sphere(V(0, 0, 0), 0)), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(1e-170, 0, 0), V(1e-170, 1e-170, 0)), new Sphere(V(0, 0, 0), 0)), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e-170), new Sphere(V(1e-171, 0, 0), 1e-170)), Is.True);
            // One square out of range, the other in it.
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e160), new Sphere(V(1, 0, 0), 1e160)), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e-200), new Sphere(V(1, 0, 0), 1e-200)), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(1e200, 0, 0), new Sphere(V(0, 0, 0), 1)), Is.False);
            // Both squares overflow.
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e160), new Sphere(V(3e160, 0, 0), 1e160)), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(0, 0, 0), 1e160), new Sphere(V(1.5e160, 0, 0), 1e160)), Is.True);
            // A line whose origin lies 2e308 from the ball, 5e307 from its centre: the difference overflows and the
            // residual's square is NaN.
            Assert.That(ProximityQuery.Overlaps(new Line3(V(-1e308, 0, 0), V(1, 0, 0)), new Sphere(V(1e308, 5e307, 0), 6e307)), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Line3(V(-1e308, 0, 0), V(1, 0, 0)), new Sphere(V(1e308, 5e307, 0), 4e307)), Is.False);
        }

        /// <summary>
        /// With r² in range, a squared distance that overflowed (∞, or NaN from an overflowed difference times a zero
        /// component) is trusted to mean "far": it does for a difference of points, a box of moderate size and a segment
        /// of length in range, whose every point lies near its ends. These fail if the fast path misreads ∞ or NaN.
        /// </summary>
        [Test]
        public void BallVerdictsWhereTheGapOverflows()
        {
            var far = new Sphere(V(1e308, 0, 0), 1);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(-1e308, 0, 0), 1), far), Is.False);
            Assert.That(ProximityQuery.Overlaps(V(-1e308, -1e308, 0), far), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-1e308, 0, 0), V(-1e308, 1, 0)), far), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Capsule3(V(-1e308, 0, 0), V(-1e308, 1, 0), 1), far), Is.False);
            Assert.That(ProximityQuery.Overlaps(Aabb3.FromCenter(V(-1e308, 0, 0), V(1, 1, 1)), far), Is.False);
            Assert.That(ProximityQuery.Overlaps(new Obb3(V(-1e308, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 1)), far), Is.False);
            // The same shapes next to the ball: the fast path's true verdicts.
            var near = new Sphere(V(-1e308, 0, 0), 1);
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-1e308, 0.5, 0), V(-1e308, 1, 0)), near), Is.True);
            Assert.That(ProximityQuery.Overlaps(Aabb3.FromCenter(V(-1e308, 1.5, 0), V(1, 1, 1)), near), Is.True);
        }

        [Test]
        public void FarPointsHaveAFiniteDistance()
        {
            var r = ClosestDistance.Between(V(0, 0, 0), V(1e155, 0, 0));
            Assert.That(r.Distance, Is.EqualTo(1e155));
            // 1e310 is beyond the double range: +∞ is IEEE's rounding of the true square, as documented.
            Assert.That(r.DistanceSquared, Is.EqualTo(double.PositiveInfinity));
            Assert.That(r.PointB, Is.EqualTo(V(1e155, 0, 0)));
        }

        [Test]
        public void HugeBoxesApart()
        {
            var obb = new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1e154, 1e154, 1e154));
            var aabb = Aabb3.FromCenter(V(3e154, 0, 0), V(1e153, 1e153, 1e153));
            var r = ClosestDistance.Between(obb, aabb);
            Assert.That(Exactly.Error(obb, aabb, r.Distance), Is.LessThanOrEqualTo(32), $"D={r.Distance:R}");
            Assert.That(r.PointA.IsFinite && r.PointB.IsFinite, Is.True, $"{r.PointA} {r.PointB}");
            Assert.That(ProximityQuery.Overlaps(obb, aabb), Is.False);
            Assert.That(ProximityQuery.Overlaps(aabb, obb), Is.False);
        }

        [Test]
        public void ExtremeCoordinatesNearTheEndsOfTheRange()
        {
            // Differences of these overflow; the answers do not.
            var a = new Segment3(V(-1.5e308, 0, 0), V(-1e308, 1e308, 0));
            var b = new Segment3(V(1.5e308, 0, 0), V(1e308, 1e308, 0));
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(double.PositiveInfinity), "the distance, 2e308, is itself beyond the range");
            Assert.That(r.PointA.IsFinite && r.PointB.IsFinite, Is.True, $"{r.PointA} {r.PointB}");
            var box = new Aabb3(V(-1.7e308, -1.7e308, -1.7e308), V(1.7e308, 1.7e308, 1.7e308));
            var inside = ClosestDistance.Between(V(1e308, 0, 0), box);
            Assert.That(inside.Distance, Is.EqualTo(-0.7e308).Within(1e293));
            Assert.That(ProximityQuery.Overlaps(box, new Sphere(V(1.6e308, 1.6e308, 0), 1e307)), Is.True);
        }

        [Test]
        public void TinyConfigurationFarFromTheOrigin()
        {
            // Size 2e-300 at coordinates 1e300: pure scaling would underflow it, so the slow path translates first.
            var s = new Segment3(V(1e-300, 1e300, 0), V(3e-300, 1e300, 0));
            var p = V(2e-300, 1e300, 1e-300);
            var r = ClosestDistance.Between(p, s);
            Assert.That(r.Distance, Is.EqualTo(1e-300).Within(1e-315));
            Assert.That(ProximityQuery.Overlaps(p, s), Is.False);
            var c = new Sphere(V(2e-300, 1e300, 0), 0.5e-300);
            Assert.That(ClosestDistance.Between(c, s).Distance, Is.EqualTo(-0.5e-300).Within(1e-315));
        }

        /// <summary>
        /// Ordered pairs of the ten double shapes (ten random pairs per scale) at scales 2^-1000 … 2^1000, with and
        /// without a translation of 2^40 times the scale, one in four with the two shapes at different scales: E within the pair's bound, no NaN,
        /// witnesses finite, verdicts right outside the band.
        /// </summary>
        [Test]
        public void EveryPairOverTheWholeRange([Values(3, 2)] int dim)
        {
            var rng = new Random(2650 + dim);
            int checkedCount = 0;
            for (int k = -1000; k <= 1000; k += 100)
            {
                double scale = Math.Pow(2, k);
                foreach (double shift in new[] { 0.0, Math.Pow(2, Math.Min(k + 40, 1000)) })
                    for (int pair = 0; pair < 10; pair++)
                        {
                            int kindA = rng.Next(5), kindB = rng.Next(5);
                            int kb = rng.Next(4) == 0 ? Math.Max(-1000, Math.Min(1000, k + rng.Next(-60, 61))) : k;
                            var a = Shape(rng, kindA, dim, scale, shift).Shape;
                            var b = Shape(rng, kindB, dim, Math.Pow(2, kb), shift + (rng.NextDouble() - 0.5) * 4 * scale).Shape;
                            CheckPair(a, b);
                            checkedCount++;
                        }
            }
            Assert.That(checkedCount, Is.EqualTo(21 * 2 * 10));
        }

        /// <summary>
        /// Power-of-two scaling is exact across the boundary between the fast path and the slow path: the answer at
        /// 2^k times the inputs is 2^k times the answer, bit for bit.
        /// </summary>
        [Test]
        public void ScalingIsExactAcrossThePaths([Values(3, 2)] int dim)
        {
            var rng = new Random(2660 + dim);
            for (int i = 0; i < 40; i++)
                foreach (int kindA in Kinds)
                    foreach (int kindB in Kinds)
                    {
                        var (a, scaleA) = Shape(rng, kindA, dim, 1, 0);
                        var (b, scaleB) = Shape(rng, kindB, dim, 1, (rng.NextDouble() - 0.5) * 4);
                        dynamic r = Api.Between(a, b);
                        bool o = Api.Overlaps(a, b);
                        foreach (int k in new[] { -900, -600, -300, 300, 600, 900 })
                        {
                            double f = Math.Pow(2, k);
                            var sa = scaleA(f);
                            var sb = scaleB(f);
                            dynamic s = Api.Between(sa, sb);
                            string what = $"2^{k}: {Describe(a)} vs {Describe(b)}";
                            Assert.That((double)s.Distance, Is.EqualTo((double)r.Distance * f), what);
                            Assert.That((object)s.PointA, Is.EqualTo((object)(r.PointA * f)), what);
                            Assert.That((object)s.PointB, Is.EqualTo((object)(r.PointB * f)), what);
                            Assert.That((double)s.ParameterA, Is.EqualTo((double)r.ParameterA), what);
                            Assert.That((double)s.ParameterB, Is.EqualTo((double)r.ParameterB), what);
                            Assert.That((bool)Api.Overlaps(sa, sb), Is.EqualTo(o), what);
                        }
                    }
        }

        /// <summary>
        /// Gaps of 2^-100 of the configuration's size, exact in the inputs (a coordinate offset from 0 or 1), scaled by
        /// 2^k. At 2^-443 and 2^-470 the gap is a normal number but its square underflows to 0: a kernel that takes a
        /// zero squared gap for touching answered 0 (capsules: minus the radius, and overlap). The exact answers are
        /// known by hand: 2^-100·2^k, and for the capsules (axis 3·2^-100 away, radius 2^-100) 2^-99·2^k.
        /// </summary>
        [TestCase(0), TestCase(-443), TestCase(-470), TestCase(300)]
        public void GapsWhoseSquareUnderflowAreNotTouching(int k)
        {
            double d = Math.Pow(2, -100), f = Math.Pow(2, k), gap = d * f;
            Vector3D P(double x, double y, double z) => new Vector3D(x * f, y * f, z * f);
            Vector2D Q(double x, double y) => new Vector2D(x * f, y * f);
            var tri = new Triangle3(P(0, 0, 0), P(1, 0, 0), P(0, 1, 0));
            var seg = new Segment3(P(0.2, 0.2, d), P(0.3, 0.3, 1));
            var cap = new Capsule3(P(0.2, 0.2, 3 * d), P(0.3, 0.3, 1), gap);
            var x = new Segment3(P(0, 0, 0), P(1, 0, 0));
            var parallel = new Segment3(P(0.5, d, 0), P(1.5, d, 0));
            var capX = new Capsule3(P(0.5, 3 * d, 0), P(1.5, 3 * d, 0), gap);
            Assert.That(ClosestDistance.Between(seg, tri).Distance, Is.EqualTo(gap), "segment–triangle");
            Assert.That(ProximityQuery.Overlaps(seg, tri), Is.False, "segment–triangle");
            Assert.That(ClosestDistance.Between(new Triangle3(P(0.2, 0.2, d), P(0.3, 0.3, 1), P(0.1, 0.5, 1)), tri).Distance, Is.EqualTo(gap), "triangle–triangle");
            Assert.That(ClosestDistance.Between(new Line3(P(0.2, 0.2, d), new Vector3D(1, 0, 0)), tri).Distance, Is.EqualTo(gap), "line–triangle");
            Assert.That(ClosestDistance.Between(new Ray3(P(0.2, 0.2, d), new Vector3D(1, 0, 0)), tri).Distance, Is.EqualTo(gap), "ray–triangle");
            Assert.That(ClosestDistance.Between(cap, tri).Distance, Is.EqualTo(2 * gap), "capsule–triangle");
            Assert.That(ProximityQuery.Overlaps(cap, tri), Is.False, "capsule–triangle");
            Assert.That(ClosestDistance.Between(x, parallel).Distance, Is.EqualTo(gap), "parallel segments");
            Assert.That(ProximityQuery.Overlaps(x, parallel), Is.False, "parallel segments");
            Assert.That(ClosestDistance.Between(new Line3(P(0.5, d, 0), new Vector3D(1, 0, 0)), x).Distance, Is.EqualTo(gap), "line–segment");
            Assert.That(ClosestDistance.Between(new Ray3(P(0.5, d, 0), new Vector3D(1, 0, 0)), x).Distance, Is.EqualTo(gap), "ray–segment");
            Assert.That(ClosestDistance.Between(capX, x).Distance, Is.EqualTo(2 * gap), "capsule–segment");
            Assert.That(ProximityQuery.Overlaps(capX, x), Is.False, "capsule–segment");

            var tri2 = new Triangle2(Q(0, 0), Q(1, 0), Q(0, 1));
            var x2 = new Segment2(Q(0, 0), Q(1, 0));
            var below = new Segment2(Q(0.2, -d), Q(0.8, -1));
            Assert.That(ClosestDistance.Between(below, tri2).Distance, Is.EqualTo(gap), "2D segment–triangle");
            Assert.That(ProximityQuery.Overlaps(below, tri2), Is.False, "2D segment–triangle");
            Assert.That(ClosestDistance.Between(new Capsule2(Q(0.2, -3 * d), Q(0.8, -1), gap), tri2).Distance, Is.EqualTo(2 * gap), "2D capsule–triangle");
            Assert.That(ProximityQuery.Overlaps(new Capsule2(Q(0.2, -3 * d), Q(0.8, -1), gap), tri2), Is.False, "2D capsule–triangle");
            var flat = new Triangle2(Q(0, 0), Q(1, 0), Q(2, 0));
            var up = new Segment2(Q(0.5, d), Q(0.5, 1));
            Assert.That(ClosestDistance.Between(up, flat).Distance, Is.EqualTo(gap), "2D segment–flat triangle");
            Assert.That(ProximityQuery.Overlaps(up, flat), Is.False, "2D segment–flat triangle");
            Assert.That(ClosestDistance.Between(x2, new Segment2(Q(0.5, d), Q(1.5, d))).Distance, Is.EqualTo(gap), "2D parallel segments");
            Assert.That(ProximityQuery.Overlaps(x2, new Segment2(Q(0.5, d), Q(1.5, d))), Is.False, "2D parallel segments");
        }

        private static readonly int[] Kinds = { 0, 1, 2, 3, 4 };

        private static void CheckPair(object a, object b)
        {
            string what = $"{Describe(a)} vs {Describe(b)}";
            dynamic r = Api.Between(a, b);
            double d = r.Distance;
            Assert.That(double.IsNaN(d), Is.False, what);
            Assert.That(IsFinite(r.PointA) && IsFinite(r.PointB), Is.True, $"witnesses {r.PointA} {r.PointB}, {what}");
            double e = Exactly.Error(a, b, d), exact = Exactly.Distance(a, b), scale = Exactly.Scale(a, b);
            Assert.That(e, Is.LessThanOrEqualTo(Bound(a, b)), $"E, exact {exact:R}, got {d:R}, {what}");
            if (Math.Abs(exact) > 32 * Exactly.U * scale)
                Assert.That((bool)Api.Overlaps(a, b), Is.EqualTo(exact <= 0), $"verdict, exact {exact:R}, {what}");
        }

        private static bool IsFinite(Vector3D v) => v.IsFinite;
        private static bool IsFinite(Vector2D v) => v.IsFinite;

        private static double Bound(object a, object b)
        {
            bool round = a is Sphere || a is Circle || b is Sphere || b is Circle;
            bool pointAabb = (a is Vector3D || a is Vector2D) && (b is Aabb3 || b is Aabb2) || (b is Vector3D || b is Vector2D) && (a is Aabb3 || a is Aabb2);
            bool pointSegment = (a is Vector3D || a is Vector2D) && (b is Segment3 || b is Segment2) || (b is Vector3D || b is Vector2D) && (a is Segment3 || a is Segment2);
            return round || pointAabb || pointSegment ? 4 : 32;
        }

        /// <summary>
        /// A random shape of about the given size near (shift, shift, shift) — point, segment, sphere, AABB, OBB — and
        /// the same shape with every input scaled by a factor (OBBs rebuilt from their quaternion or angle, so the
        /// stored axes are the same bits).
        /// </summary>
        private static (object Shape, Func<double, object> Scaled) Shape(Random rng, int kind, int dim, double size, double shift)
        {
            Vector3D P() => V(shift + (rng.NextDouble() - 0.5) * 2 * size, shift + (rng.NextDouble() - 0.5) * 2 * size, dim == 3 ? shift + (rng.NextDouble() - 0.5) * 2 * size : 0);
            double L() => (0.1 + rng.NextDouble()) * size;
            var c = P();
            var c2 = V(c.X, c.Y);
            switch (kind)
            {
                case 0:
                    return dim == 3 ? ((object)c, f => c * f) : (c2, f => c2 * f);
                case 1:
                    var e = P();
                    var e2 = V(e.X, e.Y);
                    return dim == 3 ? ((object)new Segment3(c, e), f => new Segment3(c * f, e * f)) : (new Segment2(c2, e2), f => new Segment2(c2 * f, e2 * f));
                case 2:
                    double r = L();
                    return dim == 3 ? ((object)new Sphere(c, r), f => new Sphere(c * f, r * f)) : (new Circle(c2, r), f => new Circle(c2 * f, r * f));
                case 3:
                    var h = V(L(), L(), L());
                    var h2 = V(h.X, h.Y);
                    return dim == 3 ? ((object)Aabb3.FromCenter(c, h), f => Aabb3.FromCenter(c * f, h * f)) : (Aabb2.FromCenter(c2, h2), f => Aabb2.FromCenter(c2 * f, h2 * f));
                default:
                    double qx = rng.NextDouble() - 0.5, qy = rng.NextDouble() - 0.5, qz = rng.NextDouble() - 0.5, qw = rng.NextDouble() - 0.5, angle = rng.NextDouble() * 6.3;
                    var hb = V(L(), L(), L());
                    var hb2 = V(hb.X, hb.Y);
                    return dim == 3
                        ? ((object)Obb3.FromQuaternion(c, qx, qy, qz, qw, hb), f => Obb3.FromQuaternion(c * f, qx, qy, qz, qw, hb * f))
                        : (new Obb2(c2, angle, hb2), f => new Obb2(c2 * f, angle, hb2 * f));
            }
        }

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
