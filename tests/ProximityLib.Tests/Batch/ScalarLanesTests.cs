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
            var points = new PointSet(s.Points);
            var spheres = new SphereSet(s.Spheres);
            var spheres2 = new SphereSet(s.Spheres2);
            var boxes = new AabbSet(s.Boxes);
            var boxes2 = new AabbSet(s.Boxes2);
            var obbs = new ObbSet(s.Obbs);
            var obbs2 = new ObbSet(s.Obbs2);
            var segments = new SegmentSet(s.Segments);
            var segments2 = new SegmentSet(s.Segments2);
            for (int k = 0; k < 3; k++)
            {
                // One-against-many with a few different first shapes.
                int j = k * n / 3;
                SameBits("sphere–sphere", n, x => BatchQuery.Distances(spheres, spheres2, x));
                SameBits("sphere–sphere one", n, x => BatchQuery.Distances(s.Spheres[j], spheres2, x));
                SameVerdicts("sphere–sphere", n, x => BatchQuery.Overlaps(spheres, spheres2, x));
                SameVerdicts("sphere–sphere one", n, x => BatchQuery.Overlaps(s.Spheres[j], spheres2, x));
                SameBits("point–AABB", n, x => BatchQuery.Distances(points, boxes, x));
                SameBits("point–AABB one", n, x => BatchQuery.Distances(s.Points[j], boxes, x));
                SameVerdicts("point–AABB", n, x => BatchQuery.Overlaps(points, boxes, x));
                SameVerdicts("point–AABB one", n, x => BatchQuery.Overlaps(s.Points[j], boxes, x));
                SameBits("sphere–AABB", n, x => BatchQuery.Distances(spheres, boxes2, x));
                SameBits("sphere–AABB one", n, x => BatchQuery.Distances(s.Spheres[j], boxes2, x));
                SameVerdicts("sphere–AABB", n, x => BatchQuery.Overlaps(spheres, boxes2, x));
                SameVerdicts("sphere–AABB one", n, x => BatchQuery.Overlaps(s.Spheres[j], boxes2, x));
                SameVerdicts("AABB–AABB", n, x => BatchQuery.Overlaps(boxes, boxes2, x));
                SameVerdicts("AABB–AABB one", n, x => BatchQuery.Overlaps(s.Boxes[j], boxes2, x));
                SameBits("sphere–OBB", n, x => BatchQuery.Distances(spheres, obbs, x));
                SameBits("sphere–OBB one", n, x => BatchQuery.Distances(s.Spheres[j], obbs, x));
                SameVerdicts("sphere–OBB", n, x => BatchQuery.Overlaps(spheres, obbs, x));
                SameVerdicts("sphere–OBB one", n, x => BatchQuery.Overlaps(s.Spheres[j], obbs, x));
                SameBits("segment–segment", n, x => BatchQuery.Distances(segments, segments2, x));
                SameBits("segment–segment one", n, x => BatchQuery.Distances(s.Segments[j], segments2, x));
                SameVerdicts("OBB–OBB", n, x => BatchQuery.Overlaps(obbs, obbs2, x));
                SameVerdicts("OBB–OBB one", n, x => BatchQuery.Overlaps(s.Obbs[j], obbs2, x));
            }
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
        public void MinimumOrdersSignedZerosAndPropagatesNaN()
        {
            Assert.That(BitConverter.SingleToInt32Bits(Runner.Min(0f, -0f)), Is.EqualTo(BitConverter.SingleToInt32Bits(-0f)));
            Assert.That(BitConverter.SingleToInt32Bits(Runner.Min(-0f, 0f)), Is.EqualTo(BitConverter.SingleToInt32Bits(-0f)));
            Assert.That(Runner.Min(2f, -3f), Is.EqualTo(-3f));
            Assert.That(float.IsNaN(Runner.Min(float.NaN, 1f)) && float.IsNaN(Runner.Min(1f, float.NaN)), Is.True);
        }
    }
}
