using System;
using System.Collections.Generic;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Batch;
using F = ProximityLib;

namespace ProximityTests.Batch
{
    /// <summary>
    /// The scalar lanes (what runs where <see cref="Vector{T}"/> is not hardware-accelerated, as on Mono) against the
    /// vector lanes: every batch query, bit for bit for distances and verdict for verdict, on random pairs and on
    /// pairs built to reach the edges of each kernel (touching, on a face, −0 coordinates, degenerate shapes, far from
    /// the origin, tiny and huge scales, beyond the batch range).
    /// </summary>
    public class ScalarLanesTests
    {
        private static readonly float[] Edge = { 0f, -0f, 1f, -1f, 0.5f, 1e-30f, -1e-30f, 3e-8f, 1e6f, -2e6f, 1e19f, -1e19f };

        private static Vector3 Pick(Random r, float scale) => r.Next(4) == 0
            ? new Vector3(Edge[r.Next(Edge.Length)], Edge[r.Next(Edge.Length)], Edge[r.Next(Edge.Length)])
            : new Vector3((float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1), (float)(r.NextDouble() * 2 - 1)) * scale;

        private static float Size(Random r, float scale) => r.Next(5) switch { 0 => 0, 1 => Edge[r.Next(Edge.Length)] is var e && e > 0 ? e : 1, _ => (float)r.NextDouble() * scale };

        internal sealed class Sets
        {
            public readonly Vector3[] Points;
            public readonly F.Sphere[] Spheres, Spheres2;
            public readonly F.Aabb3[] Boxes, Boxes2;
            public readonly F.Obb3[] Obbs, Obbs2;
            public readonly F.Segment3[] Segments, Segments2;

            public Sets(int n, int seed)
            {
                var r = new Random(seed);
                var points = new List<Vector3>();
                var spheres = new List<F.Sphere>();
                var spheres2 = new List<F.Sphere>();
                var boxes = new List<F.Aabb3>();
                var boxes2 = new List<F.Aabb3>();
                var obbs = new List<F.Obb3>();
                var obbs2 = new List<F.Obb3>();
                var segments = new List<F.Segment3>();
                var segments2 = new List<F.Segment3>();
                for (int i = 0; i < n; i++)
                {
                    float scale = new[] { 1f, 1e-6f, 1e5f, 3f }[r.Next(4)];
                    var c = Pick(r, scale);
                    var h = new Vector3(Size(r, scale), Size(r, scale), Size(r, scale));
                    var box = new F.Aabb3(c - h, c + h);
                    // Points on the box's faces, edges and corners, or anywhere.
                    var p = r.Next(3) switch
                    {
                        0 => new Vector3(r.Next(2) == 0 ? box.Min.X : box.Max.X, r.Next(2) == 0 ? box.Min.Y : c.Y, c.Z),
                        1 => r.Next(2) == 0 ? box.Min : box.Max,
                        _ => c + Pick(r, scale),
                    };
                    var q = Quaternion.Normalize(new Quaternion(Pick(r, 1), r.Next(3) == 0 ? 0 : 1));
                    if (!(Math.Abs(q.Length() - 1) < 1e-3f)) q = Quaternion.Identity;
                    points.Add(p);
                    boxes.Add(box);
                    boxes2.Add(r.Next(3) == 0 ? box : new F.Aabb3(Vector3.Min(p, c + Pick(r, scale)), Vector3.Max(p, c + Pick(r, scale))));
                    float radius = Size(r, scale);
                    spheres.Add(new F.Sphere(p, radius));
                    spheres2.Add(r.Next(3) == 0 ? new F.Sphere(p + new Vector3(radius + radius, 0, 0), radius) : new F.Sphere(c, Size(r, scale)));
                    obbs.Add(new F.Obb3(c, q, h));
                    obbs2.Add(r.Next(4) == 0 ? new F.Obb3(c, q, h) : new F.Obb3(p, Quaternion.Normalize(new Quaternion((float)r.NextDouble(), (float)r.NextDouble(), -(float)r.NextDouble(), 1)), new Vector3(Size(r, scale), Size(r, scale), Size(r, scale))));
                    var a = new F.Segment3(p, r.Next(4) == 0 ? p : c + Pick(r, scale));
                    segments.Add(a);
                    segments2.Add(r.Next(3) switch
                    {
                        0 => new F.Segment3(a.Start + new Vector3(0, scale * 1e-3f, 0), a.End + new Vector3(0, scale * 1e-3f, 0)),
                        1 => new F.Segment3(c, c),
                        _ => new F.Segment3(c + Pick(r, scale), p),
                    });
                }
                Points = points.ToArray(); Spheres = spheres.ToArray(); Spheres2 = spheres2.ToArray(); Boxes = boxes.ToArray(); Boxes2 = boxes2.ToArray();
                Obbs = obbs.ToArray(); Obbs2 = obbs2.ToArray(); Segments = segments.ToArray(); Segments2 = segments2.ToArray();
            }

            /// <summary>
            /// Every batch query, paired and one against many (the first shape being shape j), on the first n shapes of
            /// each set: <paramref name="values"/> for the distances, <paramref name="verdicts"/> for the overlaps.
            /// </summary>
            public void EachQuery(int n, int j, Action<string, Action<float[]>> values, Action<string, Action<bool[]>> verdicts)
            {
                var points = new PointSet(Points.AsSpan(0, n));
                var spheres = new SphereSet(Spheres.AsSpan(0, n));
                var spheres2 = new SphereSet(Spheres2.AsSpan(0, n));
                var boxes = new AabbSet(Boxes.AsSpan(0, n));
                var boxes2 = new AabbSet(Boxes2.AsSpan(0, n));
                var obbs = new ObbSet(Obbs.AsSpan(0, n));
                var obbs2 = new ObbSet(Obbs2.AsSpan(0, n));
                var segments = new SegmentSet(Segments.AsSpan(0, n));
                var segments2 = new SegmentSet(Segments2.AsSpan(0, n));
                values("sphere–sphere", x => BatchQuery.Distances(spheres, spheres2, x));
                values("sphere–sphere one", x => BatchQuery.Distances(Spheres[j], spheres2, x));
                verdicts("sphere–sphere", x => BatchQuery.Overlaps(spheres, spheres2, x));
                verdicts("sphere–sphere one", x => BatchQuery.Overlaps(Spheres[j], spheres2, x));
                values("point–AABB", x => BatchQuery.Distances(points, boxes, x));
                values("point–AABB one", x => BatchQuery.Distances(Points[j], boxes, x));
                verdicts("point–AABB", x => BatchQuery.Overlaps(points, boxes, x));
                verdicts("point–AABB one", x => BatchQuery.Overlaps(Points[j], boxes, x));
                values("sphere–AABB", x => BatchQuery.Distances(spheres, boxes2, x));
                values("sphere–AABB one", x => BatchQuery.Distances(Spheres[j], boxes2, x));
                verdicts("sphere–AABB", x => BatchQuery.Overlaps(spheres, boxes2, x));
                verdicts("sphere–AABB one", x => BatchQuery.Overlaps(Spheres[j], boxes2, x));
                verdicts("AABB–AABB", x => BatchQuery.Overlaps(boxes, boxes2, x));
                verdicts("AABB–AABB one", x => BatchQuery.Overlaps(Boxes[j], boxes2, x));
                values("sphere–OBB", x => BatchQuery.Distances(spheres, obbs, x));
                values("sphere–OBB one", x => BatchQuery.Distances(Spheres[j], obbs, x));
                verdicts("sphere–OBB", x => BatchQuery.Overlaps(spheres, obbs, x));
                verdicts("sphere–OBB one", x => BatchQuery.Overlaps(Spheres[j], obbs, x));
                values("segment–segment", x => BatchQuery.Distances(segments, segments2, x));
                values("segment–segment one", x => BatchQuery.Distances(Segments[j], segments2, x));
                var triangles = new TriangleSet(Enumerable.Range(0, n).Select(i => new F.Triangle3(Points[i], Boxes[i].Min, Spheres2[i].Center)).ToArray());
                var toward = Spheres2[j].Center - Points[j];
                var ray = new F.Ray3(Points[j], toward == Vector3.Zero ? Vector3.UnitX : toward);
                values("ray–sphere", x => BatchQuery.Raycasts(ray, spheres2, x));
                values("ray–AABB", x => BatchQuery.Raycasts(ray, boxes2, x));
                values("ray–triangle", x => BatchQuery.Raycasts(ray, triangles, x));
                verdicts("OBB–OBB", x => BatchQuery.Overlaps(obbs, obbs2, x));
                verdicts("OBB–OBB one", x => BatchQuery.Overlaps(Obbs[j], obbs2, x));
            }
        }

        private static T[] Run<T>(bool vectorized, int n, Action<T[]> query)
        {
            bool saved = Runner.Vectorized;
            Runner.Vectorized = vectorized;
            try
            {
                var result = new T[n];
                query(result);
                return result;
            }
            finally { Runner.Vectorized = saved; }
        }

        private static void SameBits(string name, int n, Action<float[]> query)
        {
            var vector = Run(true, n, query);
            var scalar = Run(false, n, query);
            for (int i = 0; i < n; i++)
            {
                if (float.IsNaN(vector[i]) && float.IsNaN(scalar[i])) continue;
                Assert.That(BitConverter.SingleToInt32Bits(scalar[i]), Is.EqualTo(BitConverter.SingleToInt32Bits(vector[i])), $"{name}, lane {i}: scalar {scalar[i]:R}, vector {vector[i]:R}");
            }
        }

        private static void SameVerdicts(string name, int n, Action<bool[]> query) =>
            Assert.That(Run(false, n, query), Is.EqualTo(Run(true, n, query)), name);

        [TestCase(1003, 1), TestCase(4099, 2), TestCase(5, 3)]
        public void ScalarLanesGiveTheVectorLanesResults(int n, int seed)
        {
            var s = new Sets(n, seed);
            // One-against-many with a few different first shapes.
            for (int k = 0; k < 3; k++)
                s.EachQuery(n, k * n / 3, (name, query) => SameBits(name, n, query), (name, query) => SameVerdicts(name, n, query));
        }

        [Test]
        public void PointsOnAFaceAtMinusZeroKeepTheSignOfZero()
        {
            // A point with a −0 coordinate on the face x = 0 of a box: depth (−0) − 0 is −0, and the IEEE minimum picks it.
            var box = new F.Aabb3(new Vector3(0, -1, -1), new Vector3(1, 1, 1));
            var points = new PointSet(new[] { new Vector3(-0f, 0, 0), new Vector3(0f, 0, 0), new Vector3(1, 1, 1) });
            SameBits("point–AABB on a face", 3, x => BatchQuery.Distances(points, new AabbSet(new[] { box, box, box }), x));
            var scalar = Run<float>(false, 3, x => BatchQuery.Distances(points, new AabbSet(new[] { box, box, box }), x));
            Assert.That(scalar.Select(BitConverter.SingleToInt32Bits), Is.EqualTo(new[] { BitConverter.SingleToInt32Bits(0f), BitConverter.SingleToInt32Bits(-0f), BitConverter.SingleToInt32Bits(-0f) }));
        }

        [Test]
        public void PointsOffABoxByLessThanSquaresResolveAreInsideInEveryLane()
        {
            // A float gap g squares to 0 when |g| ≤ 2^-75 (g² ≤ 2^-150 rounds to 0, ties to even) and to 2^-149 or more
            // beyond, so a point 2^-75 outside the box has squared distance 0 and counts as inside; one float step
            // farther it does not. The scalar verdict lanes compare the gap with 2^-75 instead of squaring it.
            float g = MathF.Pow(2, -75), beyond = BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(g) + 1);
            // Below the box [0, 1]³ (gaps at its min faces) and above [−1, 0]³ (at its max faces), on each axis.
            var low = new F.Aabb3(new Vector3(0, 0, 0), new Vector3(1, 1, 1));
            var high = new F.Aabb3(new Vector3(-1, -1, -1), new Vector3(0, 0, 0));
            var cases = new (Vector3 Point, F.Aabb3 Box, bool Inside)[]
            {
                (new Vector3(-g, 0.5f, 0.5f), low, true), (new Vector3(-beyond, 0.5f, 0.5f), low, false),
                (new Vector3(0.5f, -g, 0.5f), low, true), (new Vector3(0.5f, -beyond, 0.5f), low, false),
                (new Vector3(0.5f, 0.5f, -g), low, true), (new Vector3(0.5f, 0.5f, -beyond), low, false),
                (new Vector3(g, -0.5f, -0.5f), high, true), (new Vector3(beyond, -0.5f, -0.5f), high, false),
                (new Vector3(-0.5f, g, -0.5f), high, true), (new Vector3(-0.5f, beyond, -0.5f), high, false),
                (new Vector3(-0.5f, -0.5f, g), high, true), (new Vector3(-0.5f, -0.5f, beyond), high, false),
                (new Vector3(g, g, g), high, true), (new Vector3(-g, -g, -beyond), low, false),
            };
            var points = new PointSet(cases.Select(c => c.Point).ToArray());
            var boxes = new AabbSet(cases.Select(c => c.Box).ToArray());
            VerdictsInEveryLane(cases.Select(c => c.Inside).ToArray(), x => BatchQuery.Overlaps(points, boxes, x),
                (i, x) => BatchQuery.Overlaps(cases[i].Point, new AabbSet(new[] { cases[i].Box }), x));
        }

        [Test]
        public void BoxesTouchingAtZerosOfEitherSignTouchInEveryLane()
        {
            // Faces meeting at 0 with the zeros' signs in every combination, on each axis, and boxes one float step
            // apart. The scalar verdicts read the sign bits of differences, where (−0) − (+0) = −0 would look like a gap:
            // this fails if the shapes stop storing −0 as +0.
            var cases = new List<(F.Aabb3 A, F.Aabb3 B, bool Touch)>();
            float step = float.Epsilon;
            foreach (float high in new[] { 0f, -0f })
                foreach (float low in new[] { 0f, -0f })
                    for (int axis = 0; axis < 3; axis++)
                    {
                        Vector3 Along(float v, float rest) => new Vector3(axis == 0 ? v : rest, axis == 1 ? v : rest, axis == 2 ? v : rest);
                        var below = new F.Aabb3(Along(-1, -1), Along(high, 1));
                        var above = new F.Aabb3(Along(low, -1), Along(1, 1));
                        var apart = new F.Aabb3(Along(step, -1), Along(1, 1));
                        cases.Add((below, above, true));
                        cases.Add((above, below, true));
                        cases.Add((below, apart, false));
                        cases.Add((apart, below, false));
                    }
            var a = new AabbSet(cases.Select(c => c.A).ToArray());
            var b = new AabbSet(cases.Select(c => c.B).ToArray());
            VerdictsInEveryLane(cases.Select(c => c.Touch).ToArray(), x => BatchQuery.Overlaps(a, b, x),
                (i, x) => BatchQuery.Overlaps(cases[i].A, new AabbSet(new[] { cases[i].B }), x));
        }

        /// <summary>
        /// The expected verdicts from the paired query and from case i's first shape against a one-shape set, on the
        /// vector lanes and on the scalar lanes.
        /// </summary>
        private static void VerdictsInEveryLane(bool[] expected, Action<bool[]> paired, Action<int, bool[]> oneToMany)
        {
            foreach (bool vectorized in new[] { true, false })
            {
                Assert.That(Run(vectorized, expected.Length, paired), Is.EqualTo(expected), $"paired, vectorized {vectorized}");
                for (int i = 0; i < expected.Length; i++)
                    Assert.That(Run<bool>(vectorized, 1, x => oneToMany(i, x))[0], Is.EqualTo(expected[i]), $"one-to-many, case {i}, vectorized {vectorized}");
            }
        }

        [Test]
        public void MinimumOrdersSignedZerosAndPropagatesNaN()
        {
            Assert.That(BitConverter.SingleToInt32Bits(Runner.Min(0f, -0f)), Is.EqualTo(BitConverter.SingleToInt32Bits(-0f)));
            Assert.That(BitConverter.SingleToInt32Bits(Runner.Min(-0f, 0f)), Is.EqualTo(BitConverter.SingleToInt32Bits(-0f)));
            Assert.That(Runner.Min(2f, -3f), Is.EqualTo(-3f));
            Assert.That(float.IsNaN(Runner.Min(float.NaN, 1f)) && float.IsNaN(Runner.Min(1f, float.NaN)), Is.True);
        }
    }
}
