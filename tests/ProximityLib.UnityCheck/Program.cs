using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Security.Cryptography;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

// dotnet run --project tests/ProximityLib.UnityCheck -- sync
//     regenerate unity-demo's copy of the library and scene source, its asmdefs, and every missing .meta
// dotnet run --project tests/ProximityLib.UnityCheck -- check [--compile DIR]
//     verify the copy is in sync, the .meta files are complete and unique, package.json is valid; with --compile,
//     write one netstandard2.1 project per asmdef (as Unity would compile it) under DIR, plus DIR/All/All.csproj
namespace ProximityUnityCheck
{
    internal static class Program
    {
        private static int Main(string[] args)
        {
            var package = new UnityPackage(FindRepo());
            switch (args.FirstOrDefault())
            {
                case "sync":
                    foreach (var line in package.Sync()) Console.WriteLine(line);
                    return 0;
                case "check":
                    var problems = package.Check();
                    int at = Array.IndexOf(args, "--compile");
                    if (at >= 0 && at + 1 < args.Length && problems.Count == 0)
                        problems.AddRange(package.WriteCompileProjects(Path.GetFullPath(args[at + 1])));
                    foreach (var p in problems) Console.WriteLine($"unity-demo: {p}");
                    Console.WriteLine(problems.Count == 0
                        ? "unity-demo: package.json valid, source copy in sync, .meta files complete and unique"
                        : $"unity-demo: {problems.Count} problem(s); run `dotnet run --project tests/ProximityLib.UnityCheck -- sync` for the generated parts");
                    return problems.Count == 0 ? 0 : 1;
                default:
                    Console.WriteLine("usage: ProximityLib.UnityCheck sync | check [--compile DIR]");
                    return 2;
            }
        }

        private static string FindRepo()
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "ProximityLib.sln"))) return dir.FullName;
            throw new InvalidOperationException("run from inside the repository (ProximityLib.sln not found above the tool).");
        }
    }

    /// <summary>A source folder of the repository that reaches Unity as a copy with its own asmdef.</summary>
    internal sealed record SourceCopy(string From, string To, string Assembly, string[] References, bool Unsafe);

    internal sealed class UnityPackage
    {
        private static readonly SourceCopy[] Copies =
        {
            // The library pins result spans for the multi-core batch (AllowUnsafeBlocks in its csproj).
            new("src/ProximityLib", "Runtime/ProximityLib", "ProximityLib", Array.Empty<string>(), true),
            new("src/ProximityLib.Scenes", "Runtime/ProximityLib.Scenes", "ProximityLib.Scenes", new[] { "ProximityLib" }, false),
        };

        private readonly string _repo, _root;

        public UnityPackage(string repo)
        {
            _repo = repo;
            _root = Path.Combine(repo, "unity-demo");
        }

        /// <summary>Every generated file of the package (relative path → content): the source copies, their asmdefs, the license.</summary>
        private SortedDictionary<string, string> Generated()
        {
            var files = new SortedDictionary<string, string>(StringComparer.Ordinal);
            foreach (var copy in Copies)
            {
                string from = Path.Combine(_repo, copy.From);
                foreach (var file in Directory.EnumerateFiles(from, "*.cs", SearchOption.AllDirectories))
                {
                    string rel = Rel(from, file);
                    if (rel.StartsWith("bin/", StringComparison.Ordinal) || rel.StartsWith("obj/", StringComparison.Ordinal)) continue;
                    // The library builds with <Nullable>enable</Nullable>; Unity does not, so each copy says it itself.
                    files[$"{copy.To}/{rel}"] =
                        $"// Copied from {copy.From}/{rel} by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.\n" +
                        "#nullable enable\n" + File.ReadAllText(file).Replace("\r\n", "\n");
                }
                files[$"{copy.To}/{copy.Assembly}.asmdef"] = Asmdef(copy.Assembly, copy.References, copy.Unsafe);
            }
            files["LICENSE.md"] = File.ReadAllText(Path.Combine(_repo, "LICENSE")).Replace("\r\n", "\n");
            return files;
        }

        private static string Asmdef(string name, string[] references, bool unsafeCode) =>
            "{\n" +
            $"    \"name\": \"{name}\",\n" +
            $"    \"rootNamespace\": \"{name}\",\n" +
            $"    \"references\": [{string.Join(", ", references.Select(r => $"\"{r}\""))}],\n" +
            "    \"includePlatforms\": [],\n" +
            "    \"excludePlatforms\": [],\n" +
            $"    \"allowUnsafeCode\": {(unsafeCode ? "true" : "false")},\n" +
            "    \"overrideReferences\": false,\n" +
            "    \"precompiledReferences\": [],\n" +
            "    \"autoReferenced\": true,\n" +
            "    \"defineConstraints\": [],\n" +
            "    \"versionDefines\": [],\n" +
            "    \"noEngineReferences\": true\n" +
            "}\n";

        public IEnumerable<string> Sync()
        {
            var generated = Generated();
            foreach (var copy in Copies)
            {
                string dir = Path.Combine(_root, copy.To);
                if (!Directory.Exists(dir)) continue;
                foreach (var file in Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories).ToList())
                {
                    string rel = Rel(_root, file);
                    string asset = rel.EndsWith(".meta", StringComparison.Ordinal) ? rel[..^5] : rel;
                    if (!generated.ContainsKey(asset) && !Directory.Exists(Path.Combine(_root, asset)))
                    {
                        File.Delete(file);
                        yield return $"removed {rel}";
                    }
                }
            }
            foreach (var (rel, content) in generated)
            {
                string path = Path.Combine(_root, rel);
                if (File.Exists(path) && File.ReadAllText(path) == content) continue;
                Directory.CreateDirectory(Path.GetDirectoryName(path)!);
                File.WriteAllText(path, content);
                yield return $"wrote {rel}";
            }
            foreach (var dir in Directory.EnumerateDirectories(_root, "*", SearchOption.AllDirectories).Where(d => !Directory.EnumerateFileSystemEntries(d).Any()).ToList())
                Directory.Delete(dir);
            foreach (var asset in Assets())
            {
                string meta = Path.Combine(_root, asset + ".meta");
                if (File.Exists(meta)) continue;
                File.WriteAllText(meta, Meta(asset, Directory.Exists(Path.Combine(_root, asset))));
                yield return $"wrote {asset}.meta";
            }
        }

        public List<string> Check()
        {
            var problems = new List<string>();
            var generated = Generated();
            foreach (var (rel, content) in generated)
            {
                string path = Path.Combine(_root, rel);
                if (!File.Exists(path)) problems.Add($"{rel} is missing from the source copy");
                else if (File.ReadAllText(path) != content) problems.Add($"{rel} differs from what sync produces from src/");
            }
            var expected = new HashSet<string>(generated.Keys, StringComparer.Ordinal);
            foreach (var copy in Copies)
            {
                string dir = Path.Combine(_root, copy.To);
                if (!Directory.Exists(dir)) continue;
                foreach (var file in Directory.EnumerateFiles(dir, "*", SearchOption.AllDirectories))
                {
                    string rel = Rel(_root, file);
                    if (!rel.EndsWith(".meta", StringComparison.Ordinal) && !expected.Contains(rel))
                        problems.Add($"{rel} is in the source copy but not in src/");
                }
            }

            var assets = new HashSet<string>(Assets(), StringComparer.Ordinal);
            var guids = new Dictionary<string, string>(StringComparer.Ordinal);
            foreach (var asset in assets)
            {
                string meta = Path.Combine(_root, asset + ".meta");
                if (!File.Exists(meta)) { problems.Add($"{asset} has no .meta"); continue; }
                var m = Regex.Match(File.ReadAllText(meta), @"^guid: ([0-9a-f]{32})\s*$", RegexOptions.Multiline);
                if (!m.Success) { problems.Add($"{asset}.meta has no 32-hex-digit guid line"); continue; }
                if (guids.TryGetValue(m.Groups[1].Value, out var other)) problems.Add($"{asset}.meta and {other}.meta share guid {m.Groups[1].Value}");
                else guids[m.Groups[1].Value] = asset;
            }
            foreach (var meta in Directory.EnumerateFiles(_root, "*.meta", SearchOption.AllDirectories))
            {
                string asset = Rel(_root, meta)[..^5];
                if (!assets.Contains(asset)) problems.Add($"{asset}.meta has no asset (orphan .meta)");
            }
            // Scenes reach scripts only through these GUIDs: a reference to a GUID no .meta carries is a missing script.
            foreach (var scene in Directory.EnumerateFiles(_root, "*.unity", SearchOption.AllDirectories))
                foreach (Match m in Regex.Matches(File.ReadAllText(scene), @"guid: ([0-9a-f]{32})"))
                    if (!guids.ContainsKey(m.Groups[1].Value))
                        problems.Add($"{Rel(_root, scene)} references guid {m.Groups[1].Value}, which no .meta in the package has");
            problems.AddRange(CheckPackageJson());
            return problems;
        }

        private IEnumerable<string> CheckPackageJson()
        {
            string path = Path.Combine(_root, "package.json");
            if (!File.Exists(path)) { yield return "package.json is missing"; yield break; }
            JsonElement json;
            string? error = null;
            try { json = JsonDocument.Parse(File.ReadAllText(path)).RootElement.Clone(); }
            catch (JsonException e) { json = default; error = e.Message; }
            if (error != null) { yield return $"package.json is not valid JSON: {error}"; yield break; }

            string Str(string key) => json.TryGetProperty(key, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString()! : "";
            if (!Regex.IsMatch(Str("name"), @"^[a-z][a-z0-9-]*(\.[a-z0-9-]+){2,}$"))
                yield return $"package.json name \"{Str("name")}\" is not a lowercase reverse-domain name (e.g. com.company.package)";
            if (!Regex.IsMatch(Str("version"), @"^\d+\.\d+\.\d+(-[0-9A-Za-z.-]+)?$"))
                yield return $"package.json version \"{Str("version")}\" is not semver";
            string libraryVersion = Regex.Match(File.ReadAllText(Path.Combine(_repo, "src/ProximityLib/ProximityLib.csproj")), "<Version>([^<]+)</Version>").Groups[1].Value;
            if (Str("version") != libraryVersion)
                yield return $"package.json version {Str("version")} differs from the library's {libraryVersion} (src/ProximityLib/ProximityLib.csproj)";
            if (Str("unity") != "2021.3") yield return "package.json unity must be \"2021.3\"";
            foreach (var key in new[] { "displayName", "description" })
                if (Str(key).Length == 0) yield return $"package.json needs a {key}";
            if (!json.TryGetProperty("samples", out var samples) || samples.ValueKind != JsonValueKind.Array || samples.GetArrayLength() == 0)
            {
                yield return "package.json needs a samples array";
                yield break;
            }
            foreach (var sample in samples.EnumerateArray())
            {
                string S(string key) => sample.TryGetProperty(key, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString()! : "";
                if (S("displayName").Length == 0 || S("description").Length == 0) yield return "every sample needs displayName and description";
                if (!S("path").StartsWith("Samples~/", StringComparison.Ordinal) || !Directory.Exists(Path.Combine(_root, S("path"))))
                    yield return $"sample path \"{S("path")}\" is not a folder under Samples~/";
            }
        }

        /// <summary>Writes one project per asmdef, compiled the way Unity compiles it (netstandard2.1, C# 9).</summary>
        public IEnumerable<string> WriteCompileProjects(string dir)
        {
            var asmdefs = Directory.EnumerateFiles(_root, "*.asmdef", SearchOption.AllDirectories).OrderBy(p => p, StringComparer.Ordinal).ToList();
            var folders = asmdefs.Select(Path.GetDirectoryName).ToList();
            var parsed = asmdefs.Select(a => JsonDocument.Parse(File.ReadAllText(a)).RootElement).ToList();
            var names = parsed.Select(j => j.GetProperty("name").GetString()!).ToList();
            string stub = Path.Combine(_repo, "tests/ProximityLib.UnityCheck/UnityEngineStub/UnityEngine.csproj");
            for (int n = 0; n < asmdefs.Count; n++)
            {
                string asmdef = asmdefs[n], name = names[n];
                var json = parsed[n];
                var refs = json.TryGetProperty("references", out var r) ? r.EnumerateArray().Select(e => e.GetString()!).ToList() : new List<string>();
                bool engine = !(json.TryGetProperty("noEngineReferences", out var ne) && ne.GetBoolean());
                bool unsafeCode = json.TryGetProperty("allowUnsafeCode", out var au) && au.GetBoolean();
                string folder = Path.GetDirectoryName(asmdef)!;
                // Unity gives a script to the asmdef of its nearest enclosing folder.
                var sources = Directory.EnumerateFiles(folder, "*.cs", SearchOption.AllDirectories)
                    .Where(f => folders.Where(d => f.StartsWith(d + Path.DirectorySeparatorChar, StringComparison.Ordinal)).OrderByDescending(d => d!.Length).First() == folder)
                    .OrderBy(f => f, StringComparer.Ordinal).ToList();
                var sb = new StringBuilder();
                sb.AppendLine("<Project Sdk=\"Microsoft.NET.Sdk\">");
                sb.AppendLine("  <PropertyGroup>");
                sb.AppendLine($"    <TargetFramework>netstandard2.1</TargetFramework><LangVersion>9.0</LangVersion><AssemblyName>{name}</AssemblyName>");
                sb.AppendLine("    <EnableDefaultCompileItems>false</EnableDefaultCompileItems><Nullable>disable</Nullable><TreatWarningsAsErrors>true</TreatWarningsAsErrors>");
                sb.AppendLine($"    <AllowUnsafeBlocks>{(unsafeCode ? "true" : "false")}</AllowUnsafeBlocks><DefineConstants>UNITY_2021_3;UNITY_2021_3_OR_NEWER;UNITY_5_3_OR_NEWER</DefineConstants>");
                sb.AppendLine("  </PropertyGroup>");
                sb.AppendLine("  <ItemGroup>");
                foreach (var s in sources) sb.AppendLine($"    <Compile Include=\"{s}\" />");
                foreach (var reference in refs) sb.AppendLine($"    <ProjectReference Include=\"../{reference}/{reference}.csproj\" />");
                if (engine) sb.AppendLine($"    <ProjectReference Include=\"{stub}\" />");
                sb.AppendLine("  </ItemGroup>");
                sb.AppendLine("</Project>");
                Directory.CreateDirectory(Path.Combine(dir, name));
                File.WriteAllText(Path.Combine(dir, name, name + ".csproj"), sb.ToString());
                foreach (var reference in refs.Where(x => !names.Contains(x)))
                    yield return $"{Rel(_root, asmdef)} references {reference}, which is not an asmdef of this package";
            }
            Directory.CreateDirectory(Path.Combine(dir, "All"));
            File.WriteAllText(Path.Combine(dir, "All", "All.csproj"),
                "<Project Sdk=\"Microsoft.NET.Sdk\">\n  <PropertyGroup><TargetFramework>netstandard2.1</TargetFramework></PropertyGroup>\n  <ItemGroup>\n" +
                string.Concat(names.Select(n => $"    <ProjectReference Include=\"../{n}/{n}.csproj\" />\n")) + "  </ItemGroup>\n</Project>\n");
            Console.WriteLine($"unity-demo: {names.Count} compile projects ({string.Join(", ", names)}) in {dir}");
        }

        /// <summary>Every file and folder Unity imports from the package, as paths relative to its root.</summary>
        private IEnumerable<string> Assets()
        {
            var stack = new Stack<string>();
            stack.Push(_root);
            while (stack.Count > 0)
            {
                string dir = stack.Pop();
                foreach (var entry in Directory.EnumerateFileSystemEntries(dir).OrderBy(e => e, StringComparer.Ordinal))
                {
                    string name = Path.GetFileName(entry);
                    if (name.StartsWith(".", StringComparison.Ordinal) || name.EndsWith(".meta", StringComparison.Ordinal)) continue;
                    bool isDir = Directory.Exists(entry);
                    // Unity skips "Samples~"-style folders; their contents are imported (with these metas) when a
                    // sample is copied into a project, so everything inside still needs one.
                    if (isDir && name.EndsWith("~", StringComparison.Ordinal)) { stack.Push(entry); continue; }
                    yield return Rel(_root, entry);
                    if (isDir) stack.Push(entry);
                }
            }
        }

        /// <summary>A .meta with a GUID derived from the asset's path, so regenerating never changes a reference.</summary>
        private static string Meta(string asset, bool folder)
        {
            var hash = MD5.HashData(Encoding.UTF8.GetBytes("ProximityLib/unity-demo/" + asset));
            string guid = Convert.ToHexString(hash).ToLowerInvariant();
            string importer = folder ? "DefaultImporter" : Path.GetExtension(asset) switch
            {
                ".cs" => "MonoImporter",
                ".asmdef" => "AssemblyDefinitionImporter",
                ".md" or ".json" or ".txt" => "TextScriptImporter",
                _ => "DefaultImporter",
            };
            var sb = new StringBuilder();
            sb.Append("fileFormatVersion: 2\n").Append($"guid: {guid}\n");
            if (folder) sb.Append("folderAsset: yes\n");
            sb.Append($"{importer}:\n  externalObjects: {{}}\n");
            if (importer == "MonoImporter")
                sb.Append("  serializedVersion: 2\n  defaultReferences: []\n  executionOrder: 0\n  icon: {instanceID: 0}\n");
            sb.Append("  userData: \n  assetBundleName: \n  assetBundleVariant: \n");
            return sb.ToString();
        }

        private static string Rel(string root, string path) => Path.GetRelativePath(root, path).Replace('\\', '/');
    }
}
