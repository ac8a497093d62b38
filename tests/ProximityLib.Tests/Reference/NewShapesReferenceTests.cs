using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Reference
{
    /// <summary>
    /// The exact reference (tests/ProximityLib.Reference) on the issue-12 shapes — lines, rays, capsules, triangles,
    /// half-spaces/half-planes — against hand-worked values (integer and power-of-two coordinates, axis directions, so
    /// the stored unit vectors are exact), the −∞ cases, and consistency checks that do not rely on any hand value:
    /// argument-order symmetry, exact translation, Overlaps against the sign, and equalities between shapes that are
    /// the same set (a zero-length capsule and a sphere, a degenerate triangle and its segment, a ray or line and a long
    /// segment, a half-space and a huge box).
    /// </summary>
    public class NewShapesReferenceTests
    {
        private static Vector3D V(double x, double y, double z) => new Vector3D(x, y, z);
        private static Vector2D P(double x, double y) => new Vector2D(x, y);
        private static RShape R(object shape) => RShape.FromAny(shape);

        /// <summary>Asserts the exact signed distance equals the rational <paramref name="expected"/> exactly, in both orders, and Overlaps agrees.</summary>
        private static void Exactly(object a, object b, Rational expected) => Exactly(R(a), R(b), expected, $"{a} / {b}");

        private static void Exactly(RShape a, RShape b, Rational expected, string what)
        {
            Assert.That(Exact.IsUnbounded(a, b), Is.False, what);
            foreach (var (x, y) in new[] { (a, b), (b, a) })
            {
                var d = Exact.SignedDistance(x, y);
                Assert.That(d.CompareTo(expected), Is.EqualTo(0), $"{what}: got {d}, expected {expected}");
                Assert.That(Exact.Overlaps(x, y), Is.EqualTo(expected.Sign <= 0), $"Overlaps, {what}");
            }
        }

        /// <summary>For irrational answers: within 1e-15 relative (the reference's root is good to ~2^-160).</summary>
        private static void Near(object a, object b, double expected)
        {
            foreach (var (x, y) in new[] { (a, b), (b, a) })
            {
                double d = Exact.SignedDistance(R(x), R(y)).ToDouble();
                Assert.That(d, Is.EqualTo(expected).Within(1e-15 * Math.Max(1, Math.Abs(expected))), $"{x} / {y}");
                Assert.That(Exact.Overlaps(R(x), R(y)), Is.EqualTo(expected <= 0), $"Overlaps {x} / {y}");
            }
        }

        private static void Unbounded(object a, object b)
        {
            foreach (var (x, y) in new[] { (R(a), R(b)), (R(b), R(a)) })
            {
                Assert.That(Exact.IsUnbounded(x, y), Is.True, $"{a} / {b}");
                Assert.That(Exact.SignedDistanceOrNull(x, y), Is.Null);
                Assert.That(Exact.Approximate(x, y), Is.EqualTo(double.NegativeInfinity));
                Assert.That(Exact.Overlaps(x, y), Is.True);
                Assert.Throws<InvalidOperationException>(() => Exact.SignedDistance(x, y));
                Assert.That(Exact.Error(double.NegativeInfinity, x, y, 1.0 / (1L << 53)), Is.EqualTo(0));
                Assert.That(Exact.Error(-1e300, x, y, 1.0 / (1L << 53)), Is.EqualTo(double.PositiveInfinity));
            }
        }

        private static Rational Q(int n, int d = 1) => new Rational(n, d);

        // ---- lines ------------------------------------------------------------------------------------------------

        [Test]
        public void Line3AgainstBoundedShapes()
        {
            var x = new Line3(V(0, 0, 0), V(1, 0, 0));
            Exactly(x, V(3, 4, 0), 4);
            Exactly(x, V(-50, 0, 3), 3);
            Exactly(x, V(7, 0, 0), 0);
            Exactly(x, new Segment3(V(0, -1, 2), V(0, 1, 2)), 2);
            Exactly(x, new Segment3(V(0, -1, 0), V(0, 1, 0)), 0);
            Exactly(x, new Segment3(V(5, 2, 0), V(9, 2, 0)), 2); // parallel segment
            Exactly(x, new Sphere(V(7, 0, 3), 1), 2);
            Exactly(x, new Sphere(V(7, 0, 3), 5), -2); // line through the sphere: 3 − 5
            Exactly(x, new Aabb3(V(-1, 1, -1), V(1, 3, 1)), 1);
            // Inside a box: the shallowest way out is across y (1.5 either side ≥ 1.5) or z (2): depth 1.5.
            Exactly(new Line3(V(0, 0.5, 0), V(1, 0, 0)), new Aabb3(V(-1, -1, -2), V(1, 3, 5)), Q(-3, 2));
            Exactly(x, new Obb3(V(0, 3, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0), V(1, 1, 1)), 2);
            // A 3D line through a capsule's axis: the difference line − axis is flat, so −r.
            Exactly(x, new Capsule3(V(2, -1, -1), V(2, 1, 1), 0.5), Q(-1, 2));
            Exactly(x, new Capsule3(V(2, 3, 0), V(6, 3, 0), 0.5), Q(5, 2));
        }

        [Test]
        public void LineNearlyParallelToABoxFaceKeepsTheTrueDepth()
        {
            // Direction (1, 0, 2^-10) exactly (face value, not unit): the clipped ends must not offer a shallower exit.
            // Every unit direction m ⊥ d sees the box [-1, 1]^3 at support |m|₁ ≥ 1, and m = y gives exactly 1.
            var line = RShape.LinearOf(RKind.Line, RVec.Zero, new RVec(1, 0, Math.ScaleB(1, -10)), false);
            var box = R(new Aabb3(V(-1, -1, -1), V(1, 1, 1)));
            Exactly(line, box, -1, "nearly parallel line in a box");
            var ray = RShape.LinearOf(RKind.Ray, RVec.Zero, new RVec(1, 0, Math.ScaleB(1, -10)), false);
            Exactly(ray, box, -1, "nearly parallel ray in a box");

            // A line nearly along the short side of a tall box must leave sideways (across its length), not out of an
            // end: d = (1023, 64) (a Pythagorean direction, |d| = 1025) in [−1, 1] × [−10, 10]. The only exit in 2D is
            // along m = (−64, 1023)/1025, where the box reaches (64·1 + 1023·10)/1025. A clip margin under ~8 along x
            // would offer a shallower, false exit through the segment's ends.
            var tall2 = R(new Aabb2(P(-1, -10), P(1, 10)));
            var slanted2 = RShape.LinearOf(RKind.Line, RVec.Zero, new RVec(1023, 64, 0), true);
            Exactly(slanted2, tall2, Q(-10294, 1025), "slanted line in a tall box (2D)");
            // 3D: the box is deeper still along z (20), so the same exit is the shallowest.
            var tall3 = R(new Aabb3(V(-1, -10, -20), V(1, 10, 20)));
            var slanted3 = RShape.LinearOf(RKind.Line, RVec.Zero, new RVec(1023, 64, 0), false);
            Exactly(slanted3, tall3, Q(-10294, 1025), "slanted line in a tall box (3D)");
        }

        [Test]
        public void Line2AgainstBoundedShapes()
        {
            var x = new Line2(P(0, 0), P(1, 0));
            Exactly(x, P(3, -4), 4);
            Exactly(x, new Segment2(P(-3, 1), P(3, 2)), 1);
            Exactly(x, new Segment2(P(1, -1), P(2, 3)), 0);
            Exactly(x, new Circle(P(9, 3), 1), 2);
            Exactly(x, new Circle(P(9, 1), 2), -1);
            // Line inside a 2D box: exits across y: min(1, 3) = 1.
            Exactly(x, new Aabb2(P(-1, -1), P(1, 3)), -1);
            Exactly(x, new Obb2(P(0, 5), P(0, 1), P(1, 2)), 4); // box turned 90°: y half-extent 1
            // 2D: line − axis is a strip, so a capsule whose axis the line crosses is deeper than r:
            // the axis (0,0)–(4,0) against the line x = 1 leaves by 1 (left), so depth 1 + r.
            Exactly(new Line2(P(1, 7), P(0, 1)), new Capsule2(P(0, 0), P(4, 0), 1), -2);
            Exactly(new Line3(V(1, 7, 0), V(0, 1, 0)), new Capsule3(V(0, 0, 0), V(4, 0, 0), 1), -1); // 3D: flat, −r
            Exactly(new Line2(P(0, 3), P(1, 0)), new Capsule2(P(0, 0), P(4, 0), 1), 2); // parallel, separated
        }

        [Test]
        public void LinesAndRaysAgainstEachOther()
        {
            var x = new Line3(V(0, 0, 0), V(1, 0, 0));
            Exactly(x, new Line3(V(0, 0, 3), V(0, 1, 0)), 3); // skew
            Exactly(x, new Line3(V(5, 4, 0), V(-1, 0, 0)), 4); // parallel (antiparallel direction)
            Exactly(x, new Line3(V(5, 4, 0), V(0, 1, 0)), 0); // crossing
            Exactly(x, x, 0);
            var ray = new Ray3(V(0, 0, 0), V(1, 0, 0));
            Exactly(ray, new Line3(V(7, 0, 3), V(0, 1, 0)), 3);
            Exactly(ray, new Line3(V(-4, 0, 3), V(0, 1, 0)), 5); // the line's nearest point is behind the ray: √(16 + 9)
            Exactly(ray, new Line3(V(9, 2, 0), V(1, 0, 0)), 2); // parallel
            Exactly(ray, new Ray3(V(-5, 1, 0), V(-1, 0, 0)), Rational.Sqrt(Q(26))); // pointing away: origins
            Exactly(ray, new Ray3(V(5, 1, 0), V(-1, 0, 0)), 1); // facing, overlapping in x
            Exactly(ray, new Ray3(V(-5, 1, 0), V(1, 0, 0)), 1); // same direction
            Exactly(ray, new Ray3(V(-3, -4, 5), V(0, 0, 1)), Rational.Sqrt(Q(25 + 25))); // both clamped at their origins
            Exactly(ray, new Ray3(V(4, -3, 0), V(0, 1, 0)), 0); // crossing at (4, 0, 0)
            Exactly(ray, new Ray3(V(-4, -3, 0), V(0, 1, 0)), 4); // would cross behind the origin
            // 2D: non-parallel lines always cross; parallel ones keep their gap.
            var x2 = new Line2(P(0, 0), P(1, 0));
            Exactly(x2, new Line2(P(3, 8), P(3, 4)), 0);
            Exactly(x2, new Line2(P(3, -8), P(-1, 0)), 8);
            Exactly(new Ray2(P(0, 0), P(1, 0)), new Ray2(P(-2, 3), P(0, 1)), Rational.Sqrt(Q(13)));
            Exactly(new Ray2(P(0, 0), P(1, 0)), new Ray2(P(2, 3), P(0, -1)), 0);
            Exactly(new Ray2(P(0, 0), P(1, 0)), new Line2(P(-2, 3), P(1, 0)), 3);
        }

        // ---- rays -------------------------------------------------------------------------------------------------

        [Test]
        public void RayAgainstBoundedShapes()
        {
            var ray = new Ray3(V(0, 0, 0), V(1, 0, 0));
            Exactly(ray, V(-3, 4, 0), 5); // behind: the origin is nearest
            Exactly(ray, V(3, 4, 0), 4);
            Exactly(ray, new Sphere(V(-5, 0, 0), 1), 4); // pointing away
            Exactly(ray, new Sphere(V(5, 0, 0), 1), -1); // through the center: −r
            Exactly(ray, new Sphere(V(0, 0, 0), 2), -2); // starting at the center
            Exactly(ray, new Segment3(V(-2, -1, 0), V(-2, 1, 0)), 2);
            Exactly(ray, new Aabb3(V(2, -1, -1), V(4, 1, 1)), -1);
            Exactly(ray, new Aabb3(V(-4, -1, -1), V(-2, 1, 1)), 2);
            // Starting inside a box: the ray's true end matters. Pointing +x from x = 3.5 in [2, 4] × [−3, 3]²:
            // push it out across x = 4 by 0.5; pointing −x it must move to x = 2, 1.5 away (y, z need 3).
            var box = new Aabb3(V(2, -3, -3), V(4, 3, 3));
            Exactly(new Ray3(V(3.5, 0, 0), V(1, 0, 0)), box, Q(-1, 2));
            Exactly(new Ray3(V(3.5, 0, 0), V(-1, 0, 0)), box, Q(-3, 2));
            Exactly(new Ray3(V(5, 0, 0), V(1, 0, 0)), box, 1);
            Exactly(new Ray3(V(5, 0, 0), V(-1, 0, 0)), box, -3);
            // Capsules: 3D flat (−r); 2D the ray crossing the axis adds the strip depth.
            Exactly(new Ray3(V(1, 5, 0), V(0, -1, 0)), new Capsule3(V(0, 0, 0), V(4, 0, 0), 1), -1);
            Exactly(new Ray2(P(1, 5), P(0, -1)), new Capsule2(P(0, 0), P(4, 0), 1), -2);
            Exactly(new Ray2(P(1, 5), P(0, 1)), new Capsule2(P(0, 0), P(4, 0), 1), 4);
            Exactly(new Ray2(P(-3, 0), P(-1, 0)), new Triangle2(P(0, 0), P(4, 0), P(0, 4)), 3);
            // A 2D ray ending inside a solid triangle (0,0),(4,0),(0,4): from (1, 10) down through x = 1; leaves across x = 0.
            Exactly(new Ray2(P(1, 10), P(0, -1)), new Triangle2(P(0, 0), P(4, 0), P(0, 4)), -1);
        }

        // ---- half-spaces ------------------------------------------------------------------------------------------

        [Test]
        public void HalfSpaceAgainstBoundedShapes()
        {
            var h = HalfSpace.FromPointNormal(V(3, -2, 1), V(0, 0, 1)); // z ≤ 1
            Exactly(h, V(0, 0, 4), 3);
            Exactly(h, V(0, 0, 0), -1);
            Exactly(h, V(9, 9, 1), 0);
            Exactly(h, new Sphere(V(5, 5, 4), 1), 2);
            Exactly(h, new Sphere(V(0, 0, 1.5), 1), Q(-1, 2));
            Exactly(h, new Segment3(V(0, 0, 3), V(1, 0, 5)), 2);
            Exactly(h, new Segment3(V(0, 0, 3), V(0, 0, -1)), -2);
            Exactly(h, new Capsule3(V(0, 0, 3), V(0, 0, 6), 1), 1);
            Exactly(h, new Capsule3(V(0, 0, 3), V(5, 0, 0), 0.5), Q(-3, 2));
            Exactly(h, new Triangle3(V(0, 0, 2), V(1, 0, 3), V(0, 1, 5)), 1);
            Exactly(h, new Triangle3(V(0, 0, 2), V(1, 0, -3), V(0, 1, 5)), -4);
            Exactly(h, new Aabb3(V(0, 0, -1), V(1, 1, 3)), -2);
            Exactly(h, new Obb3(V(0, 0, 4), V(0, 0, 1), V(1, 0, 0), V(0, 1, 0), V(2, 1, 1)), 1);
            Exactly(h, new Line3(V(0, 0, 3), V(1, 1, 0)), 2); // parallel line (n·d = 0 exactly)
            Exactly(h, new Line3(V(0, 0, -1), V(1, 0, 0)), -2);
            Exactly(h, new Ray3(V(0, 0, 3), V(0, 0, 1)), 2); // pointing away
            Exactly(h, new Ray3(V(0, 0, 3), V(1, 0, 0)), 2); // parallel
            Exactly(h, new Ray3(V(0, 0, -1), V(0, 0, 1)), -2); // inside heading out: the difference is a half-space
            Exactly(h, new Ray3(V(0, 0, 1), V(1, 2, 3)), 0);
        }

        [Test]
        public void HalfSpaceIsTakenAtFaceValue()
        {
            // A non-unit normal: the distance divides by |n| = 5.
            var h = RShape.HalfSpaceOf(RVec.Zero, new RVec(3, 4, 0), false);
            Exactly(h, R(V(6, 8, 1)), 10, "|n| = 5");
            Exactly(h, R(new Sphere(V(-3, -4, 7), 2)), -7, "|n| = 5, sphere");
            // The stored rounded unit normal of (1, 1, 0): both components equal, so n·p/|n| = 2√2 for p = (2, 2, 0).
            Near(HalfSpace.FromPointNormal(V(0, 0, 0), V(1, 1, 0)), V(2, 2, 0), 2 * Math.Sqrt(2));
            // A ray exactly parallel to a face-value normal (n·d = 0 in rationals) stays bounded.
            var ray = RShape.LinearOf(RKind.Ray, new RVec(0, 0, 0), new RVec(4, -3, 1), false);
            Exactly(h, ray, 0, "parallel ray on the boundary");
        }

        [Test]
        public void HalfPlaneAgainstTwoDimensionalShapes()
        {
            var h = HalfPlane.FromPointNormal(P(0, 1), P(0, 1)); // y ≤ 1
            Exactly(h, new Circle(P(0, 3), 1), 1);
            Exactly(h, new Triangle2(P(0, 0), P(4, 0), P(0, 4)), -1);
            Exactly(h, new Capsule2(P(0, 4), P(4, 6), 1), 2);
            Exactly(h, new Aabb2(P(-1, 5), P(1, 6)), 4);
            Exactly(h, new Segment2(P(-1, 5), P(1, -6)), -7);
            Exactly(h, new Line2(P(0, -1), P(1, 0)), -2);
            Exactly(h, new Ray2(P(0, 3), P(1, 0)), 2);
            Exactly(h, new Ray2(P(0, 3), P(1, 1)), 2);
            Exactly(h, HalfPlane.FromPointNormal(P(0, 4), P(0, -1)), 3); // y ≥ 4: a gap of 3
            Exactly(h, HalfPlane.FromPointNormal(P(7, -2), P(0, -1)), -3); // y ≥ −2: a slab of width 3
        }

        [Test]
        public void UnboundedPenetrationIsMinusInfinity()
        {
            var h = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));
            Unbounded(h, new Line3(V(0, 0, 50), V(0, 0, 1)));
            Unbounded(h, new Line3(V(0, 0, 50), V(1, 0, 1)));
            Unbounded(h, new Ray3(V(0, 0, 50), V(0, 0, -1))); // crossing inward
            Unbounded(h, new Ray3(V(0, 0, -5), V(1, 0, -1))); // inside, heading inward
            Unbounded(h, new Ray3(V(0, 0, 1), V(0, 0, -1))); // on the boundary, heading inward
            Unbounded(h, HalfSpace.FromPointNormal(V(0, 0, 9), V(0, 0, 1))); // same normal
            Unbounded(h, HalfSpace.FromPointNormal(V(0, 0, 9), V(1, 0, 0)));
            Unbounded(h, h);
            // Not exactly opposite, by 2^-40 in one component (face value): the difference is the whole space.
            var hr = R(h);
            var tilted = RShape.HalfSpaceOf(new RVec(0, 0, 9), new RVec(0, Math.ScaleB(1, -40), -1), false);
            Assert.That(Exact.IsUnbounded(hr, tilted), Is.True);
            Assert.That(Exact.IsUnbounded(tilted, hr), Is.True);
            var h2 = HalfPlane.FromPointNormal(P(0, 1), P(0, 1));
            Unbounded(h2, new Line2(P(0, 5), P(1, 1)));
            Unbounded(h2, new Ray2(P(0, 5), P(1, -1)));
            Unbounded(h2, new Ray2(P(0, -5), P(0, -1)));
            Unbounded(h2, HalfPlane.FromPointNormal(P(0, 1), P(1, 0)));
        }

        // ---- capsules ---------------------------------------------------------------------------------------------

        [Test]
        public void CapsuleAgainstShapes()
        {
            var c = new Capsule3(V(0, 0, 0), V(4, 0, 0), 1);
            Exactly(c, V(2, 3, 0), 2);
            Exactly(c, V(6, 0, 0), 1);
            Exactly(c, V(2, 0.5, 0), Q(-1, 2));
            Exactly(c, new Segment3(V(2, -1, 0), V(2, 1, 0)), -1); // crossing in 3D: flat difference, −r
            Exactly(c, new Segment3(V(2, 3, -1), V(2, 3, 1)), 2);
            Exactly(c, new Capsule3(V(1, 3, 0), V(3, 3, 0), 1), 1); // parallel
            Exactly(c, new Capsule3(V(2, -1, 0), V(2, 1, 0), 1), -2); // crossing axes in 3D
            Exactly(c, new Capsule3(V(2, -1, 5), V(2, 1, 5), 0.5), Q(7, 2)); // skew
            Exactly(c, new Sphere(V(9, 0, 0), 2), 2);
            Exactly(c, new Aabb3(V(-1, 2, -1), V(5, 3, 1)), 1);
            // The axis in the box [−1, 5] × [−1/2, 3] × [−1, 1]: shallowest exit across y = −1/2 (plus r).
            Exactly(c, new Aabb3(V(-1, -0.5, -1), V(5, 3, 1)), Q(-3, 2));
            var c2 = new Capsule2(P(0, 0), P(4, 0), 1);
            // 2D crossing axes: the parallelogram difference [−2, 2] × [−3, 1] holds the origin 1 deep, plus r.
            Exactly(c2, new Segment2(P(2, -1), P(2, 3)), -2);
            Exactly(c2, new Capsule2(P(2, -1), P(2, 3), 1), -3);
            Exactly(c2, new Capsule2(P(1, 0), P(3, 0), 1), -2); // collinear overlapping axes: flat, −(r + r)
            Exactly(c2, new Circle(P(2, 4), 1), 2);
            Exactly(c2, new Aabb2(P(6, -1), P(7, 1)), 1);
        }

        [Test]
        public void CapsuleReducesToSphereAndSegment()
        {
            // Zero length: a sphere, for every partner (and the same S).
            var cap = new Capsule3(V(1, 2, 3), V(1, 2, 3), 2);
            var sphere = new Sphere(V(1, 2, 3), 2);
            foreach (var x in Partners3())
                Same(R(cap), R(sphere), R(x), $"{x}");
            var cap2 = new Capsule2(P(1, 2), P(1, 2), 2);
            var circle = new Circle(P(1, 2), 2);
            foreach (var x in Partners2())
                Same(R(cap2), R(circle), R(x), $"{x}");
            Assert.That(Exact.LocalScale(R(cap), R(V(0, 0, 0))).CompareTo(Exact.LocalScale(R(sphere), R(V(0, 0, 0)))), Is.EqualTo(0));

            // Radius 0 against its own axis: 0 in both 2D and 3D (the difference of a segment with itself is flat).
            Exactly(new Capsule3(V(0, 0, 0), V(4, 2, 0), 0), new Segment3(V(0, 0, 0), V(4, 2, 0)), 0);
            Exactly(new Capsule2(P(0, 0), P(4, 2), 0), new Segment2(P(0, 0), P(4, 2)), 0);
            // Radius 0 equals the segment whenever they are apart or the partner is solid (and in 3D against a segment,
            // line or ray, whose difference with the axis is flat); a 2D crossing is the documented exception.
            var axis3 = new Segment3(V(-1, 0, 1), V(3, 2, 0));
            var zero3 = new Capsule3(V(-1, 0, 1), V(3, 2, 0), 0);
            foreach (var x in Partners3())
            {
                var rx = R(x);
                if (x is Triangle3 && Exact.Overlaps(R(axis3), rx)) continue; // segment − triangle can be a prism
                Same(R(zero3), R(axis3), rx, $"{x}");
            }
            var axis2 = new Segment2(P(-1, 0), P(3, 2));
            var zero2 = new Capsule2(P(-1, 0), P(3, 2), 0);
            foreach (var x in Partners2())
            {
                var rx = R(x);
                if (!rx.IsSolid && Exact.Overlaps(R(axis2), rx)) continue;
                Same(R(zero2), R(axis2), rx, $"{x}");
            }
        }

        // ---- triangles --------------------------------------------------------------------------------------------

        [Test]
        public void Triangle3AgainstShapes()
        {
            var t = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));
            Exactly(t, V(1, 1, 3), 3); // above the face
            Exactly(t, V(-3, -4, 0), 5); // vertex A
            Exactly(t, V(2, -3, 4), 5); // edge AB
            Near(t, V(3, 3, 0), Math.Sqrt(2)); // edge BC
            Exactly(t, V(1, 1, 0), 0);
            Exactly(t, new Segment3(V(1, 1, -1), V(1, 1, 1)), 0); // piercing
            Exactly(t, new Segment3(V(0, 0, 2), V(4, 0, 2)), 2); // parallel above
            Exactly(t, new Segment3(V(5, 5, 1), V(5, 5, -1)), Rational.Sqrt(Q(18))); // beside edge BC, across the plane
            Exactly(t, new Sphere(V(1, 1, 3), 1), 2);
            Exactly(t, new Sphere(V(1, 1, 3), 5), -2); // not solid: the flat difference gives the center's distance − r
            Exactly(t, new Sphere(V(1, 1, 0), 1), -1);
            // A capsule piercing the face: axis − triangle is a prism holding the origin 1/2 deep (down through z = 0).
            Exactly(t, new Capsule3(V(1, 2, -0.5), V(1, 2, 3), 0.25), Q(-3, 4));
            Exactly(t, new Capsule3(V(1, 1, 2), V(1, 1, 5), 1), 1);
            Exactly(t, new Aabb3(V(-1, -1, 1), V(1, 1, 2)), 1);
            // The triangle through a box [−1, 1] × [−1, 1] × [−1/4, 1]: leaves down across z = −1/4... or up, 1; 1/4.
            Exactly(t, new Aabb3(V(-1, -1, -0.25), V(1, 1, 1)), Q(-1, 4));
            Exactly(t, new Line3(V(0, 0, 2), V(1, 0, 0)), 2);
            Exactly(t, new Line3(V(1, 1, 7), V(0, 0, 1)), 0);
            Exactly(t, new Ray3(V(1, 1, 7), V(0, 0, 1)), 7); // pointing away
            Exactly(t, new Ray3(V(1, 1, 7), V(0, 0, -1)), 0);
            Exactly(t, new Triangle3(V(0, 0, 2), V(1, 0, 2), V(0, 1, 2)), 2); // parallel planes
            Exactly(t, new Triangle3(V(1, 1, 0), V(9, 1, 0), V(1, 9, 0)), 0); // coplanar overlap
            Exactly(t, new Triangle3(V(1, 1, -1), V(1, 1, 1), V(9, 9, 0)), 0); // crossing
            Exactly(t, new Triangle3(V(3, 3, -1), V(3, 3, 1), V(9, 9, 0)), Rational.Sqrt(Q(2))); // beside edge BC
        }

        [Test]
        public void Triangle2IsSolid()
        {
            var t = new Triangle2(P(0, 0), P(4, 0), P(0, 4));
            Exactly(t, P(1, 1), -1); // inside: 1 from both legs
            Exactly(t, P(1, 1.5), -1); // 1 from x = 0, 1.5 from y = 0, 1.5/√2 from the hypotenuse
            Near(t, P(3, 3), Math.Sqrt(2));
            Exactly(t, P(-3, -4), 5);
            Exactly(t, new Circle(P(1, 1), 0.5), Q(-3, 2));
            // A segment through it along x = 1 (y from −1 to 5): shallowest exit to the left, by 1.
            Exactly(t, new Segment2(P(1, -1), P(1, 5)), -1);
            Exactly(t, new Line2(P(1, 0), P(0, 1)), -1);
            Exactly(t, new Aabb2(P(-2, -2), P(-1, 9)), 1);
            Exactly(t, new Aabb2(P(-2, -2), P(0.5, 9)), Q(-1, 2));
            // A copy moved by (1, 0): the shallowest exit is along the hypotenuse normal, 3/√2.
            Near(t, new Triangle2(P(1, 0), P(5, 0), P(1, 4)), -3 / Math.Sqrt(2));
            Exactly(t, new Triangle2(P(5, 0), P(9, 0), P(5, 4)), 1);
            Exactly(t, new Triangle2(P(4, 0), P(9, 0), P(5, 4)), 0); // touching at a vertex
            // A capsule whose axis crosses it: solid triangle ⊕ … depth of axis − triangle plus r.
            Exactly(t, new Capsule2(P(1, -1), P(1, 5), 0.5), Q(-3, 2));
        }

        [Test]
        public void DegenerateTrianglesAreTheirSegmentOrPoint()
        {
            // Collinear (middle vertex listed first) and coincident, 3D and 2D, for every partner.
            var seg3 = new Segment3(V(0, 0, 0), V(4, 0, 0));
            var tri3 = new Triangle3(V(2, 0, 0), V(0, 0, 0), V(4, 0, 0));
            var dot3 = new Triangle3(V(1, 2, 3), V(1, 2, 3), V(1, 2, 3));
            foreach (var x in Partners3())
            {
                Same(R(tri3), R(seg3), R(x), $"{x}");
                Same(R(dot3), R(V(1, 2, 3)), R(x), $"{x}");
            }
            var seg2 = new Segment2(P(0, 0), P(4, 0));
            var tri2 = new Triangle2(P(2, 0), P(0, 0), P(4, 0));
            var dot2 = new Triangle2(P(1, 2), P(1, 2), P(1, 2));
            foreach (var x in Partners2())
            {
                Same(R(tri2), R(seg2), R(x), $"{x}");
                Same(R(dot2), R(P(1, 2)), R(x), $"{x}");
            }
            Assert.That(R(tri2).IsSolid, Is.False);
            Assert.That(R(new Triangle2(P(0, 0), P(4, 0), P(0, 4))).IsSolid, Is.True);
            Assert.That(R(new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0))).IsSolid, Is.False);
            // Hand values: a degenerate 2D triangle crossed by a segment is not solid, so 0 (a real triangle gives −1).
            Exactly(tri2, new Segment2(P(1, -1), P(1, 1)), 0);
            Exactly(tri2, P(2, 3), 3);
            Exactly(tri3, new Sphere(V(6, 0, 0), 1), 1);
        }

        // ---- cross-checks between equal sets ---------------------------------------------------------------------

        [Test]
        public void RaysAndLinesEqualLongSegmentsWhereTheAnswerIsInside()
        {
            // Partners lie within a few units of the origin; 2^20 along the direction is far beyond any answer's reach, so
            // the long segment's ends (real ends, unlike the reference's clipping margin) never matter: an independent
            // check that the clip margin neither adds nor removes depth.
            double far = Math.ScaleB(1, 20);
            foreach (var (o, d) in new[] { (V(0, 0, 0), V(1, 0, 0)), (V(-1, 2, 0.5), V(1, 2, -2)), (V(3, -1, 1), V(-2, 1, 1)), (V(0, 0.5, -0.25), V(0, 0, 1)) })
            {
                var ray = R(new Ray3(o, d));
                var line = R(new Line3(o, d));
                var dd = ray.Direction;
                var raySeg = RShape.Segment(ray.Center, ray.Center + dd * far, false);
                var lineSeg = RShape.Segment(ray.Center - dd * far, ray.Center + dd * far, false);
                foreach (var x in Partners3())
                {
                    if (x is HalfSpace) continue;
                    Same(ray, raySeg, R(x), $"ray {o} {d} vs {x}");
                    Same(line, lineSeg, R(x), $"line {o} {d} vs {x}");
                }
            }
            foreach (var (o, d) in new[] { (P(0, 0), P(1, 0)), (P(-1, 2), P(1, 2)), (P(3, -1), P(-2, 1)), (P(0.5, -0.25), P(0, 1)) })
            {
                var ray = R(new Ray2(o, d));
                var line = R(new Line2(o, d));
                var dd = ray.Direction;
                var raySeg = RShape.Segment(ray.Center, ray.Center + dd * far, true);
                var lineSeg = RShape.Segment(ray.Center - dd * far, ray.Center + dd * far, true);
                foreach (var x in Partners2())
                {
                    if (x is HalfPlane) continue;
                    Same(ray, raySeg, R(x), $"ray {o} {d} vs {x}");
                    Same(line, lineSeg, R(x), $"line {o} {d} vs {x}");
                }
            }
        }

        [Test]
        public void LinePairsEqualLongSegmentPairs()
        {
            // The active-set QP against the feature enumeration of long segments (answers attained well inside).
            double far = Math.ScaleB(1, 24);
            var rng = new Random(12);
            for (int i = 0; i < 200; i++)
            {
                bool planar = i % 2 == 1;
                var a = RandomLinear(rng, planar);
                var b = RandomLinear(rng, planar);
                var sa = RShape.Segment(a.Kind == RKind.Ray ? a.Center : a.Center - a.Direction * far, a.Center + a.Direction * far, planar);
                var sb = RShape.Segment(b.Kind == RKind.Ray ? b.Center : b.Center - b.Direction * far, b.Center + b.Direction * far, planar);
                var d2 = Exact.LinearDistance2(a, b);
                var segments = Exact.Intersects(sa, sb) ? Rational.Zero : Exact.Distance2(sa, sb);
                Assert.That(d2.CompareTo(segments), Is.EqualTo(0), $"case {i}: {Describe(a)} / {Describe(b)}");
            }
        }

        [Test]
        public void HalfSpacesEqualHugeBoxes()
        {
            // {z ≤ 1} as the box [−2^30, 2^30]² × [−2^30, 1] (and 2D alike): for partners near the origin the far faces
            // never matter, so the half-space formula must agree with the polytope machinery.
            double big = Math.ScaleB(1, 30);
            var h3 = R(HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1)));
            var box3 = R(new Aabb3(V(-big, -big, -big), V(big, big, 1)));
            var below3 = R(HalfSpace.FromPointNormal(V(0, 0, -1), V(0, 0, -1))); // z ≥ −1
            var boxBelow3 = R(new Aabb3(V(-big, -big, -1), V(big, big, big)));
            foreach (var x in Partners3())
            {
                if (x is Line3 || x is Ray3 || x is HalfSpace) continue;
                Same(h3, box3, R(x), $"{x}");
                Same(below3, boxBelow3, R(x), $"{x}");
            }
            var h2 = R(HalfPlane.FromPointNormal(P(1, 0), P(1, 0)));
            var box2 = R(new Aabb2(P(-big, -big), P(1, big)));
            foreach (var x in Partners2())
            {
                if (x is Line2 || x is Ray2 || x is HalfPlane) continue;
                Same(h2, box2, R(x), $"{x}");
            }
        }

        /// <summary>
        /// Signed distance and verdict of (a, x) equal those of (b, x), both orders, and their unbounded flags. Exact:
        /// the same squared quantity gives the same approximated root, so equality is as rationals.
        /// </summary>
        private static void Same(RShape a, RShape b, RShape x, string what)
        {
            Assert.That(Exact.IsUnbounded(a, x), Is.EqualTo(Exact.IsUnbounded(b, x)), what);
            var da = Exact.SignedDistanceOrNull(a, x);
            var db = Exact.SignedDistanceOrNull(b, x);
            Assert.That(da.HasValue, Is.EqualTo(db.HasValue), what);
            if (da.HasValue)
                Assert.That(da!.Value.CompareTo(db!.Value), Is.EqualTo(0), $"{what}: {da} vs {db}");
            Assert.That(Exact.Overlaps(a, x), Is.EqualTo(Exact.Overlaps(b, x)), what);
            Assert.That(Exact.Overlaps(x, a), Is.EqualTo(Exact.Overlaps(x, b)), what);
        }

        // ---- random invariants -----------------------------------------------------------------------------------

        [Test]
        public void SymmetricTranslationInvariantAndConsistentOnRandomConfigurations([Values(false, true)] bool planar)
        {
            var rng = new Random(planar ? 2 : 3);
            int unbounded = 0, overlapping = 0, separated = 0;
            for (int i = 0; i < 240; i++)
            {
                // One case in six is a half-space against a line, ray or half-space (the −∞ candidates); the rest any kinds.
                bool unboundedKinds = i % 6 == 0;
                var a = R(RandomShape(rng, planar, unboundedKinds ? 7 : rng.Next(10)));
                var b = R(RandomShape(rng, planar, unboundedKinds ? new[] { 2, 3, 7 }[rng.Next(3)] : rng.Next(10)));
                string what = $"case {i}: {Describe(a)} / {Describe(b)}";
                var ab = Exact.SignedDistanceOrNull(a, b);
                var ba = Exact.SignedDistanceOrNull(b, a);
                Assert.That(Exact.IsUnbounded(b, a), Is.EqualTo(Exact.IsUnbounded(a, b)), what);
                Assert.That(ab.HasValue, Is.EqualTo(ba.HasValue), what);
                bool o = Exact.Overlaps(a, b);
                Assert.That(Exact.Overlaps(b, a), Is.EqualTo(o), what);
                if (!ab.HasValue)
                {
                    unbounded++;
                    Assert.That(o, Is.True, what);
                    continue;
                }
                Assert.That(ab!.Value.CompareTo(ba!.Value), Is.EqualTo(0), $"{what}: {ab} vs {ba}");
                Assert.That(o, Is.EqualTo(ab.Value.Sign <= 0), $"{what}: {ab}");
                if (o) overlapping++; else separated++;
                if (!a.IsSolid && !b.IsSolid) Assert.That(ab.Value.Sign, Is.GreaterThanOrEqualTo(0), what);
                // A common translation by a non-dyadic rational changes nothing.
                var t = new RVec(new Rational(1, 3), new Rational(-7, 5), planar ? Rational.Zero : new Rational(2, 7));
                var moved = Exact.SignedDistanceOrNull(a.Translated(t), b.Translated(t));
                Assert.That(moved!.Value.CompareTo(ab.Value), Is.EqualTo(0), $"translated, {what}");
                Assert.That(Exact.LocalScale(a.Translated(t), b.Translated(t)).CompareTo(Exact.LocalScale(a, b)), Is.EqualTo(0), what);
            }
            // The generator reaches all three outcomes (a test that only saw one would prove little).
            Assert.That(unbounded, Is.GreaterThan(3));
            Assert.That(overlapping, Is.GreaterThan(20));
            Assert.That(separated, Is.GreaterThan(20));
        }

        [Test]
        public void LocalScaleCountsTheNewDefiningPoints()
        {
            // Line/ray origin, half-space point, triangle vertices, capsule endpoints and Start + (r, 0, 0).
            Assert.That(Exact.Scale(R(new Line3(V(1, 2, 3), V(0, 0, 1))), R(V(1, 2, 3))), Is.EqualTo(0));
            Assert.That(Exact.Scale(R(new Ray3(V(1, 2, 3), V(0, 0, 1))), R(V(1, -5, 3))), Is.EqualTo(7));
            Assert.That(Exact.Scale(R(HalfSpace.FromPointNormal(V(0, 0, 9), V(0, 0, 1))), R(V(1, 0, 0))), Is.EqualTo(9));
            Assert.That(Exact.Scale(R(new Triangle3(V(0, 0, 0), V(3, 0, 0), V(0, 0, -6))), R(V(0, 0, 0))), Is.EqualTo(6));
            Assert.That(Exact.Scale(R(new Capsule3(V(0, 0, 0), V(0, 2, 0), 5)), R(V(0, 0, 0))), Is.EqualTo(5));
            Assert.That(Exact.Scale(R(new Capsule2(P(0, 0), P(0, 2), 1)), R(P(-3, 0))), Is.EqualTo(4));
            Assert.That(Exact.Scale(R(new Triangle2(P(0, 0), P(1, 0), P(0, 8))), R(new Ray2(P(0, 0), P(1, 0)))), Is.EqualTo(8));
            Assert.That(Exact.Scale(R(HalfPlane.FromPointNormal(P(4, 0), P(1, 0))), R(new Line2(P(0, -2), P(1, 0)))), Is.EqualTo(4));
        }

        // ---- helpers ----------------------------------------------------------------------------------------------

        /// <summary>Partners of every 3D kind near the origin (small integer / half-integer coordinates).</summary>
        private static IEnumerable<object> Partners3()
        {
            yield return V(3, -1, 2);
            yield return V(0.5, 0, 0.25);
            yield return new Segment3(V(-2, 1, 1), V(2, -1, 3));
            yield return new Segment3(V(1, -2, 0), V(1, 2, 0));
            yield return new Line3(V(0, 3, 0), V(1, 0, 1));
            yield return new Ray3(V(2, 2, 2), V(-1, -1, 0));
            yield return new Ray3(V(-3, 0, 0), V(-1, 0, 0));
            yield return new Sphere(V(1, 4, -1), 1.5);
            yield return new Sphere(V(1, 0.5, 0), 0.75);
            yield return new Capsule3(V(-1, -1, -1), V(2, 3, 1), 0.5);
            yield return new Triangle3(V(-2, -1, 1), V(3, 0, -1), V(0, 3, 2));
            yield return new Triangle3(V(4, 4, 4), V(5, 4, 4), V(4, 6, 5));
            yield return HalfSpace.FromPointNormal(V(0, 0, -1), V(0, 0, 1));
            yield return HalfSpace.FromPointNormal(V(0, 5, 0), V(0, -1, 0));
            yield return new Aabb3(V(-1, -0.5, -1), V(0.5, 2, 0.5));
            yield return new Aabb3(V(5, 5, 5), V(6, 7, 8));
            yield return new Obb3(V(0.5, 0.5, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0), V(1, 0.5, 2));
        }

        /// <summary>Partners of every 2D kind near the origin.</summary>
        private static IEnumerable<object> Partners2()
        {
            yield return P(3, -1);
            yield return P(0.5, 0.25);
            yield return new Segment2(P(-2, 1), P(2, -1));
            yield return new Segment2(P(1, -2), P(1, 2));
            yield return new Line2(P(0, 3), P(1, 1));
            yield return new Ray2(P(2, 2), P(-1, -2));
            yield return new Ray2(P(-3, 0), P(-1, 0));
            yield return new Circle(P(1, 4), 1.5);
            yield return new Circle(P(1, 0.5), 0.75);
            yield return new Capsule2(P(-1, -1), P(2, 3), 0.5);
            yield return new Triangle2(P(-2, -1), P(3, 0), P(0, 3));
            yield return new Triangle2(P(4, 4), P(5, 4), P(4, 6));
            yield return HalfPlane.FromPointNormal(P(0, -1), P(0, 1));
            yield return HalfPlane.FromPointNormal(P(5, 0), P(-1, 0));
            yield return new Aabb2(P(-1, -0.5), P(0.5, 2));
            yield return new Aabb2(P(5, 5), P(6, 7));
            yield return new Obb2(P(0.5, 0.5), P(1, 1), P(1, 0.5));
        }

        private static double Coord(Random r) => r.Next(-8, 9) / 2.0;
        private static Vector3D RV(Random r) => V(Coord(r), Coord(r), Coord(r));
        private static Vector2D RP(Random r) => P(Coord(r), Coord(r));

        private static Vector3D RDir(Random r)
        {
            while (true)
            {
                var d = V(r.Next(-2, 3), r.Next(-2, 3), r.Next(-2, 3));
                if (d != Vector3D.Zero) return d;
            }
        }

        private static Vector2D RDir2(Random r)
        {
            while (true)
            {
                var d = P(r.Next(-2, 3), r.Next(-2, 3));
                if (d != Vector2D.Zero) return d;
            }
        }

        private static RShape RandomLinear(Random r, bool planar)
        {
            bool ray = r.Next(2) == 0;
            if (planar) return ray ? R(new Ray2(RP(r), RDir2(r))) : R(new Line2(RP(r), RDir2(r)));
            return ray ? R(new Ray3(RV(r), RDir(r))) : R(new Line3(RV(r), RDir(r)));
        }

        /// <summary>A random shape of kind 0–9 (point, segment, line, ray, sphere, capsule, triangle, half-space, AABB, OBB), small half-integer coordinates (degenerate ones included).</summary>
        private static object RandomShape(Random r, bool planar, int kind)
        {
            double rad = r.Next(0, 5) / 2.0;
            if (planar)
            {
                switch (kind)
                {
                    case 0: return RP(r);
                    case 1: return new Segment2(RP(r), RP(r));
                    case 2: return new Line2(RP(r), RDir2(r));
                    case 3: return new Ray2(RP(r), RDir2(r));
                    case 4: return new Circle(RP(r), rad);
                    case 5: return new Capsule2(RP(r), RP(r), rad);
                    case 6: return r.Next(4) == 0 ? Collinear2(r) : new Triangle2(RP(r), RP(r), RP(r));
                    case 7: return HalfPlane.FromPointNormal(RP(r), r.Next(2) == 0 ? P(0, r.Next(2) * 2 - 1) : RDir2(r));
                    case 8: { var a = RP(r); return new Aabb2(a, a + P(r.Next(0, 4), r.Next(0, 4))); }
                    default: return new Obb2(RP(r), RDir2(r), P(r.Next(0, 4) / 2.0, r.Next(0, 4) / 2.0));
                }
            }
            switch (kind)
            {
                case 0: return RV(r);
                case 1: return new Segment3(RV(r), RV(r));
                case 2: return new Line3(RV(r), RDir(r));
                case 3: return new Ray3(RV(r), RDir(r));
                case 4: return new Sphere(RV(r), rad);
                case 5: return new Capsule3(RV(r), RV(r), rad);
                case 6: return new Triangle3(RV(r), RV(r), RV(r));
                case 7: return HalfSpace.FromPointNormal(RV(r), r.Next(2) == 0 ? V(0, 0, r.Next(2) * 2 - 1) : RDir(r));
                case 8: { var a = RV(r); return new Aabb3(a, a + V(r.Next(0, 4), r.Next(0, 4), r.Next(0, 4))); }
                default: return new Obb3(RV(r), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0), V(r.Next(0, 4) / 2.0, r.Next(0, 4) / 2.0, 1));
            }
        }

        /// <summary>A collinear 2D triangle (coincident vertices when d is zero).</summary>
        private static Triangle2 Collinear2(Random r)
        {
            var a = RP(r);
            var d = P(r.Next(-2, 3), r.Next(-2, 3));
            return new Triangle2(a + d, a, a + d * 3);
        }

        private static string Describe(RShape s) =>
            $"{s.Kind}{(s.Planar ? "2" : "3")}[{string.Join(" ", s.Defining.ConvertAll(v => v.ToDouble().ToString()))}"
            + $"{(s.IsLinear ? " d=" + s.Direction.ToDouble() : "")}{(s.Kind == RKind.HalfSpace ? " n=" + s.Normal.ToDouble() : "")} r={s.Radius}]";
    }
}
