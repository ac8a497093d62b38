using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    public class TriangleRaycastTests
    {
        private static readonly Triangle3 Tri = new Triangle3(V(0, 0, 0), V(4, 0, 0), V(0, 4, 0));

        [Test]
        public void TwoSided()
        {
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 5), V(0, 0, -1)), Tri), 5, V(1, 1, 0), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, -3), V(0, 0, 1)), Tri), 3, V(1, 1, 0), V(0, 0, -1));
            Miss(Raycast.Cast(new Ray3(V(1, 1, 5), V(0, 0, 1)), Tri));
            Miss(Raycast.Cast(new Ray3(V(3, 3, 5), V(0, 0, -1)), Tri));
        }

        [Test]
        public void EdgesAndVerticesBelongToTheTriangle()
        {
            IsHit(Raycast.Cast(new Ray3(V(2, 2, 5), V(0, 0, -1)), Tri), 5, V(2, 2, 0), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(0, 0, 5), V(0, 0, -1)), Tri), 5, V(0, 0, 0), V(0, 0, 1));
            IsHit(Raycast.Cast(new Ray3(V(4, 0, -1), V(0, 0, 1)), Tri), 1, V(4, 0, 0), V(0, 0, -1));
            Miss(Raycast.Cast(new Ray3(V(2.0000000000000004, 2, 5), V(0, 0, -1)), Tri));
        }

        [Test]
        public void ObliqueHit()
        {
            var h = Raycast.Cast(new Ray3(V(-1, 1, 2), V(1, 0, -1)), Tri);
            IsHit(h, 2 * Math.Sqrt(2), V(1, 1, 0), V(0, 0, 1), 1e-15);
        }

        [Test]
        public void RayInThePlaneSeesTheTriangleEdgeOn()
        {
            IsHit(Raycast.Cast(new Ray3(V(-2, 1, 0), V(1, 0, 0)), Tri), 2, V(0, 1, 0), V(-1, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 0), V(1, 0, 0)), Tri), 0, V(1, 1, 0), V(0, 0, 1));
            Miss(Raycast.Cast(new Ray3(V(-2, 5, 0), V(1, 0, 0)), Tri));
            Miss(Raycast.Cast(new Ray3(V(-2, 1, 1), V(1, 0, 0)), Tri)); // parallel, above
        }

        [Test]
        public void DegenerateTrianglesAreSegmentsAndPoints()
        {
            var line = new Triangle3(V(0, 0, 0), V(2, 0, 0), V(4, 0, 0));
            IsHit(Raycast.Cast(new Ray3(V(1, -3, 0), V(0, 1, 0)), line), 3, V(1, 0, 0), V(0, -1, 0));
            Miss(Raycast.Cast(new Ray3(V(1, -3, 0.5), V(0, 1, 0)), line));
            var point = new Triangle3(V(1, 1, 1), V(1, 1, 1), V(1, 1, 1));
            IsHit(Raycast.Cast(new Ray3(V(1, 1, 5), V(0, 0, -1)), point), 4, V(1, 1, 1), V(0, 0, 1));
        }

        /// <summary>
        /// Watertightness: a fan of triangles with irrational vertices around a shared center; rays from random origins
        /// through points on the shared edges (and through the center) must hit at least one triangle, and random rays
        /// through the fan's inside must hit one.
        /// </summary>
        [Test]
        public void RaysThroughSharedEdgesHitAtLeastOneTriangleOfAFan()
        {
            var r = new Random(12);
            const int n = 13;
            var center = V(0.1, -0.2, 0.3);
            var rim = new Vector3D[n];
            var tilt = V(0.3, -0.2, 1);
            var u = Vector3D.Cross(tilt, V(1, 0, 0));
            u /= u.Length;
            var v = Vector3D.Cross(tilt, u);
            v /= v.Length;
            for (int i = 0; i < n; i++)
            {
                double a = 2 * Math.PI * i / n + 0.1 * Math.Sin(i);
                rim[i] = center + u * (Math.Cos(a) * (1 + 0.2 * Math.Cos(3 * i))) + v * Math.Sin(a);
            }
            var fan = new Triangle3[n];
            for (int i = 0; i < n; i++) fan[i] = new Triangle3(center, rim[i], rim[(i + 1) % n]);
            int misses = 0, cases = 0;
            for (int k = 0; k < 4000; k++)
            {
                int i = r.Next(n);
                double s = k % 50 == 0 ? 0 : r.NextDouble() * 0.9;
                var target = k % 3 == 0 ? center + (rim[i] - center) * s                           // on a shared edge
                    : center + ((rim[i] - center) * r.NextDouble() + (rim[(i + 1) % n] - center) * r.NextDouble()) * 0.45;
                var origin = target + V(r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2) * Math.Pow(2, r.Next(-20, 6));
                if (origin == target) continue;
                var ray = new Ray3(origin, target - origin);
                bool any = false;
                foreach (var t in fan) any |= Raycast.Cast(ray, t).Hit;
                cases++;
                if (!any) misses++;
            }
            Assert.That(misses, Is.Zero, $"{misses} of {cases} rays slipped through the fan");
        }

        [Test]
        public void Triangle2IsASolid()
        {
            var t = new Triangle2(V(0, 0), V(4, 0), V(0, 4));
            var cw = new Triangle2(V(0, 0), V(0, 4), V(4, 0));
            foreach (var tri in new[] { t, cw })
            {
                IsHit(Raycast.Cast(new Ray2(V(-2, 1), V(1, 0)), tri), 2, V(0, 1), V(-1, 0));
                IsHit(Raycast.Cast(new Ray2(V(3, 3), V(-1, -1)), tri), Math.Sqrt(2), V(2, 2), V(Math.Sqrt(0.5), Math.Sqrt(0.5)), 1e-15);
                Inside(Raycast.Cast(new Ray2(V(1, 1), V(1, 0)), tri), V(1, 1));
                IsHit(Raycast.Cast(new Ray2(V(2, 0), V(0, -1)), tri), 0, V(2, 0), V(0, -1));
                Miss(Raycast.Cast(new Ray2(V(5, 5), V(1, 0)), tri));
                Miss(Raycast.Cast(new Ray2(V(-1, -1), V(1, 0)), tri));
                IsHit(Raycast.Cast(new Ray2(V(-1, 0), V(1, 0)), tri), 1, V(0, 0), V(-1, 0)); // along an edge
            }
            var flat = new Triangle2(V(0, 0), V(2, 0), V(4, 0));
            IsHit(Raycast.Cast(new Ray2(V(1, -3), V(0, 1)), flat), 3, V(1, 0), V(0, -1));
        }
    }
}
