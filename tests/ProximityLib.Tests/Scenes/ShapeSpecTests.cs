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

        [Test]
        public void ParsesTheNewShapes()
        {
            var line = (F.Line3)ShapeSpec.Parse("line:0,2,0,3,0,0");
            Assert.That(line.Origin, Is.EqualTo(new Vector3(0, 2, 0)));
            Assert.That(line.Direction, Is.EqualTo(new Vector3(1, 0, 0)), "normalised");
            Assert.That(((F.Line2)ShapeSpec.Parse("line:0,2,0,-5")).Direction, Is.EqualTo(new Vector2(0, -1)));
            Assert.That(((F.Ray3)ShapeSpec.Parse("ray:-3,0,0,1,0,0")).Origin, Is.EqualTo(new Vector3(-3, 0, 0)));
            Assert.That(((F.Ray2)ShapeSpec.Parse("ray:-3,0,2,0")).Direction, Is.EqualTo(new Vector2(1, 0)));
            var c3 = (F.Capsule3)ShapeSpec.Parse("capsule:0,0,0,0,2,0,0.5");
            Assert.That((c3.End, c3.Radius), Is.EqualTo((new Vector3(0, 2, 0), 0.5f)));
            Assert.That(((F.Capsule2)ShapeSpec.Parse("capsule:0,0,2,0,0.25")).Radius, Is.EqualTo(0.25f));
            Assert.That(((F.Triangle3)ShapeSpec.Parse("triangle:0,0,0,2,0,0,0,2,0")).C, Is.EqualTo(new Vector3(0, 2, 0)));
            Assert.That(((F.Triangle2)ShapeSpec.Parse("triangle:0,0,2,0,0,2")).B, Is.EqualTo(new Vector2(2, 0)));
            var h = (F.HalfSpace)ShapeSpec.Parse("halfspace:0,2,0,3");
            Assert.That((h.Normal, h.Offset), Is.EqualTo((new Vector3(0, 1, 0), 1.5f)), "the normal is normalised, the offset with it");
            Assert.That(((F.HalfPlane)ShapeSpec.Parse("halfplane:0,1,0")).Normal, Is.EqualTo(new Vector2(0, 1)));
            foreach (var (spec, dim) in new[] { ("line:0,2,1,0", 2), ("ray:0,0,1,0", 2), ("capsule:0,0,2,0,1", 2), ("triangle:0,0,2,0,0,2", 2), ("halfplane:0,1,0", 2),
                                                ("line:0,2,0,1,0,0", 3), ("ray:0,0,0,1,0,0", 3), ("capsule:0,0,0,0,2,0,1", 3), ("triangle:0,0,0,2,0,0,0,2,0", 3), ("halfspace:0,1,0,0", 3) })
                Assert.That(ShapeSpec.Dimension(ShapeSpec.Parse(spec)), Is.EqualTo(dim), spec);
        }

        [TestCase("line:0,0,0,0", "direction")]
        [TestCase("ray:0,0,0,1,0", "ray takes 4 or 6 numbers, not 5")]
        [TestCase("capsule:0,0,2,0,-1", "radius")]
        [TestCase("halfspace:0,0,0,1", "normal")]
        [TestCase("plane:0,1,0", "unknown kind 'plane' (point, segment, circle, sphere, aabb, obb, line, ray, capsule, triangle, halfplane, halfspace)")]
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
