using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Scenes.Picker;
using F = ProximityLib;

namespace ProximityTests.Scenes
{
    public class PickerOptionsTests
    {
        [Test]
        public void ReadsOptionsAndTwoShapesInAnyOrder()
        {
            var o = PickerOptions.Parse(new[] { "sphere:0,0,0,1", "--svg", "a.svg", "aabb:2,0,0,3,1,1", "--proximity" });
            Assert.That(o.Help, Is.False);
            Assert.That(o.Proximity, Is.True);
            Assert.That(o.SvgFile, Is.EqualTo("a.svg"));
            Assert.That(((F.Sphere)o.First!).Radius, Is.EqualTo(1f));
            Assert.That(((F.Aabb3)o.Second!).Max, Is.EqualTo(new Vector3(3, 1, 1)));
            var plain = PickerOptions.Parse(new[] { "point:0,0", "circle:3,0,1" });
            Assert.That(plain.Proximity, Is.False);
            Assert.That(plain.SvgFile, Is.Null);
        }

        [TestCase("--help")]
        [TestCase("-h")]
        [TestCase("sphere:0,0,0,1 --help")]
        [TestCase("--bogus --help")]
        public void HelpWinsOverEverythingElse(string args)
        {
            Assert.That(PickerOptions.Parse(args.Split(' ')).Help, Is.True);
        }

        [TestCase("--bogus", "unknown option '--bogus'")]
        [TestCase("--bogus sphere:0,0,0,1 aabb:2,0,0,3,1,1", "unknown option '--bogus'")]
        [TestCase("sphere:0,0,0,1 aabb:2,0,0,3,1,1 --svg", "'--svg' needs a file name")]
        [TestCase("sphere:0,0,0,1", "picker needs two shapes (got 1)")]
        [TestCase("point:0,0 point:1,1 point:2,2", "picker needs two shapes (got 3)")]
        [TestCase("sphere:0,0,0,1 circle:0,0,1", "is 3D and 'circle:0,0,1' is 2D")]
        [TestCase("sphere:0,0,0,-1 circle:0,0,1", "radius")]
        public void BadArgumentsGetOneLineNamingTheProblem(string args, string message)
        {
            Assert.That(() => PickerOptions.Parse(args.Split(' ')),
                Throws.InstanceOf<FormatException>().With.Message.Contains(message).And.Message.Not.Contains("\n"));
        }

        [Test]
        public void TheHelpListsEveryShapeFormWithAWorkingExampleAndStatesTheUnits()
        {
            var help = PickerOptions.HelpLines();
            Assert.That(ShapeSpec.Forms, Has.Count.EqualTo(20));
            foreach (var form in ShapeSpec.Forms)
            {
                Assert.That(help.Any(l => l.Contains(form.Syntax) && l.Contains(form.Meaning)), form.Syntax);
                Assert.That(help.Any(l => l.Trim() == "e.g. " + form.Example), form.Example);
                var shape = ShapeSpec.Parse(form.Example);
                Assert.That(ShapeSpec.Dimension(shape), Is.EqualTo(form.Syntax.IndexOf("z", StringComparison.OrdinalIgnoreCase) >= 0 ? 3 : 2), form.Example);
            }
            Assert.That(help, Has.Some.Contains("radians"));
            Assert.That(help, Has.Some.Contains("x,y,z,w"));
        }

        [Test]
        public void TheFormsExamplesDescribeWhatTheySay()
        {
            var box2 = (F.Obb2)ShapeSpec.Parse(ShapeSpec.Forms.Single(f => f.Syntax == "obb:cx,cy,angle,hx,hy").Example);
            // 0.7853982 rad is 45°: the first axis points along (1, 1)/√2.
            Assert.That(box2.AxisX.X, Is.EqualTo(MathF.Sqrt(0.5f)).Within(1e-6f));
            Assert.That(box2.AxisX.Y, Is.EqualTo(MathF.Sqrt(0.5f)).Within(1e-6f));
            var box3 = (F.Obb3)ShapeSpec.Parse(ShapeSpec.Forms.Single(f => f.Kind == "obb" && f.Count == 10).Example);
            // (0, 0, sin 22.5°, cos 22.5°) in x,y,z,w order is 45° about z.
            Assert.That(box3.AxisX.X, Is.EqualTo(MathF.Sqrt(0.5f)).Within(1e-6f));
            Assert.That(box3.AxisX.Y, Is.EqualTo(MathF.Sqrt(0.5f)).Within(1e-6f));
            Assert.That(box3.AxisZ, Is.EqualTo(Vector3.UnitZ));
        }
    }
}
