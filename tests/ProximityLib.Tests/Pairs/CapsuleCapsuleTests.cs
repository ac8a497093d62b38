using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class CapsuleCapsuleTests
    {
        [Test]
        public void Separated3DAndSymmetric()
        {
            var a = new Capsule3(V(0, 0, 0), V(4, 0, 0), 1);
            var b = new Capsule3(V(2, -1, 3), V(2, 1, 3), 0.5);
            var r = ClosestDistance.Between(a, b);
            Result(r, 1.5, V(2, 0, 1), V(2, 0, 2.5));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(r.Swapped()));
        }

        /// <summary>2D crossing: the second axis's start is 1 below the first axis's line: depth 1 + 1 + 0.5.</summary>
        [Test]
        public void Crossing2DAddsTheCrossingDepth()
        {
            var a = new Capsule2(V(0, 0), V(4, 0), 1);
            var b = new Capsule2(V(2, -1), V(2, 3), 0.5);
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(-2.5));
            Assert.That(Vector2D.Distance(r.PointA, r.PointB), Is.EqualTo(2.5));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(r.Swapped()));
            // Identical axes, different radii: the same answer in either order; 3D meeting axes push by the radii.
            var c = new Capsule3(V(0, 0, 0), V(2, 0, 0), 1);
            var d = new Capsule3(V(0, 0, 0), V(2, 0, 0), 0.25);
            Assert.That(ClosestDistance.Between(c, d).Distance, Is.EqualTo(-1.25));
            Assert.That(ClosestDistance.Between(d, c), Is.EqualTo(ClosestDistance.Between(c, d).Swapped()));
        }

        [Test]
        public void PointSizedCapsulesAreSpheres() =>
            Result(ClosestDistance.Between(new Capsule2(V(0, 0), V(0, 0), 1), new Capsule2(V(5, 0), V(5, 0), 2)), 2, V(1, 0), V(3, 0));
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("capsule", "capsule"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("capsule", "capsule");

        /// <summary>
        /// Axes 1e-9 … 1e-15 apart (size ~3, radii 0.3 + 0.2): A moved by PointB − PointA must touch B to within 64 u·S,
        /// checked exactly. The rounded residual's direction is off by about u·S/gap there, and a radius pushed along it
        /// left up to 7e-7 of overlap. Modes: 0 two interior points (3D), 1 B's end against A's interior, 2 A's end
        /// against B's interior, 3 mode 1 in the plane.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        public void NearlyTouchingAxesPushOutToTouching(int mode)
        {
            var rnd = new Random(41 + mode);
            Vector3D R() => new Vector3D(rnd.NextDouble() - 0.5, rnd.NextDouble() - 0.5, mode == 3 ? 0 : rnd.NextDouble() - 0.5);
            Vector3D Unit(Vector3D v) => v * (1 / v.Length);
            for (int i = 0; i < 70; i++)
            {
                double h = Math.Pow(10, -9 - i % 7);
                var a0 = new Vector3D(rnd.NextDouble() * 3, rnd.NextDouble() * 3, mode == 3 ? 0 : rnd.NextDouble() * 3);
                var dA = R();
                var p = a0 + dA * 0.4;
                Vector3D b0, b1;
                if (mode == 0)
                {
                    var dB = R();
                    var n = Unit(Vector3D.Cross(dA, dB));
                    b0 = p + n * h - dB * 0.3;
                    b1 = p + n * h + dB * 0.7;
                }
                else
                {
                    // q: a unit direction perpendicular to A; B leaves A's side along q, tilted.
                    var q = R();
                    q = Unit(q - dA * (Vector3D.Dot(q, dA) / dA.LengthSquared));
                    b0 = p + q * h;
                    b1 = b0 + q * 0.8 + dA * (rnd.NextDouble() - 0.5);
                }
                object a, b;
                if (mode == 3) { a = new Capsule2(new Vector2D(a0.X, a0.Y), new Vector2D(a0.X + dA.X, a0.Y + dA.Y), 0.3); b = new Capsule2(new Vector2D(b0.X, b0.Y), new Vector2D(b1.X, b1.Y), 0.2); }
                else if (mode == 2) { a = new Capsule3(b1, b0, 0.2); b = new Capsule3(a0, a0 + dA, 0.3); }
                else { a = new Capsule3(a0, a0 + dA, 0.3); b = new Capsule3(b0, b1, 0.2); }
                var ra = RShape.FromAny(a);
                var rb = RShape.FromAny(b);
                double tol = 64 * Exactly.U * Exact.Scale(ra, rb);
                foreach (var (x, y, rx, ry) in new[] { (a, b, ra, rb), (b, a, rb, ra) })
                {
                    RVec pa, pb;
                    double d;
                    if (x is Capsule2 c2) { var r = ClosestDistance.Between(c2, (Capsule2)y); pa = RVec.From(r.PointA); pb = RVec.From(r.PointB); d = r.Distance; }
                    else { var r = ClosestDistance.Between((Capsule3)x, (Capsule3)y); pa = RVec.From(r.PointA); pb = RVec.From(r.PointB); d = r.Distance; }
                    double after = Exact.SignedDistance(rx.Translated(pb - pa), ry).ToDouble();
                    Assert.That(d, Is.LessThan(0), $"case {i}: {x} vs {y}");
                    Assert.That(Math.Abs(after), Is.LessThanOrEqualTo(tol), $"case {i} (gap {h:G1}): {x} vs {y} moved by PointB − PointA is {after:R} from touching");
                }
                // The normal's exact steps scale: inputs scaled by 2^-440 and 2^400 give the same witnesses scaled.
                if (a is Capsule3 ca && b is Capsule3 cb)
                    foreach (int e in new[] { -440, 400 })
                    {
                        double f = Math.ScaleB(1, e);
                        var r = ClosestDistance.Between(ca, cb);
                        var rs = ClosestDistance.Between(new Capsule3(ca.Start * f, ca.End * f, ca.Radius * f), new Capsule3(cb.Start * f, cb.End * f, cb.Radius * f));
                        Assert.That(rs.PointA, Is.EqualTo(r.PointA * f), $"case {i}, 2^{e}");
                        Assert.That(rs.PointB, Is.EqualTo(r.PointB * f), $"case {i}, 2^{e}");
                    }
            }
        }
    

        /// <summary>
        /// Distance and Overlaps (the axes' distance less the radii where the axes are clear of each other in both argument
        /// orders, in 3D always; 2D Overlaps also where the axes lie within the radii) against Between, bit for bit, across the
        /// near-touch band
        /// (<see cref="LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand"/>).
        /// </summary>
        [Test]
        public void DistanceOnlyIsBetweenAcrossTheNearTouchBand() => LinearFamilies.CheckAgainstBetweenAcrossTheNearTouchBand("capsule", 20261207);
    }
}
