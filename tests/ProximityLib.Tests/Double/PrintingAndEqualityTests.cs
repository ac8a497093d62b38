using System;
using System.Globalization;
using NUnit.Framework;
using ProximityLib.Double;

namespace ProximityTests.Double
{
    /// <summary>Double shapes and results print readably (invariant, round-trip by default) and compare by value.</summary>
    public class PrintingAndEqualityTests
    {
        private static readonly Vector3D One = new Vector3D(1, 1, 1);

        [Test]
        public void ShapesPrintTheirFields()
        {
            Assert.That(new Segment3(new Vector3D(1, 2, 3), new Vector3D(-4, 0.5, 6)).ToString(), Is.EqualTo("Segment3 { Start = <1, 2, 3>, End = <-4, 0.5, 6> }"));
            Assert.That(new Segment2(Vector2D.Zero, new Vector2D(4, 0)).ToString(), Is.EqualTo("Segment2 { Start = <0, 0>, End = <4, 0> }"));
            Assert.That(new Sphere(new Vector3D(0, 0.05, 0), 0.04).ToString(), Is.EqualTo("Sphere { Center = <0, 0.05, 0>, Radius = 0.04 }"));
            Assert.That(new Circle(new Vector2D(1.5, -2), 0.25).ToString(), Is.EqualTo("Circle { Center = <1.5, -2>, Radius = 0.25 }"));
            Assert.That(new Aabb3(new Vector3D(-1, -0.1, -1), new Vector3D(1, 0, 1)).ToString(), Is.EqualTo("Aabb3 { Min = <-1, -0.1, -1>, Max = <1, 0, 1> }"));
            Assert.That(new Aabb2(Vector2D.Zero, new Vector2D(2, 1)).ToString(), Is.EqualTo("Aabb2 { Min = <0, 0>, Max = <2, 1> }"));
            Assert.That(new Obb3(new Vector3D(1, 2, 3), Vector3D.UnitY, -Vector3D.UnitX, Vector3D.UnitZ, new Vector3D(0.5, 1, 2)).ToString(),
                Is.EqualTo("Obb3 { Center = <1, 2, 3>, AxisX = <0, 1, 0>, AxisY = <-1, 0, 0>, AxisZ = <0, 0, 1>, HalfExtents = <0.5, 1, 2> }"));
            // cos(π/2) in double is 6.123233995736766E-17, not 0: round-trip printing shows it, "F3" hides it.
            var quarterTurn = new Obb2(Vector2D.Zero, Math.PI / 2, new Vector2D(1, 0.5));
            Assert.That(quarterTurn.ToString(), Is.EqualTo("Obb2 { Center = <0, 0>, AxisX = <6.123233995736766E-17, 1>, HalfExtents = <1, 0.5> }"));
            Assert.That(quarterTurn.ToString("F3", CultureInfo.InvariantCulture), Is.EqualTo("Obb2 { Center = <0.000, 0.000>, AxisX = <0.000, 1.000>, HalfExtents = <1.000, 0.500> }"));
        }

        [Test]
        public void ResultsPrintTheirFields()
        {
            var r3 = ClosestDistance.Between(new Sphere(new Vector3D(0, 3, 0), 1), new Aabb3(-One, One));
            Assert.That(r3.ToString(),
                Is.EqualTo("DistanceResult3 { Distance = 1, DistanceSquared = 1, PointA = <0, 2, 0>, PointB = <0, 1, 0>, ParameterA = 0, ParameterB = 0 }"));
            var r2 = ClosestDistance.Between(new Vector2D(1, 1), new Segment2(Vector2D.Zero, new Vector2D(4, 0)));
            Assert.That(r2.ToString(),
                Is.EqualTo("DistanceResult2 { Distance = 1, DistanceSquared = 1, PointA = <1, 1>, PointB = <1, 0>, ParameterA = 0, ParameterB = 0.25 }"));
        }

        [Test]
        public void RoundTripByDefaultAndAnyFormatOnRequest()
        {
            // 0.1f widened to double is 0.100000001490116119384765625; "R" gives the shortest digits that read back to it.
            var s = new Sphere(new Vector3D(0.1f, 0, 0), 0.1f);
            Assert.That(s.ToString(), Is.EqualTo("Sphere { Center = <0.10000000149011612, 0, 0>, Radius = 0.10000000149011612 }"));
            Assert.That(double.Parse("0.10000000149011612", CultureInfo.InvariantCulture), Is.EqualTo((double)0.1f));
            Assert.That(s.ToString("G3", null), Is.EqualTo("Sphere { Center = <0.1, 0, 0>, Radius = 0.1 }"));
            var comma = new NumberFormatInfo { NumberDecimalSeparator = ",", NumberGroupSeparator = ";" };
            Assert.That(new Vector2D(1.5, -2).ToString(null, comma), Is.EqualTo("<1,5; -2>"));
            Assert.That(new Vector3D(1.5, -2, 0.26).ToString("F1", CultureInfo.InvariantCulture), Is.EqualTo("<1.5, -2.0, 0.3>"));
        }

        [Test]
        public void EqualShapesAreEqualAndHashAlike()
        {
            Same(new Segment3(Vector3D.Zero, One), new Segment3(Vector3D.Zero, One), new Segment3(One, Vector3D.Zero));
            Same(new Segment2(Vector2D.Zero, Vector2D.UnitX), new Segment2(Vector2D.Zero, Vector2D.UnitX), new Segment2(Vector2D.Zero, Vector2D.UnitY));
            Same(new Sphere(Vector3D.Zero, 1), new Sphere(new Vector3D(-0.0, 0, 0), 1), new Sphere(Vector3D.Zero, 1.0000000000000002));
            Same(new Circle(Vector2D.UnitX, 1), new Circle(Vector2D.UnitX, 1), new Circle(Vector2D.UnitY, 1));
            Same(new Aabb3(Vector3D.Zero, One), Aabb3.FromCenter(One * 0.5, One * 0.5), new Aabb3(-One, One));
            Same(new Aabb2(Vector2D.Zero, Vector2D.UnitX), Aabb2.FromOrigin(Vector2D.Zero, 1, 0), new Aabb2(Vector2D.Zero, Vector2D.UnitY));
            Same(default(Obb3), Obb3.FromQuaternion(Vector3D.Zero, 0, 0, 0, 1, Vector3D.Zero), Obb3.FromQuaternion(Vector3D.Zero, 0, 0, 1, 1, Vector3D.Zero));
            Same(default(Obb2), new Obb2(Vector2D.Zero, Vector2D.UnitX, Vector2D.Zero), new Obb2(Vector2D.Zero, Math.PI, Vector2D.Zero));
        }

        // Documented: an OBB compares its stored, re-orthonormalised frame, so routes to the same rotation can differ in the last bits.
        [Test]
        public void BoxesCompareTheirStoredFrame()
        {
            var a = new Obb2(Vector2D.Zero, Math.PI / 2, Vector2D.UnitX);
            var b = new Obb2(Vector2D.Zero, Vector2D.UnitY, Vector2D.UnitX);
            Assert.That(a.AxisX.X, Is.EqualTo(6.123233995736766E-17));
            Assert.That(b.AxisX.X, Is.EqualTo(0));
            Assert.That(a == b, Is.False);
        }

        [Test]
        public void EqualResultsAreEqualAndHashAlike()
        {
            var sphere = new Sphere(new Vector3D(0, 3, 0), 1);
            var box = new Aabb3(-One, One);
            Same(ClosestDistance.Between(sphere, box), ClosestDistance.Between(sphere, box), ClosestDistance.Between(box, sphere));
            var seg = new Segment2(Vector2D.Zero, new Vector2D(4, 0));
            var p = new Vector2D(1, 1);
            Same(ClosestDistance.Between(p, seg), ClosestDistance.Between(p, seg), ClosestDistance.Between(seg, p));
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
