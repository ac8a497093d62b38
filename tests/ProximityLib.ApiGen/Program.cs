using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Text;
using System.Text.RegularExpressions;

// dotnet run --project tests/ProximityLib.ApiGen -- sync
//     write src/ProximityLib/Pairs/<Pair>.g.cs from each hand-written src/ProximityLib/Pairs/<Pair>.cs, and
//     src/ProximityLib/Raycasts/<Shape>.g.cs from each src/ProximityLib/Raycasts/<Shape>.cs
// dotnet run --project tests/ProximityLib.ApiGen -- check
//     fail (exit 1) when a committed .g.cs differs from what sync would write, or has no hand-written source
// Both also cover docs/catalogue.md, the paper's catalogue of pairs (docs/seed-pairs.csv) against the pair files, and
// docs/pairs.md, every pair's and ray cast's contract as its kernel's summary states it, and the picker scene's
// dispatch table (src/ProximityLib.Scenes/Picker/Dispatch.g.cs: every pair of its primitive kinds).
//
// A ray-cast file holds internal kernels RayHit3/RayHit2 Core(Ray3/Ray2 ray, S shape, out bool inRange) in Raycast,
// summary "First hit of a ray on {noun} ({n}D): …"; the public double Cast adds the range guard, the rescaling slow
// path and maxDistance, and the float Cast calls it and rounds once.
//
// A pair file holds the pair's double algorithm as internal kernels, and nothing else:
//   ClosestDistance: DistanceResult Core(A a, B b, out bool inRange)   (summary: the contract, then "Algorithm: …")
//                    double DistanceCore(A a, B b, out bool inRange)   (optional: the distance alone, the same bits)
//   ProximityQuery:  bool Core(A a, B b[, out bool inRange])          (summary optional)
// inRange false sends the call to the rescaling slow path (Wide). Every public overload is generated from these: the
// double Between/Distance/Overlaps in both argument orders and the float wrappers, which convert, call the same Core
// and round once. The float layer thus cannot drift from the double one, and a new pair is written once.
namespace ProximityApiGen
{
    internal static class Program
    {
        private static int Main(string[] args)
        {
            string pairs = Path.Combine(FindRepo(), "src", "ProximityLib", "Pairs");
            string raycasts = Path.Combine(FindRepo(), "src", "ProximityLib", "Raycasts");
            var wanted = new SortedDictionary<string, string>(StringComparer.Ordinal);
            string catalogue, pairsPage;
            try
            {
                var kernels = new List<(string, string, string)>();
                var contracts = new List<(string File, int Dim, string A, string B, string Summary)>();
                foreach (var file in Sources(pairs))
                {
                    wanted[Path.ChangeExtension(file, ".g.cs")] = Generator.Generate(Path.GetFileName(file), File.ReadAllText(file));
                    kernels.AddRange(Generator.Queries(Path.GetFileName(file), File.ReadAllText(file)));
                    contracts.AddRange(Generator.Contracts(Path.GetFileName(file), File.ReadAllText(file)).Select(c => (Path.GetFileName(file), c.Dim, c.A, c.B, c.Summary)));
                }
                var casts = new List<(string File, string Summary)>();
                foreach (var file in Sources(raycasts))
                {
                    wanted[Path.ChangeExtension(file, ".g.cs")] = RayGenerator.Generate(Path.GetFileName(file), File.ReadAllText(file));
                    casts.AddRange(RayGenerator.Contracts(Path.GetFileName(file), File.ReadAllText(file)).Select(c => (Path.GetFileName(file), c)));
                }
                catalogue = Catalogue.Generate(FindRepo(), kernels);
                wanted[SceneDispatch.Path(FindRepo())] = SceneDispatch.Generate(kernels);
                pairsPage = Contracts.Generate(contracts, casts);
            }
            catch (FormatException e)
            {
                Console.Error.WriteLine($"error: {e.Message}");
                return 2;
            }
            var existing = Directory.GetFiles(pairs, "*.g.cs").Concat(Directory.Exists(raycasts) ? Directory.GetFiles(raycasts, "*.g.cs") : Array.Empty<string>())
                .Append(SceneDispatch.Path(FindRepo())).Where(File.Exists).ToArray();
            switch (args.FirstOrDefault())
            {
                case "sync":
                    foreach (var orphan in existing.Where(f => !wanted.ContainsKey(f))) { File.Delete(orphan); Console.WriteLine($"deleted {Rel(orphan)}"); }
                    foreach (var (path, text) in wanted)
                    {
                        if (File.Exists(path) && File.ReadAllText(path) == text) continue;
                        File.WriteAllText(path, text);
                        Console.WriteLine($"wrote {Rel(path)}");
                    }
                    if (!File.Exists(Catalogue.Path(FindRepo())) || File.ReadAllText(Catalogue.Path(FindRepo())) != catalogue)
                    {
                        File.WriteAllText(Catalogue.Path(FindRepo()), catalogue);
                        Console.WriteLine("wrote docs/catalogue.md");
                    }
                    if (!File.Exists(Contracts.Path(FindRepo())) || File.ReadAllText(Contracts.Path(FindRepo())) != pairsPage)
                    {
                        File.WriteAllText(Contracts.Path(FindRepo()), pairsPage);
                        Console.WriteLine("wrote docs/pairs.md");
                    }
                    Console.WriteLine($"{wanted.Count} generated files in sync");
                    return 0;
                case "check":
                    var problems = existing.Where(f => !wanted.ContainsKey(f)).Select(f => $"{Rel(f)} has no hand-written source file").ToList();
                    problems.AddRange(wanted.Where(w => !File.Exists(w.Key) || File.ReadAllText(w.Key) != w.Value).Select(w => $"{Rel(w.Key)} is not what its source file generates"));
                    if (!File.Exists(Catalogue.Path(FindRepo())) || File.ReadAllText(Catalogue.Path(FindRepo())) != catalogue)
                        problems.Add("docs/catalogue.md is not what the pair files and docs/seed-pairs.csv generate");
                    if (!File.Exists(Contracts.Path(FindRepo())) || File.ReadAllText(Contracts.Path(FindRepo())) != pairsPage)
                        problems.Add("docs/pairs.md is not what the pair and ray-cast files generate");
                    foreach (var p in problems) Console.WriteLine($"api: {p}");
                    Console.WriteLine(problems.Count == 0
                        ? $"api: {wanted.Count} generated files in sync (pairs and ray casts)"
                        : $"api: {problems.Count} problem(s); run `dotnet run --project tests/ProximityLib.ApiGen -- sync`");
                    return problems.Count == 0 ? 0 : 1;
                default:
                    Console.WriteLine("usage: ProximityLib.ApiGen sync | check");
                    return 2;
            }
        }

        /// <summary>The hand-written sources of a folder (none when it does not exist), in ordinal order.</summary>
        private static IEnumerable<string> Sources(string dir) =>
            Directory.Exists(dir)
                ? Directory.GetFiles(dir, "*.cs").Where(f => !f.EndsWith(".g.cs", StringComparison.Ordinal)).OrderBy(f => f, StringComparer.Ordinal)
                : Enumerable.Empty<string>();

        private static string Rel(string path) => Path.GetRelativePath(FindRepo(), path);

        private static string FindRepo()
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "ProximityLib.sln"))) return dir.FullName;
            throw new InvalidOperationException("ProximityLib.sln not found above " + AppContext.BaseDirectory);
        }
    }

    /// <summary>One shape type of the double API and its float counterpart.</summary>
    internal sealed class Shape
    {
        public readonly string Double, Float, Noun;
        public readonly int Dim;
        private readonly bool _vector;

        private Shape(string dbl, string flt, string noun, int dim, bool vector) { Double = dbl; Float = flt; Noun = noun; Dim = dim; _vector = vector; }

        public bool IsVector => _vector;

        /// <summary>The float argument as the double shape the kernels take: a cast for vectors, the wrapped shape otherwise.</summary>
        public string FromFloat(string arg) => _vector ? $"(Dbl.{Double}){arg}" : $"{arg}.Inner";

        public static readonly IReadOnlyDictionary<string, Shape> All = new[]
        {
            new Shape("Vector3D", "Vector3", "a point", 3, true), new Shape("Vector2D", "Vector2", "a point", 2, true),
            new Shape("Segment3", "Segment3", "a segment", 3, false), new Shape("Segment2", "Segment2", "a segment", 2, false),
            new Shape("Sphere", "Sphere", "a sphere", 3, false), new Shape("Circle", "Circle", "a circle", 2, false),
            new Shape("Aabb3", "Aabb3", "an AABB", 3, false), new Shape("Aabb2", "Aabb2", "an AABB", 2, false),
            new Shape("Obb3", "Obb3", "an OBB", 3, false), new Shape("Obb2", "Obb2", "an OBB", 2, false),
            new Shape("Line3", "Line3", "a line", 3, false), new Shape("Line2", "Line2", "a line", 2, false),
            new Shape("Ray3", "Ray3", "a ray", 3, false), new Shape("Ray2", "Ray2", "a ray", 2, false),
            new Shape("Capsule3", "Capsule3", "a capsule", 3, false), new Shape("Capsule2", "Capsule2", "a capsule", 2, false),
            new Shape("Triangle3", "Triangle3", "a triangle", 3, false), new Shape("Triangle2", "Triangle2", "a triangle", 2, false),
            new Shape("HalfSpace", "HalfSpace", "a half-space", 3, false), new Shape("HalfPlane", "HalfPlane", "a half-plane", 2, false),
        }.ToDictionary(s => s.Double);
    }

    /// <summary>A kernel found in a pair file: which query, its argument types, whether it is guarded, its summary.</summary>
    internal sealed class Kernel
    {
        public string Query = "", Result = "";
        public Shape A = null!, B = null!;
        public bool Guarded;
        /// <summary>
        /// Whether the Core takes the range its witnesses must stay in (double range): the double overloads pass
        /// double.MaxValue, the float ones float.MaxValue, so a witness the float result cannot hold is never chosen.
        /// </summary>
        public bool Ranged;
        public string? Summary;
        /// <summary>Whether the Core takes a, or b, by reference (<c>in</c>).</summary>
        public bool InA, InB;
        /// <summary>
        /// The float overload's parameters for (a, b), or swapped for (b, a). A shape goes by reference where its Core
        /// takes it so: the wrapper then hands the float shape's double form on without a copy. By value there, two
        /// float OBBs (128 bytes each) took 3D OBB–OBB and AABB–OBB Overlaps from 15–17 to 27–29 ns on .NET, PGO or
        /// not. Where the Core copies anyway, a reference measured no gain and up to 1.13× slower (line, ray and
        /// capsule queries). Points stay by value: they are converted to double vectors either way.
        /// </summary>
        public string FloatParams(bool swapped = false) =>
            swapped ? $"{Param(B, InB)} a, {Param(A, InA)} b" : $"{Param(A, InA)} a, {Param(B, InB)} b";

        /// <summary>The float parameter types alone, for a cref.</summary>
        public string FloatTypes => $"{Param(A, InA)}, {Param(B, InB)}";

        private static string Param(Shape s, bool byRef) => byRef && !s.IsVector ? "in " + s.Float : s.Float;

        public int Dim => A.Dim;
        public string Pair => $"{A.Noun} and {B.Noun} ({Dim}D)";
        public string SwappedPair => $"{B.Noun} and {A.Noun} ({Dim}D)";
        public bool SameTypes => A.Double == B.Double;
    }

    internal static class Generator
    {
        private static readonly Regex Declaration = new Regex(
            @"^\s*internal static (?<result>\w+) (?<name>Core|DistanceCore)\((?<ina>in )?(?<a>\w+) a, (?<inb>in )?(?<b>\w+) b(?<range>, double range)?(?<guard>, out bool inRange)?\)");
        private static readonly Regex Class = new Regex(@"^\s*public static partial class (?<name>\w+)");

        /// <summary>The contract of each public Between a pair file yields: (dimension, A, B as double type names, its summary).</summary>
        public static IEnumerable<(int Dim, string A, string B, string Summary)> Contracts(string fileName, string source) =>
            Parse(fileName, source).Where(k => k.Query == "Between").Select(k => (k.Dim, k.A.Double, k.B.Double, k.Summary!));

        /// <summary>The public queries a pair file yields: (Between or Overlaps, A, B) with the double type names.</summary>
        public static IEnumerable<(string Query, string A, string B)> Queries(string fileName, string source) =>
            Parse(fileName, source).Where(k => k.Query != "Distance").Select(k => (k.Query, k.A.Double, k.B.Double));

        public static string Generate(string fileName, string source)
        {
            var kernels = Parse(fileName, source);
            var between = kernels.Where(k => k.Query == "Between").ToList();
            var distance = kernels.Where(k => k.Query == "Distance").ToList();
            var overlaps = kernels.Where(k => k.Query == "Overlaps").ToList();
            if (between.Count == 0 || overlaps.Count == 0) throw new FormatException($"{fileName}: a pair file needs a ClosestDistance.Core and a ProximityQuery.Core");
            foreach (var d in distance)
                if (!between.Any(b => b.A.Double == d.A.Double && b.B.Double == d.B.Double && b.Guarded == d.Guarded))
                    throw new FormatException($"{fileName}: DistanceCore({d.A.Double}, {d.B.Double}) has no Core of the same types and guard");

            var w = new Writer();
            w.Line($"// Generated by tests/ProximityLib.ApiGen from {fileName}: do not edit. Edit that file, then run");
            w.Line("// `dotnet run --project tests/ProximityLib.ApiGen -- sync`. The public overloads of the pair, double and float.");
            w.Line("using System.Numerics;");
            w.Line("using System.Runtime.CompilerServices;");
            w.Line("using Dbl = ProximityLib.Double;");
            w.Line();
            w.Open("namespace ProximityLib.Double");

            w.Open("public static partial class ClosestDistance");
            foreach (var k in between)
            {
                w.Doc(k.Summary!);
                w.Inline();
                Guarded(w, $"public static {k.Result} Between(in {k.A.Double} a, in {k.B.Double} b)", "Core", k.Guarded, "Slow(a, b)", range: Range(k, "double"));
                if (!k.SameTypes) w.Method($"Closest distance between {k.SwappedPair}: the swapped call, with PointA/PointB and parameters swapped.", $"public static {k.Result} Between(in {k.B.Double} a, in {k.A.Double} b) => Between(b, a).Swapped();");
            }
            foreach (var k in between)
            {
                var d = distance.FirstOrDefault(x => x.A.Double == k.A.Double && x.B.Double == k.B.Double);
                w.Doc($"Signed closest distance between {k.Pair} without the witness points: the Distance of <see cref=\"Between(in {k.A.Double}, in {k.B.Double})\"/>, bit for bit.");
                w.Inline();
                if (d == null) w.Line($"public static double Distance(in {k.A.Double} a, in {k.B.Double} b) => Between(a, b).Distance;");
                else Guarded(w, $"public static double Distance(in {k.A.Double} a, in {k.B.Double} b)", "DistanceCore", d.Guarded, "Slow(a, b).Distance", scalar: true);
                if (!k.SameTypes) w.Method($"Signed closest distance between {k.SwappedPair}: Distance(b, a).", $"public static double Distance(in {k.B.Double} a, in {k.A.Double} b) => Distance(b, a);");
            }
            w.Line();
            foreach (var k in between.Where(k => k.Guarded))
            {
                w.Line("[MethodImpl(MethodImplOptions.NoInlining)]");
                // A ranged Core hears the range in the rescaled frame, so the witnesses it picks stay finite mapped back.
                w.Line(k.Ranged
                    ? $"private static {k.Result} Slow(in {k.A.Double} a, in {k.B.Double} b) => Wide.Between(a, b, double.MaxValue, static (x, y, range) => Core(x, y, range, out _));"
                    : $"private static {k.Result} Slow(in {k.A.Double} a, in {k.B.Double} b) => Wide.Between(a, b, static (x, y) => Core(x, y, out _));");
            }
            w.Close();
            w.Line();

            w.Open("public static partial class ProximityQuery");
            foreach (var k in overlaps)
            {
                w.Doc(k.Summary ?? $"Whether {k.Pair} touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.");
                w.Inline();
                Guarded(w, $"public static bool Overlaps(in {k.A.Double} a, in {k.B.Double} b)", "Core", k.Guarded, "Slow(a, b)", scalar: true);
                if (!k.SameTypes) w.Method($"Whether {k.SwappedPair} touch or overlap: Overlaps(b, a).", $"public static bool Overlaps(in {k.B.Double} a, in {k.A.Double} b) => Overlaps(b, a);");
            }
            if (overlaps.Any(k => k.Guarded)) w.Line();
            foreach (var k in overlaps.Where(k => k.Guarded))
            {
                w.Line("[MethodImpl(MethodImplOptions.NoInlining)]");
                w.Line($"private static bool Slow(in {k.A.Double} a, in {k.B.Double} b) => Wide.Overlaps(a, b, static (x, y) => Core(x, y, out _));");
            }
            w.Close();
            w.Close();
            w.Line();

            // The float API: the same kernels on the converted shapes, rounded once. Float magnitudes are far inside the
            // double fast path's range, so the guard is not needed.
            w.Open("namespace ProximityLib");
            w.Open("public static partial class ClosestDistance");
            foreach (var k in between)
            {
                w.Method(FloatSummary(k), $"public static {k.Result} Between({k.FloatParams()}) => new {k.Result}(Dbl.ClosestDistance.Core({Args(k, Range(k, "float"))}));");
                if (!k.SameTypes) w.Method($"Closest distance between {k.SwappedPair}: the swapped call, with PointA/PointB and parameters swapped.", $"public static {k.Result} Between({k.FloatParams(true)}) => Between(b, a).Swapped();");
            }
            foreach (var k in between)
            {
                var d = distance.FirstOrDefault(x => x.A.Double == k.A.Double && x.B.Double == k.B.Double);
                w.Method($"Signed closest distance between {k.Pair}, computed in double, without the witness points: the Distance of <see cref=\"Between({k.FloatTypes})\"/>, bit for bit.",
                    d == null
                        ? $"public static float Distance({k.FloatParams()}) => Between(a, b).Distance;"
                        : $"public static float Distance({d.FloatParams()}) => (float)Dbl.ClosestDistance.DistanceCore({Args(k)});");
                if (!k.SameTypes) w.Method($"Signed closest distance between {k.SwappedPair}: Distance(b, a).", $"public static float Distance({(d ?? k).FloatParams(true)}) => Distance(b, a);");
            }
            w.Close();
            w.Line();
            w.Open("public static partial class ProximityQuery");
            foreach (var k in overlaps)
            {
                w.Method($"Whether {k.Pair} touch or overlap.", $"public static bool Overlaps({k.FloatParams()}) => Dbl.ProximityQuery.Core({Args(k)});");
                if (!k.SameTypes) w.Method($"Whether {k.SwappedPair} touch or overlap.", $"public static bool Overlaps({k.FloatParams(true)}) => Overlaps(b, a);");
            }
            w.Close();
            w.Close();
            return w.ToString();
        }

        private static string Args(Kernel k, string range = "") => $"{k.A.FromFloat("a")}, {k.B.FromFloat("b")}{range}" + (k.Guarded ? ", out _" : "");

        /// <summary>The range argument of a <see cref="Kernel.Ranged"/> Core for the precision's API ("double" or "float"), else nothing.</summary>
        private static string Range(Kernel k, string precision) => k.Ranged ? $", {precision}.MaxValue" : "";

        /// <summary>The double summary for the float overload: "computed in double", without the algorithm sentence.</summary>
        private static string FloatSummary(Kernel k)
        {
            string s = k.Summary!;
            int algorithm = s.IndexOf(" Algorithm: ", StringComparison.Ordinal);
            if (algorithm >= 0) s = s.Substring(0, algorithm);
            string head = $"Closest distance between {k.Pair}";
            return head + ", computed in double" + s.Substring(head.Length);
        }

        private static void Guarded(Writer w, string signature, string core, bool guarded, string slow, bool scalar = false, string range = "")
        {
            if (!guarded) { w.Line($"{signature} => {core}(a, b{range});"); return; }
            w.Open(signature);
            w.Line($"var r = {core}(a, b{range}, out bool inRange);");
            if (scalar) { w.Line($"return inRange ? r : {slow};"); w.Close(); return; }
            // A struct result is not chosen by `inRange ? r : slow`: without dynamic PGO that form copies the kernel's
            // result, written by a call the JIT did not inline, into a second temporary with one wide load that cannot
            // be forwarded from the callee's narrower stores, a stall each query (half-space–half-space Between with
            // DOTNET_TieredPGO=0: 33 → 22 ns). For a double or bool the ternary measured faster.
            w.Line($"if (!inRange) r = {slow};");
            w.Line("return r;");
            w.Close();
        }

        private static List<Kernel> Parse(string fileName, string source)
        {
            var lines = source.Replace("\r\n", "\n").Split('\n');
            var kernels = new List<Kernel>();
            string? cls = null;
            for (int i = 0; i < lines.Length; i++)
            {
                var c = Class.Match(lines[i]);
                if (c.Success) cls = c.Groups["name"].Value;
                if (Regex.IsMatch(lines[i], @"^\s*public static (?!partial class)"))
                    throw new FormatException($"{fileName}:{i + 1}: public overloads are generated; a pair file declares internal kernels only");
                var m = Declaration.Match(lines[i]);
                if (!m.Success) continue;
                if (!Shape.All.TryGetValue(m.Groups["a"].Value, out var a) || !Shape.All.TryGetValue(m.Groups["b"].Value, out var b))
                    throw new FormatException($"{fileName}:{i + 1}: unknown shape type in {m.Value.Trim()}");
                if (a.Dim != b.Dim) throw new FormatException($"{fileName}:{i + 1}: {a.Double} and {b.Double} differ in dimension");
                string name = m.Groups["name"].Value, result = m.Groups["result"].Value;
                string query = cls switch
                {
                    "ClosestDistance" when name == "Core" && result == $"DistanceResult{a.Dim}" => "Between",
                    "ClosestDistance" when name == "DistanceCore" && result == "double" => "Distance",
                    "ProximityQuery" when name == "Core" && result == "bool" => "Overlaps",
                    _ => throw new FormatException($"{fileName}:{i + 1}: {cls}.{name} returning {result} is not a kernel the generator knows"),
                };
                var k = new Kernel { Query = query, Result = result, A = a, B = b, Guarded = m.Groups["guard"].Success, Ranged = m.Groups["range"].Success, Summary = SummaryAbove(lines, i),
                    InA = m.Groups["ina"].Success, InB = m.Groups["inb"].Success };
                if (k.Ranged && query != "Between") throw new FormatException($"{fileName}:{i + 1}: only a ClosestDistance.Core may take a range");
                if (query == "Between")
                {
                    string head = $"Closest distance between {k.Pair}: ";
                    if (k.Summary == null || !k.Summary.StartsWith(head, StringComparison.Ordinal))
                        throw new FormatException($"{fileName}:{i + 1}: the Core's summary must start \"{head}\" (it documents the public Between)");
                }
                kernels.Add(k);
            }
            return kernels;
        }

        /// <summary>The one-line or multi-line summary of the doc comment above line i (attributes skipped), or null.</summary>
        internal static string? SummaryAbove(string[] lines, int i)
        {
            int j = i - 1;
            while (j >= 0 && lines[j].TrimStart().StartsWith("[", StringComparison.Ordinal)) j--;
            var doc = new List<string>();
            for (; j >= 0 && lines[j].TrimStart().StartsWith("///", StringComparison.Ordinal); j--) doc.Insert(0, lines[j].TrimStart().Substring(3).Trim());
            var m = Regex.Match(string.Join(" ", doc), "<summary>(.*?)</summary>");
            return m.Success ? m.Groups[1].Value.Trim() : null;
        }
    }

    /// <summary>The public ray casts of a src/ProximityLib/Raycasts file: one double and one float Cast per kernel.</summary>
    internal static class RayGenerator
    {
        private static readonly Regex Declaration = new Regex(
            @"^\s*internal static (?<result>RayHit[23]) Core\((?<ray>Ray[23]) ray, (?<b>\w+) shape, out bool inRange\)");

        /// <summary>The summaries of a ray-cast file's kernels, in file order.</summary>
        public static IEnumerable<string> Contracts(string fileName, string source)
        {
            var lines = source.Replace("\r\n", "\n").Split('\n');
            for (int i = 0; i < lines.Length; i++)
                if (Declaration.IsMatch(lines[i]))
                    yield return Generator.SummaryAbove(lines, i) ?? throw new FormatException($"{fileName}:{i + 1}: a ray-cast kernel needs a summary");
        }

        public static string Generate(string fileName, string source)
        {
            var lines = source.Replace("\r\n", "\n").Split('\n');
            var w = new Writer();
            var kernels = new List<(string Result, string Ray, Shape B, string Summary)>();
            for (int i = 0; i < lines.Length; i++)
            {
                if (Regex.IsMatch(lines[i], @"^\s*public static (?!partial class)"))
                    throw new FormatException($"{fileName}:{i + 1}: public overloads are generated; a ray-cast file declares internal kernels only");
                var m = Declaration.Match(lines[i]);
                if (!m.Success) continue;
                if (!Shape.All.TryGetValue(m.Groups["b"].Value, out var b))
                    throw new FormatException($"{fileName}:{i + 1}: unknown shape type in {m.Value.Trim()}");
                int dim = m.Groups["ray"].Value == "Ray3" ? 3 : 2;
                if (b.Dim != dim || m.Groups["result"].Value != $"RayHit{dim}")
                    throw new FormatException($"{fileName}:{i + 1}: {m.Groups["ray"].Value}, {b.Double} and {m.Groups["result"].Value} differ in dimension");
                string head = $"First hit of a ray on {b.Noun} ({dim}D): ";
                string? summary = Generator.SummaryAbove(lines, i);
                if (summary == null || !summary.StartsWith(head, StringComparison.Ordinal))
                    throw new FormatException($"{fileName}:{i + 1}: the Core's summary must start \"{head}\" (it documents the public Cast)");
                kernels.Add((m.Groups["result"].Value, m.Groups["ray"].Value, b, summary));
            }
            if (kernels.Count == 0) throw new FormatException($"{fileName}: a ray-cast file needs at least one Raycast.Core");

            w.Line($"// Generated by tests/ProximityLib.ApiGen from Raycasts/{fileName}: do not edit. Edit that file, then run");
            w.Line("// `dotnet run --project tests/ProximityLib.ApiGen -- sync`. The public ray casts against the shape, double and float.");
            w.Line("using System.Numerics;");
            w.Line("using System.Runtime.CompilerServices;");
            w.Line("using Dbl = ProximityLib.Double;");
            w.Line();
            w.Open("namespace ProximityLib.Double");
            w.Open("public static partial class Raycast");
            foreach (var k in kernels)
            {
                w.Doc(k.Summary + " A hit farther than maxDistance is a miss; a negative or NaN maxDistance throws System.ArgumentException.");
                w.Inline();
                w.Open($"public static {k.Result} Cast({k.Ray} ray, {k.B.Double} shape, double maxDistance = double.PositiveInfinity)");
                w.Line("var hit = Core(ray, shape, out bool inRange);");
                w.Line($"return {k.Result}.Within(inRange ? hit : Slow(ray, shape), maxDistance);");
                w.Close();
            }
            w.Line();
            foreach (var k in kernels)
            {
                w.Line("[MethodImpl(MethodImplOptions.NoInlining)]");
                w.Line($"private static {k.Result} Slow({k.Ray} ray, {k.B.Double} shape) => Wide.Cast(ray, shape, static (x, y) => Core(x, y, out _));");
            }
            w.Close();
            w.Close();
            w.Line();
            w.Open("namespace ProximityLib");
            w.Open("public static partial class Raycast");
            foreach (var k in kernels)
            {
                string s = k.Summary;
                int algorithm = s.IndexOf(" Algorithm: ", StringComparison.Ordinal);
                if (algorithm >= 0) s = s.Substring(0, algorithm);
                string head = $"First hit of a ray on {k.B.Noun} ({k.B.Dim}D)";
                w.Method(head + ", computed in double and rounded once" + s.Substring(head.Length) + " A hit farther than maxDistance is a miss; a negative or NaN maxDistance throws System.ArgumentException.",
                    $"public static {k.Result} Cast({k.Ray} ray, {k.B.Float} shape, float maxDistance = float.PositiveInfinity) => new {k.Result}(Dbl.Raycast.Cast(ray.Inner, {k.B.FromFloat("shape")}, maxDistance));");
            }
            w.Close();
            w.Close();
            return w.ToString();
        }
    }

    /// <summary>Indented C# text, four spaces a level, "\n" line ends.</summary>
    internal sealed class Writer
    {
        private readonly StringBuilder _text = new StringBuilder();
        private int _depth;

        public void Line(string line = "")
        {
            if (line.Length > 0) _text.Append(' ', 4 * _depth).Append(line);
            _text.Append('\n');
        }

        public void Open(string header) { Line(header); Line("{"); _depth++; }
        public void Close() { _depth--; Line("}"); }
        public void Doc(string summary) => Line($"/// <summary>{summary}</summary>");
        public void Inline() => Line("[MethodImpl(MethodImplOptions.AggressiveInlining)]");

        /// <summary>A documented, inlined one-line method.</summary>
        public void Method(string summary, string line) { Doc(summary); Inline(); Line(line); }
        public override string ToString() => _text.ToString();
    }

    /// <summary>
    /// docs/pairs.md: every pair's contract and every ray cast's, as the summaries of their kernels state them (the same
    /// text the public overloads' XML docs carry), so the page cannot drift from the code.
    /// </summary>
    internal static class Contracts
    {
        public static string Path(string repo) => System.IO.Path.Combine(repo, "docs", "pairs.md");

        public static string Generate(IReadOnlyList<(string File, int Dim, string A, string B, string Summary)> pairs, IReadOnlyList<(string File, string Summary)> casts)
        {
            var sb = new StringBuilder();
            sb.Append("# Every pair's contract\n\n");
            sb.Append("Generated by `dotnet run --project tests/ProximityLib.ApiGen -- sync` from the summaries of the kernels in\n");
            sb.Append("`src/ProximityLib/Pairs/` and `src/ProximityLib/Raycasts/` (the text the public overloads' XML docs carry); `-- check`\n");
            sb.Append("in CI fails when it is out of date. Each pair answers `ClosestDistance.Between` and `Distance` and\n");
            sb.Append("`ProximityQuery.Overlaps` in both argument orders (the swapped call swaps the witnesses and parameters), in double\n");
            sb.Append("(`ProximityLib.Double`) and float (`ProximityLib`). The result contract common to all is in [api.md](api.md#the-result-contract-distanceresult2-distanceresult3);\n");
            sb.Append("the error bounds in [accuracy.md](accuracy.md) and [accuracy-fuzz.md](accuracy-fuzz.md).\n\n");
            foreach (int dim in new[] { 3, 2 })
            {
                var rows = pairs.Where(p => p.Dim == dim).ToList();
                sb.Append($"## {dim}D ({rows.Count} pairs)\n\n| pair | contract and algorithm | file |\n| --- | --- | --- |\n");
                foreach (var p in rows)
                {
                    string text = Markdown(p.Summary);
                    string head = "Closest distance between ";
                    int colon = text.IndexOf(": ", StringComparison.Ordinal);
                    string body = text.StartsWith(head, StringComparison.Ordinal) && colon > 0 ? text.Substring(colon + 2) : text;
                    sb.Append($"| `{p.A}`–`{p.B}` | {Cap(body)} | [{p.File}](../src/ProximityLib/Pairs/{p.File}) |\n");
                }
                sb.Append('\n');
            }
            sb.Append($"## Ray casts ({casts.Count})\n\n`Raycast.Cast(ray, shape, maxDistance = ∞)`: the first hit within maxDistance (a hit whose T or Point lies past the precision's range is a miss: in float past float's, though computed in double).\n\n| target | contract and algorithm | file |\n| --- | --- | --- |\n");
            foreach (var c in casts)
            {
                string text = Markdown(c.Summary);
                int colon = text.IndexOf(": ", StringComparison.Ordinal);
                string target = colon > 0 ? text.Substring(0, colon).Replace("First hit of a ray on ", "") : "";
                sb.Append($"| {target} | {Cap(colon > 0 ? text.Substring(colon + 2) : text)} | [{c.File}](../src/ProximityLib/Raycasts/{c.File}) |\n");
            }
            return sb.ToString();
        }

        private static string Cap(string s) => s.Length == 0 ? s : char.ToUpperInvariant(s[0]) + s.Substring(1);

        /// <summary>XML doc markup as Markdown: &lt;c&gt;x&lt;/c&gt; and &lt;see cref="x"/&gt; as code, entities decoded, pipes escaped.</summary>
        private static string Markdown(string xml)
        {
            string s = Regex.Replace(xml, "<c>(.*?)</c>", "`$1`");
            s = Regex.Replace(s, "<see cref=\"(?:[A-Za-z]:)?([^\"]*)\"\\s*/>", m => "`" + m.Groups[1].Value.Split('.').Last() + "`");
            s = Regex.Replace(s, "<paramref name=\"([^\"]*)\"\\s*/>", "`$1`");
            s = s.Replace("&lt;", "<").Replace("&gt;", ">").Replace("&amp;", "&");
            return s.Replace("|", "\\|");
        }
    }

    /// <summary>
    /// The picker scene's dispatch (src/ProximityLib.Scenes/Picker/Dispatch.g.cs): for every pair of primitive kinds, in
    /// both dimensions, the library call with both shapes built on the stack (a frame allocates nothing). Generated so
    /// the 100 pairs per query cannot go out of step with the kinds; a pair the library lacks fails generation.
    /// </summary>
    internal static class SceneDispatch
    {
        /// <summary>The picker's kinds: the enum member and the typed accessors of Primitive with their double shape types.</summary>
        private static readonly (string Kind, string Get3, string Type3, string Get2, string Type2)[] Kinds =
        {
            ("Point", "P3", "Vector3D", "P2", "Vector2D"),
            ("Segment", "Seg3", "Segment3", "Seg2", "Segment2"),
            ("Round", "Rnd3", "Sphere", "Rnd2", "Circle"),
            ("Aabb", "Box3", "Aabb3", "Box2", "Aabb2"),
            ("Obb", "Obb3", "Obb3", "Obb2", "Obb2"),
            ("Line", "Line3", "Line3", "Line2", "Line2"),
            ("Ray", "Ray3", "Ray3", "Ray2", "Ray2"),
            ("Capsule", "Cap3", "Capsule3", "Cap2", "Capsule2"),
            ("Triangle", "Tri3", "Triangle3", "Tri2", "Triangle2"),
            ("HalfSpace", "Half3", "HalfSpace", "Half2", "HalfPlane"),
        };

        public static string Path(string repo) => System.IO.Path.Combine(repo, "src", "ProximityLib.Scenes", "Picker", "Dispatch.g.cs");

        public static string Generate(IReadOnlyCollection<(string Query, string A, string B)> kernels)
        {
            var have = new HashSet<(string, string, string)>(kernels.SelectMany(k => new[] { (k.Query, k.A, k.B), (k.Query, k.B, k.A) }));
            var sb = new StringBuilder();
            sb.Append("// Generated by tests/ProximityLib.ApiGen (SceneDispatch): do not edit. Run\n");
            sb.Append("// `dotnet run --project tests/ProximityLib.ApiGen -- sync` after changing the picker's kinds or the pairs.\n");
            sb.Append("using System;\n\nnamespace ProximityLib.Scenes.Picker\n{\n");
            sb.Append("    /// <summary>\n    /// Calls the library for two primitives by kind, with the shapes built on the stack: a picker frame costs its one\n");
            sb.Append("    /// query and allocates nothing.\n    /// </summary>\n    internal static class Dispatch\n    {\n");
            foreach (var (method, cls, call, result, dim) in new[]
            {
                ("Distance3", "ClosestDistance", "Between", "DistanceResult3", 3), ("Overlaps3", "ProximityQuery", "Overlaps", "bool", 3),
                ("Distance2", "ClosestDistance", "Between", "DistanceResult2", 2), ("Overlaps2", "ProximityQuery", "Overlaps", "bool", 2),
            })
            {
                sb.Append($"        internal static {result} {method}(Primitive a, Primitive b) => (a.Kind, b.Kind) switch\n        {{\n");
                foreach (var x in Kinds)
                    foreach (var y in Kinds)
                    {
                        string tx = dim == 3 ? x.Type3 : x.Type2, ty = dim == 3 ? y.Type3 : y.Type2;
                        if (!have.Contains((call, tx, ty))) throw new FormatException($"the picker pairs {tx} with {ty}, but the library has no {call} for them");
                        string gx = dim == 3 ? x.Get3 : x.Get2, gy = dim == 3 ? y.Get3 : y.Get2;
                        sb.Append($"            (PrimitiveKind.{x.Kind}, PrimitiveKind.{y.Kind}) => {cls}.{call}(a.{gx}(), b.{gy}()),\n");
                    }
                sb.Append("            _ => throw new InvalidOperationException(),\n        };\n\n");
            }
            sb.Length -= 1;
            sb.Append("    }\n}\n");
            return sb.ToString();
        }
    }
}
