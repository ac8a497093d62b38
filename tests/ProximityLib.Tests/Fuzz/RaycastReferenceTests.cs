using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference.Fuzz;

namespace ProximityTests.Fuzz
{
    /// <summary>
    /// The ray-cast fuzz's exact reference (tests/ProximityLib.Reference/Fuzz/RaycastReference.cs) on hand-worked
    /// configurations, and its checks catching answers that are wrong by more than the allowed perturbation.
    /// </summary>
    public class RaycastReferenceTests
    {
        private static DyVec P(double x, double y, double z = 0) => new DyVec(x, y, z);
        private static readonly DyVec X = P(1, 0, 0);

        private static double T(Surd? s) => s!.Value.ToDouble();

        [Test]
        public void SurdSignsAndRootsAreExact()
        {
            // 3 − 2√2 > 0, 3 − 2√3 < 0, −2 + √4 = 0, 1 + √2 − √5 > 0 (0.18…), 1 + √4 − √9 = 0, and below 0 when 9 grows by an ulp.
            Assert.That(Surd.SignOf(3, -2, 2), Is.EqualTo(1));
            Assert.That(Surd.SignOf(3, -2, 3), Is.EqualTo(-1));
            Assert.That(Surd.SignOf(-2, 1, 4), Is.EqualTo(0));
            Assert.That(Surd.SignOf(1, 1, 2, -1, 5), Is.EqualTo(1));
            Assert.That(Surd.SignOf(1, 1, 4, -1, 9), Is.EqualTo(0));
            Assert.That(Surd.SignOf(1, 1, 4, -1, 9.000000000000002), Is.EqualTo(-1));
            Assert.That(Roots.ISqrt(BigInteger.Parse("152415787532388367501905199875019052100")), Is.EqualTo(BigInteger.Parse("12345678901234567890")));
            Assert.That(Roots.ISqrt(BigInteger.Parse("152415787532388367501905199875019052099")), Is.EqualTo(BigInteger.Parse("12345678901234567889")));
            Assert.That(Roots.Sqrt(2, 60).ToDouble(), Is.EqualTo(1.4142135623730951).Within(4e-16));
        }

        [Test]
        public void SphereFirstHitsGrownAndShrunk()
        {
            // From (−5, 0, 0) along +x to the unit ball at the origin: 4; grown by 0.5: 3.5; shrunk: 4.5.
            var r = (SolidRef)CastRef.For(new Sphere(default, 1), P(-5, 0), X);
            Assert.That(T(r.Nominal), Is.EqualTo(4));
            var (lo, hi) = r.Interval(0.5);
            Assert.That(T(lo), Is.EqualTo(3.5));
            Assert.That(T(hi), Is.EqualTo(4.5));
            // Passing at height 0.6: the chord's entry at −0.8, so t = 4.2 (exactly: √(1 − 0.36) = 0.8).
            var g = (SolidRef)CastRef.For(new Sphere(default, 1), P(-5, 0.6), X);
            Assert.That(T(g.Nominal), Is.EqualTo(4.2).Within(1e-15));
            // Height 1.25: misses the ball and the ball shrunk by 0.5, hits it grown by 0.5 (radius 1.5: entry at −√(2.25 − 1.5625)).
            var m = (SolidRef)CastRef.For(new Sphere(default, 1), P(-5, 1.25), X);
            Assert.That(m.Nominal, Is.Null);
            var (mlo, mhi) = m.Interval(0.5);
            Assert.That(T(mlo), Is.EqualTo(5 - System.Math.Sqrt(0.6875)).Within(1e-15));
            Assert.That(mhi, Is.Null);
        }

        [Test]
        public void CapsuleSideBoxHalfSpaceAndTriangle()
        {
            // Capsule along y from (0, 0, 0) to (0, 4, 0), radius 1: from (−5, 2, 0) along +x hits the side at t = 4.
            Assert.That(T(CastRef.For(new Capsule3(default, new Vector3D(0, 4, 0), 1), P(-5, 2), X).Nominal), Is.EqualTo(4));
            // …from (−5, 5, 0) along +x: only the end ball at (0, 4, 0) (height 1 above it): a graze at t = 5.
            Assert.That(T(CastRef.For(new Capsule3(default, new Vector3D(0, 4, 0), 1), P(-5, 5), X).Nominal), Is.EqualTo(5));
            // Box [1, 2]³ from the origin along (1, 1, 1)/√3 stored: enters at the corner (1, 1, 1), t = 1/d.x.
            var d = new Ray3(default, new Vector3D(1, 1, 1)).Direction;
            var box = CastRef.For(new Aabb3(new Vector3D(1, 1, 1), new Vector3D(2, 2, 2)), P(0, 0), DyVec.From(d));
            Assert.That(T(box.Nominal), Is.EqualTo(1 / d.X).Within(1e-15));
            // Half-space x ≤ 3 from the origin along +x: 3; from inside: 0.
            Assert.That(T(CastRef.For(HalfSpace.FromPointNormal(new Vector3D(3, 0, 0), Vector3D.UnitX), P(4, 0), -X).Nominal), Is.EqualTo(1));
            Assert.That(T(CastRef.For(HalfSpace.FromPointNormal(new Vector3D(3, 0, 0), Vector3D.UnitX), P(0, 0), X).Nominal), Is.EqualTo(0));
            // 3D triangle in z = 0 from (1, 1, 5) down: 5; beside it: a miss. 2D solid triangle from (−2, 1) along +x: 2.
            var tri = new Triangle3(default, new Vector3D(4, 0, 0), new Vector3D(0, 4, 0));
            Assert.That(T(CastRef.For(tri, P(1, 1, 5), P(0, 0, -1)).Nominal), Is.EqualTo(5));
            Assert.That(CastRef.For(tri, P(3, 3, 5), P(0, 0, -1)).Nominal, Is.Null);
            Assert.That(T(CastRef.For(new Triangle2(default, new Vector2D(4, 0), new Vector2D(0, 4)), P(-2, 1), X).Nominal), Is.EqualTo(2));
        }

        [Test]
        public void ThePassThroughCandidatesFollowTheTolerance()
        {
            // A point 3 ahead and 2^−40·3·(1 ± 2^−8) off the ray: in tol and out of it.
            double tol = 3 * System.Math.ScaleB(1, -40);
            var inside = CastRef.For(new Vector3D(3, tol * (1 - 1.0 / 256), 0), P(0, 0), X);
            var outside = CastRef.For(new Vector3D(3, tol * (1 + 1.0 / 256), 0), P(0, 0), X);
            Assert.That(T(inside.Nominal), Is.EqualTo(3));
            Assert.That(outside.Nominal, Is.Null);
            var problems = new List<string>();
            inside.CheckT(false, 0, false, 1e-15, 0, problems);
            Assert.That(problems, Is.Not.Empty, "a miss of a point within tol must fail");
            problems.Clear();
            outside.CheckT(true, 3, false, 1e-15, 0, problems);
            Assert.That(problems, Is.Not.Empty, "a hit of a point beyond tol must fail");
        }

        [Test]
        public void TheChecksCatchWrongAnswers()
        {
            var r = CastRef.For(new Sphere(default, 1), P(-5, 0), X);
            var problems = new List<string>();
            r.CheckT(true, 4, false, 1e-14, 1e-15, problems);
            Assert.That(problems, Is.Empty, string.Join("; ", problems));
            r.CheckT(true, 4.001, false, 1e-14, 1e-15, problems);
            Assert.That(problems, Is.Not.Empty, "T past the shrunk ball's entry");
            problems.Clear();
            r.CheckT(true, 3.999, false, 1e-14, 1e-15, problems);
            Assert.That(problems, Is.Not.Empty, "T before the grown ball's entry");
            problems.Clear();
            r.CheckT(false, 0, false, 1e-14, 0, problems);
            Assert.That(problems, Is.Not.Empty, "a miss of a hit");
            problems.Clear();
            CastRef.For(new Sphere(default, 1), P(0, 0.5), X).CheckT(true, 0.866, false, 1e-14, 1e-15, problems);
            Assert.That(problems, Is.Not.Empty, "an origin inside the shrunk ball must start inside");
            problems.Clear();
            // A 2D wall crossed at t = 2 from the origin: T = 2.001 is too far.
            CastRef.For(new Segment2(new Vector2D(2, -1), new Vector2D(2, 1)), P(0, 0), X).CheckT(true, 2.001, false, 1e-14, 1e-15, problems);
            Assert.That(problems, Is.Not.Empty, "a wall crossed at 2");
        }
    }
}
