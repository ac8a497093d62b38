using System;
using System.Collections.Generic;
using ProximityLib.Double;
using ProximityReference;
using Dbl = ProximityLib.Double;

namespace ProximityBenchmarks
{
    /// <summary>Seeded query inputs in three distributions: all apart, all overlapping, and half and half shuffled.</summary>
    public static class Inputs
    {
        public const int Count = 1024;
        public static readonly string[] Distributions = { "apart", "overlapping", "mixed" };

        /// <summary>Pairs of double-API shapes of the query's kinds ("3D sphere–OBB").</summary>
        public static (object A, object B)[] Make(string query, string distribution, int seed = 7)
        {
            int dim = query[0] - '0';
            var kinds = query.Substring(3).Split('–');
            string ka = Kind(kinds[0]), kb = Kind(kinds[1]);
            var r = new Random(seed);
            var result = new (object, object)[Count];
            for (int i = 0; i < Count; i++)
            {
                bool overlapping = distribution == "overlapping" || (distribution == "mixed" && r.Next(2) == 0);
                result[i] = overlapping ? Overlapping(r, ka, kb, dim) : Apart(r, ka, kb, dim);
            }
            return result;
        }

        private static string Kind(string name) => name switch { "circle" => "sphere", "AABB" => "aabb", "OBB" => "obb", _ => name };

        private static (object, object) Apart(Random r, string ka, string kb, int dim)
        {
            while (true)
            {
                var a = Families.Shape(r, ka, dim, Center(r, 3));
                var b = Families.Shape(r, kb, dim, Center(r, 3));
                if (!ProximityQuery.Overlaps((dynamic)a, (dynamic)b)) return (a, b);
            }
        }

        /// <summary>B is built around a point of A, so the pair always touches or overlaps.</summary>
        private static (object, object) Overlapping(Random r, string ka, string kb, int dim)
        {
            var a = Families.Shape(r, ka, dim, Center(r, 1));
            var x = PointIn(a, r);
            return (a, Families.Shape(r, kb, dim, x));
        }

        private static Vector3D Center(Random r, double range) =>
            new Vector3D((r.NextDouble() * 2 - 1) * range, (r.NextDouble() * 2 - 1) * range, (r.NextDouble() * 2 - 1) * range);

        private static Vector3D PointIn(object shape, Random r)
        {
            double u = r.NextDouble(), v = r.NextDouble() * 2 - 1, w = r.NextDouble() * 2 - 1, z = r.NextDouble() * 2 - 1;
            return shape switch
            {
                Vector3D p => p,
                Vector2D p => new Vector3D(p.X, p.Y, 0),
                Dbl.Segment3 s => s.PointAt(u),
                Dbl.Segment2 s => new Vector3D(s.PointAt(u).X, s.PointAt(u).Y, 0),
                Dbl.Sphere s => s.Center + new Vector3D(v, w, z) * (s.Radius / 2),
                Dbl.Circle s => new Vector3D(s.Center.X + v * s.Radius / 2, s.Center.Y + w * s.Radius / 2, 0),
                Dbl.Aabb3 b => b.Center + new Vector3D(v * (b.Max.X - b.Min.X), w * (b.Max.Y - b.Min.Y), z * (b.Max.Z - b.Min.Z)) * 0.5,
                Dbl.Aabb2 b => new Vector3D(b.Center.X + v * (b.Max.X - b.Min.X) / 2, b.Center.Y + w * (b.Max.Y - b.Min.Y) / 2, 0),
                Dbl.Obb3 b => b.Center + b.AxisX * (v * b.HalfExtents.X) + b.AxisY * (w * b.HalfExtents.Y) + b.AxisZ * (z * b.HalfExtents.Z),
                Dbl.Obb2 b => new Vector3D(b.Center.X, b.Center.Y, 0) + new Vector3D(b.AxisX.X, b.AxisX.Y, 0) * (v * b.HalfExtents.X)
                              + new Vector3D(b.AxisY.X, b.AxisY.Y, 0) * (w * b.HalfExtents.Y),
                _ => throw new ArgumentException(shape.GetType().Name),
            };
        }

        /// <summary>The inputs in the benchmark's precision: float shapes are the double ones rounded.</summary>
        public static (TA[] A, TB[] B) Typed<TA, TB>(string query, string distribution, bool isFloat)
        {
            var pairs = Make(query, distribution);
            var a = new TA[pairs.Length];
            var b = new TB[pairs.Length];
            for (int i = 0; i < pairs.Length; i++)
            {
                a[i] = (TA)(isFloat ? Shapes.ToFloat(pairs[i].A) : pairs[i].A);
                b[i] = (TB)(isFloat ? Shapes.ToFloat(pairs[i].B) : pairs[i].B);
            }
            return (a, b);
        }
    }
}
