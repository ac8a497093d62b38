using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;

namespace ProximityApiGen
{
    /// <summary>
    /// docs/catalogue.md: the paper's 200 contact pairs (docs/seed-pairs.csv, its Appendix I) against the library —
    /// for each row, the public query that answers it, or why none does. The answers come from the pair files the
    /// generator reads, so the table cannot claim a query that does not exist; the mapping from the catalogue's
    /// primitive names to the library's shapes is the one hand-written part, below.
    /// </summary>
    internal static class Catalogue
    {
        /// <summary>Catalogue primitive → library shapes (double API names), per dimension; a note where the match is partial.</summary>
        private static readonly Dictionary<(string Dim, string Primitive), (string[] Shapes, string? Note)> Map = new Dictionary<(string, string), (string[], string?)>
        {
            [("3D", "point")] = (new[] { "Vector3D" }, null),
            [("3D", "segment")] = (new[] { "Segment3" }, null),
            [("3D", "line")] = (new[] { "Line3" }, null),
            [("3D", "ray")] = (new[] { "Ray3" }, null),
            [("3D", "linear-component")] = (new[] { "Line3", "Ray3", "Segment3" }, null),
            [("3D", "sphere")] = (new[] { "Sphere" }, "solid ball"),
            [("3D", "capsule")] = (new[] { "Capsule3" }, null),
            [("3D", "sphere-swept-volume")] = (new[] { "Capsule3" }, "the sphere-swept segment only"),
            [("3D", "triangle")] = (new[] { "Triangle3" }, null),
            [("3D", "plane")] = (new[] { "HalfSpace" }, "as the half-space below it: equal to the plane's distance on the outside"),
            [("3D", "aabb")] = (new[] { "Aabb3" }, null),
            [("3D", "obb")] = (new[] { "Obb3" }, null),
            [("3D", "rectangle")] = (new[] { "Obb3" }, "a flat OBB (one half-extent 0)"),
            [("2D", "point")] = (new[] { "Vector2D" }, null),
            [("2D", "segment")] = (new[] { "Segment2" }, null),
            [("2D", "line")] = (new[] { "Line2" }, null),
            [("2D", "ray")] = (new[] { "Ray2" }, null),
            [("2D", "linear-component")] = (new[] { "Line2", "Ray2", "Segment2" }, null),
            [("2D", "ray or line-segment")] = (new[] { "Ray2", "Segment2" }, null),
            [("2D", "circle")] = (new[] { "Circle" }, "solid disc"),
            [("2D", "triangle")] = (new[] { "Triangle2" }, null),
            [("2D", "rectangle")] = (new[] { "Aabb2" }, "the paper's rectangle is axis-aligned"),
            [("2D", "oriented-rectangle")] = (new[] { "Obb2" }, null),
        };

        public static string Path(string repo) => System.IO.Path.Combine(repo, "docs", "catalogue.md");

        /// <summary>The table for the given pair kernels (query, A, B as double type names).</summary>
        public static string Generate(string repo, IReadOnlyCollection<(string Query, string A, string B)> kernels)
        {
            var rows = ReadCsv(System.IO.Path.Combine(repo, "docs", "seed-pairs.csv"));
            var have = new HashSet<(string, string, string)>(kernels.SelectMany(k => new[] { (k.Query, k.A, k.B), (k.Query, k.B, k.A) }));
            var sb = new StringBuilder();
            int answered = 0, partly = 0;
            var lines = new List<string>();
            foreach (var r in rows)
            {
                string dim = r["dim"], query = r["query"];
                Map.TryGetValue((dim, r["primitive_a"]), out var a);
                Map.TryGetValue((dim, r["primitive_b"]), out var b);
                string answer, note = string.Join("; ", new[] { a.Note, b.Note }.Where(n => n != null).Distinct());
                if (a.Shapes == null || b.Shapes == null)
                {
                    var missing = new[] { (r["primitive_a"], a.Shapes), (r["primitive_b"], b.Shapes) }.Where(x => x.Item2 == null).Select(x => x.Item1).Distinct();
                    answer = "—";
                    note = $"no {string.Join(" or ", missing)} shape";
                }
                else
                {
                    string name = query == "distance" ? "Between" : "Overlaps";
                    string cls = query == "distance" ? "ClosestDistance" : "ProximityQuery";
                    var calls = (from x in a.Shapes from y in b.Shapes select (x, y)).Distinct().ToList();
                    var present = calls.Where(c => have.Contains((name, c.x, c.y))).ToList();
                    answer = present.Count == 0 ? "— (not yet)" : string.Join(", ", present.Select(c => $"`{cls}.{name}({c.x}, {c.y})`"));
                    if (present.Count == calls.Count) answered++;
                    else if (present.Count > 0) { partly++; note = (note.Length > 0 ? note + "; " : "") + "partly: " + string.Join(", ", calls.Except(present).Select(c => $"{c.x}–{c.y}")) + " not yet"; }
                }
                lines.Add($"| {query} | {dim} | {r["pair"]} | {Escape(r["reference"])} | {answer} | {note} |");
            }
            sb.Append("# The paper's catalogue of contact pairs, and what answers each\n\n");
            sb.Append("Generated by `dotnet run --project tests/ProximityLib.ApiGen -- sync` from [seed-pairs.csv](seed-pairs.csv) (the paper's\n");
            sb.Append("Appendix I: 200 pairs from the literature, with its references) and the library's pair files; `-- check` in CI fails\n");
            sb.Append("when it is out of date. A distance row is answered by `ClosestDistance.Between` (and `Distance`), a proximity row by\n");
            sb.Append("`ProximityQuery.Overlaps`, in both argument orders, float (`ProximityLib`) and double (`ProximityLib.Double`).\n");
            sb.Append("Where the catalogue's primitive is not exactly a library shape, the note says how it is read.\n\n");
            sb.Append($"**{answered} of {rows.Count} rows answered**{(partly > 0 ? $", {partly} partly" : "")}.\n\n");
            sb.Append("| query | dim | pair | reference | answered by | note |\n| --- | --- | --- | --- | --- | --- |\n");
            foreach (var l in lines) sb.Append(l).Append('\n');
            return sb.ToString();
        }

        private static string Escape(string s) => s.Replace("|", "\\|");

        /// <summary>A minimal RFC 4180 reader (quoted fields, doubled quotes); the header row names the fields.</summary>
        private static List<Dictionary<string, string>> ReadCsv(string path)
        {
            var records = new List<List<string>>();
            var field = new StringBuilder();
            var record = new List<string>();
            string text = File.ReadAllText(path).Replace("\r\n", "\n");
            bool quoted = false;
            for (int i = 0; i < text.Length; i++)
            {
                char c = text[i];
                if (quoted)
                {
                    if (c == '"' && i + 1 < text.Length && text[i + 1] == '"') { field.Append('"'); i++; }
                    else if (c == '"') quoted = false;
                    else field.Append(c);
                }
                else if (c == '"') quoted = true;
                else if (c == ',') { record.Add(field.ToString()); field.Clear(); }
                else if (c == '\n') { record.Add(field.ToString()); field.Clear(); records.Add(record); record = new List<string>(); }
                else field.Append(c);
            }
            if (field.Length > 0 || record.Count > 0) { record.Add(field.ToString()); records.Add(record); }
            var header = records[0];
            return records.Skip(1).Select(r => header.Select((h, j) => (h, v: j < r.Count ? r[j] : "")).ToDictionary(x => x.h, x => x.v)).ToList();
        }
    }
}
