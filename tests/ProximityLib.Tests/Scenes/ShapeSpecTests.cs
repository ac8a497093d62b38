using System;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Scenes.Picker;
using F = ProximityLib;

namespace ProximityTests.Scenes
{
    public class ShapeSpecTests
    {
        [Test]
        public void EveryKindParses()
        {
            Assert.That(ShapeSpec.Parse("point:1,2"), Is.EqualTo(new Vector2(1, 2)));
            Assert.That(ShapeSpec.Parse("point:1,2,3"), Is.EqualTo(new Vector3(1, 2, 3)));
            Assert.That(((F.Segment3)ShapeSpec.Parse("segment:0,0,0,1,2,3")).End, Is.EqualTo(new Vector3(1, 2, 3)));
            Assert.That(((F.Segment2)ShapeSpec.Parse("segment:0,0,1,2")).End, Is.EqualTo(new Vector2(1, 2)));
            Assert.That(((F.Circle)ShapeSpec.Parse("circle:1,1,0.5")).Radius, Is.EqualTo(0.5f));
            Assert.That(((F.Sphere)ShapeSpec.Parse("Sphere: 0, 0, 0, 2")).Radius, Is.EqualTo(2f));
            Assert.That(((F.Aabb3)ShapeSpec.Parse("aabb:0,0,0,1,2,3")).Max, Is.EqualTo(new Vector3(1, 2, 3)));
            Assert.That(((F.Aabb2)ShapeSpec.Parse("aabb:0,0,1,2")).Max, Is.EqualTo(new Vector2(1, 2)));
            Assert.That(((F.Obb2)ShapeSpec.Parse("obb:0,0,0,1,2")).HalfExtents, Is.EqualTo(new Vector2(1, 2)));
            Assert.That(((F.Obb3)ShapeSpec.Parse("obb:0,0,0,0,0,0,1,1,2,3")).HalfExtents, Is.EqualTo(new Vector3(1, 2, 3)));
            Assert.That(ShapeSpec.Dimension(ShapeSpec.Parse("circle:1,1,0.5")), Is.EqualTo(2));
            Assert.That(ShapeSpec.Dimension(ShapeSpec.Parse("obb:0,0,0,0,0,0,1,1,2,3")), Is.EqualTo(3));
        }

        [TestCase("sphere", "expected kind:numbers")]
        [TestCase("cube:1,2,3", "unknown kind 'cube'")]
        [TestCase("sphere:0,0,zero,1", "'zero' is not a finite number")]
        [TestCase("sphere:0,0,0,NaN", "'NaN' is not a finite number")]
        [TestCase("sphere:0,0,1", "sphere takes 4 numbers, not 3")]
        [TestCase("circle:0,0,-1", "radius")]
        [TestCase("aabb:1,1,0,0", "min")]
        [TestCase("obb:0,0,0,0,0,0,0,1,1,1", "rotation")]
        public void BadSpecsNameTheProblem(string spec, string message)
        {
            Assert.That(() => ShapeSpec.Parse(spec), Throws.InstanceOf<FormatException>().With.Message.Contains(message).And.Message.Contains(spec));
        }
    }
}
