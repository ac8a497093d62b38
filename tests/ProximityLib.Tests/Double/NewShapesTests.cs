using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using F = ProximityLib;

namespace ProximityTests.Double
{
    /// <summary>Lines, rays, capsules, triangles and half-spaces: validation naming the parameter, and what construction stores.</summary>
    public class NewShapesTests
    {
        private static readonly Vector3D Nan3 = V(double.NaN, 0, 0);
        private static readonly Vector2D Inf2 = V(0, double.PositiveInfinity);

        private static void Rejects(string param, TestDelegate make) =>
            Assert.That(make, NUnit.Framework.Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo(param));

        [Test]
        public void LinesAndRaysRejectBadInputAndNormaliseTheDirection()
        {
            Rejects("origin", () => new Line3(Nan3, V(1, 0, 0)));
            Rejects("direction", () => new Line3(V(0, 0, 0), V(0, 0, 0)));
            Rejects("direction", () => new Ray3(V(0, 0, 0), Nan3));
            Rejects("origin", () => new Ray2(Inf2, V(1, 0)));
            Rejects("direction", () => new Line2(V(0, 0), V(0, 0)));
            Rejects("direction", () => new F.Ray3(System.Numerics.Vector3.Zero, System.Numerics.Vector3.Zero));

            // 3-4-5 directions at every magnitude (subnormal 2^-1060 included) normalise to (0.6, 0.8) to rounding; the squares never under/overflow.
            foreach (double s in new[] { 1.0, 1e-300, Math.Pow(2, -1060), 1e300, 4e307 })
            {
                var d = new Line2(V(1, 2), V(3 * s, 4 * s)).Direction;
                Assert.That(d.X, Is.EqualTo(0.6).Within(2e-16), $"scale {s}");
                Assert.That(d.Y, Is.EqualTo(0.8).Within(2e-16), $"scale {s}");
            }
            var axis = new Ray3(V(1, 2, 3), V(0, 0, -1e-310)).Direction;
            Assert.That(axis, Is.EqualTo(V(0, 0, -1)));
            Assert.That(new Ray3(V(1, 2, 3), V(0, 0, -1e-310)).PointAt(2), Is.EqualTo(V(1, 2, 1)));
            // No −0 is stored: the origin's −0 becomes 0 (swap-symmetric differences, as for the other shapes).
            Assert.That(1 / new Line3(V(-0.0, 0, 0), V(1, 0, 0)).Origin.X, Is.EqualTo(double.PositiveInfinity));
        }

        [Test]
        public void CapsulesRejectBadInputAndAllowDegenerateForms()
        {
            Rejects("start", () => new Capsule3(Nan3, V(0, 0, 0), 1));
            Rejects("end", () => new Capsule3(V(0, 0, 0), Nan3, 1));
            Rejects("radius", () => new Capsule3(V(0, 0, 0), V(1, 0, 0), -1));
            Rejects("radius", () => new Capsule2(V(0, 0), V(1, 0), double.NaN));
            Rejects("end", () => new Capsule2(V(0, 0), Inf2, 1));
            var sphereLike = new Capsule3(V(1, 1, 1), V(1, 1, 1), 2);
            Assert.That(sphereLike.Axis, Is.EqualTo(new Segment3(V(1, 1, 1), V(1, 1, 1))));
            Assert.That(new Capsule2(V(0, 0), V(3, 0), 0).Radius, Is.EqualTo(0));
        }

        [Test]
        public void TrianglesRejectNonFiniteVerticesAndAcceptDegenerateOnes()
        {
            Rejects("a", () => new Triangle3(Nan3, V(0, 0, 0), V(1, 0, 0)));
            Rejects("b", () => new Triangle3(V(0, 0, 0), Nan3, V(1, 0, 0)));
            Rejects("c", () => new Triangle2(V(0, 0), V(1, 0), Inf2));
            Assert.DoesNotThrow(() => new Triangle3(V(0, 0, 0), V(1, 1, 1), V(2, 2, 2)));
            Assert.DoesNotThrow(() => new Triangle2(V(5, 5), V(5, 5), V(5, 5)));
        }

        [Test]
        public void HalfSpacesNormaliseAndStoreABoundaryPoint()
        {
            Rejects("normal", () => new HalfSpace(V(0, 0, 0), 1));
            Rejects("offset", () => new HalfSpace(V(0, 0, 1), double.NaN));
            Rejects("point", () => HalfSpace.FromPointNormal(Nan3, V(0, 0, 1)));
            Rejects("normal", () => HalfPlane.FromPointNormal(V(0, 0), V(0, 0)));
            // A boundary beyond the double range: offset 1e300 over a normal of length 1e-300.
            Rejects("offset", () => new HalfSpace(V(1e-300, 0, 0), 1e300));

            // normal·x ≤ offset with normal (0, 3, 4), offset 10: the unit normal (0, 0.6, 0.8), boundary 2 from the origin.
            var h = new HalfSpace(V(0, 3, 4), 10);
            Assert.That(h.Normal.X, Is.EqualTo(0));
            Assert.That(h.Normal.Y, Is.EqualTo(0.6).Within(2e-16));
            Assert.That(h.Normal.Z, Is.EqualTo(0.8).Within(2e-16));
            Assert.That(h.Offset, Is.EqualTo(2).Within(1e-15));
            Assert.That(h.SignedDistance(V(0, 0, 0)), Is.EqualTo(-2).Within(1e-15));
            Assert.That(h.SignedDistance(V(5, 3, 4)), Is.EqualTo(3).Within(1e-15));

            // From a point: the point is stored exactly, and distances are measured from it (no rounding at |Offset|).
            var ground = HalfSpace.FromPointNormal(V(1e6, 1e15, 0), V(0, 2, 0));
            Assert.That(ground.Point, Is.EqualTo(V(1e6, 1e15, 0)));
            Assert.That(ground.Normal, Is.EqualTo(V(0, 1, 0)));
            Assert.That(ground.SignedDistance(V(0, 1e15 + 0.125, 7)), Is.EqualTo(0.125));
            var line = HalfPlane.FromPointNormal(V(2, 3), V(-1e-310, 0));
            Assert.That(line.Normal, Is.EqualTo(V(-1, 0)));
            Assert.That(line.SignedDistance(V(-1, 100)), Is.EqualTo(3));
        }

        [Test]
        public void FloatFormsReadBackTheirValues()
        {
            var c = new F.Capsule3(new System.Numerics.Vector3(1, 2, 3), new System.Numerics.Vector3(4, 5, 6), 0.5f);
            Assert.That(c.Start, Is.EqualTo(new System.Numerics.Vector3(1, 2, 3)));
            Assert.That(c.Radius, Is.EqualTo(0.5f));
            var p = new F.HalfPlane(new System.Numerics.Vector2(0, 2), 3);
            Assert.That(p.Normal, Is.EqualTo(new System.Numerics.Vector2(0, 1)));
            Assert.That(p.Offset, Is.EqualTo(1.5f));
            Assert.That(p.Point, Is.EqualTo(new System.Numerics.Vector2(0, 1.5f)));
            var r = new F.Ray2(new System.Numerics.Vector2(1, 1), new System.Numerics.Vector2(0, -4));
            Assert.That(r.Direction, Is.EqualTo(new System.Numerics.Vector2(0, -1)));
            Assert.That(r.PointAt(2), Is.EqualTo(new System.Numerics.Vector2(1, -1)));
            var t = new F.Triangle2(new System.Numerics.Vector2(0, 0), new System.Numerics.Vector2(1, 0), new System.Numerics.Vector2(0, 1));
            Assert.That(t.C, Is.EqualTo(new System.Numerics.Vector2(0, 1)));
            Assert.That(t, Is.EqualTo(new F.Triangle2(new System.Numerics.Vector2(0, 0), new System.Numerics.Vector2(1, 0), new System.Numerics.Vector2(0, 1))));
            Assert.That(t.ToString(), Is.EqualTo("Triangle2 { A = <0, 0>, B = <1, 0>, C = <0, 1> }"));
        }
    }
}
