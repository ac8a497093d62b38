using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using ProximityLib.Double;
using ProximityReference;
using Dbl = ProximityLib.Double;

namespace ProximitySpeed
{
    /// <summary>
    /// Seeded query inputs in three distributions (all apart, all overlapping, half and half shuffled), written once per
    /// run to the file every probe reads (ProximityLib.Speed.Cases/InputSet.cs), so every mode, process and library
    /// version measures the same pairs.
    /// </summary>
    public static class Inputs
    {
        public const int Count = 1024;
        public static readonly string[] Distributions = { "mixed", "apart", "overlapping" };

        private static readonly string[] Kinds = { "point", "segment", "sphere", "AABB", "OBB" };

        /// <summary>Every query of the library, "3D point–point" … "2D OBB–OBB", one per unordered pair of kinds.</summary>
        public static IEnumerable<string> Queries()
        {
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < Kinds.Length; i++)
                    for (int j = i; j < Kinds.Length; j++)
                        yield return $"{dim}D {Name(Kinds[i], dim)}–{Name(Kinds[j], dim)}";
        }

        private static string Name(string kind, int dim) => dim == 2 && kind == "sphere" ? "circle" : kind;

        public static void Write(string path, string distribution, int seed = 7)
        {
            var text = new StringBuilder();
            text.Append($"# ProximityLib speed inputs: {distribution}, seed {seed}, {Count} pairs per query\n");
            foreach (var query in Queries())
            {
                text.Append("query ").Append(query).Append('\n');
                foreach (var (a, b) in Make(query, distribution, seed))
                    text.Append(string.Join(" ", Numbers(a).Select(R))).Append(" | ").Append(string.Join(" ", Numbers(b).Select(R))).Append('\n');
            }
            File.WriteAllText(path, text.ToString());
        }

        private static string R(double x) => x.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>The numbers that define a shape, in the order InputSet documents.</summary>
        private static IEnumerable<double> Numbers(object shape) => shape switch
        {
            Vector3D p => new[] { p.X, p.Y, p.Z },
            Vector2D p => new[] { p.X, p.Y },
            Dbl.Segment3 s => Numbers(s.Start).Concat(Numbers(s.End)),
            Dbl.Segment2 s => Numbers(s.Start).Concat(Numbers(s.End)),
            Dbl.Sphere s => Numbers(s.Center).Append(s.Radius),
            Dbl.Circle s => Numbers(s.Center).Append(s.Radius),
            Dbl.Aabb3 b => Numbers(b.Min).Concat(Numbers(b.Max)),
            Dbl.Aabb2 b => Numbers(b.Min).Concat(Numbers(b.Max)),
            Dbl.Obb3 b => new[] { b.Center, b.AxisX, b.AxisY, b.AxisZ, b.HalfExtents }.SelectMany(v => Numbers(v)),
            Dbl.Obb2 b => new[] { b.Center, b.AxisX, b.HalfExtents }.SelectMany(v => Numbers(v)),
            _ => throw new ArgumentException(shape.GetType().Name),
        };

        /// <summary>Pairs of double-API shapes of the query's kinds ("3D sphere–OBB").</summary>
        private static (object A, object B)[] Make(string query, string distribution, int seed)
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
    }
}
