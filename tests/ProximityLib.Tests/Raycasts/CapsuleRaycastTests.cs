using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    public class CapsuleRaycastTests
    {
        private static readonly Capsule3 Pill = new Capsule3(V(0, 0, 0), V(0, 0, 4), 1);

        [Test]
        public void SideCapAndGraze()
        {
            IsHit(Raycast.Cast(new Ray3(V(-3, 0, 2), V(1, 0, 0)), Pill), 2, V(-1, 0, 2), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, -5), V(0, 0, 1)), Pill), 4, V(0, 0, -1), V(0, 0, -1));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 9), V(0, 0, -1)), Pill), 4, V(0, 0, 5), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(1, -5, 2), V(0, 1, 0)), Pill), 5, V(1, 0, 2), V(1, 0, 0), 1e-15);
        }

        [Test]
        public void ParallelToTheAxis()
        {
            Miss(Raycast.Cast(new Ray3(V(2, 0, -5), V(0, 0, 1)), Pill));
            IsHit(Raycast.Cast(new Ray3(V(1, 0, -5), V(0, 0, 1)), Pill), 5, V(1, 0, 0), V(1, 0, 0), 1e-15);
        }

        [Test]
        public void InsideAndOnTheSurface()
        {
            Inside(Raycast.Cast(new Ray3(V(0, 0.5, 1), V(1, 0, 0)), Pill), V(0, 0.5, 1));
            IsHit(Raycast.Cast(new Ray3(V(1, 0, 2), V(1, 0, 0)), Pill), 0, V(1, 0, 2), V(1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 5), V(0, 0, 1)), Pill), 0, V(0, 0, 5), V(0, 0, 1));
        }

        [Test]
        public void DegenerateCapsules()
        {
            // Zero length: a ball; zero radius: the segment, hit at T = 0 from an origin on it (normal −Direction).
            IsHit(Raycast.Cast(new Ray3(V(-5, 0, 0), V(1, 0, 0)), new Capsule3(V(0, 0, 0), V(0, 0, 0), 2)), 3, V(-2, 0, 0), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 1), V(1, 0, 0)), new Capsule3(V(0, 0, 0), V(0, 0, 4), 0)), 0, V(0, 0, 1), V(-1, 0, 0));
        }

        /// <summary>
        /// A zero-radius capsule (a segment) crossed at T &gt; 0 faces the ray: its normal is the segment's perpendicular on
        /// the side the ray comes from, in the outward cone at an end. The ray-cast fuzz found it (seed 1: 1:885, 1:775,
        /// 1:15255): the normal came from the rounding residue of the hit point's offset from the axis (zero at radius 0),
        /// Normal·Direction up to +1 and outside the end's outward cone.
        /// </summary>
        [Test]
        public void ZeroRadiusCapsulesFaceTheRay()
        {
            // Through the start (−0.375, 0.375, 0) of an axis along +y, from above and beside it.
            var h = Raycast.Cast(new Ray3(V(-0.25, 0.375, 0.125), V(-1, 0, -1)), new Capsule3(V(-0.375, 0.375, 0), V(-0.375, 0.875, 0), 0));
            IsHit(h, 0.125 * Math.Sqrt(2), V(-0.375, 0.375, 0), V(Math.Sqrt(0.5), 0, Math.Sqrt(0.5)), 1e-15);
            // Across the middle of a diagonal axis (2D), and through an end from the side.
            var h2 = Raycast.Cast(new Ray2(V(-2.5, -4.5), V(-1.0000043227651774, 0.9999959613463463)), new Capsule2(V(-3, -3), V(-4, -4), 0));
            Assert.That(h2.Hit && (h2.Normal - V(Math.Sqrt(0.5), -Math.Sqrt(0.5))).Length < 1e-15, h2.ToString());
            var h3 = Raycast.Cast(new Ray2(V(7.234557777650801, -0.5325044578103769), V(1.443500664152218, 0.5325044578103769)),
                new Capsule2(V(8.678058441803019, 0), V(6.9424467534424155, 0), 0));
            Assert.That(h3.Hit && (h3.Normal - V(0, -1)).Length < 1e-15, h3.ToString());
        }

        /// <summary>
        /// A ray along a zero-radius capsule's axis from an origin on it starts on it (T = 0, −Direction), even where the
        /// origin's residual from the axis rounds to a few ulps. The ray-cast fuzz found it (seed 1: 1:134175): the origin
        /// counted as outside, and the ray ran along the segment to its far end, hit at T = 3 with a normal pointing out of
        /// that end's outward cone.
        /// </summary>
        [Test]
        public void AlongAZeroRadiusCapsuleFromAnOriginOnIt()
        {
            var o = V(-5.000000000000001, 2);
            IsHit(Raycast.Cast(new Ray2(o, V(-1, 0)), new Capsule2(V(-8, 2), V(-2, 2), 0)), 0, o, V(1, 0));
            IsHit(Raycast.Cast(new Ray2(o, V(1, 0)), new Capsule2(V(-8, 2), V(-2, 2), 0)), 0, o, V(-1, 0));
            // An origin on the axis whose residual underflows (seed 2: 2:158575): −Direction too (it was along the axis).
            var tiny = V(-5e-324, 6);
            IsHit(Raycast.Cast(new Ray2(tiny, V(0, -1)), new Capsule2(V(0, 6), V(-4, 6), 0)), 0, tiny, V(0, 1));
            // From behind the axis along it (seed 13: 13:172385): the near end, not the far end the rounding let through.
            var ray = new Ray3(V(-12, -16, -24), V(24, 24, 24));
            IsHit(Raycast.Cast(ray, new Capsule3(V(-4, -8, -16), V(12, 8, 0), 0)), 8 * Math.Sqrt(3), V(-4, -8, -16), -ray.Direction, 1e-14);
        }

        [Test]
        public void Capsule2()
        {
            var c = new Capsule2(V(0, 0), V(4, 0), 1);
            IsHit(Raycast.Cast(new Ray2(V(2, 3), V(0, -1)), c), 2, V(2, 1), V(0, 1));
            IsHit(Raycast.Cast(new Ray2(V(-3, 0), V(1, 0)), c), 2, V(-1, 0), V(-1, 0));
            Inside(Raycast.Cast(new Ray2(V(2, 0), V(0, 1)), c), V(2, 0));
            Miss(Raycast.Cast(new Ray2(V(-3, 1.5), V(1, 0)), c));
        }
    }
}
