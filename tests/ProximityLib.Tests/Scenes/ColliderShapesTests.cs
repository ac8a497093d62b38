using System;
using System.Numerics;
using NUnit.Framework;
using ProximityLib;
using ProximityLib.Scenes;

namespace ProximityTests.Scenes
{
    public class ColliderShapesTests
    {
        [Test]
        public void CapsuleFollowsUnitysSizingRules()
        {
            // Unity's default capsule (radius 0.5, height 2, along Y) at (1, 2, 3): half-length 2/2 − 0.5, axis y = 1.5 … 2.5.
            var c = ColliderShapes.Capsule(new Vector3(1, 2, 3), Quaternion.Identity, Vector3.One, 0.5f, 2, 1);
            Assert.That(c.Start, Is.EqualTo(new Vector3(1, 1.5f, 3)));
            Assert.That(c.End, Is.EqualTo(new Vector3(1, 2.5f, 3)));
            Assert.That(c.Radius, Is.EqualTo(0.5f));
            // Scale (3, 2, -4) along X: radius by max(|2|, |-4|) = 4 → 2; height 10 by 3 → 30; half-length 15 − 2 = 13.
            c = ColliderShapes.Capsule(Vector3.Zero, Quaternion.Identity, new Vector3(3, 2, -4), 0.5f, 10, 0);
            Assert.That(c.Radius, Is.EqualTo(2));
            Assert.That(c.End, Is.EqualTo(new Vector3(13, 0, 0)));
            // Height below the diameter: a sphere (zero-length axis).
            c = ColliderShapes.Capsule(Vector3.One, Quaternion.Identity, Vector3.One, 1, 1, 2);
            Assert.That(c.Start, Is.EqualTo(c.End));
            // Rotated a quarter turn about Z, a Y capsule lies along −X.
            var q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2);
            c = ColliderShapes.Capsule(Vector3.Zero, q, Vector3.One, 0.5f, 3, 1);
            Assert.That(c.End.X, Is.EqualTo(-1).Within(1e-6));
            Assert.That(c.End.Y, Is.EqualTo(0).Within(1e-6));
            Assert.That(() => ColliderShapes.Capsule(Vector3.Zero, q, Vector3.One, 0.5f, 3, 3),
                Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo("direction"));
            // A negative radius from script counts as 0 instead of throwing.
            Assert.That(ColliderShapes.Capsule(Vector3.Zero, q, Vector3.One, -1, 3, 1).Radius, Is.EqualTo(0));
        }

        [Test]
        public void PlaneBecomesTheHalfSpaceBehindIt()
        {
            // Unity: normal·x + distance = 0 with normal (0, 2, 0), distance −4 is the plane y = 2; behind it is y ≤ 2.
            var h = ColliderShapes.BehindPlane(new Vector3(0, 2, 0), -4);
            Assert.That(h.Normal, Is.EqualTo(Vector3.UnitY));
            Assert.That(h.SignedDistance(new Vector3(7, 5, -1)), Is.EqualTo(3));
            Assert.That(h.SignedDistance(new Vector3(0, 0, 0)), Is.EqualTo(-2));
        }

        [Test]
        public void MeshTrianglesAreCheckedAndBuilt()
        {
            var v = new[] { Vector3.Zero, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ };
            var t = ColliderShapes.Triangles(v, new[] { 0, 1, 2, 0, 2, 3 });
            Assert.That(t, Has.Length.EqualTo(2));
            Assert.That(t[1], Is.EqualTo(new Triangle3(Vector3.Zero, Vector3.UnitY, Vector3.UnitZ)));
            Assert.That(() => ColliderShapes.Triangles(v, new[] { 0, 1 }),
                Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo("indices"));
            Assert.That(() => ColliderShapes.Triangles(v, new[] { 0, 1, 4 }),
                Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo("indices"));
            Assert.That(() => ColliderShapes.Triangles(v, new[] { 0, -1, 2 }),
                Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo("indices"));
        }
    }
}
