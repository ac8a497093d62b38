using System.Numerics;
using NUnit.Framework;
using ProximityLib;
using ProximityLib.Scenes;

namespace ProximityTests.Scenes
{
    public class ShapeSizesTests
    {
        [TestCase(2.5f, 2.5f)]
        [TestCase(0f, 0f)]
        [TestCase(-0f, 0f)]
        [TestCase(-1f, 0f)]
        [TestCase(float.NegativeInfinity, 0f)]
        [TestCase(float.NaN, 0f)]
        [TestCase(float.PositiveInfinity, float.MaxValue)]
        public void NonNegative(float size, float expected) => Assert.That(ShapeSizes.NonNegative(size), Is.EqualTo(expected));

        [TestCase(0.5f, -3f, 1.5f)]
        [TestCase(-1f, 2f, 0f)]
        [TestCase(1f, float.NaN, 0f)]
        [TestCase(1e38f, 10f, float.MaxValue)]
        [TestCase(float.PositiveInfinity, 0f, 0f)]
        public void Scaled(float size, float scale, float expected) => Assert.That(ShapeSizes.Scaled(size, scale), Is.EqualTo(expected));

        [Test]
        public void ClampedSizesMakeValidShapes()
        {
            Assert.DoesNotThrow(() => new Sphere(Vector3.Zero, ShapeSizes.Scaled(-0.5f, 2)));
            Assert.DoesNotThrow(() => new Obb3(Vector3.One, Quaternion.Identity, new Vector3(ShapeSizes.Scaled(float.NaN, 1), ShapeSizes.Scaled(1e38f, 1e3f), 1)));
        }
    }
}
