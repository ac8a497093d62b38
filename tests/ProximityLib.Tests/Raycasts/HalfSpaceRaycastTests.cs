using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    public class HalfSpaceRaycastTests
    {
        private static readonly HalfSpace Floor = HalfSpace.FromPointNormal(V(0, 0, 1), V(0, 0, 1));

        [Test]
        public void HitsParallelLeavingInsideOnTheBoundary()
        {
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 5), V(0, 0, -1)), Floor), 4, V(0, 0, 1), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 3), V(1, 0, -1)), Floor), 2 * Math.Sqrt(2), V(2, 0, 1), V(0, 0, 1), 1e-15);
            Miss(Raycast.Cast(new Ray3(V(0, 0, 5), V(1, 0, 0)), Floor));
            Miss(Raycast.Cast(new Ray3(V(0, 0, 5), V(0, 0, 1)), Floor));
            Inside(Raycast.Cast(new Ray3(V(0, 0, 0), V(0, 0, 1)), Floor), V(0, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(3, 3, 1), V(1, 0, 0)), Floor), 0, V(3, 3, 1), V(0, 0, 1));
        }

        [Test]
        public void GrazingBeyondTheDoubleRangeIsAMiss()
        {
            // Approach rate 2^-1074: the hit is 2^1074 away, beyond the double range.
            var h = Raycast.Cast(new Ray3(V(0, 0, 2), V(1, 0, -double.Epsilon)), Floor);
            Sane(h);
            Miss(h);
        }

        [Test]
        public void HalfPlanes()
        {
            var h = HalfPlane.FromPointNormal(V(2, 0), V(1, 0));
            IsHit(Raycast.Cast(new Ray2(V(5, 1), V(-1, 0)), h), 3, V(2, 1), V(1, 0));
            Inside(Raycast.Cast(new Ray2(V(0, 1), V(-1, 0)), h), V(0, 1));
            Miss(Raycast.Cast(new Ray2(V(5, 1), V(0, 1)), h));
        }
    }
}
