using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference.Fuzz;

namespace ProximityTests.Fuzz
{
    /// <summary>
    /// The fuzz's exact machinery for issue 12's kinds on hand-worked cases (power-of-two coordinates): membership with
    /// a tolerance, support functions (+∞ where unbounded), direction fitting, the −∞ contract's cases, and the case
    /// index spaces.
    /// </summary>
    [TestFixture]
    public class FuzzCoreTests
    {
        private static DyVec V(double x, double y, double z) => DyVec.From(new Vector3D(x, y, z));

        [Test]
        public void LineAndRayMembershipUsesTheReportedParameter()
        {
            var line = Core.Of(new Line3(new Vector3D(1, 0, 0), new Vector3D(0, 2, 0)));
            Assert.That(line.Contains(V(1, -3, 0), -3, Dy.Zero), Is.True);
            Assert.That(line.Contains(V(1, -3, 0), 3, Dy.Zero), Is.False, "point at t = −3, reported t = 3");
            Assert.That(line.Contains(V(1.25, -3, 0), -3, (Dy)0.25), Is.True);
            Assert.That(line.Contains(V(1.25, -3, 0), -3, (Dy)0.125), Is.False);
            var ray = Core.Of(new Ray3(new Vector3D(1, 0, 0), new Vector3D(0, 2, 0)));
            Assert.That(ray.Contains(V(1, -3, 0), -3, Dy.Zero), Is.False, "a ray has t ≥ 0");
            Assert.That(ray.Contains(V(1, 3, 0), 3, Dy.Zero), Is.True);
        }

        [Test]
        public void CapsuleMembershipIsTheAxisPointPlusTheRadius()
        {
            var c = Core.Of(new Capsule3(new Vector3D(0, 0, 0), new Vector3D(4, 0, 0), 1));
            Assert.That(c.IsSolid, Is.True);
            Assert.That(c.Contains(V(2, 1, 0), 0.5, Dy.Zero), Is.True);
            Assert.That(c.Contains(V(2, 1.5, 0), 0.5, Dy.Zero), Is.False);
            Assert.That(c.Contains(V(2, 1.5, 0), 0.5, (Dy)0.5), Is.True);
            Assert.That(c.Contains(V(2, 1, 0), 1.5, Dy.Zero), Is.False, "axis parameter out of [0, 1]");
            Assert.That(c.Contains(V(-1, 0, 0), 0, Dy.Zero), Is.True, "cap");
        }

        [Test]
        public void TriangleMembershipInsideOnEdgesAndNear()
        {
            var t = Core.Of(new Triangle3(new Vector3D(0, 0, 0), new Vector3D(4, 0, 0), new Vector3D(0, 4, 0)));
            Assert.That(t.IsSolid, Is.False);
            Assert.That(t.Contains(V(1, 1, 0), 0, Dy.Zero), Is.True);
            Assert.That(t.Contains(V(1, 1, 0.5), 0, (Dy)0.5), Is.True);
            Assert.That(t.Contains(V(1, 1, 0.5), 0, (Dy)0.25), Is.False);
            Assert.That(t.Contains(V(2, 2, 0), 0, Dy.Zero), Is.True, "on the hypotenuse");
            Assert.That(t.Contains(V(3, 3, 0), 0, Dy.Zero), Is.False);
            // (3, 3) is √2 from the hypotenuse x + y = 4.
            Assert.That(t.Contains(V(3, 3, 0), 0, (Dy)1.5), Is.True);
            Assert.That(t.Contains(V(3, 3, 0), 0, (Dy)1.375), Is.False);
            Assert.That(t.Contains(V(-1, -1, 0), 0, (Dy)1.5), Is.True, "√2 from the vertex");
            // A degenerate (collinear) triangle is its segment.
            var d = Core.Of(new Triangle3(new Vector3D(0, 0, 0), new Vector3D(2, 0, 0), new Vector3D(4, 0, 0)));
            Assert.That(d.Contains(V(3, 0, 0), 0, Dy.Zero), Is.True);
            Assert.That(d.Contains(V(3, 0.5, 0), 0, (Dy)0.25), Is.False);
            var solid = Core.Of(new Triangle2(new Vector2D(0, 0), new Vector2D(4, 0), new Vector2D(0, 4)));
            Assert.That(solid.IsSolid, Is.True);
            Assert.That(solid.Contains(V(1, 1, 0), 0, Dy.Zero), Is.True);
            Assert.That(solid.Contains(V(1, 1, 0.5), 0, (Dy)1), Is.False, "2D witnesses have z = 0");
        }

        [Test]
        public void HalfSpaceMembershipMeasuresFromTheStoredPoint()
        {
            var h = Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 2), new Vector3D(0, 0, 8)));
            Assert.That(h.IsSolid, Is.True);
            Assert.That(h.Contains(V(5, -7, 2), 0, Dy.Zero), Is.True);
            Assert.That(h.Contains(V(5, -7, -100), 0, Dy.Zero), Is.True);
            Assert.That(h.Contains(V(5, -7, 2.5), 0, (Dy)0.5), Is.True);
            Assert.That(h.Contains(V(5, -7, 2.5), 0, (Dy)0.25), Is.False);
        }

        [Test]
        public void SupportIsFiniteOnlyWhereTheShapeIsBounded()
        {
            var line = Core.Of(new Line3(new Vector3D(1, 2, 3), new Vector3D(0, 0, 1)));
            Assert.That(line.TrySupport(V(1, 0, 0), out var s) && s == (Dy)1, Is.True);
            Assert.That(line.TrySupport(V(1, 0, 1), out _), Is.False);
            var ray = Core.Of(new Ray3(new Vector3D(1, 2, 3), new Vector3D(0, 0, 1)));
            Assert.That(ray.TrySupport(V(0, 0, -1), out s) && s == (Dy)(-3), Is.True);
            Assert.That(ray.TrySupport(V(0, 0, 1), out _), Is.False);
            var h = Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 2), new Vector3D(0, 0, 1)));
            Assert.That(h.TrySupport(V(0, 0, 4), out s) && s == (Dy)8, Is.True);
            Assert.That(h.TrySupport(V(0, 0, -1), out _), Is.False);
            Assert.That(h.TrySupport(V(0, 1, 1), out _), Is.False);
            var cap = Core.Of(new Capsule3(new Vector3D(0, 0, 0), new Vector3D(4, 0, 0), 1));
            Assert.That(cap.TrySupport(V(1, 0, 0), out s) && s == (Dy)4, Is.True, "the core's support; the radius is the caller's");
            var tri = Core.Of(new Triangle3(new Vector3D(0, 0, 0), new Vector3D(4, 0, 0), new Vector3D(0, 4, 0)));
            Assert.That(tri.TrySupport(V(1, 2, 0), out s) && s == (Dy)8, Is.True);
        }

        [Test]
        public void FittedDirectionsMakeTheSupportFinite()
        {
            var line = Core.Of(new Line3(new Vector3D(0, 0, 0), new Vector3D(0.75, 0.5, 0.25)));
            var f = line.Fit(V(0.1, 0.2, 0.7), 1);
            Assert.That(line.TrySupport(f, out _), Is.True);
            var h = Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 0), new Vector3D(0.1, 0.7, 0.2)));
            Assert.That(h.TrySupport(h.Fit(V(1, 0, 0), 1), out _), Is.True);
            Assert.That(h.TrySupport(-h.Fit(V(1, 0, 0), -1), out _), Is.True, "B's support along −n");
        }

        [Test]
        public void UnboundedPenetrationCases()
        {
            var h = Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 0), new Vector3D(0, 0, 1)));
            Assert.That(Checker.MustBeInfinite(Core.Of(new Line3(new Vector3D(0, 0, 5), new Vector3D(0, 1, 1))), h), Is.True);
            Assert.That(Checker.MustBeInfinite(Core.Of(new Line3(new Vector3D(0, 0, 5), new Vector3D(0, 1, 0))), h), Is.False);
            Assert.That(Checker.MustBeInfinite(h, Core.Of(new Ray3(new Vector3D(0, 0, 5), new Vector3D(0, 1, -1)))), Is.True);
            Assert.That(Checker.MustBeInfinite(h, Core.Of(new Ray3(new Vector3D(0, 0, -5), new Vector3D(0, 1, 1)))), Is.False);
            Assert.That(Checker.MustBeInfinite(h, Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 3), new Vector3D(0, 0, -1)))), Is.False);
            Assert.That(Checker.MustBeInfinite(h, Core.Of(HalfSpace.FromPointNormal(new Vector3D(0, 0, 3), new Vector3D(0, 1, -1)))), Is.True);
            Assert.That(Checker.MustBeInfinite(h, Core.Of(new Sphere(new Vector3D(0, 0, 0), 1))), Is.False);
        }

        [Test]
        public void TheOriginalIndexSpaceIsUnchangedAndTheNewOneIsSeparate()
        {
            Assert.That(FuzzCase.Pairs.Length, Is.EqualTo(30));
            Assert.That(FuzzCase.NewPairs.Length, Is.EqualTo(80));
            var (dim, a, b, isFloat, _) = FuzzCase.Slot(31);
            Assert.That((dim, a, b, isFloat), Is.EqualTo((3, Kind.Point, Kind.Segment, true)));
            (dim, a, b, isFloat, _) = FuzzCase.Slot(FuzzCase.NewBase);
            Assert.That((dim, a, b, isFloat), Is.EqualTo((3, Kind.Point, Kind.Line, false)));
            (dim, a, b, isFloat, _) = FuzzCase.Slot(FuzzCase.NewBase + 159);
            Assert.That((dim, a, b, isFloat), Is.EqualTo((2, Kind.HalfSpace, Kind.Obb, true)));
            foreach (var (_, ka, kb) in FuzzCase.NewPairs) Assert.That(Kinds.Rank(ka), Is.LessThanOrEqualTo(Kinds.Rank(kb)));
        }

        [Test]
        public void TheGapSpaceCoversEveryPairInDouble()
        {
            Assert.That(FuzzCase.GapBase, Is.GreaterThan(FuzzCase.NewBase + 1_000_000_000));
            var seen = new System.Collections.Generic.HashSet<(int, Kind, Kind)>();
            for (long i = 0; i < 110; i++)
            {
                var (dim, a, b, isFloat, round) = FuzzCase.Slot(FuzzCase.GapBase + i);
                Assert.That(isFloat, Is.False);
                Assert.That(round, Is.EqualTo(0));
                seen.Add((dim, a, b));
            }
            Assert.That(seen.Count, Is.EqualTo(110));
            var c = FuzzCase.Create(7, FuzzCase.GapBase + 5);
            Assert.That(c.Generator, Is.EqualTo("tiny-gap"));
            Assert.That(c.Float, Is.False);
        }

        [Test]
        public void TheShallowSpaceCoversEveryPairWithEdgesInBothPrecisions()
        {
            Assert.That(FuzzCase.ShallowBase, Is.GreaterThan(FuzzCase.NearBase + 1_000_000_000));
            Assert.That(FuzzCase.ShallowPairs.Length * 2, Is.EqualTo(100));
            Assert.That(DifferentialFuzzTests.DefaultShallowCases % 100, Is.EqualTo(0));
            var seen = new System.Collections.Generic.HashSet<(int, Kind, Kind, bool)>();
            for (long i = 0; i < 100; i++)
            {
                var (dim, a, b, isFloat, round) = FuzzCase.Slot(FuzzCase.ShallowBase + i);
                Assert.That(round, Is.EqualTo(0));
                Assert.That(Generators.Crosses(a, b), Is.True);
                seen.Add((dim, a, b, isFloat));
            }
            Assert.That(seen.Count, Is.EqualTo(100));
            Assert.That(seen, Does.Contain((3, Kind.Segment, Kind.Line, false)));
            Assert.That(seen, Does.Not.Contain((3, Kind.Aabb, Kind.Obb, false)));
        }

        [Test]
        public void ShallowSegmentPairsCrossInsideBothAtShallowAngles()
        {
            // 3D segment–segment in double: the guest's segment passes through a point inside the host's at
            // 10^-0.5…10^-3 rad, so the lines' closest parameters lie inside both and sin θ is in that range.
            int found = 0;
            for (long i = 0; found < 20 && i < 100_000; i++)
            {
                long index = FuzzCase.ShallowBase + i;
                var (dim, a, b, isFloat, _) = FuzzCase.Slot(index);
                if (dim != 3 || a != Kind.Segment || b != Kind.Segment || isFloat) continue;
                var c = FuzzCase.Create(3, index);
                Assert.That(c.Generator, Is.EqualTo("shallow-cross"));
                Vector3D d0 = c.A.Q - c.A.P, d1 = c.B.Q - c.B.P, w = c.B.P - c.A.P;
                var n = Vector3D.Cross(d0, d1);
                double sin = n.Length / (d0.Length * d1.Length);
                Assert.That(sin, Is.InRange(Math.Sin(0.0009), Math.Sin(0.33)), $"case {index}");
                double s = Vector3D.Dot(Vector3D.Cross(w, d1), n) / n.LengthSquared, t = Vector3D.Dot(Vector3D.Cross(w, d0), n) / n.LengthSquared;
                Assert.That(s, Is.InRange(0.0, 1.0), $"case {index}");
                Assert.That(t, Is.InRange(0.0, 1.0), $"case {index}");
                found++;
            }
            Assert.That(found, Is.EqualTo(20));
        }

        [Test]
        public void NewSpecsRebuildThroughTheirConstructorsAndScaleAndTranslate()
        {
            var off = Spec.HalfSpaceOffset(3, new Vector3D(0, 0, 2), 3);
            var built = (HalfSpace)off.Build();
            // {x : (0, 0, 2)·x ≤ 3}: the plane z = 1.5.
            Assert.That(built.Point, Is.EqualTo(new Vector3D(0, 0, 1.5)));
            Assert.That(off.ToCSharp(), Is.EqualTo("new HalfSpace(new Vector3D(0.0, 0.0, 2.0), 3.0)"));
            var moved = (HalfSpace)off.Translated(new Vector3D(1, 2, 4)).Build();
            Assert.That(moved.Point, Is.EqualTo(new Vector3D(1, 2, 5.5)));
            Assert.That(moved.Normal, Is.EqualTo(built.Normal));
            var scaled = (HalfSpace)off.ScaledBy2(3).Build();
            Assert.That((scaled.Point, scaled.Normal), Is.EqualTo((new Vector3D(0, 0, 12), built.Normal)));
            var ray = Spec.Ray(2, new Vector3D(1, 2, 0), new Vector3D(0, 3, 0));
            Assert.That(ray.ScaledBy2(2).ToCSharp(), Is.EqualTo("new Ray2(new Vector2D(4.0, 8.0), new Vector2D(0.0, 3.0))"));
            Assert.That(ray.ToFloat().Build(), Is.TypeOf<ProximityLib.Ray2>());
            var tri = Spec.Triangle(3, new Vector3D(0, 0, 0), new Vector3D(1, 0, 0), new Vector3D(0, 1, 0));
            Assert.That(tri.Translated(new Vector3D(2, 2, 2)).ToCSharp(),
                Is.EqualTo("new Triangle3(new Vector3D(2.0, 2.0, 2.0), new Vector3D(3.0, 2.0, 2.0), new Vector3D(2.0, 3.0, 2.0))"));
        }
    }
}
