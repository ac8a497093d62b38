using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;

namespace ProximitySpeed
{
    /// <summary>The programs the modes run besides this one: the Mono probe, and the cases compiled against an older library (for .NET and for Mono).</summary>
    public static class Builds
    {
        /// <summary>The repository's root (the folder holding ProximityLib.sln), found upwards from this program.</summary>
        public static string Root { get; } = FindRoot();

        private static string FindRoot()
        {
            for (var dir = new DirectoryInfo(AppContext.BaseDirectory); dir != null; dir = dir.Parent)
                if (File.Exists(Path.Combine(dir.FullName, "ProximityLib.sln"))) return dir.FullName;
            throw new IOException("the repository root (ProximityLib.sln) is not above " + AppContext.BaseDirectory);
        }

        private static string CasesDir => Path.Combine(Root, "tests", "ProximityLib.Speed.Cases");

        /// <summary>Sources of the cases; paper formulas and scenes only when <paramref name="all"/> (not in A/B builds).</summary>
        private static List<string> CaseSources(bool all)
        {
            var files = Directory.GetFiles(CasesDir, "*.cs").Where(f => !f.Contains("/obj/") && !f.Contains("/bin/")).ToList();
            if (all) files.Add(Path.Combine(Root, "tests", "ProximityLib.Reference", "PaperFormulas.cs"));
            else files.RemoveAll(f => Path.GetFileName(f) is "PaperCases.cs" or "GaitCase.cs");
            files.Sort(StringComparer.Ordinal);
            return files;
        }

        /// <summary>
        /// The Mono probe: the library and scene sources compiled by the SDK's Roslyn against Mono's own class libraries
        /// (as tests/ProximityLib.MonoCheck/run.sh and Unity do: -nostdlib, lib/mono/4.5 and Facades/netstandard.dll, C# 9,
        /// unsafe code allowed, no NET define, so the netstandard2.1 code paths), then the cases and Probe/ into one program. Returns its path.
        /// </summary>
        public static string Mono(string work)
        {
            var refs = MonoReferences();
            Directory.CreateDirectory(work);
            string Sources(string project) => string.Join("\n", Directory.GetFiles(Path.Combine(Root, "src", project), "*.cs", SearchOption.AllDirectories)
                .Where(f => !f.Contains("/obj/") && !f.Contains("/bin/")).OrderBy(f => f, StringComparer.Ordinal));
            string library = Path.Combine(work, "ProximityLib.dll"), scenes = Path.Combine(work, "ProximityLib.Scenes.dll");
            // The library's batch runner pins spans (unsafe), as its csproj and Unity asmdef allow.
            Csc(work, refs, "-t:library", "-unsafe+", "-out:" + library, Sources("ProximityLib"));
            Csc(work, refs, "-t:library", "-out:" + scenes, "-r:" + library, Sources("ProximityLib.Scenes"));
            string probe = Path.Combine(work, "ProximityLib.Speed.Probe.exe");
            var probeSources = CaseSources(true).Concat(Directory.GetFiles(Path.Combine(Root, "tests", "ProximityLib.Speed", "Probe"), "*.cs"));
            Csc(work, refs, "-t:exe", "-main:ProximitySpeed.ProbeProgram", "-out:" + probe, "-r:" + library, "-r:" + scenes, string.Join("\n", probeSources));
            return probe;
        }

        /// <summary>-r: options for Mono's class libraries (lib/mono/4.5 and Facades/netstandard.dll beside the mono on PATH).</summary>
        private static List<string> MonoReferences()
        {
            string mono = Which("mono") ?? throw new IOException("mono is not installed (apt-get install mono-devel)");
            string lib = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(ResolveLink(mono))!, "..", "lib", "mono", "4.5"));
            if (!File.Exists(Path.Combine(lib, "mscorlib.dll")) || !File.Exists(Path.Combine(lib, "Facades", "netstandard.dll")))
                throw new IOException("Mono's class libraries are not under " + lib);
            return Directory.GetFiles(lib, "*.dll").Append(Path.Combine(lib, "Facades", "netstandard.dll")).Select(f => "-r:" + f).ToList();
        }

        private static void Csc(string work, List<string> refs, params string[] args)
        {
            string sdk = Sdk();
            string csc = Path.Combine(sdk, "Roslyn", "bincore", "csc.dll");
            if (!File.Exists(csc)) throw new IOException("Roslyn (csc.dll) not found in the .NET SDK at " + sdk);
            // One response file: the source lists are long.
            string rsp = Path.Combine(work, "csc-" + Guid.NewGuid().ToString("N") + ".rsp");
            File.WriteAllLines(rsp, new[] { "-nologo", "-noconfig", "-nostdlib", "-langversion:9", "-nullable:enable", "-optimize+", "-deterministic" }
                .Concat(refs).Concat(args.SelectMany(a => a.Split('\n'))).Select(a => a.Contains(' ') ? "\"" + a + "\"" : a));
            var (code, output) = Shell.Run("dotnet", new[] { csc, "@" + rsp }, null);
            if (code != 0) throw new IOException("csc failed:\n" + string.Join("\n", output.Split('\n').Where(l => l.Contains("error")).Distinct().Take(20)));
        }

        /// <summary>The newest .NET 10 SDK's folder.</summary>
        private static string Sdk()
        {
            var (_, output) = Shell.Run("dotnet", new[] { "--list-sdks" }, null);
            var m = output.Split('\n').Select(l => Regex.Match(l, @"^(10\.\S+) \[(.*)\]$")).Where(x => x.Success).LastOrDefault()
                ?? throw new IOException("no .NET 10 SDK found by dotnet --list-sdks");
            return Path.Combine(m.Groups[2].Value, m.Groups[1].Value);
        }

        /// <summary>
        /// The cases compiled against the library at <paramref name="gitRef"/>: src/ProximityLib exported at that ref and
        /// built as an assembly named ProximityLibOld, the cases' sources (without paper formulas and scenes) built against
        /// it. Returns the path of the cases' assembly, for the probe's --old.
        /// </summary>
        public static string Old(string gitRef, string work)
        {
            string lib = Export(gitRef, work);
            File.WriteAllText(Path.Combine(work, "ProximityLibOld.csproj"), $"""
                <Project Sdk="Microsoft.NET.Sdk">
                  <PropertyGroup>
                    <TargetFramework>net10.0</TargetFramework>
                    <AssemblyName>ProximityLibOld</AssemblyName>
                    <AllowUnsafeBlocks>true</AllowUnsafeBlocks>
                    <LangVersion>9.0</LangVersion>
                    <Nullable>enable</Nullable>
                    <Optimize>true</Optimize>
                    <EnableDefaultCompileItems>false</EnableDefaultCompileItems>
                  </PropertyGroup>
                  <ItemGroup><Compile Include="{lib}/**/*.cs" Exclude="{lib}/obj/**;{lib}/bin/**" /></ItemGroup>
                </Project>
                """);
            var sources = OldCaseSources(lib);
            string casesProject = Path.Combine(work, "ProximityLib.Speed.CasesOld.csproj");
            void WriteCases() => File.WriteAllText(casesProject, $"""
                <Project Sdk="Microsoft.NET.Sdk">
                  <PropertyGroup>
                    <TargetFramework>net10.0</TargetFramework>
                    <LangVersion>9.0</LangVersion>
                    <Nullable>enable</Nullable>
                    <Optimize>true</Optimize>
                    <EnableDefaultCompileItems>false</EnableDefaultCompileItems>
                  </PropertyGroup>
                  <ItemGroup>
                {string.Join("\n", sources.Select(s => $"    <Compile Include=\"{s}\" />"))}
                    <ProjectReference Include="ProximityLibOld.csproj" />
                  </ItemGroup>
                </Project>
                """);
            WriteCases();
            string outDir = Path.Combine(work, "out");
            string[] build = { "build", casesProject, "-c", "Release", "-o", outDir, "-nologo", "-v", "q" };
            var (built, log) = Shell.Run("dotnet", build, null);
            // An older library may lack the distance-only entry point (ProximityLib.Speed.Cases/Pairs.cs): those rows are n/a.
            if (built != 0 && sources.RemoveAll(s => Path.GetFileName(s) == "DistanceOnly.cs") > 0)
            {
                WriteCases();
                (built, log) = Shell.Run("dotnet", build, null);
            }
            if (built != 0) throw new IOException($"the cases do not build against the library at {gitRef}:\n" +
                string.Join("\n", log.Split('\n').Where(l => l.Contains("error")).Distinct().Take(20)));
            return Path.Combine(outDir, "ProximityLib.Speed.CasesOld.dll");
        }

        /// <summary>
        /// The Mono twin of <see cref="Old"/>: src/ProximityLib at <paramref name="gitRef"/> compiled by Roslyn against Mono's
        /// class libraries as ProximityLibOld.dll (as <see cref="Mono"/> compiles the working tree's), and the cases against
        /// it as ProximityLib.Speed.CasesOld.dll beside it, for the Mono probe's --old. Returns the cases' path.
        /// </summary>
        public static string OldMono(string gitRef, string work)
        {
            string lib = Export(gitRef, work);
            var refs = MonoReferences();
            string library = Path.Combine(work, "ProximityLibOld.dll"), cases = Path.Combine(work, "ProximityLib.Speed.CasesOld.dll");
            Csc(work, refs, "-t:library", "-unsafe+", "-out:" + library, string.Join("\n", Directory.GetFiles(lib, "*.cs", SearchOption.AllDirectories)
                .Where(f => !f.Contains("/obj/") && !f.Contains("/bin/")).OrderBy(f => f, StringComparer.Ordinal)));
            var sources = OldCaseSources(lib);
            try { Csc(work, refs, "-t:library", "-out:" + cases, "-r:" + library, string.Join("\n", sources)); }
            catch (IOException) when (sources.RemoveAll(s => Path.GetFileName(s) == "DistanceOnly.cs") > 0)
            {
                // An older library may lack the distance-only entry point: those rows are n/a, as in Old.
                Csc(work, refs, "-t:library", "-out:" + cases, "-r:" + library, string.Join("\n", sources));
            }
            return cases;
        }

        /// <summary>src/ProximityLib at <paramref name="gitRef"/>, exported under <paramref name="work"/>; returns its folder.</summary>
        private static string Export(string gitRef, string work)
        {
            Directory.CreateDirectory(work);
            var (code, output) = Shell.Run("git", new[] { "-C", Root, "rev-parse", "--verify", gitRef + "^{commit}" }, null);
            if (code != 0) throw new ArgumentException("'" + gitRef + "' is not a commit of this repository");
            string commit = output.Trim();
            var tar = Path.Combine(work, "old.tar");
            if (Shell.Run("git", new[] { "-C", Root, "archive", "-o", tar, commit, "src/ProximityLib" }, null).Code != 0
                || Shell.Run("tar", new[] { "-xf", tar, "-C", work }, null).Code != 0)
                throw new IOException("could not export src/ProximityLib at " + gitRef);
            return Path.Combine(work, "src", "ProximityLib");
        }

        /// <summary>The cases' sources for an A/B build against the exported library at <paramref name="lib"/>.</summary>
        private static List<string> OldCaseSources(string lib)
        {
            var sources = CaseSources(false);
            // Issue 12's cases need its shapes and ray casts: left out against a library without them (no RayHit.cs).
            if (!File.Exists(Path.Combine(lib, "RayHit.cs")))
                sources.RemoveAll(s => Path.GetFileName(s) is "PairsNew.cs" or "BaselinesNew.cs" or "Raycasts.cs" or "ShapesNew.cs");
            return sources;
        }

        private static string? Which(string program) =>
            (Environment.GetEnvironmentVariable("PATH") ?? "").Split(':').Select(d => Path.Combine(d, program)).FirstOrDefault(File.Exists);

        private static string ResolveLink(string path) => new FileInfo(path).ResolveLinkTarget(true)?.FullName ?? path;
    }

    /// <summary>Runs a program and collects what it prints.</summary>
    public static class Shell
    {
        /// <summary>Exit code and stdout (plus stderr when it failed); <paramref name="env"/> adds (value) or removes (null) variables.</summary>
        public static (int Code, string Output) Run(string program, IEnumerable<string> args, IDictionary<string, string?>? env)
        {
            var start = new ProcessStartInfo(program) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false };
            foreach (var a in args) start.ArgumentList.Add(a);
            if (env != null)
                foreach (var (k, v) in env)
                    if (v == null) start.Environment.Remove(k); else start.Environment[k] = v;
            using var p = Process.Start(start) ?? throw new IOException("could not start " + program);
            var stderr = p.StandardError.ReadToEndAsync();
            string stdout = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            return (p.ExitCode, p.ExitCode == 0 ? stdout : stdout + stderr.Result);
        }
    }
}
