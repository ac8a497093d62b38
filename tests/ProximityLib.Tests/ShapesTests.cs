using System;
using System.Numerics;
using NUnit.Framework;
using ProximityLib;

namespace ProximityTests
{
    /// <summary>The float shapes validate like the double ones (same parameter names) and read back their inputs.</summary>
    public class ShapesTests
    {
        private static void Rejects(string param, TestDelegate make) =>
            Assert.That(make, NUnit.Framework.Throws.ArgumentException.With.Property(nameof(ArgumentException.ParamName)).EqualTo(param));

        [Test]
        public void FloatConstructorsValidate()
        {
            Rejects("start", () => new Segment3(new Vector3(float.NaN), Vector3.Zero));
            Rejects("end", () => new Segment2(Vector2.Zero, new Vector2(float.PositiveInfinity, 0)));
            Rejects("radius", () => new Sphere(Vector3.Zero, -1));
            Rejects("center", () => new Circle(new Vector2(float.NaN, 0), 1));
            Rejects("min", () => new Aabb3(Vector3.One, Vector3.Zero));
            Rejects("height", () => Aabb2.FromOrigin(Vector2.Zero, 1, -1));
            Rejects("rotation", () => new Obb3(Vector3.Zero, default(Quaternion), Vector3.One));
            Rejects("axisY", () => new Obb3(Vector3.Zero, Vector3.UnitX, Vector3.UnitX, Vector3.UnitZ, Vector3.One));
            Rejects("halfExtents", () => new Obb2(Vector2.Zero, 0f, new Vector2(-1, 1)));
            Rejects("corners", () => Obb3.FromCorners(new Vector3[4], Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ));
        }

        [Test]
        public void FloatShapesReadBackTheirInputs()
        {
            var s = new Segment3(new Vector3(1, 2, 3), new Vector3(4, 5, 6));
            Assert.That((s.Start, s.End), Is.EqualTo((new Vector3(1, 2, 3), new Vector3(4, 5, 6))));
            Assert.That(s.PointAt(0.5f), Is.EqualTo(new Vector3(2.5f, 3.5f, 4.5f)));
            var box = Aabb3.FromOrigin(new Vector3(1, 1, 1), 1, 2, 3);
            Assert.That(box.Max, Is.EqualTo(new Vector3(2, 3, 4)));
            var obb = new Obb3(new Vector3(1, 2, 3), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.PI / 2), new Vector3(1, 2, 3));
            Assert.That(Vector3.Distance(obb.AxisX, Vector3.UnitY), Is.LessThan(1e-7f));
            Assert.That(obb.HalfExtents, Is.EqualTo(new Vector3(1, 2, 3)));
            var obb2 = new Obb2(Vector2.Zero, MathF.PI / 2, Vector2.One);
            Assert.That(Vector2.Distance(obb2.AxisY, -Vector2.UnitX), Is.LessThan(1e-7f));
            ProximityLib.Double.Sphere wide = new Sphere(new Vector3(1, 2, 3), 0.1f);
            Assert.That(wide.Radius, Is.EqualTo((double)0.1f));
        }

        [Test]
        public void FloatObbAxesOfAnyLengthAreNormalised()
        {
            var box = new Obb3(Vector3.Zero, new Vector3(2, 0, 0), new Vector3(0, 0, 0.5f), new Vector3(0, -3, 0), Vector3.One);
            Assert.That((box.AxisX, box.AxisY, box.AxisZ), Is.EqualTo((Vector3.UnitX, Vector3.UnitZ, -Vector3.UnitY)));
            Assert.That(Vector2.Distance(new Obb2(Vector2.Zero, new Vector2(3, 4), Vector2.One).AxisX, new Vector2(0.6f, 0.8f)), Is.LessThan(1e-7f));
        }

        [Test]
        public void FloatQueriesMatchTheDoubleOnes()
        {
            var a = new Obb3(new Vector3(0.1f, 0.2f, 0.3f), Quaternion.CreateFromYawPitchRoll(0.3f, 0.2f, 0.1f), new Vector3(0.5f, 0.4f, 0.3f));
            var b = new Sphere(new Vector3(1.1f, 0.9f, 0.2f), 0.25f);
            var f = ClosestDistance.Between(a, b);
            var d = ProximityLib.Double.ClosestDistance.Between((ProximityLib.Double.Obb3)a, (ProximityLib.Double.Sphere)b);
            Assert.That(f.Distance, Is.EqualTo((float)d.Distance));
            Assert.That(f.PointA, Is.EqualTo((Vector3)d.PointA));
            Assert.That(ClosestDistance.Between(b, a).PointA, Is.EqualTo(f.PointB));
        }
    }
}
