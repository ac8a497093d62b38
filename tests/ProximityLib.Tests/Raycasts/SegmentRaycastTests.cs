using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    /// <summary>Zero-thickness targets: points and segments (3D, hit when passed through), and the 2D walls: segments, lines, rays.</summary>
    public class SegmentRaycastTests
    {
        private static readonly Ray3 AlongX = new Ray3(V(0, 0, 0), V(1, 0, 0));
        private static readonly Ray2 AlongX2 = new Ray2(V(0, 0), V(1, 0));

        [Test]
        public void Points()
        {
            var toward = new Ray3(V(0, 0, 0), V(3, 4, 0));
            var h = Raycast.Cast(toward, V(3, 4, 0));
            IsHit(h, 5, V(3, 4, 0), -toward.Direction, 1e-15);
            Assert.That(h.Point, Is.EqualTo(V(3, 4, 0)));
            Miss(Raycast.Cast(toward, V(3, 4.001, 0)));
            Miss(Raycast.Cast(new Ray3(V(0, 0, 0), V(-3, -4, 0)), V(3, 4, 0)));
            IsHit(Raycast.Cast(AlongX, V(0, 0, 0)), 0, V(0, 0, 0), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray2(V(1, 1), V(1, 1)), V(5, 5)), 4 * System.Math.Sqrt(2), V(5, 5), -new Ray2(V(1, 1), V(1, 1)).Direction, 1e-14);
            Miss(Raycast.Cast(AlongX2, V(5, 1e-3)));
        }

        [Test]
        public void Segments3D()
        {
            IsHit(Raycast.Cast(AlongX, new Segment3(V(1, -1, 0), V(1, 1, 0))), 1, V(1, 0, 0), V(-1, 0, 0));
            Miss(Raycast.Cast(AlongX, new Segment3(V(1, -1, 1e-3), V(1, 1, 1e-3))));
            IsHit(Raycast.Cast(AlongX, new Segment3(V(4, 0, 0), V(2, 0, 0))), 2, V(2, 0, 0), V(-1, 0, 0));     // along the ray
            IsHit(Raycast.Cast(AlongX, new Segment3(V(0, -1, 0), V(0, 1, 0))), 0, V(0, 0, 0), V(-1, 0, 0));   // origin on it
            IsHit(Raycast.Cast(AlongX, new Segment3(V(1, 0, 0), V(1, 1, 0))), 1, V(1, 0, 0), V(-1, 0, 0));    // an endpoint
            Miss(Raycast.Cast(AlongX, new Segment3(V(-1, -1, 0), V(-1, 1, 0))));
            IsHit(Raycast.Cast(AlongX, new Segment3(V(3, 0, 0), V(3, 0, 0))), 3, V(3, 0, 0), V(-1, 0, 0));    // a point
        }

        [Test]
        public void Segments2DAreWalls()
        {
            IsHit(Raycast.Cast(AlongX2, new Segment2(V(1, -1), V(1, 1))), 1, V(1, 0), V(-1, 0));
            IsHit(Raycast.Cast(new Ray2(V(3, 0), V(-1, 0)), new Segment2(V(1, -1), V(1, 1))), 2, V(1, 0), V(1, 0));
            IsHit(Raycast.Cast(AlongX2, new Segment2(V(1, 0), V(1, 1))), 1, V(1, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Segment2(V(1, 0.5), V(1, 1))));
            IsHit(Raycast.Cast(AlongX2, new Segment2(V(4, 0), V(2, 0))), 2, V(2, 0), V(-1, 0));
            IsHit(Raycast.Cast(AlongX2, new Segment2(V(-1, 0), V(1, 0))), 0, V(0, 0), V(-1, 0));
            IsHit(Raycast.Cast(AlongX2, new Segment2(V(0, -1), V(0, 1))), 0, V(0, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Segment2(V(-1, -1), V(-1, 1))));
            // A polyline's shared vertex on the ray: both segments see it.
            Assert.That(Raycast.Cast(AlongX2, new Segment2(V(1, -1), V(1, 0))).Hit && Raycast.Cast(AlongX2, new Segment2(V(1, 0), V(2, 1))).Hit);
        }

        [Test]
        public void LinesAndRays2D()
        {
            IsHit(Raycast.Cast(AlongX2, new Line2(V(3, 0), V(0, 1))), 3, V(3, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Line2(V(0, 1), V(1, 0))));
            IsHit(Raycast.Cast(AlongX2, new Line2(V(5, 0), V(1, 0))), 0, V(0, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Line2(V(-3, 0), V(1, 1))));
            IsHit(Raycast.Cast(AlongX2, new Ray2(V(3, -1), V(0, 1))), 3, V(3, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Ray2(V(3, 1), V(0, 1))));
            IsHit(Raycast.Cast(AlongX2, new Ray2(V(2, 0), V(1, 0))), 2, V(2, 0), V(-1, 0));
            IsHit(Raycast.Cast(AlongX2, new Ray2(V(2, 0), V(-1, 0))), 0, V(0, 0), V(-1, 0));
            Miss(Raycast.Cast(AlongX2, new Ray2(V(-2, 0), V(-1, 0))));
            IsHit(Raycast.Cast(AlongX2, new Ray2(V(-2, 0), V(1, 0))), 0, V(0, 0), V(-1, 0));
        }
    }
}
