using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Double
{
    /// <summary>Every constructor rejects bad input with an ArgumentException naming the parameter.</summary>
    public class ShapeValidationTests
    {
        private static readonly Vector3D Nan3 = V(double.NaN, 0, 0);
        private static readonly Vector3D Inf3 = V(0, double.PositiveInfinity, 0);
        private static readonly Vector2D Nan2 = V(0, double.NaN);

        private static void Rejects(string param, TestDelegate make) =>
            Assert.That(make, NUnit.Framework.Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo(param));

        [Test]
        public void Segments()
        {
            Rejects("start", () => new Segment3(Nan3, V(0, 0, 0)));
            Rejects("end", () => new Segment3(V(0, 0, 0), Inf3));
            Rejects("start", () => new Segment2(Nan2, V(0, 0)));
            Rejects("end", () => new Segment2(V(0, 0), V(double.NegativeInfinity, 0)));
        }

        [Test]
        public void SpheresAndCircles()
        {
            Rejects("center", () => new Sphere(Nan3, 1));
            Rejects("radius", () => new Sphere(V(0, 0, 0), -1));
            Rejects("radius", () => new Sphere(V(0, 0, 0), double.NaN));
            Rejects("radius", () => new Sphere(V(0, 0, 0), double.PositiveInfinity));
            Rejects("center", () => new Circle(Nan2, 1));
            Rejects("radius", () => new Circle(V(0, 0), -1e-300));
        }

        [Test]
        public void Aabbs()
        {
            Rejects("min", () => new Aabb3(Nan3, V(1, 1, 1)));
            Rejects("max", () => new Aabb3(V(0, 0, 0), Inf3));
            Rejects("min", () => new Aabb3(V(0, 2, 0), V(1, 1, 1)));
            Rejects("length", () => Aabb3.FromOrigin(V(0, 0, 0), -1, 1, 1));
            Rejects("height", () => Aabb3.FromOrigin(V(0, 0, 0), 1, double.NaN, 1));
            Rejects("width", () => Aabb3.FromOrigin(V(0, 0, 0), 1, 1, -2));
            Rejects("origin", () => Aabb3.FromOrigin(Nan3, 1, 1, 1).ToString());
            Rejects("halfExtents", () => Aabb3.FromCenter(V(0, 0, 0), V(1, -1, 1)));
            Rejects("center", () => Aabb3.FromCenter(Nan3, V(1, 1, 1)));
            Rejects("min", () => new Aabb2(V(3, 0), V(1, 1)));
            Rejects("max", () => new Aabb2(V(0, 0), Nan2));
            Rejects("length", () => Aabb2.FromOrigin(V(0, 0), -1, 1));
            Rejects("halfExtents", () => Aabb2.FromCenter(V(0, 0), V(-1, 1)));
        }

        [Test]
        public void Obb3Axes()
        {
            var h = V(1, 1, 1);
            Rejects("center", () => new Obb3(Nan3, V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), h));
            Rejects("halfExtents", () => new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, -1, 1)));
            Rejects("axisX", () => new Obb3(V(0, 0, 0), V(0, 0, 0), V(0, 1, 0), V(0, 0, 1), h));
            Rejects("axisY", () => new Obb3(V(0, 0, 0), V(1, 0, 0), Inf3, V(0, 0, 1), h));
            Rejects("axisZ", () => new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), Nan3, h));
            Rejects("axisY", () => new Obb3(V(0, 0, 0), V(1, 0, 0), V(Math.Sqrt(0.5), Math.Sqrt(0.5), 0), V(0, 0, 1), h));
            Rejects("axisZ", () => new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0.6, 0, 0.8), h));
            Rejects("corners", () => Obb3.FromCorners(new Vector3D[7], V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)));
            Rejects("axisX", () => Obb3.FromCorners(new Vector3D[8], V(0, 0, 0), V(0, 1, 0), V(0, 0, 1)));
        }

        [Test]
        public void Obb3AcceptsAxesWithinTheToleranceAndStoresThemOrthonormal()
        {
            double e = Obb3.AxisTolerance / 4;
            var box = new Obb3(V(0, 0, 0), V(1 + e, e, 0), V(0, 1, e), V(0, 0, 1 - e), V(1, 1, 1));
            Assert.That(box.AxisX.Length, Is.EqualTo(1).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisX, box.AxisY), Is.EqualTo(0).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisX, box.AxisZ), Is.EqualTo(0).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisY, box.AxisZ), Is.EqualTo(0).Within(1e-15));
        }

        [Test]
        public void Obb2()
        {
            Rejects("center", () => new ProximityLib.Double.Obb2(Nan2, V(1, 0), V(1, 1)));
            Rejects("axisX", () => new ProximityLib.Double.Obb2(V(0, 0), V(0, 0), V(1, 1)));
            Rejects("axisX", () => new ProximityLib.Double.Obb2(V(0, 0), Nan2, V(1, 1)));
            Rejects("halfExtents", () => new ProximityLib.Double.Obb2(V(0, 0), V(1, 0), V(1, -1)));
            Rejects("angle", () => new ProximityLib.Double.Obb2(V(0, 0), double.NaN, V(1, 1)));
            Rejects("corners", () => ProximityLib.Double.Obb2.FromCorners(new Vector2D[3], V(1, 0), V(0, 1)));
            Rejects("axisY", () => ProximityLib.Double.Obb2.FromCorners(new Vector2D[4], V(1, 0), V(1, 0)));
        }

        [Test]
        public void DefaultsAreValidPointShapes()
        {
            Assert.That(default(Obb3).AxisX, Is.EqualTo(Vector3D.UnitX));
            Assert.That(default(Obb3).AxisZ, Is.EqualTo(Vector3D.UnitZ));
            Assert.That(default(ProximityLib.Double.Obb2).AxisY, Is.EqualTo(Vector2D.UnitY));
            Assert.That(ClosestDistance.Between(default(Segment3), default(Sphere)).Distance, Is.EqualTo(0));
            Assert.That(ClosestDistance.Between(default(Aabb3), V(0, 0, 2)).Distance, Is.EqualTo(2));
        }
    }
}
