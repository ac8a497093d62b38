using System;
using NUnit.Framework;
using ProximityLib.Double;
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
    }
}
