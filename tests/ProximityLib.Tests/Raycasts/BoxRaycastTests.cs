using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    public class BoxRaycastTests
    {
        private static readonly Aabb3 Cube = new Aabb3(V(0, 0, 0), V(2, 2, 2));

        [Test]
        public void FaceEdgeCornerAndAlongAFace()
        {
            IsHit(Raycast.Cast(new Ray3(V(-1, 1, 1), V(1, 0, 0)), Cube), 1, V(0, 1, 1), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 7), V(0, 0, -1)), Cube), 5, V(1, 1, 2), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(-1, 0, 1), V(1, 0, 0)), Cube), 1, V(0, 0, 1), V(-1, 0, 0));       // along the face y = 0
            IsHit(Raycast.Cast(new Ray3(V(-1, -1, 1), V(1, 1, 0)), Cube), Math.Sqrt(2), V(0, 0, 1), V(-1, 0, 0), 1e-15); // through an edge
            IsHit(Raycast.Cast(new Ray3(V(-1, -1, -1), V(1, 1, 1)), Cube), Math.Sqrt(3), V(0, 0, 0), V(-1, 0, 0), 1e-15);
            IsHit(Raycast.Cast(new Ray3(V(-1, 1, 1), V(1, 1, 0)), Cube), Math.Sqrt(2), V(0, 2, 1), V(-1, 0, 0), 1e-15); // grazes the edge only
        }

        [Test]
        public void ParallelMissesInsideAndOnTheSurface()
        {
            Miss(Raycast.Cast(new Ray3(V(-1, 3, 1), V(1, 0, 0)), Cube));
            Miss(Raycast.Cast(new Ray3(V(-1, 1, 1), V(-1, 0, 0)), Cube));
            Miss(Raycast.Cast(new Ray3(V(-1, -1e-300, 1), V(1, 0, 0)), Cube));
            Inside(Raycast.Cast(new Ray3(V(1, 1, 1), V(1, 0, 0)), Cube), V(1, 1, 1));
            IsHit(Raycast.Cast(new Ray3(V(2, 1, 1), V(1, 0, 0)), Cube), 0, V(2, 1, 1), V(1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 0), V(1, 1, 1)), Cube), 0, V(0, 0, 0), V(-1, 0, 0));
        }

        [Test]
        public void FlatBoxFacesTheRay()
        {
            var plate = new Aabb3(V(0, 0, 0), V(2, 2, 0));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 5), V(0, 0, -1)), plate), 5, V(1, 1, 0), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, -5), V(0, 0, 1)), plate), 5, V(1, 1, 0), V(0, 0, -1));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 0), V(0, 0, -1)), plate), 0, V(1, 1, 0), V(0, 0, 1));
        }

        [Test]
        public void Obb3InItsFrame()
        {
            var box = new Obb3(V(0, 0, 0), V(0, 1, 0), V(-1, 0, 0), V(0, 0, 1), V(1, 2, 3));
            IsHit(Raycast.Cast(new Ray3(V(-5, 0, 0), V(1, 0, 0)), box), 3, V(-2, 0, 0), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(0, 5, 0), V(0, -1, 0)), box), 4, V(0, 1, 0), V(0, 1, 0));
            Inside(Raycast.Cast(new Ray3(V(0, 0, 0), V(0, -1, 0)), box), V(0, 0, 0));
        }

        [Test]
        public void Boxes2D()
        {
            var r = new Aabb2(V(0, 0), V(2, 2));
            IsHit(Raycast.Cast(new Ray2(V(-1, 1), V(1, 1)), r), Math.Sqrt(2), V(0, 2), V(-1, 0), 1e-15); // grazes a corner
            IsHit(Raycast.Cast(new Ray2(V(3, 1), V(-1, 0)), r), 1, V(2, 1), V(1, 0));
            Inside(Raycast.Cast(new Ray2(V(1, 1), V(-1, 0)), r), V(1, 1));
            Miss(Raycast.Cast(new Ray2(V(-1, 3), V(1, 0)), r));
            var o = new Obb2(V(0, 0), V(0, 1), V(1, 2));
            IsHit(Raycast.Cast(new Ray2(V(-5, 0), V(1, 0)), o), 3, V(-2, 0), V(-1, 0));
            IsHit(Raycast.Cast(new Ray2(V(0, -5), V(0, 1)), o), 4, V(0, -1), V(0, -1));
        }
    }
}
