using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;
using F = ProximityLib;

namespace ProximityTests.Raycasts
{
    public class SphereRaycastTests
    {
        private static readonly Sphere Ball = new Sphere(V(0, 0, 0), 2);
        private static Ray3 R(Vector3D o, Vector3D d) => new Ray3(o, d);

        [Test]
        public void HeadOnHitIsExact() => IsHit(Raycast.Cast(R(V(-5, 0, 0), V(1, 0, 0)), Ball), 3, V(-2, 0, 0), V(-1, 0, 0));

        [Test]
        public void GrazingRayHitsAtTheTouchPoint() => IsHit(Raycast.Cast(R(V(-5, 2, 0), V(1, 0, 0)), Ball), 5, V(0, 2, 0), V(0, 1, 0), 1e-15);

        [Test]
        public void PassingAndReceding()
        {
            Miss(Raycast.Cast(R(V(-5, 2.5, 0), V(1, 0, 0)), Ball));
            Miss(Raycast.Cast(R(V(5, 0, 0), V(1, 0, 0)), Ball));
            Miss(Raycast.Cast(R(V(-5, 0, 0), V(0, 1, 0)), Ball));
        }

        [Test]
        public void InsideAndOnTheSurface()
        {
            Inside(Raycast.Cast(R(V(0.5, 0, 0), V(0, 0, 1)), Ball), V(0.5, 0, 0));
            IsHit(Raycast.Cast(R(V(2, 0, 0), V(1, 0, 0)), Ball), 0, V(2, 0, 0), V(1, 0, 0));   // leaving: still a hit at 0
            IsHit(Raycast.Cast(R(V(0, -2, 0), V(0, 1, 0)), Ball), 0, V(0, -2, 0), V(0, -1, 0));
        }

        [Test]
        public void PointSphere()
        {
            IsHit(Raycast.Cast(R(V(0, 0, 0), V(1, 0, 0)), new Sphere(V(3, 0, 0), 0)), 3, V(3, 0, 0), V(-1, 0, 0));
            IsHit(Raycast.Cast(R(V(1, 2, 3), V(0, 1, 0)), new Sphere(V(1, 2, 3), 0)), 0, V(1, 2, 3), V(0, -1, 0));
            Miss(Raycast.Cast(R(V(0, 0, 0), V(1, 0, 0)), new Sphere(V(3, 1e-15, 0), 0)));
        }

        /// <summary>
        /// A zero-radius sphere hit at T &gt; 0 has the normal −Direction, not the direction of the rounding residue of its
        /// hit point's offset from the centre (+Direction here: −0.1 + 0.01/0.1 rounds to +1.4e-17). The ray-cast fuzz found
        /// the capsule analogue (seed 1: 1:885, a zero-radius capsule's end).
        /// </summary>
        [Test]
        public void ZeroRadiusSphereFacesTheRay() =>
            IsHit(Raycast.Cast(R(V(-0.1, 0, 0), V(1, 0, 0)), new Sphere(V(0, 0, 0), 0)), 0.10000000000000002, V(0, 0, 0), V(-1, 0, 0));

        [Test]
        public void MaxDistanceCutsAndIsValidated()
        {
            var ray = R(V(-5, 0, 0), V(1, 0, 0));
            Miss(Raycast.Cast(ray, Ball, 2.5));
            IsHit(Raycast.Cast(ray, Ball, 3), 3, V(-2, 0, 0), V(-1, 0, 0));
            Inside(Raycast.Cast(R(V(0, 0, 0), V(1, 0, 0)), Ball, 0), V(0, 0, 0));
            Assert.That(() => Raycast.Cast(ray, Ball, -1), Throws.ArgumentException.With.Property("ParamName").EqualTo("maxDistance"));
            Assert.That(() => Raycast.Cast(ray, Ball, double.NaN), Throws.ArgumentException.With.Property("ParamName").EqualTo("maxDistance"));
            Assert.That(() => F.Raycast.Cast(new F.Ray3(default, System.Numerics.Vector3.UnitX), new F.Sphere(default, 1), float.NaN),
                Throws.ArgumentException.With.Property("ParamName").EqualTo("maxDistance"));
        }

        [Test]
        public void Circle()
        {
            var c = new Circle(V(1, 1), 1);
            IsHit(Raycast.Cast(new Ray2(V(-2, 1), V(1, 0)), c), 2, V(0, 1), V(-1, 0));
            Inside(Raycast.Cast(new Ray2(V(1, 1.5), V(1, 0)), c), V(1, 1.5));
            Miss(Raycast.Cast(new Ray2(V(-2, 2.5), V(1, 0)), c));
            IsHit(Raycast.Cast(new Ray2(V(-2, 2), V(1, 0)), c), 3, V(1, 2), V(0, 1), 1e-15);
        }

        [Test]
        public void FloatIsTheDoubleAnswerRounded()
        {
            var ray = new F.Ray3(new System.Numerics.Vector3(-5, 0.25f, 0.5f), new System.Numerics.Vector3(1, 0.125f, 0));
            var s = new F.Sphere(new System.Numerics.Vector3(0.5f, 0, 0), 1.5f);
            var f = F.Raycast.Cast(ray, s);
            var d = Raycast.Cast(ray.Inner, s.Inner);
            Assert.That(f.Hit && d.Hit);
            Assert.That(f.T, Is.EqualTo((float)d.T));
            Assert.That(f.Point, Is.EqualTo((System.Numerics.Vector3)d.Point));
            Assert.That(f.Normal, Is.EqualTo((System.Numerics.Vector3)d.Normal));
            var c = F.Raycast.Cast(new F.Ray2(new System.Numerics.Vector2(-3, 0), System.Numerics.Vector2.UnitX), new F.Circle(System.Numerics.Vector2.Zero, 1), 1f);
            Assert.That(c.Hit, Is.False);
            Assert.That(float.IsPositiveInfinity(c.T));
        }
    }
}
