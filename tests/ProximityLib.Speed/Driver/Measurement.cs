using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;

namespace ProximitySpeed
{
    /// <summary>A runtime setting the probes run in.</summary>
    public sealed class Mode
    {
        private Mode(string name, string title) { Name = name; Title = title; }
        public string Name { get; }
        public string Title { get; }

        public static readonly Mode Pgo = new Mode("pgo", ".NET 10");
        public static readonly Mode NoPgo = new Mode("nopgo", ".NET 10, DOTNET_TieredPGO=0");
        public static readonly Mode Mono = new Mode("mono", "Mono");
        public static readonly Mode[] All = { Pgo, NoPgo, Mono };

        public static Mode Parse(string name) => All.FirstOrDefault(m => m.Name == name)
            ?? throw new ArgumentException($"unknown mode '{name}' (pgo, nopgo, mono)");
    }

    /// <summary>One case's rounds in one process.</summary>
    public sealed class CaseRun
    {
        public CaseRun(string group, string name, double bytesPerQuery, double[] times)
        {
            Group = group; Name = name; BytesPerQuery = bytesPerQuery; Times = times;
            Median = Stats.Median(times);
        }
        public string Group { get; }
        public string Name { get; }
        public double BytesPerQuery { get; }
        /// <summary>Nanoseconds per query, one per round.</summary>
        public double[] Times { get; }
        public double Median { get; }
    }

    /// <summary>One probe process: what it reported and how long it took.</summary>
    public sealed class ProbeRun
    {
        public ProbeRun(Mode mode, string runtime, string clock, string vector, int warmUpPasses, Dictionary<string, CaseRun> cases, TimeSpan elapsed)
        {
            Mode = mode; Runtime = runtime; Clock = clock; Vector = vector; WarmUpPasses = warmUpPasses; Cases = cases; Elapsed = elapsed;
        }
        public Mode Mode { get; }
        public string Runtime { get; }
        public string Clock { get; }
        /// <summary>"accelerated, 8 float lanes": Vector&lt;T&gt; in that runtime, which the batch queries run on.</summary>
        public string Vector { get; }
        public int WarmUpPasses { get; }
        /// <summary>By key, "group | name".</summary>
        public Dictionary<string, CaseRun> Cases { get; }
        public TimeSpan Elapsed { get; }

        public static ProbeRun Parse(Mode mode, string output, TimeSpan elapsed)
        {
            string runtime = "", clock = "", vector = "";
            int passes = 0;
            var cases = new Dictionary<string, CaseRun>();
            foreach (var line in output.Split('\n'))
            {
                var f = line.Split('\t');
                if (f[0] == "# runtime") runtime = f[1];
                else if (f[0] == "# clock") clock = f[1];
                else if (f[0] == "# vector") vector = f[1];
                else if (f[0] == "# warm-up passes") passes = int.Parse(f[1], CultureInfo.InvariantCulture);
                else if (f[0] == "case")
                    cases[Measurement.Key(f[1], f[2])] = new CaseRun(f[1], f[2], double.Parse(f[4], CultureInfo.InvariantCulture),
                        f[5].Split(' ').Select(x => double.Parse(x, CultureInfo.InvariantCulture)).ToArray());
            }
            if (cases.Count == 0) throw new IOException($"the {mode.Name} probe reported no cases:\n{output}");
            return new ProbeRun(mode, runtime, clock, vector, passes, cases, elapsed);
        }
    }

    /// <summary>A median across processes with the processes' spread.</summary>
    public readonly struct Spread
    {
        public Spread(IReadOnlyList<double> values) { Median = Stats.Median(values); Min = values.Min(); Max = values.Max(); }
        public double Median { get; }
        public double Min { get; }
        public double Max { get; }
        /// <summary>The largest distance of a process from the median, relative to it.</summary>
        public double Relative => Median > 0 ? Math.Max(Max - Median, Median - Min) / Median : 0;
    }

    /// <summary>Every probe of a run, by mode, and the statistics over them.</summary>
    public sealed class Measurement
    {
        public Measurement(Dictionary<Mode, List<ProbeRun>> runs, Options options, TimeSpan elapsed)
        {
            Runs = runs; Options = options; Elapsed = elapsed;
        }

        public Dictionary<Mode, List<ProbeRun>> Runs { get; }
        public Options Options { get; }
        public TimeSpan Elapsed { get; }
        public IEnumerable<Mode> Modes => Mode.All.Where(Runs.ContainsKey);

        public static string Key(string group, string name) => group + " | " + name;

        public bool Has(Mode mode, string key) => Runs.TryGetValue(mode, out var runs) && runs.All(r => r.Cases.ContainsKey(key));

        /// <summary>
        /// Nanoseconds per query: the median over rounds in each process, divided by the process's
        /// <see cref="Slowdown"/>, then the median across processes.
        /// </summary>
        public Spread? Time(Mode mode, string key)
        {
            if (!Has(mode, key)) return null;
            var slowdown = Slowdown(mode);
            return new Spread(Runs[mode].Select((r, p) => r.Cases[key].Median / slowdown[p]).ToList());
        }

        /// <summary>
        /// How much longer each process of the mode took than the fastest, one factor for all its cases: per process, the
        /// median over the cases of its time ÷ the case's median across processes, then divided by the least of those
        /// (so the fastest process has 1). On the shared VM a whole process now and then runs about 1.4 times as long for
        /// its lifetime, every case alike (in one run of 5 .NET processes, three did): the median across processes then
        /// follows whichever speed most processes had, and two reports differed by 40% on most cases. Dividing the factor
        /// out gives every case the fastest process's speed. Ratios taken within a process (library ÷ baseline, new ÷ old)
        /// do not need it and do not use it.
        /// </summary>
        public IReadOnlyList<double> Slowdown(Mode mode)
        {
            if (_slowdown.TryGetValue(mode, out var known)) return known;
            var runs = Runs[mode];
            var keys = Keys(mode).Where(k => Has(mode, k)).ToList();
            var across = keys.Select(k => Stats.Median(runs.Select(r => r.Cases[k].Median).ToList())).ToList();
            var factor = runs.Select(r => keys.Count == 0 ? 1 : Stats.Median(keys.Select((k, i) => r.Cases[k].Median / across[i]).ToList())).ToArray();
            double least = factor.Min();
            var result = factor.Select(f => f / least).ToArray();
            _slowdown[mode] = result;
            return result;
        }

        private readonly Dictionary<Mode, double[]> _slowdown = new Dictionary<Mode, double[]>();

        /// <summary>
        /// a ÷ b: in each process the median over rounds of the round's ratio (the two ran back to back when they share a
        /// group), then across processes.
        /// </summary>
        public Spread? Ratio(Mode mode, string a, string b) =>
            Has(mode, a) && Has(mode, b)
                ? new Spread(Runs[mode].Select(r => Stats.Median(r.Cases[a].Times.Zip(r.Cases[b].Times, (x, y) => x / y).ToList())).ToList())
                : null;

        /// <summary>Every case key measured in the mode.</summary>
        public IEnumerable<string> Keys(Mode mode) => Runs.TryGetValue(mode, out var runs) ? runs[0].Cases.Keys : Enumerable.Empty<string>();

        public double MaxBytesPerQuery(Mode mode, string key) => Runs[mode].Max(r => r.Cases.TryGetValue(key, out var c) ? c.BytesPerQuery : 0);

        /// <summary>
        /// Runs the probes: <see cref="Options.Processes"/> per mode, the modes interleaved (pgo 1, nopgo 1, mono 1, pgo 2,
        /// …) so a change of machine load falls on every mode alike. Progress goes to stderr.
        /// </summary>
        /// <remarks><paramref name="old"/> and <paramref name="oldMono"/>: the cases compiled against another library for .NET and
        /// for Mono (<see cref="Builds.Old"/>, <see cref="Builds.OldMono"/>), measured as "old …" cases in the same processes.</remarks>
        public static Measurement Run(Options options, string work, string? old, string? oldMono, string? oldFilter)
        {
            var clock = Stopwatch.StartNew();
            Directory.CreateDirectory(work);
            string inputs = Path.Combine(work, $"inputs-{options.Distribution}.txt");
            Inputs.Write(inputs, options.Distribution);
            string? monoProbe = options.Modes.Contains(Mode.Mono) ? Builds.Mono(Path.Combine(work, "mono")) : null;
            if (monoProbe != null) Console.Error.WriteLine($"built the Mono probe ({clock.Elapsed.TotalSeconds:0} s)");

            var probeArgs = new List<string> { "--inputs", inputs, "--rounds", options.Rounds.ToString(CultureInfo.InvariantCulture),
                "--sample-ms", options.SampleMs.ToString(CultureInfo.InvariantCulture) };
            if (options.Filter != null) probeArgs.AddRange(new[] { "--filter", options.Filter });
            var runs = options.Modes.ToDictionary(m => m, m => new List<ProbeRun>());
            for (int p = 0; p < options.Processes; p++)
                foreach (var mode in options.Modes)
                {
                    var args = new List<string>(probeArgs) { "--seed", (p + 1).ToString(CultureInfo.InvariantCulture) };
                    string? against = mode == Mode.Mono ? oldMono : old;
                    if (against != null) args.AddRange(new[] { "--old", against });
                    if (against != null && oldFilter != null) args.AddRange(new[] { "--old-filter", oldFilter });
                    var env = new Dictionary<string, string?> { ["DOTNET_TieredPGO"] = mode == Mode.NoPgo ? "0" : null };
                    var started = Stopwatch.StartNew();
                    var (code, output) = mode == Mode.Mono
                        ? Shell.Run("mono", new[] { monoProbe! }.Concat(args), env)
                        : Shell.Run("dotnet", new[] { typeof(Program).Assembly.Location, "probe" }.Concat(args), env);
                    if (code != 0) throw new IOException($"the {mode.Name} probe failed (exit code {code}):\n{output}");
                    runs[mode].Add(ProbeRun.Parse(mode, output, started.Elapsed));
                    Console.Error.WriteLine($"{mode.Name} process {p + 1}/{options.Processes}: {started.Elapsed.TotalSeconds:0} s (load {Load()})");
                }
            return new Measurement(runs, options, clock.Elapsed);
        }

        /// <summary>The 1-minute load average, as uptime shows it.</summary>
        public static string Load()
        {
            try { return File.ReadAllText("/proc/loadavg").Split(' ')[0]; }
            catch (IOException) { return "unknown"; }
        }
    }

    public static class Stats
    {
        public static double Median(IReadOnlyList<double> values)
        {
            var s = values.OrderBy(x => x).ToArray();
            return s.Length % 2 == 1 ? s[s.Length / 2] : (s[s.Length / 2 - 1] + s[s.Length / 2]) / 2;
        }
    }
}
