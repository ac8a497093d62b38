using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentSphereTests
    {
        private static readonly Sphere Unit = new Sphere(V(0, 0, 0), 1);

        [Test]
        public void Apart()
        {
            var r = ClosestDistance.Between(new Segment3(V(-2, 3, 0), V(2, 3, 0)), Unit);
            Result(r, 2, V(0, 3, 0), V(0, 1, 0));
            Assert.That(r.ParameterA, Is.EqualTo(0.5));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 3, 0), V(2, 3, 0)), Unit), Is.False);
            Result(ClosestDistance.Between(new Circle(V(0, 0), 1), new Segment2(V(3, -1), V(3, 1))), 2, V(1, 0), V(3, 0));
        }

        [Test]
        public void EnteringIsNegative()
        {
            var r = ClosestDistance.Between(new Segment3(V(-2, 0.5, 0), V(2, 0.5, 0)), Unit);
            Result(r, -0.5, V(0, 0.5, 0), V(0, 1, 0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 0.5, 0), V(2, 0.5, 0)), Unit), Is.True);
        }

        [Test]
        public void ThroughTheCenterPushesPerpendicular()
        {
            // The segment runs along x through the center: no direction is preferred, and the documented one is a
            // perpendicular of the segment, here moving it by +y onto the sphere's top.
            var r = ClosestDistance.Between(new Segment3(V(-2, 0, 0), V(2, 0, 0)), Unit);
            Result(r, -1, V(0, 0, 0), V(0, 1, 0));
        }

        [Test]
        public void TangentTouches()
        {
            Assert.That(ClosestDistance.Between(new Segment3(V(-2, 1, 0), V(2, 1, 0)), Unit).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(-2, 1, 0), V(2, 1, 0)), Unit), Is.True);
        }
        /// <summary>
        /// Centres 2^-27 … 2^-48 of the length off a 3D axis (size ~2, radius 0.05 … 1, one case in three translated by
        /// ~10^4): the sphere moved by PointB − PointA must touch the segment, capsule, line or ray to within 64 u·S (plus
        /// 16 u·|coordinates|, the witnesses' own rounding), checked exactly. The rounded residual is off by u·S, so a normal tilted along the axis leaves r·(u·S/gap)²/2
        /// of overlap (up to 10^-6 here); across the axis a tilt costs nothing, which is why the interior needs only the
        /// residual less its part along the axis. Modes: 0 segment interior, 1 a foot within 2^-44 … 2^-54 of an end
        /// (either side, about the rounding of the foot: the end and the interior compete, the exact path), 2 capsule interior, 3 line, 4 ray.
        /// </summary>
        [TestCase(0)]
        [TestCase(1)]
        [TestCase(2)]
        [TestCase(3)]
        [TestCase(4)]
        public void CentresNearAnAxisPushOutToTouching(int mode)
        {
            var rnd = new Random(53 + mode);
            Vector3D R() => new Vector3D(rnd.NextDouble() * 2 - 1, rnd.NextDouble() * 2 - 1, rnd.NextDouble() * 2 - 1);
            double Max(Vector3D v) => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));
            for (int i = 0; i < 120; i++)
            {
                var a = R() + (i % 3 == 0 ? R() * 1e4 : default);
                var d = R();
                var q = R();
                q -= d * (Vector3D.Dot(q, d) / d.LengthSquared);
                q *= 1 / q.Length;
                double gap = Math.ScaleB(d.Length, -27 - i % 22), radius = 0.05 + rnd.NextDouble() * 0.95;
                double t = mode == 1 ? (i % 2 == 0 ? 1 : 0) + (i % 4 < 2 ? 1 : -1) * Math.ScaleB(1, -44 - i % 11) : 0.1 + 0.8 * rnd.NextDouble();
                var centre = new Sphere(a + d * t + q * gap, radius);
                object host = mode switch
                {
                    2 => new Capsule3(a, a + d, 0.25),
                    3 => new Line3(a, d),
                    4 => new Ray3(a, d),
                    _ => new Segment3(a, a + d),
                };
                var rs = RShape.FromAny(centre);
                var rh = RShape.FromAny(host);
                DistanceResult3 r = host switch
                {
                    Capsule3 c => ClosestDistance.Between(centre, c),
                    Line3 l => ClosestDistance.Between(centre, l),
                    Ray3 l => ClosestDistance.Between(centre, l),
                    _ => ClosestDistance.Between(centre, (Segment3)host),
                };
                // The witnesses are coordinates: each rounds by u·|coordinate| (the fuzz's tolerance has the same term).
                double m = Math.Max(Max(a), Math.Max(Max(a + d), Math.Max(Max(r.PointA), Max(r.PointB))));
                double tol = 64 * Exactly.U * Exact.Scale(rs, rh) + 16 * Exactly.U * m;
                double after = Exact.SignedDistance(rs.Translated(RVec.From(r.PointB) - RVec.From(r.PointA)), rh).ToDouble();
                Assert.That(r.Distance, Is.LessThan(0), $"case {i}: {centre} vs {host}");
                Assert.That(Math.Abs(after), Is.LessThanOrEqualTo(tol), $"case {i} (gap {gap:G3}, t {t:R}): {centre} vs {host} moved by PointB − PointA is {after:R} from touching");
            }
        }
    }
}
