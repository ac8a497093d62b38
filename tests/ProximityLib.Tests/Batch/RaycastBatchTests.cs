using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Batch;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximityTests.Batch
{
    /// <summary>
    /// One ray against many spheres, boxes and triangles: every lane against the scalar double ray cast (hit flags outside
    /// a band, T within the float bound), the vector lanes against the scalar lanes bit for bit, maxDistance, and bad
    /// arguments. (ScalarLanesTests and WorkersTests also run these through Sets.EachQuery.)
    /// </summary>
    public class RaycastBatchTests
    {
        private const double UFloat = 1.0 / (1 << 24);

        private static Vector3 P(Random r, float s = 4) => new Vector3((float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1)) * s;

        private static void Check(string name, float[] batch, Func<int, D.RayHit3> scalar, Func<int, double> scale)
        {
            int hits = 0, decided = 0;
            for (int i = 0; i < batch.Length; i++)
            {
                var h = scalar(i);
                double s = scale(i), band = 64 * UFloat * s;
                Assert.That(float.IsNaN(batch[i]), Is.False, $"{name} lane {i}");
                if (h.Hit && !float.IsPositiveInfinity(batch[i]))
                {
                    hits++;
                    Assert.That(Math.Abs(batch[i] - h.T), Is.LessThanOrEqualTo(band), $"{name} lane {i}: batch {batch[i]:R}, scalar {h}");
                }
                else if (h.Hit != !float.IsPositiveInfinity(batch[i]))
                {
                    // A disagreement only within the band: a graze the float rounding decides.
                    var near = D.Raycast.Cast(new D.Ray3(Ray.Inner.Origin, Ray.Inner.Direction), Inflate(i, band)).Hit;
                    Assert.That(near, Is.EqualTo(true), $"{name} lane {i}: batch {batch[i]:R}, scalar {h}");
                }
                else decided++;
            }
            Assert.That(hits, Is.GreaterThan(batch.Length / 10), name);
        }

        // The shapes of the current check, for Inflate.
        private static F.Ray3 Ray;
        private static Func<int, double, D.Sphere> _inflate = (i, b) => default;
        private static D.Sphere Inflate(int i, double band) => _inflate(i, band);

        [TestCase(1000, 1), TestCase(37, 2)]
        public void SpheresMatchTheScalarCast(int n, int seed)
        {
            var r = new Random(seed);
            Ray = new F.Ray3(P(r), P(r));
            var ray = Ray;
            // Centers near the ray's line, ahead and behind.
            var spheres = Enumerable.Range(0, n).Select(i => new F.Sphere(ray.Origin + ray.Direction * ((float)r.NextDouble() * 12 - 4) + P(r, 1.5f), i % 7 == 0 ? 0 : (float)r.NextDouble() * 2)).ToArray();
            var t = new float[n];
            BatchQuery.Raycasts(Ray, new SphereSet(spheres), t);
            _inflate = (i, b) => new D.Sphere(spheres[i].Inner.Center, spheres[i].Inner.Radius + b);
            Check("sphere", t, i => D.Raycast.Cast(Ray.Inner, spheres[i].Inner), i => 8 + spheres[i].Radius);
        }

        [TestCase(1000, 3), TestCase(37, 4)]
        public void BoxesMatchTheScalarCast(int n, int seed)
        {
            var r = new Random(seed);
            var boxes = Enumerable.Range(0, n).Select(i => F.Aabb3.FromCenter(P(r), Vector3.Abs(P(r, 1)))).ToArray();
            foreach (var d in new[] { P(r), new Vector3(0, 0.5f, 1), Vector3.UnitX })
            {
                Ray = new F.Ray3(P(r), d);
                var t = new float[n];
                BatchQuery.Raycasts(Ray, new AabbSet(boxes), t);
                _inflate = (i, b) => new D.Sphere(boxes[i].Inner.Center, (boxes[i].Inner.Max - boxes[i].Inner.Min).Length);
                for (int i = 0; i < n; i++)
                {
                    var h = D.Raycast.Cast(Ray.Inner, boxes[i].Inner);
                    if (h.Hit == !float.IsPositiveInfinity(t[i]))
                    {
                        if (h.Hit) Assert.That(Math.Abs(t[i] - h.T), Is.LessThanOrEqualTo(64 * UFloat * 16), $"lane {i}: {t[i]:R} vs {h}");
                        continue;
                    }
                    // Disagreements only at grazes: the scalar hit is at an entry equal to the exit within rounding.
                    var shrunk = D.Raycast.Cast(Ray.Inner, D.Aabb3.FromCenter(boxes[i].Inner.Center, boxes[i].Inner.Max - boxes[i].Inner.Center - new D.Vector3D(1e-5, 1e-5, 1e-5)));
                    var grown = D.Raycast.Cast(Ray.Inner, D.Aabb3.FromCenter(boxes[i].Inner.Center, boxes[i].Inner.Max - boxes[i].Inner.Center + new D.Vector3D(1e-5, 1e-5, 1e-5)));
                    Assert.That(!shrunk.Hit && grown.Hit, $"lane {i}: batch {t[i]:R}, scalar {h}");
                }
            }
        }

        [TestCase(1000, 5), TestCase(37, 6)]
        public void TrianglesMatchTheScalarCast(int n, int seed)
        {
            var r = new Random(seed);
            Ray = new F.Ray3(P(r, 8), P(r));
            var ray = Ray;
            var tris = Enumerable.Range(0, n).Select(i =>
            {
                var c = ray.Origin + ray.Direction * ((float)r.NextDouble() * 12 - 2);
                return new F.Triangle3(c + P(r), c + P(r), c + P(r));
            }).ToArray();
            var t = new float[n];
            BatchQuery.Raycasts(Ray, new TriangleSet(tris), t);
            int hits = 0;
            for (int i = 0; i < n; i++)
            {
                var h = D.Raycast.Cast(Ray.Inner, tris[i].Inner);
                if (h.Hit == !float.IsPositiveInfinity(t[i]))
                {
                    if (h.Hit) { hits++; Assert.That(Math.Abs(t[i] - h.T), Is.LessThanOrEqualTo(1e-4 * 16), $"lane {i}: {t[i]:R} vs {h}"); }
                    continue;
                }
                // Near an edge: the hit point of the scalar cast (or the plane crossing) lies within float rounding of the boundary.
                var e = tris[i].Inner;
                var moved = D.Raycast.Cast(new D.Ray3(Ray.Inner.Origin + new D.Vector3D(1e-4, 1e-4, 1e-4), Ray.Inner.Direction), e).Hit
                    != D.Raycast.Cast(new D.Ray3(Ray.Inner.Origin - new D.Vector3D(1e-4, 1e-4, 1e-4), Ray.Inner.Direction), e).Hit;
                Assert.That(moved, $"lane {i}: batch {t[i]:R}, scalar {h}");
            }
            Assert.That(hits, Is.GreaterThan(n / 10));
        }

        [Test]
        public void HandWorkedLanesAndMaxDistance()
        {
            var ray = new F.Ray3(new Vector3(-5, 0, 0), Vector3.UnitX);
            var spheres = new SphereSet(new[] { new F.Sphere(Vector3.Zero, 2), new F.Sphere(new Vector3(0, 2, 0), 2), new F.Sphere(new Vector3(-5, 0, 0), 1), new F.Sphere(new Vector3(-9, 0, 0), 1) });
            var t = new float[4];
            BatchQuery.Raycasts(ray, spheres, t);
            Assert.That(t, Is.EqualTo(new[] { 3f, 5f, 0f, float.PositiveInfinity }));
            BatchQuery.Raycasts(ray, spheres, t, 4);
            Assert.That(t, Is.EqualTo(new[] { 3f, float.PositiveInfinity, 0f, float.PositiveInfinity }));
            var boxes = new AabbSet(new[] { new F.Aabb3(Vector3.Zero, new Vector3(2)), new F.Aabb3(new Vector3(0, -1, -1), new Vector3(1, 0, 1)), new F.Aabb3(new Vector3(0, 0.5f, 0), new Vector3(1)) });
            BatchQuery.Raycasts(ray, boxes, t.AsSpan(0, 3));
            Assert.That(t.Take(3), Is.EqualTo(new[] { 5f, 5f, float.PositiveInfinity })); // along a face, through an edge, parallel outside
            var tris = new TriangleSet(new[] { new F.Triangle3(new Vector3(0, -1, -1), new Vector3(0, 1, -1), new Vector3(0, 0, 1)), new F.Triangle3(new Vector3(0, 0, 0), new Vector3(0, 1, 0), new Vector3(0, 0, 1)), new F.Triangle3(new Vector3(1, 0, 0), new Vector3(2, 0, 0), new Vector3(3, 0, 0)) });
            BatchQuery.Raycasts(ray, tris, t.AsSpan(0, 3));
            Assert.That(t.Take(3), Is.EqualTo(new[] { 5f, 5f, 6f })); // through the face, through a vertex, degenerate: the segment it is, met at x = 1
            Assert.That(() => BatchQuery.Raycasts(ray, spheres, t, -1), Throws.ArgumentException.With.Property("ParamName").EqualTo("maxDistance"));
            Assert.That(() => BatchQuery.Raycasts(ray, boxes, t, float.NaN), Throws.ArgumentException.With.Property("ParamName").EqualTo("maxDistance"));
            Assert.That(() => BatchQuery.Raycasts(ray, tris, new float[2]), Throws.ArgumentException.With.Property("ParamName").EqualTo("result"));
        }

        /// <summary>
        /// Lanes whose determinant is rounding give the scalar cast's T, bit for bit, among ordinary lanes, in sets that
        /// fill whole vectors and sets that do not: a needle the ray passes 1e-7 from (fuzz 12:54466, where the float lane
        /// gave T = 3.77 at a point 6e-6 off it; the scalar cast misses), and, for a ray along x, a collinear triangle
        /// across it (edge-on hit at 2) and a triangle in its plane (edge-on hit where it enters, 1.5); both were misses.
        /// </summary>
        [Test]
        public void IllConditionedLanesAreTheScalarCast()
        {
            var ray = new F.Ray3(new Vector3(-1.7267025f, 1.4057068f, -1.5268404f), new Vector3(2.4714317f, -2.0419598f, 1.9442941f));
            var needle = new F.Triangle3(new Vector3(0.508964f, -0.1677447f, 0.85423154f), new Vector3(1.0014403f, -1.1463846f, -0.058128674f), new Vector3(0.51231945f, -0.17441256f, 0.8480153f));
            var plain = new F.Triangle3(ray.Origin + ray.Direction * 2 + new Vector3(0, 1, -1), ray.Origin + ray.Direction * 2 + new Vector3(0, -1, -1), ray.Origin + ray.Direction * 2 + new Vector3(0, 0, 1));
            var alongX = new F.Ray3(Vector3.Zero, Vector3.UnitX);
            var collinear = new F.Triangle3(new Vector3(2, -1, 0), new Vector3(2, 1, 0), new Vector3(2, 0.5f, 0));
            var inPlane = new F.Triangle3(new Vector3(1, -1, 0), new Vector3(3, -1, 0), new Vector3(2, 1, 0));
            Assert.That(F.Raycast.Cast(ray, needle).Hit, Is.False);
            Assert.That(F.Raycast.Cast(alongX, collinear).T, Is.EqualTo(2f));
            Assert.That(F.Raycast.Cast(alongX, inPlane).T, Is.EqualTo(1.5f));
            foreach (var (r, shapes) in new[] { (ray, new[] { needle, plain }), (alongX, new[] { collinear, inPlane, collinear }) })
                foreach (int count in new[] { 1, 2, 3, 7, 8, 9, 16, 21 })
                    foreach (bool vectorized in new[] { true, false })
                    {
                        var tris = Enumerable.Range(0, count).Select(i => shapes[i % shapes.Length]).ToArray();
                        var t = new float[count];
                        bool saved = Runner.Vectorized;
                        try { Runner.Vectorized = vectorized; BatchQuery.Raycasts(r, new TriangleSet(tris), t); }
                        finally { Runner.Vectorized = saved; }
                        for (int i = 0; i < count; i++)
                        {
                            var h = F.Raycast.Cast(r, tris[i]);
                            if (tris[i].Equals(plain))
                                Assert.That(Math.Abs(t[i] - h.T), Is.LessThanOrEqualTo(1e-5f * h.T), $"the ordinary lane {i}: scalar cast {h}");
                            else Assert.That(t[i], Is.EqualTo(h.Hit ? h.T : float.PositiveInfinity), $"vectorized {vectorized}, {count} lanes, lane {i}: scalar cast {h}");
                        }
                    }
        }

        [Test]
        public void ScalarLanesGiveTheVectorLanesBits()
        {
            var r = new Random(9);
            int n = 1003;
            var spheres = new SphereSet(Enumerable.Range(0, n).Select(i => new F.Sphere(P(r), (float)r.NextDouble())).ToArray());
            var boxes = new AabbSet(Enumerable.Range(0, n).Select(i => F.Aabb3.FromCenter(P(r), Vector3.Abs(P(r, 1)) * (i % 5))).ToArray());
            var tris = new TriangleSet(Enumerable.Range(0, n).Select(i => new F.Triangle3(P(r), P(r), i % 9 == 0 ? Vector3.Zero : P(r))).ToArray());
            foreach (var d in new[] { P(r), Vector3.UnitY, new Vector3(0, -1, 1), new Vector3(1e-30f, 1, 0) })
            {
                var ray = new F.Ray3(P(r), d);
                foreach (var (name, query) in new (string, Action<float[]>)[] { ("sphere", x => BatchQuery.Raycasts(ray, spheres, x, 5)), ("aabb", x => BatchQuery.Raycasts(ray, boxes, x)), ("triangle", x => BatchQuery.Raycasts(ray, tris, x)) })
                {
                    bool saved = Runner.Vectorized;
                    var vector = new float[n];
                    var scalar = new float[n];
                    try
                    {
                        Runner.Vectorized = true; query(vector);
                        Runner.Vectorized = false; query(scalar);
                    }
                    finally { Runner.Vectorized = saved; }
                    for (int i = 0; i < n; i++)
                        Assert.That(BitConverter.SingleToInt32Bits(scalar[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(vector[i])), $"{name} lane {i}: {scalar[i]:R} vs {vector[i]:R}");
                }
            }
        }
    }
}
