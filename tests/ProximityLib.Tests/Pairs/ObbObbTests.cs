using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class ObbObbTests
    {
        private static Obb3 Turned(double x, double angle) =>
            Obb3.FromQuaternion(V(x, 0, 0), 0, 0, Math.Sin(angle / 2), Math.Cos(angle / 2), V(1, 1, 1));

        [Test]
        public void TwoDiamondsEdgeToEdge()
        {
            var r = ClosestDistance.Between(Turned(0, Math.PI / 4), Turned(4, Math.PI / 4));
            Assert.That(r.Distance, Is.EqualTo(4 - 2 * Math.Sqrt(2)).Within(1e-15));
            Assert.That(r.PointA.X, Is.EqualTo(Math.Sqrt(2)).Within(1e-15));
            Assert.That(r.PointB.X, Is.EqualTo(4 - Math.Sqrt(2)).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(Turned(0, Math.PI / 4), Turned(4, Math.PI / 4)), Is.False);
        }

        [Test]
        public void TwoDimensionalCornerToFace()
        {
            // A square turned 45° whose left corner is 0.5 right of an axis-aligned square's right face.
            var a = new ProximityLib.Double.Obb2(V(0, 0), 0.0, V(1, 1));
            var b = new ProximityLib.Double.Obb2(V(1.5 + Math.Sqrt(2), 0.25), Math.PI / 4, V(1, 1));
            var r = ClosestDistance.Between(a, b);
            Result(r, 0.5, V(1, 0.25), V(1.5, 0.25), 1e-15);
            Assert.That(ProximityQuery.Overlaps(a, b), Is.False);
            Assert.That(ClosestDistance.Between(a, new ProximityLib.Double.Obb2(V(0.75 + Math.Sqrt(2), 0.25), Math.PI / 4, V(1, 1))).Distance,
                Is.EqualTo(-0.25).Within(1e-15));
        }

        [Test]
        public void VertexIntoFace()
        {
            var r = ClosestDistance.Between(Turned(0, 0), Turned(2, Math.PI / 4));
            Assert.That(r.Distance, Is.EqualTo(-(Math.Sqrt(2) - 1)).Within(1e-15));
            Near(r.PointB - r.PointA, V(-(Math.Sqrt(2) - 1), 0, 0), 1e-15, "A is pushed back along −x");
            Assert.That(ProximityQuery.Overlaps(Turned(0, 0), Turned(2, Math.PI / 4)), Is.True);
        }

        [Test]
        public void SkewEdgesSeparatedOnlyByTheirCrossAxis()
        {
            // Two unit cubes: B turned 45° about x and about z... placed so only an edge × edge axis separates.
            double s = Math.Sqrt(0.5);
            var a = new Obb3(V(0, 0, 0), V(s, s, 0), V(-s, s, 0), V(0, 0, 1), V(1, 1, 1));    // edge along z at x = √2
            var b = new Obb3(V(2 * Math.Sqrt(2) + 0.25, 0, 0), V(s, 0, s), V(0, 1, 0), V(-s, 0, s), V(1, 1, 1)); // edge along y at x = c − √2
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(0.25).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(a, b), Is.False);
            var touching = new Obb3(V(2 * Math.Sqrt(2), 0, 0), V(s, 0, s), V(0, 1, 0), V(-s, 0, s), V(1, 1, 1));
            Assert.That(ClosestDistance.Between(a, touching).Distance, Is.EqualTo(0).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(a, new Obb3(V(2 * Math.Sqrt(2) - 1e-9, 0, 0), V(s, 0, s), V(0, 1, 0), V(-s, 0, s), V(1, 1, 1))), Is.True);
        }

        [Test]
        public void PaperFormCornersAndNormals()
        {
            var corners = new Vector3D[8];
            int i = 0;
            foreach (var x in new[] { -1.0, 1 })
                foreach (var y in new[] { -2.0, 2 })
                    foreach (var z in new[] { -3.0, 3 })
                        corners[i++] = V(x + 10, y, z);
            var box = Obb3.FromCorners(corners, V(1, 0, 0), V(0, 1, 0), V(0, 0, 1));
            Assert.That(box.Center, Is.EqualTo(V(10, 0, 0)));
            Assert.That(box.HalfExtents, Is.EqualTo(V(1, 2, 3)));
            var rect = Obb2.FromCorners(new[] { V(0, 0), V(2, 0), V(2, 1), V(0, 1) }, V(1, 0), V(0, 1));
            Assert.That(rect.Center, Is.EqualTo(V(1, 0.5)));
            Assert.That(rect.HalfExtents, Is.EqualTo(V(1, 0.5)));
            Assert.That(ProximityQuery.Overlaps(rect, new Obb2(V(2.5, 0.5), 0.0, V(0.5, 0.5))), Is.True);
        }

        // Regression (issue 10, item 3): edge × edge axes of nearly parallel edges were formed with a direction error
        // of u/sinθ, so the depth over them was overstated (−4.06e-10 where a push of 8.8e-11 already separates).
        [Test]
        public void NearlyIdenticalRotationsDoNotOverstateTheDepth()
        {
            var a = Obb3.FromQuaternion(V(0.286512385721557, 0.6234506031607514, 0.8550464119087189), 0.5494897961616516, 0.8015345931053162,
                0.23553642630577087, 0.011216752231121063, V(0.8142139775744704, 0.08036301521601295, 0.9474524459556921));
            var b = Obb3.FromQuaternion(V(0.57441937307967, -0.4629371176964279, 0.7969599187308414), 0.5494897961616516, 0.8015346346076113,
                0.23553642630577087, 0.011216752231121063, V(0.2764579808695512, 0, 0.4039006151277109));
            var r = ClosestDistance.Between(a, b);
            Assert.That(Exactly.Error(a, b, r.Distance), Is.LessThanOrEqualTo(32), $"D={r.Distance:R}, exact {Exactly.Distance(a, b):R}");
            AssertPushOutTouches(a, b, r);
        }

        /// <summary>
        /// Boxes whose rotations differ by 1e-6…1e-16 in the quaternion, placed edge to edge diagonally (where only an
        /// edge × edge axis of nearly parallel edges separates them) with gaps and overlaps from 1e-6 to 1e-13 of their
        /// size: distance within the bound, the verdict right outside the band, and the push-out just touching.
        /// </summary>
        [Test]
        public void NearlyIdenticalRotationsEdgeToEdge()
        {
            var rng = new Random(2630);
            foreach (double delta in new[] { 1e-6, 1e-9, 1e-12, 1e-16 })
                foreach (double gap in new[] { -1e-6, -1e-9, -1e-13, 0, 1e-13, 1e-9, 1e-6 })
                {
                    double qx = rng.NextDouble() - 0.5, qy = rng.NextDouble() - 0.5, qz = rng.NextDouble() - 0.5, qw = rng.NextDouble() - 0.5;
                    var ha = V(0.2 + rng.NextDouble(), 0.2 + rng.NextDouble(), 0.2 + rng.NextDouble());
                    var hb = V(0.2 + rng.NextDouble(), 0.2 + rng.NextDouble(), 0.2 + rng.NextDouble());
                    var a = Obb3.FromQuaternion(V(rng.NextDouble(), rng.NextDouble(), rng.NextDouble()), qx, qy, qz, qw, ha);
                    var diagonal = (a.AxisX + a.AxisY) / Math.Sqrt(2);
                    var center = a.Center + a.AxisX * (ha.X + hb.X) + a.AxisY * (ha.Y + hb.Y) + diagonal * gap;
                    var b = Obb3.FromQuaternion(center, qx + delta * (rng.NextDouble() - 0.5), qy + delta * (rng.NextDouble() - 0.5), qz, qw, hb);
                    var r = ClosestDistance.Between(a, b);
                    double exact = Exactly.Distance(a, b), scale = Exactly.Scale(a, b);
                    string what = $"δ={delta} gap={gap}: exact {exact:R}, got {r.Distance:R}";
                    Assert.That(Exactly.Error(a, b, r.Distance), Is.LessThanOrEqualTo(32), what);
                    if (Math.Abs(exact) > 32 * Exactly.U * scale)
                    {
                        Assert.That(ProximityQuery.Overlaps(a, b), Is.EqualTo(exact <= 0), "verdict, " + what);
                        Assert.That(ProximityQuery.Overlaps(b, a), Is.EqualTo(exact <= 0), "verdict swapped, " + what);
                    }
                    if (r.Distance < 0) AssertPushOutTouches(a, b, r);
                }
        }

        /// <summary>
        /// B turned 45° about z sits 0.1 deep on A's top face: the least push moves A down 0.1, and neither support corner
        /// touches after it (A's lies outside B's turned square, B's outside A), so the witnesses come from A's top edge
        /// across the push, which does.
        /// </summary>
        [Test]
        public void FaceOnFaceWitnessesFromTheEdgeAcrossThePush()
        {
            var a = Turned(0, 0);
            var b = Obb3.FromQuaternion(V(0, 0, 1.9), 0, 0, Math.Sin(Math.PI / 8), Math.Cos(Math.PI / 8), V(1, 1, 1));
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(-0.1).Within(1e-15));
            Near(r.PointB - r.PointA, V(0, 0, -0.1), 1e-15, "push");
            Assert.That(r.PointA.Z, Is.EqualTo(1).Within(1e-15));
            Assert.That(Math.Abs(r.PointB.X) + Math.Abs(r.PointB.Y), Is.LessThanOrEqualTo(Math.Sqrt(2) + 1e-15), "PointB on B's bottom square");
            Assert.That(Math.Max(Math.Abs(r.PointA.X), Math.Abs(r.PointA.Y)), Is.LessThanOrEqualTo(1 + 1e-15), "PointA on A's top face");
            Assert.That(ClosestDistance.Distance(a, b), Is.EqualTo(r.Distance));
            AssertPushOutTouches(a, b, r);
        }

        /// <summary>
        /// Overlapping boxes (B around a point of A, random rotations and sizes): the depth within the bound of the exact
        /// one, the witnesses a push that leaves the boxes touching, and the distance-only entry the same bits.
        /// </summary>
        [Test]
        public void OverlappingWitnessesPushToTouching()
        {
            var rng = new Random(1111);
            for (int i = 0; i < 150; i++)
            {
                Obb3 Box(Vector3D c) => Obb3.FromQuaternion(c, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5, rng.NextDouble() - 0.5,
                    V(0.1 + rng.NextDouble(), 0.1 + rng.NextDouble(), 0.1 + rng.NextDouble()));
                var a = Box(V(rng.NextDouble(), rng.NextDouble(), rng.NextDouble()));
                var inside = a.Center + a.AxisX * ((rng.NextDouble() * 2 - 1) * a.HalfExtents.X) + a.AxisY * ((rng.NextDouble() * 2 - 1) * a.HalfExtents.Y)
                    + a.AxisZ * ((rng.NextDouble() * 2 - 1) * a.HalfExtents.Z);
                var b = Box(inside);
                var r = ClosestDistance.Between(a, b);
                Assert.That(Exactly.Error(a, b, r.Distance), Is.LessThanOrEqualTo(32), $"case {i}");
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(a, b)), Is.EqualTo(BitConverter.DoubleToInt64Bits(r.Distance)), $"case {i}: distance alone");
                Assert.That(BitConverter.DoubleToInt64Bits(ClosestDistance.Distance(b, a)), Is.EqualTo(BitConverter.DoubleToInt64Bits(r.Distance)), $"case {i}: swapped");
                Assert.That((r.PointB - r.PointA).Length, Is.EqualTo(-r.Distance).Within(1e-12), $"case {i}: push length");
                AssertPushOutTouches(a, b, r);
            }
        }

        /// <summary>Moving A by PointB − PointA must leave the boxes touching: exact signed distance ≈ 0 afterwards.</summary>
        private static void AssertPushOutTouches(Obb3 a, Obb3 b, DistanceResult3 r)
        {
            var moved = new Obb3(a.Center + (r.PointB - r.PointA), a.AxisX, a.AxisY, a.AxisZ, a.HalfExtents);
            double scale = Exactly.Scale(a, b);
            Assert.That(Math.Abs(Exactly.Distance(moved, b)), Is.LessThanOrEqualTo(32 * Exactly.U * scale),
                $"after the push {r.PointB - r.PointA}: {Exactly.Distance(moved, b):R}");
        }
    }
}
