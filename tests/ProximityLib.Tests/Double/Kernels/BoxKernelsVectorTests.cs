using System;
using NUnit.Framework;
using ProximityLib.Double;

namespace ProximityTests.Double.Kernels
{
    /// <summary>The AVX2 box–box overlap test (modern .NET on x86) against the scalar one (netstandard2.1, other CPUs, planar boxes).</summary>
    public class BoxKernelsVectorTests
    {
        /// <summary>
        /// The reference the OBB entries must match: the overlap test on the shapes' Box forms, and whether the forms'
        /// largest magnitude (their relative origin and extents, as the box kernels measure size) is in the fast range.
        /// </summary>
        private static bool BoxForms(in Box a, in Box b, out bool inRange)
        {
            inRange = ProximityLib.Double.Range.Box(ProximityLib.Double.Range.MaxAbs(b.Origin - a.Origin, a.Hi - a.Lo, b.Hi - b.Lo));
            return ProximityLib.Double.Kernels.BoxBoxOverlaps(a, b);
        }

        /// <summary><see cref="BoxForms"/> in the plane.</summary>
        private static bool BoxForms2(in Box2 a, in Box2 b, out bool inRange)
        {
            inRange = ProximityLib.Double.Range.Box(ProximityLib.Double.Range.MaxAbs(b.Origin - a.Origin, a.Hi - a.Lo, b.Hi - b.Lo));
            return ProximityLib.Double.Kernels.BoxBoxOverlaps2(a, b);
        }

        private static Obb3 RandomBox(Random r, double spread, double scale) =>
            new Obb3(new Vector3D(r.NextDouble() * spread, r.NextDouble() * spread, r.NextDouble() * spread) * scale,
                new System.Numerics.Quaternion((float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f, (float)r.NextDouble() - 0.5f),
                new Vector3D(0.2 + r.NextDouble(), 0.2 + r.NextDouble(), 0.2 + r.NextDouble()) * scale);

        [TestCase(1.0)]
        [TestCase(1e-6)]
        [TestCase(1e6)]
        public void VerdictsAgreeWithTheScalarFormAwayFromTouching(double scale)
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(2026);
            int overlapping = 0, apart = 0;
            for (int i = 0; i < 3000; i++)
            {
                var a = RandomBox(r, 3, scale);
                // Every third B is A's own frame nearly: stacked boxes with nearly parallel edges.
                var b = i % 3 == 0
                    ? new Obb3(a.Center + new Vector3D(0, 0, a.HalfExtents.Z * (2 + (r.NextDouble() - 0.5) * 1e-3)), a.AxisX, a.AxisY, a.AxisZ, a.HalfExtents)
                    : RandomBox(r, 3, scale);
                bool scalar = ProximityLib.Double.Kernels.BoxBoxOverlapsScalar(a.ToBox(), b.ToBox());
                bool vector = ProximityLib.Double.Kernels.BoxBoxOverlapsVector(a.ToBox(), b.ToBox());
                if (scalar == vector) { if (scalar) overlapping++; else apart++; continue; }
                // The two forms may round the last additions of an edge axis differently: only just-touching pairs may differ.
                double gap = ClosestDistance.Between(a, b).Distance;
                Assert.That(Math.Abs(gap), Is.LessThan(1e-12 * scale), $"case {i}: scalar {scalar}, vector {vector}, gap {gap}");
            }
            Assert.That(overlapping, Is.GreaterThan(300));
            Assert.That(apart, Is.GreaterThan(300));
        }

        [Test]
        public void AxisAlignedAgainstOrientedAgrees()
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(7);
            for (int i = 0; i < 2000; i++)
            {
                var min = new Vector3D(r.NextDouble(), r.NextDouble(), r.NextDouble()) * 2;
                var a = new Aabb3(min, min + new Vector3D(0.1 + r.NextDouble(), 0.1 + r.NextDouble(), 0.1 + r.NextDouble()));
                var b = RandomBox(r, 3, 1);
                Assert.That(ProximityLib.Double.Kernels.BoxBoxOverlapsVector(a.ToBox(), b.ToBox()),
                    Is.EqualTo(ProximityLib.Double.Kernels.BoxBoxOverlapsScalar(a.ToBox(), b.ToBox())), $"case {i}");
            }
        }

        /// <summary>
        /// The overlap entries that make their vectors from the shapes' fields give the verdict and the range flag of the
        /// test on the shapes' <see cref="Box"/> forms, at unit scale and at scales outside the fast range.
        /// </summary>
        [TestCase(1.0)]
        [TestCase(1e-140)]
        [TestCase(1e140)]
        public void OverlapEntriesFromTheShapesMatchTheBoxForms(double scale)
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(29);
            for (int i = 0; i < 2000; i++)
            {
                var a = RandomBox(r, 3, scale);
                var b = RandomBox(r, 3, scale);
                var min = new Vector3D(r.NextDouble(), r.NextDouble(), r.NextDouble()) * (2 * scale);
                var c = new Aabb3(min, min + new Vector3D(0.1 + r.NextDouble(), 0.1 + r.NextDouble(), 0.1 + r.NextDouble()) * scale);
                bool obb = BoxForms(a.ToBox(), b.ToBox(), out bool obbIn);
                Assert.That(ProximityLib.Double.Kernels.ObbObbOverlapsVector(a, b), Is.EqualTo((obb ? 1 : 0) | (obbIn ? 2 : 0)), $"case {i}: OBB–OBB");
                bool aabb = BoxForms(c.ToBox(), b.ToBox(), out bool aabbIn);
                Assert.That(ProximityLib.Double.Kernels.AabbObbOverlapsVector(c, b), Is.EqualTo((aabb ? 1 : 0) | (aabbIn ? 2 : 0)), $"case {i}: AABB–OBB");
            }
        }

        /// <summary>
        /// The scalar overlap entries (Mono, Unity, no AVX2), which read the shapes' fields instead of building their
        /// <see cref="Box"/> forms, give the scalar test's verdict on the Box forms and their range flag, at unit scale,
        /// outside the fast range, and for default(Obb3) (no stored axes). Runs on every machine.
        /// </summary>
        [TestCase(1.0)]
        [TestCase(1e-140)]
        [TestCase(1e140)]
        public void ScalarOverlapEntriesFromTheShapesMatchTheBoxForms(double scale)
        {
            var r = new Random(31);
            int overlapping = 0;
            for (int i = 0; i < 3000; i++)
            {
                var a = i % 50 == 0 ? default : RandomBox(r, 3, scale);
                var b = i % 3 == 0
                    ? new Obb3(a.Center + new Vector3D(0, 0, a.HalfExtents.Z * (2 + (r.NextDouble() - 0.5) * 1e-3)), a.AxisX, a.AxisY, a.AxisZ, a.HalfExtents + new Vector3D(scale, scale, scale))
                    : RandomBox(r, 3, scale);
                var min = new Vector3D(r.NextDouble(), r.NextDouble(), r.NextDouble()) * (2 * scale);
                var c = new Aabb3(min, min + new Vector3D(0.1 + r.NextDouble(), 0.1 + r.NextDouble(), 0.1 + r.NextDouble()) * scale);
                bool obbIn = ProximityLib.Double.Kernels.ObbObbOverlapsScalar(a, b, out bool obbRange);
                Assert.That(obbIn, Is.EqualTo(ProximityLib.Double.Kernels.BoxBoxOverlapsScalar(a.ToBox(), b.ToBox())), $"case {i}: OBB–OBB");
                BoxForms(a.ToBox(), b.ToBox(), out bool boxRange);
                Assert.That(obbRange, Is.EqualTo(boxRange), $"case {i}: OBB–OBB range");
                bool aabbIn = ProximityLib.Double.Kernels.AabbObbOverlapsScalar(c, b, out bool aabbRange);
                Assert.That(aabbIn, Is.EqualTo(ProximityLib.Double.Kernels.BoxBoxOverlapsScalar(c.ToBox(), b.ToBox())), $"case {i}: AABB–OBB");
                BoxForms(c.ToBox(), b.ToBox(), out boxRange);
                Assert.That(aabbRange, Is.EqualTo(boxRange), $"case {i}: AABB–OBB range");
                if (obbIn) overlapping++;

                // The planar entries against the planar test on the Box2 forms.
                Obb2 Rect() => new Obb2(new Vector2D(r.NextDouble() * 3, r.NextDouble() * 3) * scale, new Vector2D(r.NextDouble() - 0.5, r.NextDouble() - 0.5),
                    new Vector2D(0.2 + r.NextDouble(), 0.2 + r.NextDouble()) * scale);
                var a2 = i % 50 == 0 ? default : Rect();
                var b2 = Rect();
                var min2 = new Vector2D(r.NextDouble(), r.NextDouble()) * (2 * scale);
                var c2 = new Aabb2(min2, min2 + new Vector2D(0.1 + r.NextDouble(), 0.1 + r.NextDouble()) * scale);
                bool obb2 = ProximityLib.Double.Kernels.ObbObbOverlaps2(a2, b2, out bool obb2Range);
                Assert.That(obb2, Is.EqualTo(BoxForms2(a2.ToBox2(), b2.ToBox2(), out bool box2Range)), $"case {i}: 2D OBB–OBB");
                Assert.That(obb2Range, Is.EqualTo(box2Range), $"case {i}: 2D OBB–OBB range");
                bool aabb2 = ProximityLib.Double.Kernels.AabbObbOverlaps2(c2, b2, out bool aabb2Range);
                Assert.That(aabb2, Is.EqualTo(BoxForms2(c2.ToBox2(), b2.ToBox2(), out box2Range)), $"case {i}: 2D AABB–OBB");
                Assert.That(aabb2Range, Is.EqualTo(box2Range), $"case {i}: 2D AABB–OBB range");
            }
            Assert.That(overlapping, Is.InRange(300, 2700));
        }

        /// <summary>
        /// The OBB entries load each Vector3D field with the double after it (the last field with the double before it):
        /// that double must lie in the same struct. The fields' order and the struct's size are what the loads assume.
        /// </summary>
        [Test]
        public void TheInPlaceLoadsStayInsideTheShapes()
        {
            var o = new Obb3(new Vector3D(1, 2, 3), Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ, new Vector3D(4, 5, 6));
            var c = new Aabb3(new Vector3D(1, 2, 3), new Vector3D(4, 5, 6));
            Assert.That(System.Runtime.CompilerServices.Unsafe.ByteOffset(ref System.Runtime.CompilerServices.Unsafe.AsRef(in o.Center.X),
                ref System.Runtime.CompilerServices.Unsafe.AsRef(in o.HalfExtents.X)), Is.EqualTo((IntPtr)24), "HalfExtents right after Center");
            Assert.That(System.Runtime.CompilerServices.Unsafe.ByteOffset(ref System.Runtime.CompilerServices.Unsafe.AsRef(in c.Min.X),
                ref System.Runtime.CompilerServices.Unsafe.AsRef(in c.Max.X)), Is.EqualTo((IntPtr)24), "Max right after Min");
            unsafe
            {
                Assert.That(sizeof(Obb3), Is.EqualTo(128));
                double* axes = Obb3.StoredAxes(&o);
                Assert.That((byte*)&o.Center.X - (byte*)axes, Is.EqualTo(80), "axes first, then the flags (8 bytes with padding), then Center");
                Assert.That(new[] { axes[0], axes[4], axes[8] }, Is.EqualTo(new[] { 1.0, 1.0, 1.0 }), "three axes of three doubles in a row");
            }
        }

        /// <summary>default(Obb3) stores no axes (they read as the world's): the in-place loads must not be used for it.</summary>
        [Test]
        public void DefaultObbOverlapsAsItsBoxForm()
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(31);
            var d = default(Obb3);
            int overlapping = 0;
            for (int i = 0; i < 500; i++)
            {
                var b = RandomBox(r, 0.6, 1);
                bool box = BoxForms(d.ToBox(), b.ToBox(), out bool boxIn);
                Assert.That(ProximityLib.Double.Kernels.ObbObbOverlapsVector(d, b), Is.EqualTo((box ? 1 : 0) | (boxIn ? 2 : 0)), $"case {i}: default first");
                bool swapped = BoxForms(b.ToBox(), d.ToBox(), out bool swappedIn);
                Assert.That(ProximityLib.Double.Kernels.ObbObbOverlapsVector(b, d), Is.EqualTo((swapped ? 1 : 0) | (swappedIn ? 2 : 0)), $"case {i}: default second");
                var c = new Aabb3(b.Center - b.HalfExtents, b.Center + b.HalfExtents);
                bool aabb = BoxForms(c.ToBox(), d.ToBox(), out bool aabbIn);
                Assert.That(ProximityLib.Double.Kernels.AabbObbOverlapsVector(c, d), Is.EqualTo((aabb ? 1 : 0) | (aabbIn ? 2 : 0)), $"case {i}: AABB–default");
                if (box) overlapping++;
            }
            Assert.That(overlapping, Is.InRange(50, 450), "both verdicts occur");
        }

        /// <summary>
        /// The box–box test and depth search on AVX2 lanes against the scalar forms: the overlap test's verdict, and for
        /// overlapping boxes the scalar depth search's axis, depth (bits) and push: random boxes, boxes stacked with nearly
        /// parallel edges, identical boxes (exact ties between axes), and boxes a tiny rotation apart (edge axes of
        /// nearly zero length), as AABB–OBB pairs too.
        /// </summary>
        [Test]
        public void DepthSearchMatchesTheScalarFormBitForBit()
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(11);
            int overlapping = 0;
            for (int i = 0; i < 4000; i++)
            {
                Box a, b;
                var oa = RandomBox(r, 1, 1);
                switch (i % 5)
                {
                    case 0: a = oa.ToBox(); b = RandomBox(r, 1, 1).ToBox(); break;
                    // Stacked, nearly parallel edges.
                    case 1:
                        a = oa.ToBox();
                        b = new Obb3(oa.Center + new Vector3D(0, 0, oa.HalfExtents.Z * (2 - r.NextDouble() * 1e-3)), oa.AxisX, oa.AxisY, oa.AxisZ, oa.HalfExtents).ToBox();
                        break;
                    // Identical centres and boxes: exact ties between axes.
                    case 2: a = oa.ToBox(); b = oa.ToBox(); break;
                    // A tiny rotation apart, shifted.
                    case 3:
                        {
                            double angle = Math.ScaleB(1, -r.Next(10, 60));
                            var q = System.Numerics.Quaternion.CreateFromAxisAngle(System.Numerics.Vector3.Normalize(new System.Numerics.Vector3(1, 2, 3)), (float)angle);
                            var c = oa.Center + new Vector3D(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5);
                            a = new Obb3(oa.Center, new System.Numerics.Quaternion(0, 0, 0, 1), oa.HalfExtents).ToBox();
                            b = new Obb3(c, q, oa.HalfExtents).ToBox();
                            break;
                        }
                    // An AABB against an OBB.
                    default:
                        a = new Aabb3(oa.Center - oa.HalfExtents, oa.Center + oa.HalfExtents * 2).ToBox();
                        b = RandomBox(r, 1, 1).ToBox();
                        break;
                }
                var t = (b.Origin - a.Origin + b.ToWorldOffset(b.LocalCenter)) - a.ToWorldOffset(a.LocalCenter);
                bool overlap = ProximityLib.Double.Kernels.OverlapDepthVector(a, b, t, out double vector, out var pushVector);
                Assert.That(overlap, Is.EqualTo(ProximityLib.Double.Kernels.BoxBoxOverlapsVector(a, b)), $"case {i}: verdict");
                if (!overlap) continue;
                overlapping++;
                double scalar = ProximityLib.Double.Kernels.PenetrationScalar(a, b, t, out var pushScalar);
                Assert.That(BitConverter.DoubleToInt64Bits(vector), Is.EqualTo(BitConverter.DoubleToInt64Bits(scalar)), $"case {i}: depth");
                Assert.That(pushVector, Is.EqualTo(pushScalar), $"case {i}: push");
            }
            Assert.That(overlapping, Is.GreaterThan(2000), "mostly overlapping boxes");
        }

        /// <summary>
        /// The vertex stage of the box–box distance on AVX2 lanes against the scalar form: the same least squared gap (bits),
        /// the same corner, the same edges to minimise, for corners inside, outside and on the other box's faces.
        /// </summary>
        [Test]
        public void VerticesMatchTheScalarFormBitForBit()
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(5);
            Vector3D V(double s) => new Vector3D(r.NextDouble() - 0.5, r.NextDouble() - 0.5, r.NextDouble() - 0.5) * s;
            for (int i = 0; i < 4000; i++)
            {
                // Grid values (multiples of 1/4) put corners exactly on faces and gaps exactly at 0 or tied.
                bool grid = i % 2 == 0;
                Vector3D G(double s) { var v = V(s); return grid ? new Vector3D(Math.Round(v.X * 4) / 4, Math.Round(v.Y * 4) / 4, Math.Round(v.Z * 4) / 4) : v; }
                Vector3D pa = G(4), dx = G(2), dy = G(2), dz = G(2), pb = G(4), ex = G(2), ey = G(2), ez = G(2);
                Vector3D Abs(Vector3D v) => new Vector3D(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));
                Vector3D loA = -Abs(G(2)), hiA = Abs(G(2)), loB = -Abs(G(2)), hiB = Abs(G(2));
                bool planar = i % 5 == 0;
                var corners = new ProximityLib.Double.Kernels.Corners(pa, dx, dy, dz, loB, hiB, pb, ex, ey, ez, loA, hiA);
                double scalar = ProximityLib.Double.Kernels.VerticesScalar(corners, planar, out int winS, out uint edgesS);
                double vector = ProximityLib.Double.Kernels.VerticesVector(corners, planar, out int winV, out uint edgesV);
                Assert.That(BitConverter.DoubleToInt64Bits(vector), Is.EqualTo(BitConverter.DoubleToInt64Bits(scalar)), $"case {i}: gap");
                Assert.That(winV, Is.EqualTo(winS), $"case {i}: corner");
                Assert.That(edgesV, Is.EqualTo(edgesS), $"case {i}: edges");
            }
        }

        /// <summary>
        /// The planar corner stage on AVX2 lanes against its scalar form: the same least squared gap (bits) and the same
        /// corner, for corners inside, outside and on the other box's sides (grid values make exact ties).
        /// </summary>
        [Test]
        public void PlanarCornersMatchTheScalarFormBitForBit()
        {
            if (!System.Runtime.Intrinsics.X86.Avx2.IsSupported) Assert.Ignore("no AVX2: only the scalar form runs here");
            var r = new Random(17);
            for (int i = 0; i < 4000; i++)
            {
                bool grid = i % 2 == 0;
                Vector2D G(double s)
                {
                    var v = new Vector2D(r.NextDouble() - 0.5, r.NextDouble() - 0.5) * s;
                    return grid ? new Vector2D(Math.Round(v.X * 4) / 4, Math.Round(v.Y * 4) / 4) : v;
                }
                Vector2D Abs(Vector2D v) => new Vector2D(Math.Abs(v.X), Math.Abs(v.Y));
                Vector2D pa = G(4), dx = G(2), dy = G(2), pb = G(4), ex = G(2), ey = G(2);
                Vector2D loA = -Abs(G(2)), hiA = Abs(G(2)), loB = -Abs(G(2)), hiB = Abs(G(2));
                double k = Math.ScaleB(1, r.Next(-4, 5));
                double scalar = ProximityLib.Double.Kernels.Corners2Scalar(pa, dx, dy, loB, hiB, pb, ex, ey, loA, hiA, k, out int winS);
                double vector = ProximityLib.Double.Kernels.Corners2Vector(pa, dx, dy, loB, hiB, pb, ex, ey, loA, hiA, k, out int winV);
                Assert.That(BitConverter.DoubleToInt64Bits(vector), Is.EqualTo(BitConverter.DoubleToInt64Bits(scalar)), $"case {i}: gap");
                Assert.That(winV, Is.EqualTo(winS), $"case {i}: corner");
            }
        }

        /// <summary>
        /// The planar box–box query on AVX2 lanes (corners and the depth search) against the planar boxes run through the
        /// 3D kernel with its scalar steps: the same distance bits and witnesses, overlapping, apart and tied.
        /// </summary>
        [Test]
        public void PlanarKernelMatchesTheThreeDimensionalOne()
        {
            var r = new Random(23);
            for (int i = 0; i < 3000; i++)
            {
                var a = new Obb2(new Vector2D(r.NextDouble() * 3, r.NextDouble() * 3), (i % 3 == 0 ? Math.Round(r.NextDouble() * 8) / 4 : r.NextDouble()) * Math.PI,
                    new Vector2D(0.2 + r.NextDouble(), 0.2 + r.NextDouble()));
                var b = i % 5 == 0 ? a : new Obb2(new Vector2D(r.NextDouble() * 3, r.NextDouble() * 3), r.NextDouble() * 7, new Vector2D(0.2 + r.NextDouble(), 0.2 + r.NextDouble()));
                var c = new Aabb2(new Vector2D(r.NextDouble() * 2, r.NextDouble() * 2), new Vector2D(2 + r.NextDouble(), 2 + r.NextDouble()));
                Check(a.ToBox2(), b.ToBox2(), a.ToBox(), b.ToBox(), i);
                Check(c.ToBox2(), b.ToBox2(), c.ToBox(), b.ToBox(), i);
            }

            static void Check(Box2 a2, Box2 b2, Box a3, Box b3, int i)
            {
                var planar = ProximityLib.Double.Kernels.BoxBox2(a2, b2, out bool in2);
                var lifted = ProximityLib.Double.Kernels.BoxBox(a3, b3, out bool in3).To2();
                Assert.That(planar.Distance, Is.EqualTo(lifted.Distance), $"case {i}: distance");
                Assert.That(planar.PointA, Is.EqualTo(lifted.PointA), $"case {i}: point A");
                Assert.That(planar.PointB, Is.EqualTo(lifted.PointB), $"case {i}: point B");
                Assert.That(in2, Is.EqualTo(in3), $"case {i}: in range");
                Assert.That(ProximityLib.Double.Kernels.BoxBoxDistance2(a2, b2, out _), Is.EqualTo(planar.Distance), $"case {i}: distance alone");
                Assert.That(ProximityLib.Double.Kernels.BoxBoxOverlaps2(a2, b2), Is.EqualTo(ProximityLib.Double.Kernels.BoxBoxOverlapsScalar(a3, b3)), $"case {i}: overlap");
            }
        }
    }
}
