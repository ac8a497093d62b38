using System;
using NUnit.Framework;
using ProximityLib.Double;

namespace ProximityTests.Raycasts
{
    /// <summary>Assertions on ray hits shared by the ray-cast tests.</summary>
    internal static class Hits
    {
        public static Vector3D V(double x, double y, double z) => new Vector3D(x, y, z);
        public static Vector2D V(double x, double y) => new Vector2D(x, y);

        public static void IsHit(RayHit3 h, double t, Vector3D point, Vector3D normal, double tol = 0, bool inside = false)
        {
            Assert.That(h.Hit, Is.True, h.ToString());
            Assert.That(h.StartsInside, Is.EqualTo(inside), h.ToString());
            Assert.That(h.T, Is.EqualTo(t).Within(tol), h.ToString());
            Assert.That((h.Point - point).Length, Is.LessThanOrEqualTo(tol), h.ToString());
            Assert.That((h.Normal - normal).Length, Is.LessThanOrEqualTo(tol), h.ToString());
        }

        public static void IsHit(RayHit2 h, double t, Vector2D point, Vector2D normal, double tol = 0, bool inside = false)
        {
            Assert.That(h.Hit, Is.True, h.ToString());
            Assert.That(h.StartsInside, Is.EqualTo(inside), h.ToString());
            Assert.That(h.T, Is.EqualTo(t).Within(tol), h.ToString());
            Assert.That((h.Point - point).Length, Is.LessThanOrEqualTo(tol), h.ToString());
            Assert.That((h.Normal - normal).Length, Is.LessThanOrEqualTo(tol), h.ToString());
        }

        public static void Inside(RayHit3 h, Vector3D origin) => IsHit(h, 0, origin, default, 0, true);
        public static void Inside(RayHit2 h, Vector2D origin) => IsHit(h, 0, origin, default, 0, true);

        public static void Miss(RayHit3 h)
        {
            Assert.That(h.Hit, Is.False, h.ToString());
            Assert.That(double.IsPositiveInfinity(h.T) && h.Point == default && h.Normal == default && !h.StartsInside, h.ToString());
        }

        public static void Miss(RayHit2 h)
        {
            Assert.That(h.Hit, Is.False, h.ToString());
            Assert.That(double.IsPositiveInfinity(h.T) && h.Point == default && h.Normal == default && !h.StartsInside, h.ToString());
        }

        /// <summary>Every field finite (T may be +∞ only on a miss), normals unit or zero.</summary>
        public static void Sane(RayHit3 h)
        {
            Assert.That(h.Point.IsFinite && h.Normal.IsFinite, h.ToString());
            Assert.That(h.Hit ? double.IsFinite(h.T) && h.T >= 0 : double.IsPositiveInfinity(h.T), h.ToString());
            double n = h.Normal.Length;
            Assert.That(n == 0 || Math.Abs(n - 1) < 1e-15, h.ToString());
        }

        public static void Sane(RayHit2 h)
        {
            Assert.That(h.Point.IsFinite && h.Normal.IsFinite, h.ToString());
            Assert.That(h.Hit ? double.IsFinite(h.T) && h.T >= 0 : double.IsPositiveInfinity(h.T), h.ToString());
            double n = h.Normal.Length;
            Assert.That(n == 0 || Math.Abs(n - 1) < 1e-15, h.ToString());
        }

        /// <summary>The hit of the 2^k-scaled configuration is the 2^k-scaled hit, bit for bit.</summary>
        public static void Scales(RayHit3 h, RayHit3 scaled, double k)
        {
            Assert.That(scaled.Hit, Is.EqualTo(h.Hit), $"{h} vs {scaled}");
            if (!h.Hit) return;
            Assert.That(scaled.T, Is.EqualTo(h.T * k), $"{h} vs {scaled}");
            Assert.That(scaled.Point, Is.EqualTo(h.Point * k), $"{h} vs {scaled}");
            Assert.That(scaled.Normal, Is.EqualTo(h.Normal), $"{h} vs {scaled}");
            Assert.That(scaled.StartsInside, Is.EqualTo(h.StartsInside));
        }

        public static void Scales(RayHit2 h, RayHit2 scaled, double k)
        {
            Assert.That(scaled.Hit, Is.EqualTo(h.Hit), $"{h} vs {scaled}");
            if (!h.Hit) return;
            Assert.That(scaled.T, Is.EqualTo(h.T * k), $"{h} vs {scaled}");
            Assert.That(scaled.Point, Is.EqualTo(h.Point * k), $"{h} vs {scaled}");
            Assert.That(scaled.Normal, Is.EqualTo(h.Normal), $"{h} vs {scaled}");
            Assert.That(scaled.StartsInside, Is.EqualTo(h.StartsInside));
        }
    }
}
