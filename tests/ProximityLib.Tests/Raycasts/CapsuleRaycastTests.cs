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
