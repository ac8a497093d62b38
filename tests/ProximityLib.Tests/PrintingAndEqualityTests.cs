using System;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib;

namespace ProximityTests
{
    /// <summary>Float shapes and results print readably (invariant, round-trip by default) and compare by value.</summary>
    public class PrintingAndEqualityTests
    {
        private static readonly Obb3 Turned = new Obb3(new Vector3(1, 2, 3), Vector3.UnitY, -Vector3.UnitX, Vector3.UnitZ, new Vector3(0.5f, 1, 2));

        [Test]
        public void ShapesPrintTheirFields()
        {
            Assert.That(new Segment3(new Vector3(1, 2, 3), new Vector3(-4, 0.5f, 6)).ToString(), Is.EqualTo("Segment3 { Start = <1, 2, 3>, End = <-4, 0.5, 6> }"));
            Assert.That(new Segment2(Vector2.Zero, new Vector2(4, 0)).ToString(), Is.EqualTo("Segment2 { Start = <0, 0>, End = <4, 0> }"));
            Assert.That(new Sphere(new Vector3(0, 0.05f, 0), 0.04f).ToString(), Is.EqualTo("Sphere { Center = <0, 0.05, 0>, Radius = 0.04 }"));
            Assert.That(new Circle(new Vector2(1.5f, -2), 0.25f).ToString(), Is.EqualTo("Circle { Center = <1.5, -2>, Radius = 0.25 }"));
            Assert.That(new Aabb3(new Vector3(-1, -0.1f, -1), new Vector3(1, 0, 1)).ToString(), Is.EqualTo("Aabb3 { Min = <-1, -0.1, -1>, Max = <1, 0, 1> }"));
            Assert.That(new Aabb2(Vector2.Zero, new Vector2(2, 1)).ToString(), Is.EqualTo("Aabb2 { Min = <0, 0>, Max = <2, 1> }"));
            Assert.That(Turned.ToString(),
                Is.EqualTo("Obb3 { Center = <1, 2, 3>, AxisX = <0, 1, 0>, AxisY = <-1, 0, 0>, AxisZ = <0, 0, 1>, HalfExtents = <0.5, 1, 2> }"));
            Assert.That(new Obb2(new Vector2(3, 0), Vector2.UnitY, new Vector2(1, 0.5f)).ToString(),
                Is.EqualTo("Obb2 { Center = <3, 0>, AxisX = <0, 1>, HalfExtents = <1, 0.5> }"));
        }

        [Test]
        public void ResultsPrintTheirFields()
        {
            // Hand-worked: the sphere's lowest point (0, 2, 0) is 1 above the box's top face at (0, 1, 0).
            var r3 = ClosestDistance.Between(new Sphere(new Vector3(0, 3, 0), 1), new Aabb3(-Vector3.One, Vector3.One));
            Assert.That(r3.ToString(),
                Is.EqualTo("DistanceResult3 { Distance = 1, DistanceSquared = 1, PointA = <0, 2, 0>, PointB = <0, 1, 0>, ParameterA = 0, ParameterB = 0 }"));
            // The point (1, 1) projects to a quarter of the way along (0, 0)–(4, 0).
            var r2 = ClosestDistance.Between(new Vector2(1, 1), new Segment2(Vector2.Zero, new Vector2(4, 0)));
            Assert.That(r2.ToString(),
                Is.EqualTo("DistanceResult2 { Distance = 1, DistanceSquared = 1, PointA = <1, 1>, PointB = <1, 0>, ParameterA = 0, ParameterB = 0.25 }"));
        }

        [Test]
        public void FormatsAndCulturesApplyToEveryNumber()
        {
            var s = new Sphere(new Vector3(0.1f, 0, -2), 1f / 3);
            // Round-trip by default: 1/3 rounded to float prints with the digits that bring it back.
            Assert.That(s.ToString(), Is.EqualTo("Sphere { Center = <0.1, 0, -2>, Radius = 0.33333334 }"));
            Assert.That(s.ToString("F2", null), Is.EqualTo("Sphere { Center = <0.10, 0.00, -2.00>, Radius = 0.33 }"));
            var comma = new NumberFormatInfo { NumberDecimalSeparator = ",", NumberGroupSeparator = ";" };
            Assert.That(s.ToString(null, comma), Is.EqualTo("Sphere { Center = <0,1; 0; -2>, Radius = 0,33333334 }"));
            Assert.That(float.Parse(s.ToString().Split("Radius = ")[1].TrimEnd(' ', '}'), CultureInfo.InvariantCulture), Is.EqualTo(s.Radius));
        }

        [Test]
        public void ToStringIgnoresTheCurrentCulture()
        {
            var before = CultureInfo.CurrentCulture;
            var comma = (CultureInfo)CultureInfo.InvariantCulture.Clone();
            comma.NumberFormat.NumberDecimalSeparator = ",";
            comma.NumberFormat.NumberGroupSeparator = ";";
            try
            {
                CultureInfo.CurrentCulture = comma;
                var c = new Circle(new Vector2(1.5f, 0), 0.5f);
                Assert.That(c.ToString(), Is.EqualTo("Circle { Center = <1.5, 0>, Radius = 0.5 }"));
                Assert.That($"{c}", Is.EqualTo("Circle { Center = <1.5, 0>, Radius = 0.5 }"));
            }
            finally
            {
                CultureInfo.CurrentCulture = before;
            }
        }

        [Test]
        public void EqualShapesAreEqualAndHashAlike()
        {
            Same(new Segment3(Vector3.Zero, Vector3.One), new Segment3(Vector3.Zero, Vector3.One), new Segment3(Vector3.One, Vector3.Zero));
            Same(new Segment2(Vector2.Zero, Vector2.One), new Segment2(Vector2.Zero, Vector2.One), new Segment2(Vector2.Zero, Vector2.UnitX));
            Same(new Sphere(Vector3.Zero, 1), new Sphere(new Vector3(-0f, 0, 0), 1), new Sphere(Vector3.Zero, 2)); // −0 equals 0
            Same(new Circle(Vector2.One, 1), new Circle(Vector2.One, 1), new Circle(Vector2.Zero, 1));
            Same(new Aabb3(Vector3.Zero, Vector3.One), Aabb3.FromOrigin(Vector3.Zero, 1, 1, 1), new Aabb3(Vector3.Zero, 2 * Vector3.One));
            Same(new Aabb2(Vector2.Zero, Vector2.One), Aabb2.FromCenter(new Vector2(0.5f), new Vector2(0.5f)), new Aabb2(-Vector2.One, Vector2.One));
            // The default box is the axis-aligned point box at the origin, whatever its storage.
            Same(default(Obb3), new Obb3(Vector3.Zero, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, Vector3.Zero), Turned);
            Same(default(Obb2), new Obb2(Vector2.Zero, 0f, Vector2.Zero), new Obb2(Vector2.Zero, Vector2.UnitY, Vector2.Zero));
            // q and −q are the same rotation, and the rotation matrix is built from products of pairs of components.
            var q = new Quaternion(0.1f, -0.7f, 0.3f, 0.64f);
            Same(new Obb3(Vector3.One, q, Vector3.One), new Obb3(Vector3.One, -q, Vector3.One), new Obb3(Vector3.One, q, 2 * Vector3.One));
        }

        [Test]
        public void EqualResultsAreEqualAndHashAlike()
        {
            var sphere = new Sphere(new Vector3(0, 3, 0), 1);
            var box = new Aabb3(-Vector3.One, Vector3.One);
            Same(ClosestDistance.Between(sphere, box), ClosestDistance.Between(sphere, box), ClosestDistance.Between(box, sphere));
            var seg = new Segment2(Vector2.Zero, new Vector2(4, 0));
            Same(ClosestDistance.Between(Vector2.One, seg), ClosestDistance.Between(Vector2.One, seg), ClosestDistance.Between(seg, Vector2.One));
        }

        // Documented: float boxes compare their stored double corners, and FromOrigin keeps a corner between floats here.
        [Test]
        public void BoxesThatPrintAlikeCanDifferBelowFloatPrecision()
        {
            var made = Aabb3.FromOrigin(new Vector3(0.1f), 0.2f, 0.2f, 0.2f); // Max = 0.1f + 0.2f exactly, which no float is
            var rounded = new Aabb3(made.Min, made.Max);
            Assert.That(rounded.ToString(), Is.EqualTo(made.ToString()));
            Assert.That(rounded, Is.Not.EqualTo(made));
            Assert.That(rounded != made);
        }

        [Test]
        public void EveryShapeAndResultShowsItsTextInTheDebugger()
        {
            var types = new[]
            {
                typeof(Segment3), typeof(Segment2), typeof(Sphere), typeof(Circle), typeof(Aabb3), typeof(Aabb2), typeof(Obb3), typeof(Obb2),
                typeof(DistanceResult3), typeof(DistanceResult2),
                typeof(ProximityLib.Double.Segment3), typeof(ProximityLib.Double.Segment2), typeof(ProximityLib.Double.Sphere),
                typeof(ProximityLib.Double.Circle), typeof(ProximityLib.Double.Aabb3), typeof(ProximityLib.Double.Aabb2),
                typeof(ProximityLib.Double.Obb3), typeof(ProximityLib.Double.Obb2),
                typeof(ProximityLib.Double.DistanceResult3), typeof(ProximityLib.Double.DistanceResult2),
                typeof(RayHit3), typeof(RayHit2), typeof(ProximityLib.Double.RayHit3), typeof(ProximityLib.Double.RayHit2),
                typeof(Line3), typeof(Line2), typeof(Ray3), typeof(Ray2), typeof(Capsule3), typeof(Capsule2), typeof(Triangle3), typeof(Triangle2),
                typeof(HalfSpace), typeof(HalfPlane),
                typeof(ProximityLib.Double.Line3), typeof(ProximityLib.Double.Line2), typeof(ProximityLib.Double.Ray3), typeof(ProximityLib.Double.Ray2),
                typeof(ProximityLib.Double.Capsule3), typeof(ProximityLib.Double.Capsule2), typeof(ProximityLib.Double.Triangle3),
                typeof(ProximityLib.Double.Triangle2), typeof(ProximityLib.Double.HalfSpace), typeof(ProximityLib.Double.HalfPlane),
            };
            // The list is every public struct of the two namespaces except the vectors.
            var publicStructs = typeof(Sphere).Assembly.GetExportedTypes()
                .Where(t => t.IsValueType && !t.IsEnum && (t.Namespace == "ProximityLib" || t.Namespace == "ProximityLib.Double"))
                .Where(t => t.Name != "Vector2D" && t.Name != "Vector3D");
            Assert.That(types, Is.EquivalentTo(publicStructs));
            foreach (var t in types)
            {
                var display = t.GetCustomAttributes(typeof(DebuggerDisplayAttribute), false).Cast<DebuggerDisplayAttribute>().SingleOrDefault();
                Assert.That(display?.Value, Is.EqualTo("{ToString(),nq}"), t.FullName);
                Assert.That(typeof(IFormattable).IsAssignableFrom(t), t.FullName);
                Assert.That(typeof(IEquatable<>).MakeGenericType(t).IsAssignableFrom(t), t.FullName);
            }
        }

        private static void Same<T>(T a, T equal, T different) where T : struct, IEquatable<T>
        {
            Assert.That(a.Equals(equal), $"{a} equals {equal}");
            Assert.That(a.Equals((object)equal));
            Assert.That(a.GetHashCode(), Is.EqualTo(equal.GetHashCode()), $"{a}: hash");
            Assert.That(a.Equals(different), Is.False, $"{a} differs from {different}");
            Assert.That(a.Equals((object)"text"), Is.False);
            dynamic da = a, de = equal, dd = different;
            Assert.That(da == de && !(da != de) && da != dd && !(da == dd), $"operators on {typeof(T).Name}");
        }
    }
}
