using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Double
{
    /// <summary>Oriented boxes from quaternions of any size and from axes of any length.</summary>
    public class ObbConstructionTests
    {
        // The quaternion (1, 2, 3, 4) turns the axes to these, by hand: 2/|q|² = 1/15 in the usual 2·q·q products.
        private static readonly Vector3D X = V(2.0 / 15, 14.0 / 15, -1.0 / 3), Y = V(-2.0 / 3, 1.0 / 3, 2.0 / 3), Z = V(11.0 / 15, 2.0 / 15, 2.0 / 3);
        private static readonly Vector3D H = V(1, 2, 3);

        private static string? ParamOf(TestDelegate make) => Assert.Throws<ArgumentException>(make)!.ParamName;

        private static double PowerOfTwo(int e) => Math.ScaleB(1.0, e);

        // |q|² underflows (1e-200, 1e-300) or overflows (1e200, 1e300) unless q is scaled before squaring.
        [TestCase(1.0)]
        [TestCase(1e-200)]
        [TestCase(1e200)]
        [TestCase(1e-300)]
        [TestCase(1e300)]
        public void AQuaternionOfAnySizeGivesTheBoxOfTheUnitQuaternion(double size)
        {
            var box = Obb3.FromQuaternion(V(1, 1, 1), size, 2 * size, 3 * size, 4 * size, H);
            Near(box.AxisX, X, 1e-15, "AxisX");
            Near(box.AxisY, Y, 1e-15, "AxisY");
            Near(box.AxisZ, Z, 1e-15, "AxisZ");
            double n = Math.Sqrt(30);
            var unit = Obb3.FromQuaternion(V(1, 1, 1), 1 / n, 2 / n, 3 / n, 4 / n, H);
            Near(box.AxisX, unit.AxisX, 1e-15, "AxisX against the unit quaternion");
            Near(box.AxisY, unit.AxisY, 1e-15, "AxisY against the unit quaternion");
            Near(box.AxisZ, unit.AxisZ, 1e-15, "AxisZ against the unit quaternion");
            Assert.That((box.Center, box.HalfExtents), Is.EqualTo((V(1, 1, 1), H)));
        }

        [Test]
        public void ScalingAQuaternionByAPowerOfTwoChangesNoBit()
        {
            var box = Obb3.FromQuaternion(default, 0.1, 0.2, 0.3, 0.9, H);
            foreach (int e in new[] { -900, -700, 700, 900 })
            {
                double k = PowerOfTwo(e);
                var scaled = Obb3.FromQuaternion(default, 0.1 * k, 0.2 * k, 0.3 * k, 0.9 * k, H);
                Assert.That((scaled.AxisX, scaled.AxisY, scaled.AxisZ), Is.EqualTo((box.AxisX, box.AxisY, box.AxisZ)), $"2^{e}");
            }
        }

        [Test]
        public void ExtremeQuaternionsGiveExactQuarterTurns()
        {
            // The smallest subnormal: (ε, 0, 0, ε) is a quarter turn about x.
            var tiny = Obb3.FromQuaternion(default, double.Epsilon, 0, 0, double.Epsilon, H);
            Assert.That((tiny.AxisX, tiny.AxisY, tiny.AxisZ), Is.EqualTo((V(1, 0, 0), V(0, 0, 1), V(0, -1, 0))));
            var identity = Obb3.FromQuaternion(default, 0, 0, 0, double.MaxValue, H);
            Assert.That((identity.AxisX, identity.AxisY, identity.AxisZ), Is.EqualTo((V(1, 0, 0), V(0, 1, 0), V(0, 0, 1))));
            // (1, 1, 1, 1) cycles the axes: x → y → z → x.
            var huge = Obb3.FromQuaternion(default, double.MaxValue, double.MaxValue, double.MaxValue, double.MaxValue, H);
            Near(huge.AxisX, V(0, 1, 0), 1e-15, "AxisX");
            Near(huge.AxisY, V(0, 0, 1), 1e-15, "AxisY");
            Near(huge.AxisZ, V(1, 0, 0), 1e-15, "AxisZ");
        }

        [Test]
        public void ABadQuaternionIsReportedByARealParameter()
        {
            var o = V(0, 0, 0);
            Assert.That(ParamOf(() => Obb3.FromQuaternion(o, 0, 0, 0, 0, H)), Is.EqualTo("w"));
            Assert.That(ParamOf(() => Obb3.FromQuaternion(o, double.NaN, 0, 0, 1, H)), Is.EqualTo("x"));
            Assert.That(ParamOf(() => Obb3.FromQuaternion(o, 0, double.PositiveInfinity, 0, 1, H)), Is.EqualTo("y"));
            Assert.That(ParamOf(() => Obb3.FromQuaternion(o, 0, 0, double.NegativeInfinity, 1, H)), Is.EqualTo("z"));
            Assert.That(ParamOf(() => Obb3.FromQuaternion(o, 0, 0, 0, double.NaN, H)), Is.EqualTo("w"));
            Assert.That(ParamOf(() => new Obb3(o, default(System.Numerics.Quaternion), H)), Is.EqualTo("rotation"));
            Assert.That(ParamOf(() => new Obb3(o, new System.Numerics.Quaternion(float.NaN, 0, 0, 1), H)), Is.EqualTo("rotation"));
            Assert.That(ParamOf(() => new Obb3(o, new System.Numerics.Quaternion(0, 0, 0, float.PositiveInfinity), H)), Is.EqualTo("rotation"));
            Assert.That(ParamOf(() => new ProximityLib.Obb3(default, default(System.Numerics.Quaternion), default)), Is.EqualTo("rotation"));
            Assert.That(ParamOf(() => new ProximityLib.Obb3(default, new System.Numerics.Quaternion(0, float.NegativeInfinity, 0, 1), default)), Is.EqualTo("rotation"));
        }

        [Test]
        public void AxesOfAnyFiniteNonZeroLengthAreNormalisedFirst()
        {
            var box = new Obb3(V(0, 0, 0), V(2, 0, 0), V(0, 1e-200, 0), V(0, 0, 1e200), H);
            Assert.That((box.AxisX, box.AxisY, box.AxisZ), Is.EqualTo((V(1, 0, 0), V(0, 1, 0), V(0, 0, 1))));
            // A quarter turn about z with lengths 3, 0.5 and 7: the unit frame (c, c, 0), (−c, c, 0), (0, 0, 1), c = √½.
            double c = Math.Sqrt(0.5);
            var turned = new Obb3(V(0, 0, 0), V(3 * c, 3 * c, 0), V(-0.5 * c, 0.5 * c, 0), V(0, 0, 7), H);
            Near(turned.AxisX, V(c, c, 0), Tol, "AxisX");
            Near(turned.AxisY, V(-c, c, 0), Tol, "AxisY");
            Assert.That(turned.AxisZ, Is.EqualTo(V(0, 0, 1)));
            Assert.That(ParamOf(() => new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 0, 0), V(0, 0, 1), H)), Is.EqualTo("axisY"));
            Assert.That(ParamOf(() => new Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, -0.0), H)), Is.EqualTo("axisZ"));
        }

        [Test]
        public void OrthogonalityIsJudgedOnTheUnitDirections()
        {
            var o = V(0, 0, 0);
            // Long axes: their raw dot product (50) is far past the tolerance, their directions' (5e-5) within it ...
            Assert.DoesNotThrow(() => new Obb3(o, V(1000, 0, 0), V(0.05, 1000, 0), V(0, 0, 1000), H));
            // ... and 2e-4 is not.
            Assert.That(ParamOf(() => new Obb3(o, V(1000, 0, 0), V(0.2, 1000, 0), V(0, 0, 1000), H)), Is.EqualTo("axisY"));
            // Short axes: a raw dot product of 2e-9 would pass, the directions' 2e-3 does not.
            Assert.That(ParamOf(() => new Obb3(o, V(1e-3, 0, 0), V(0, 1e-3, 0), V(2e-6, 0, 1e-3), H)), Is.EqualTo("axisZ"));
        }

        /// <summary>
        /// A unit quaternion turned by 10,000 steps of 0.001 rad about (1, 2, 3)/√14, multiplied in float without
        /// renormalising, as an orientation accumulated frame by frame; its norm drifts by about 2.6e-5.
        /// </summary>
        private static (float X, float Y, float Z, float W) Drifted()
        {
            float s = (float)Math.Sin(0.0005), n = (float)Math.Sqrt(14);
            float rx = s / n, ry = 2 * s / n, rz = 3 * s / n, rw = (float)Math.Cos(0.0005);
            float x = 0, y = 0, z = 0, w = 1;
            for (int i = 0; i < 10000; i++)
            {
                float nx = w * rx + x * rw + y * rz - z * ry;
                float ny = w * ry - x * rz + y * rw + z * rx;
                float nz = w * rz + x * ry - y * rx + z * rw;
                float nw = w * rw - x * rx - y * ry - z * rz;
                x = nx; y = ny; z = nz; w = nw;
            }
            return (x, y, z, w);
        }

        [Test]
        public void AxesFromADriftedQuaternionAreAcceptedAndStoredOrthonormal()
        {
            var (x, y, z, w) = Drifted();
            // q·v·q̄ turns each unit axis and scales it by |q|²: the homogeneous rotation matrix, in float as a game has it.
            var ax = new System.Numerics.Vector3(w * w + x * x - y * y - z * z, 2 * (x * y + w * z), 2 * (x * z - w * y));
            var ay = new System.Numerics.Vector3(2 * (x * y - w * z), w * w - x * x + y * y - z * z, 2 * (y * z + w * x));
            var az = new System.Numerics.Vector3(2 * (x * z + w * y), 2 * (y * z - w * x), w * w - x * x - y * y + z * z);
            // The premise: the norm drifted past what a unit-length check (|a·a − 1| ≤ AxisTolerance) lets through.
            Assert.That(Math.Abs(((Vector3D)ax).LengthSquared - 1), Is.GreaterThan(Obb3.AxisTolerance));

            var box = new Obb3(V(0, 0, 0), ax, ay, az, H);
            foreach (var a in new[] { box.AxisX, box.AxisY, box.AxisZ }) Assert.That(a.Length, Is.EqualTo(1).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisX, box.AxisY), Is.EqualTo(0).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisX, box.AxisZ), Is.EqualTo(0).Within(1e-15));
            Assert.That(Vector3D.Dot(box.AxisY, box.AxisZ), Is.EqualTo(0).Within(1e-15));
            // The stored frame is the given one, up to the inputs' float rounding.
            Vector3D dx = ax, dy = ay, dz = az;
            Near(box.AxisX, dx / dx.Length, 1e-6, "AxisX");
            Near(box.AxisY, dy / dy.Length, 1e-6, "AxisY");
            Near(box.AxisZ, dz / dz.Length, 1e-6, "AxisZ");
            var single = new ProximityLib.Obb3(System.Numerics.Vector3.Zero, ax, ay, az, System.Numerics.Vector3.One);
            Assert.That(System.Numerics.Vector3.Distance(single.AxisX, (System.Numerics.Vector3)box.AxisX), Is.LessThan(1e-7f));
        }

        [Test]
        public void FromCornersTakesNormalsOfAnyLength()
        {
            var corners = new[] { V(0, 0, 0), V(2, 0, 0), V(0, 1, 0), V(2, 1, 0), V(0, 0, 3), V(2, 0, 3), V(0, 1, 3), V(2, 1, 3) };
            var box = Obb3.FromCorners(corners, V(5, 0, 0), V(0, 0.5, 0), V(0, 0, 1e-3));
            Assert.That((box.AxisX, box.AxisY, box.AxisZ), Is.EqualTo((V(1, 0, 0), V(0, 1, 0), V(0, 0, 1))));
            Assert.That((box.Center, box.HalfExtents), Is.EqualTo((V(1, 0.5, 1.5), V(1, 0.5, 1.5))));
            Assert.That(ParamOf(() => Obb3.FromCorners(corners, V(1000, 0, 0), V(0.2, 1000, 0), V(0, 0, 1))), Is.EqualTo("axisY"));

            // A rectangle with edge directions (0.6, 0.8) and (−0.8, 0.6), half-extents 0.5 and 1, centred at (−0.5, 1).
            var rect = Obb2.FromCorners(new[] { V(0, 0), V(0.6, 0.8), V(-1, 2), V(-1.6, 1.2) }, V(3, 4), V(-8, 6));
            Near(TestShape.V3(rect.AxisX), V(0.6, 0.8, 0), Tol, "AxisX");
            Near(TestShape.V3(rect.Center), V(-0.5, 1, 0), 1e-15, "Center");
            Near(TestShape.V3(rect.HalfExtents), V(0.5, 1, 0), 1e-15, "HalfExtents");
        }

        [TestCase(1.0)]
        [TestCase(1e-200)]
        [TestCase(1e200)]
        public void Obb2TakesAnAxisOfAnyLength(double size)
        {
            var box = new Obb2(V(1, 2), V(3 * size, 4 * size), V(1, 1));
            Near(TestShape.V3(box.AxisX), V(0.6, 0.8, 0), Tol, "AxisX");
            Near(TestShape.V3(box.AxisY), V(-0.8, 0.6, 0), Tol, "AxisY");
        }
    }
}
