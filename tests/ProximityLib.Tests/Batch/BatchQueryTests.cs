using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Batch;
using ProximityReference;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximityTests.Batch
{
    /// <summary>
    /// The SIMD batch queries against the scalar double queries (themselves checked against the exact reference):
    /// every lane within the batch's float bound, one-against-many identical to paired with a repeated first shape,
    /// verdicts right outside the band, odd lengths and bad arguments handled.
    /// </summary>
    public class BatchQueryTests
    {
        private const double UFloat = 1.0 / (1 << 24);
        /// <summary>The batch bound: E ≤ 8 in float units at the configuration's scale (measured max is reported in the note).</summary>
        private const double Bound = 8;

        private static (object[] A, object[] B) Shapes(string query, int n, int seed)
        {
            var r = new Random(seed);
            var kinds = query.Split('–');
            var a = new object[n];
            var b = new object[n];
            for (int i = 0; i < n; i++)
            {
                // Half the pairs near each other, half further apart.
                var c = new D.Vector3D(r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2, r.NextDouble() * 4 - 2);
                var off = new D.Vector3D(r.NextDouble() * 3 - 1.5, r.NextDouble() * 3 - 1.5, r.NextDouble() * 3 - 1.5) * (i % 2 == 0 ? 1 : 3);
                a[i] = ProximityReference.Shapes.ToFloat(Families.Shape(r, kinds[0], 3, c));
                b[i] = ProximityReference.Shapes.ToFloat(Families.Shape(r, kinds[1], 3, c + off));
            }
            return (a, b);
        }

        private static void CheckDistances(object[] a, object[] b, float[] batch)
        {
            for (int i = 0; i < a.Length; i++)
            {
                var wa = ProximityReference.Shapes.Widen(a[i]);
                var wb = ProximityReference.Shapes.Widen(b[i]);
                double scalar = Api.Between(wa, wb).Distance;
                double scale = Exact.Scale(RShape.FromAny(wa), RShape.FromAny(wb));
                Assert.That(Math.Abs(batch[i] - scalar), Is.LessThanOrEqualTo(Bound * UFloat * scale), $"lane {i}: batch {batch[i]:R}, scalar {scalar:R}");
            }
        }

        private static void CheckVerdicts(object[] a, object[] b, bool[] batch)
        {
            int decided = 0;
            for (int i = 0; i < a.Length; i++)
            {
                var wa = ProximityReference.Shapes.Widen(a[i]);
                var wb = ProximityReference.Shapes.Widen(b[i]);
                double d = Api.Between(wa, wb).Distance;
                double scale = Exact.Scale(RShape.FromAny(wa), RShape.FromAny(wb));
                if (Math.Abs(d) <= 32 * UFloat * scale) continue;
                decided++;
                Assert.That(batch[i], Is.EqualTo(d <= 0), $"lane {i}: distance {d:R}");
            }
            Assert.That(decided, Is.GreaterThan(a.Length / 2));
        }

        /// <summary>One shape against a set gives what the paired query gives with that shape repeated.</summary>
        private static void OneMatchesRepeated<TShape, TSet, TR>(TShape first, int n, Func<TShape[], TSet> set, Action<TShape, TR[]> one, Action<TSet, TR[]> paired)
        {
            var expected = new TR[n];
            paired(set(Enumerable.Repeat(first, n).ToArray()), expected);
            var actual = new TR[n];
            one(first, actual);
            Assert.That(actual, Is.EqualTo(expected));
        }

        [TestCase(1000), TestCase(37), TestCase(1)]
        public void SphereSphere(int n)
        {
            var (a, b) = Shapes("sphere–sphere", n, n);
            var sa = new SphereSet(a.Cast<F.Sphere>().ToArray());
            var sb = new SphereSet(b.Cast<F.Sphere>().ToArray());
            var d = new float[n];
            var o = new bool[n];
            BatchQuery.Distances(sa, sb, d);
            BatchQuery.Overlaps(sa, sb, o);
            CheckDistances(a, b, d);
            CheckVerdicts(a, b, o);
            OneMatchesRepeated<F.Sphere, SphereSet, float>((F.Sphere)a[0], n, x => new SphereSet(x), (x, r) => BatchQuery.Distances(x, sb, r), (x, r) => BatchQuery.Distances(x, sb, r));
        }

        [TestCase(1000), TestCase(37)]
        public void PointAabb(int n)
        {
            var (a, b) = Shapes("point–aabb", n, n + 1);
            var pa = new PointSet(a.Cast<Vector3>().ToArray());
            var sb = new AabbSet(b.Cast<F.Aabb3>().ToArray());
            var d = new float[n];
            var o = new bool[n];
            BatchQuery.Distances(pa, sb, d);
            BatchQuery.Overlaps(pa, sb, o);
            CheckDistances(a, b, d);
            CheckVerdicts(a, b, o);
            OneMatchesRepeated<Vector3, PointSet, float>((Vector3)a[3], n, x => new PointSet(x), (x, r) => BatchQuery.Distances(x, sb, r), (x, r) => BatchQuery.Distances(x, sb, r));
        }

        [TestCase(1000), TestCase(37)]
        public void SphereAabb(int n)
        {
            var (a, b) = Shapes("sphere–aabb", n, n + 2);
            var sa = new SphereSet(a.Cast<F.Sphere>().ToArray());
            var sb = new AabbSet(b.Cast<F.Aabb3>().ToArray());
            var d = new float[n];
            var o = new bool[n];
            BatchQuery.Distances(sa, sb, d);
            BatchQuery.Overlaps(sa, sb, o);
            CheckDistances(a, b, d);
            CheckVerdicts(a, b, o);
            OneMatchesRepeated<F.Sphere, SphereSet, bool>((F.Sphere)a[1], n, x => new SphereSet(x), (x, r) => BatchQuery.Overlaps(x, sb, r), (x, r) => BatchQuery.Overlaps(x, sb, r));
        }

        [TestCase(1000), TestCase(37)]
        public void AabbAabb(int n)
        {
            var (a, b) = Shapes("aabb–aabb", n, n + 3);
            var sa = new AabbSet(a.Cast<F.Aabb3>().ToArray());
            var sb = new AabbSet(b.Cast<F.Aabb3>().ToArray());
            var o = new bool[n];
            BatchQuery.Overlaps(sa, sb, o);
            // AABB–AABB overlap is exact in float: every verdict must match the scalar one, band or not.
            for (int i = 0; i < n; i++) Assert.That(o[i], Is.EqualTo(F.ProximityQuery.Overlaps((F.Aabb3)a[i], (F.Aabb3)b[i])), $"lane {i}");
            BatchQuery.Overlaps((F.Aabb3)a[5], sb, o);
            for (int i = 0; i < n; i++) Assert.That(o[i], Is.EqualTo(F.ProximityQuery.Overlaps((F.Aabb3)a[5], (F.Aabb3)b[i])), $"lane {i}");
        }

        [TestCase(1000), TestCase(37)]
        public void SphereObb(int n)
        {
            var (a, b) = Shapes("sphere–obb", n, n + 4);
            var sa = new SphereSet(a.Cast<F.Sphere>().ToArray());
            var sb = new ObbSet(b.Cast<F.Obb3>().ToArray());
            var d = new float[n];
            var o = new bool[n];
            BatchQuery.Distances(sa, sb, d);
            BatchQuery.Overlaps(sa, sb, o);
            CheckDistances(a, b, d);
            CheckVerdicts(a, b, o);
        }

        [TestCase(1000), TestCase(37)]
        public void SegmentSegment(int n)
        {
            var (a, b) = Shapes("segment–segment", n, n + 5);
            var sa = new SegmentSet(a.Cast<F.Segment3>().ToArray());
            var sb = new SegmentSet(b.Cast<F.Segment3>().ToArray());
            var d = new float[n];
            BatchQuery.Distances(sa, sb, d);
            CheckDistances(a, b, d);
            OneMatchesRepeated<F.Segment3, SegmentSet, float>((F.Segment3)a[2], n, x => new SegmentSet(x), (x, r) => BatchQuery.Distances(x, sb, r), (x, r) => BatchQuery.Distances(x, sb, r));
        }

        [Test]
        public void NearlyParallelSegmentsStayWithinTheBound()
        {
            var cases = Families.Get("nearly-parallel", 2, 3).Where(c => c.A is D.Segment3).ToArray();
            var a = cases.Select(c => ProximityReference.Shapes.ToFloat(c.A)).ToArray();
            var b = cases.Select(c => ProximityReference.Shapes.ToFloat(c.B)).ToArray();
            var d = new float[a.Length];
            BatchQuery.Distances(new SegmentSet(a.Cast<F.Segment3>().ToArray()), new SegmentSet(b.Cast<F.Segment3>().ToArray()), d);
            CheckDistances(a, b, d);
        }

        [TestCase(1000), TestCase(37)]
        public void ObbObb(int n)
        {
            var (a, b) = Shapes("obb–obb", n, n + 6);
            var sa = new ObbSet(a.Cast<F.Obb3>().ToArray());
            var sb = new ObbSet(b.Cast<F.Obb3>().ToArray());
            var o = new bool[n];
            BatchQuery.Overlaps(sa, sb, o);
            CheckVerdicts(a, b, o);
            OneMatchesRepeated<F.Obb3, ObbSet, bool>((F.Obb3)a[4], n, x => new ObbSet(x), (x, r) => BatchQuery.Overlaps(x, sb, r), (x, r) => BatchQuery.Overlaps(x, sb, r));
        }

        [Test]
        public void MismatchedSetsAndShortResultsAreRejected()
        {
            var two = new SphereSet(new[] { new F.Sphere(Vector3.Zero, 1), new F.Sphere(Vector3.One, 1) });
            var three = new SphereSet(new[] { new F.Sphere(Vector3.Zero, 1), new F.Sphere(Vector3.One, 1), new F.Sphere(Vector3.One, 2) });
            Assert.That(() => BatchQuery.Distances(two, three, new float[3]), Throws.ArgumentException.With.Property("ParamName").EqualTo("b"));
            Assert.That(() => BatchQuery.Distances(two, two, new float[1]), Throws.ArgumentException.With.Property("ParamName").EqualTo("result"));
            Assert.That(() => new PointSet(new[] { new Vector3(float.NaN, 0, 0) }), Throws.ArgumentException);
            BatchQuery.Distances(new SphereSet(Array.Empty<F.Sphere>()), new SphereSet(Array.Empty<F.Sphere>()), Span<float>.Empty);
        }
    }
}
