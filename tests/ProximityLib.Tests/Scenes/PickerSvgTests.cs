using System;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Text.RegularExpressions;
using NUnit.Framework;
using ProximityLib.Scenes.Picker;

namespace ProximityTests.Scenes
{
    public class PickerSvgTests
    {
        private static double[] Numbers(string svg, string element, string attribute) =>
            Regex.Matches(svg, $"<{element} [^>]*{attribute}=\"([^\"]+)\"").Select(m => m.Groups[1].Value).ToArray() is var v && v.Length > 0
                ? v[0].Split(' ', ',').Select(x => double.Parse(x, CultureInfo.InvariantCulture)).ToArray()
                : Array.Empty<double>();

        [Test]
        public void ClosestDistanceDrawsTheYellowLineBetweenTheWitnessesAndTheOrangeText()
        {
            var scene = new PickerScene(PickerMode.ClosestDistance,
                new Primitive(PrimitiveKind.Round, 3, new Vector3(-2, 0, 0)), new Primitive(PrimitiveKind.Point, 3, new Vector3(2, 0, 0)));
            string svg = PickerSvg.Render(scene);
            Assert.That(svg, Does.Contain(">Minimum distance: 3.000<"));
            Assert.That(svg, Does.Contain("fill=\"#ff8c00\""));
            Assert.That(Regex.Matches(svg, "<polygon").Count, Is.EqualTo(1), "the sphere's outline");
            Assert.That(Regex.Matches(svg, "<circle").Count, Is.EqualTo(1), "the point");
            double x1 = Numbers(svg, "line", "x1")[0], x2 = Numbers(svg, "line", "x2")[0];
            double y1 = Numbers(svg, "line", "y1")[0], y2 = Numbers(svg, "line", "y2")[0];
            // From the sphere's surface (x = -1) to the point (x = 2): horizontal, left to right, 3 of the 4 world units between the extremes.
            Assert.That(y1, Is.EqualTo(y2));
            Assert.That(x2 - x1, Is.GreaterThan(0));
            double cx = Numbers(svg, "circle", "cx")[0];
            Assert.That(x2, Is.EqualTo(cx).Within(0.01), "the line ends at the point");
        }

        [Test]
        public void ProximityQueryShowsTheVerdictAndTheCollisionColour()
        {
            var scene = new PickerScene(PickerMode.ProximityQuery,
                new Primitive(PrimitiveKind.Obb, 2, Vector3.Zero, 0.7f), new Primitive(PrimitiveKind.Round, 2, new Vector3(0.5f, 0, 0)));
            string svg = PickerSvg.Render(scene);
            Assert.That(svg, Does.Contain(">Colliding<"));
            Assert.That(svg, Does.Not.Contain("<line"));
            Assert.That(Regex.Matches(svg, "fill=\"#e64545\"").Count, Is.EqualTo(3), "both shapes and the text turn red");
            // A turned 2D box projects to its own four corners.
            Assert.That(Numbers(svg, "polygon", "points").Length, Is.EqualTo(8));
        }

        [Test]
        public void TheNewShapesAreOutlined()
        {
            // A capsule (two end circles' hull), a triangle and a half-plane strip as polygons; a line as a two-point polygon.
            var view = new PickerView(PickerMode.ClosestDistance, 0.5f, new Vector3(0, 0, 0), new Vector3(0, 0.5f, 0), false);
            string svg = PickerSvg.Render(ShapeSpec.Parse("halfplane:0,1,0"), ShapeSpec.Parse("capsule:0,1,2,1,0.5"), view);
            Assert.That(Regex.Matches(svg, "<polygon").Count, Is.EqualTo(2));
            svg = PickerSvg.Render(ShapeSpec.Parse("line:0,3,1,0"), ShapeSpec.Parse("triangle:0,0,2,0,0,2"), view);
            var polygons = Regex.Matches(svg, "<polygon points=\"([^\"]*)\"");
            Assert.That(polygons.Count, Is.EqualTo(2));
            Assert.That(polygons[0].Groups[1].Value.Split(' ').Length, Is.EqualTo(2), "the line: its two drawn ends");
            Assert.That(polygons[1].Groups[1].Value.Split(' ').Length, Is.EqualTo(3), "the triangle: its three corners");
            svg = PickerSvg.Render(ShapeSpec.Parse("halfspace:0,1,0,0"), ShapeSpec.Parse("ray:0,2,0,1,0,0"), view);
            Assert.That(Regex.Matches(svg, "<polygon").Count, Is.EqualTo(2));
        }

        [Test]
        public void ATurnedBoxIsOutlinedByItsProjection()
        {
            // A cube turned 45° about y shows a rectangle √2 times wider than tall: 4 hull points, not 8 corners.
            var box = new ProximityLib.Obb3(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitY, MathF.PI / 4), Vector3.One);
            string svg = PickerSvg.Render(box, new Vector3(5, 0, 0), new PickerView(PickerMode.ProximityQuery, 0, default, default, false));
            var p = Numbers(svg, "polygon", "points");
            Assert.That(p.Length, Is.EqualTo(8));
            double w = p.Where((_, i) => i % 2 == 0).Max() - p.Where((_, i) => i % 2 == 0).Min();
            double h = p.Where((_, i) => i % 2 == 1).Max() - p.Where((_, i) => i % 2 == 1).Min();
            Assert.That(w / h, Is.EqualTo(Math.Sqrt(2)).Within(0.02));
        }

        [Test]
        public void NotAShapeIsRefused()
        {
            Assert.That(() => PickerSvg.Render("sphere", Vector3.Zero, default), Throws.ArgumentException);
        }
    }
}
