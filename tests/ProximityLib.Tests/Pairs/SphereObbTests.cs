using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using ProximityTests.Support;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SphereObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        [Test]
        public void ApartFromTheNearestEdge()
        {
            var r = ClosestDistance.Between(new Sphere(V(3, 0, 0), 1), Diamond);
            Result(r, 2 - Math.Sqrt(2), V(2, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(ProximityQuery.Overlaps(new Sphere(V(3, 0, 0), 1), Diamond), Is.False);
        }

        [Test]
        public void OverlappingFace()
        {
            // The face x' = 1 has outward normal (√½, √½, 0); a sphere centred 0.5 beyond it with radius 1.
            var c = V(S, S, 0) * 1.5;
            var r = ClosestDistance.Between(new Sphere(c, 1), Diamond);
            Assert.That(r.Distance, Is.EqualTo(-0.5).Within(1e-15));
            Near(r.PointB, V(S, S, 0), 1e-15, "PointB");
            Assert.That(ProximityQuery.Overlaps(new Sphere(c, 1), Diamond), Is.True);
            var box2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            Assert.That(ClosestDistance.Between(new Circle(V(S * 1.5, S * 1.5), 1), box2).Distance, Is.EqualTo(-0.5).Within(1e-15));
        }

        /// <summary>
        /// Sphere and circle centres 1e-9 … 1e-15 outside a rotated box's edge or corner (size ~2, radius 0.2): the sphere
        /// moved by PointB − PointA must touch the box to within 64 u·S, checked exactly. The box-frame coordinates carry
        /// u·S, so the rounded residual's direction is off by u·S/gap there: it left up to 1e-4 of overlap.
        /// </summary>
        [TestCase(3)]
        [TestCase(2)]
        public void CentresNearAnEdgePushOutToTouching(int dim)
        {
            var rnd = new Random(7 + dim);
            for (int i = 0; i < 70; i++)
            {
                double h = Math.Pow(10, -9 - i % 7);
                var c = new Vector3D(rnd.NextDouble() * 3, rnd.NextDouble() * 3, dim == 3 ? rnd.NextDouble() * 3 : 0);
                var half = new Vector3D(0.5, 0.4, 0.3);
                object a, b;
                Vector3D ax, ay, az;
                var q = default(System.Numerics.Quaternion);
                if (dim == 3)
                {
                    q = System.Numerics.Quaternion.Normalize(new System.Numerics.Quaternion((float)rnd.NextDouble(), (float)rnd.NextDouble(), (float)rnd.NextDouble(), 1f));
                    var box = Obb3.FromQuaternion(c, q.X, q.Y, q.Z, q.W, half);
                    ax = box.AxisX; ay = box.AxisY; az = box.AxisZ;
                    b = box;
                }
                else
                {
                    double t = rnd.NextDouble() * 6;
                    var box = new Obb2(new Vector2D(c.X, c.Y), new Vector2D(Math.Cos(t), Math.Sin(t)), new Vector2D(half.X, half.Y));
                    ax = new Vector3D(box.AxisX.X, box.AxisX.Y, 0); ay = new Vector3D(box.AxisY.X, box.AxisY.Y, 0); az = default;
                    b = box;
                }
                // Beyond the +x, +y edge (3D: at a z inside, or past the corner every third case), leaving diagonally.
                bool corner = dim == 3 && i % 3 == 0;
                var onEdge = c + ax * half.X + ay * half.Y + az * (corner ? half.Z : 0.1);
                var away = ax * (0.3 + rnd.NextDouble()) + ay * (0.3 + rnd.NextDouble()) + (corner ? az * (0.3 + rnd.NextDouble()) : default);
                var centre = onEdge + away * (h / away.Length);
                a = dim == 3 ? new Sphere(centre, 0.2) : (object)new Circle(new Vector2D(centre.X, centre.Y), 0.2);
                var ra = RShape.FromAny(a);
                var rb = RShape.FromAny(b);
                double tol = 64 * Exactly.U * Exact.Scale(ra, rb);
                foreach (var (x, y, rx, ry) in new[] { (a, b, ra, rb), (b, a, rb, ra) })
                {
                    var r = Api.Between(x, y);
                    var pa = dim == 3 ? RVec.From((Vector3D)r.PointA) : RVec.From((Vector2D)r.PointA);
                    var pb = dim == 3 ? RVec.From((Vector3D)r.PointB) : RVec.From((Vector2D)r.PointB);
                    double after = Exact.SignedDistance(rx.Translated(pb - pa), ry).ToDouble();
                    Assert.That((double)r.Distance, Is.LessThan(0), $"case {i}: {x} vs {y}");
                    Assert.That(Math.Abs(after), Is.LessThanOrEqualTo(tol), $"case {i} (gap {h:G1}): {x} vs {y} moved by PointB − PointA is {after:R} from touching");
                }
                // The normal's exact steps scale: inputs scaled by 2^-440 and 2^400 give the same witnesses scaled (the box
                // rebuilt from the same quaternion: the axes constructor would re-orthonormalise them).
                if (a is Sphere sp && b is Obb3 ob)
                    foreach (int e in new[] { -440, 400 })
                    {
                        double f = Math.ScaleB(1, e);
                        var r = ClosestDistance.Between(sp, ob);
                        var rs = ClosestDistance.Between(new Sphere(sp.Center * f, sp.Radius * f), Obb3.FromQuaternion(ob.Center * f, q.X, q.Y, q.Z, q.W, ob.HalfExtents * f));
                        Assert.That(rs.PointA, Is.EqualTo(r.PointA * f), $"case {i}, 2^{e}");
                        Assert.That(rs.PointB, Is.EqualTo(r.PointB * f), $"case {i}, 2^{e}");
                    }
            }
        }
    }
}
