using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using System.Text;

namespace ProximitySpeed
{
    /// <summary>One line of a targets table: what is promised, what was measured, and whether it holds.</summary>
    public sealed class TargetRow
    {
        public TargetRow(string what, string target, string measured, string verdict) { What = what; Target = target; Measured = measured; Verdict = verdict; }
        public string What { get; }
        public string Target { get; }
        public string Measured { get; }
        /// <summary>"met", "missed", "within noise" (a ratio above 1 by less than the run-to-run spread) or "n/a".</summary>
        public string Verdict { get; }
    }

    /// <summary>The issue's targets (docs/performance.md), checked against one measurement, per runtime.</summary>
    public static class Targets
    {
        /// <summary>The pairs with hand-written baselines, on which the library's ratios are promised.</summary>
        public static readonly string[] BaselinePairs =
            { "3D sphere–sphere", "3D point–AABB", "3D point–segment", "3D AABB–AABB", "3D segment–segment", "2D segment–segment" };

        private static readonly string[] Precisions = { "float", "double" };

        /// <summary>A ratio above 1 by less than this is inside the run-to-run spread the harness promises (±10%).</summary>
        public const double Noise = 1.10;

        public static List<TargetRow> For(Measurement m, Mode mode)
        {
            var rows = new List<TargetRow>();
            bool mono = mode == Mode.Mono;
            double distanceRatio = mono ? 1.5 : 1.1, betweenRatio = mono ? 3 : 1.5;
            foreach (var pair in BaselinePairs)
                foreach (var p in Precisions)
                {
                    string dist = $"{p} {pair} distance", over = $"{p} {pair} overlap";
                    rows.Add(RatioRow(m, mode, dist, "library Distance", "baseline Distance", distanceRatio));
                    rows.Add(RatioRow(m, mode, dist, "library Between", "baseline Between", betweenRatio));
                    if (m.Has(mode, Measurement.Key(over, "baseline Overlaps")))
                        rows.Add(RatioRow(m, mode, over, "library Overlaps", "baseline Overlaps", distanceRatio));
                }
            if (!mono)
            {
                foreach (var p in Precisions)
                {
                    rows.Add(TimeRow(m, mode, $"{p} 3D OBB–OBB overlap", "library Overlaps", 25));
                    rows.Add(TimeRow(m, mode, $"{p} 3D segment–segment distance", "library Between", 12));
                    foreach (var q in new[] { "3D OBB–OBB", "3D AABB–OBB" }) rows.Add(TimeRow(m, mode, $"{p} {q} distance", "library Between", 200));
                    foreach (var q in new[] { "2D OBB–OBB", "2D AABB–OBB" }) rows.Add(TimeRow(m, mode, $"{p} {q} distance", "library Between", 60));
                    foreach (var q in new[] { "3D segment–AABB", "3D segment–OBB", "2D segment–AABB", "2D segment–OBB" })
                        rows.Add(TimeRow(m, mode, $"{p} {q} distance", "library Between", 40));
                }
                if (mode == Mode.NoPgo) rows.Add(PgoOffRow(m));
                foreach (var key in m.Keys(mode).Where(k => k.Contains(" | old batch")).OrderBy(k => k, StringComparer.Ordinal))
                {
                    string now = key.Replace(" | old ", " | ");
                    var r = m.Ratio(mode, now, key);
                    if (r == null) continue;
                    rows.Add(new TargetRow($"{Label(now)}: now ÷ at {Program.BatchReference}", "≤ 1", Text.Ratio(r.Value), Verdict(r.Value.Median, 1)));
                }
            }
            else
            {
                foreach (var p in Precisions)
                    foreach (var q in new[] { "3D OBB–OBB", "2D OBB–OBB" })
                        rows.Add(TimeRow(m, mode, $"{p} {q} distance", "library Between", 1000));
                foreach (var key in m.Keys(mode).Where(k => k.Contains(" | batch ")).OrderBy(k => k, StringComparer.Ordinal))
                {
                    string group = key.Substring(0, key.IndexOf(" | ", StringComparison.Ordinal));
                    string scalar = Scalar(m, mode, key);
                    var r = m.Ratio(mode, key, Measurement.Key(group, scalar));
                    if (r == null) continue;
                    rows.Add(new TargetRow($"{Label(key)} ÷ {scalar} (per pair)", "≤ 1", Text.Ratio(r.Value), Verdict(r.Value.Median, 1)));
                }
            }
            return rows;
        }

        /// <summary>
        /// The scalar API case a batch case answers the same question as, on the same pairs: for one-to-many, the scalar
        /// API looped over those pairs where it was measured; else the paired scalar case, the distance alone where the
        /// library has it.
        /// </summary>
        public static string Scalar(Measurement m, Mode mode, string batchKey)
        {
            string group = batchKey.Substring(0, batchKey.IndexOf(" | ", StringComparison.Ordinal));
            bool overlap = group.EndsWith(" overlap", StringComparison.Ordinal);
            string sameInputs = overlap ? "scalar one-to-many Overlaps" : "scalar one-to-many Distance";
            if (batchKey.Contains(" | batch one-to-many ") && m.Has(mode, Measurement.Key(group, sameInputs))) return sameInputs;
            return overlap ? "library Overlaps" : m.Has(mode, Measurement.Key(group, "library Distance")) ? "library Distance" : "library Between";
        }

        /// <summary>A case key as a table cell: "group: name" (a key's " | " would split the cell).</summary>
        public static string Label(string key) => key.Replace(" | ", ": ");

        private static string Verdict(double value, double limit) =>
            value <= limit ? "met" : limit == 1 && value <= Noise ? "within noise" : "missed";

        private static TargetRow RatioRow(Measurement m, Mode mode, string group, string a, string b, double limit)
        {
            string what = $"{group}: {a} ÷ {b}";
            var r = m.Ratio(mode, Measurement.Key(group, a), Measurement.Key(group, b));
            if (r == null)
                return new TargetRow(what, $"≤ {limit}×", m.Has(mode, Measurement.Key(group, b)) ? $"no {a} in this library" : "not measured", "n/a");
            return new TargetRow(what, $"≤ {limit}×", Text.Ratio(r.Value), Verdict(r.Value.Median, limit));
        }

        private static TargetRow TimeRow(Measurement m, Mode mode, string group, string name, double ns)
        {
            string what = $"{group}: {name}";
            var t = m.Time(mode, Measurement.Key(group, name));
            string target = ns >= 1000 ? $"≤ {ns / 1000:0.#} µs" : $"≤ {ns:0} ns";
            return t == null ? new TargetRow(what, target, "not measured", "n/a") : new TargetRow(what, target, Text.Ns(t.Value) + " ns", Verdict(t.Value.Median, ns));
        }

        /// <summary>Every scalar library case without PGO against its default time (the medians of separate processes).</summary>
        private static TargetRow PgoOffRow(Measurement m)
        {
            var ratios = m.Keys(Mode.NoPgo).Where(k => k.Contains(" | library ") && m.Has(Mode.Pgo, k))
                .Select(k => (Key: k, Ratio: m.Time(Mode.NoPgo, k)!.Value.Median / m.Time(Mode.Pgo, k)!.Value.Median)).OrderByDescending(x => x.Ratio).ToList();
            if (ratios.Count == 0) return new TargetRow("every scalar query: time without PGO ÷ default time", "≤ 1.3×", "not measured", "n/a");
            var above = ratios.Where(x => x.Ratio > 1.3).ToList();
            string measured = $"{above.Count} of {ratios.Count} above 1.3" +
                              (above.Count > 0 ? ": " + string.Join(", ", above.Select(x => $"{Label(x.Key)} {x.Ratio:0.00}")) : $"; worst {ratios[0].Ratio:0.00} ({Label(ratios[0].Key)})");
            return new TargetRow("every scalar query: time without PGO ÷ default time", "≤ 1.3×", measured, above.Count == 0 ? "met" : "missed");
        }
    }

    /// <summary>docs/performance.md and the speed-against-error plot from a measurement in every mode.</summary>
    public static class Report
    {
        /// <summary><paramref name="reproduced"/>: how far the medians are from an earlier run's (Saved.Compare), if one was given.</summary>
        public static void Write(Measurement m, string dir, string loadBefore, string? reproduced)
        {
            Directory.CreateDirectory(dir);
            var accuracy = Accuracy.Read(Path.Combine(Builds.Root, "docs", "accuracy.md"));
            accuracy.ReadFuzz(Path.Combine(Builds.Root, "docs", "accuracy-fuzz.md"));
            var modes = m.Modes.ToList();
            var md = new StringBuilder();
            md.AppendLine("# Performance: speed against error");
            md.AppendLine();
            md.AppendLine("Generated by `dotnet run --project tests/ProximityLib.Speed -c Release -- report` " +
                          $"({m.Elapsed.TotalMinutes:0} minutes); do not edit by hand. How it measures: [below](#how-this-is-measured).");
            md.AppendLine();
            md.AppendLine($"- Machine: {Environment.ProcessorCount} logical cores, {Cpu()}; {RuntimeInformation.OSDescription.Trim()}; " +
                          $"1-minute load average {loadBefore} before the run and {Measurement.Load()} after it (the machine is shared).");
            foreach (var mode in modes)
                md.AppendLine($"- {mode.Title}: {m.Runs[mode][0].Runtime}, {m.Runs[mode].Count} processes, clock: {m.Runs[mode][0].Clock}, " +
                              $"Vector<T> {m.Runs[mode][0].Vector}, " +
                              $"warm-up passes {string.Join("/", m.Runs[mode].Select(r => r.WarmUpPasses))}, " +
                              $"process slowdowns {string.Join("/", m.Slowdown(mode).Select(f => f.ToString("0.00", CultureInfo.InvariantCulture)))}.");
            md.AppendLine($"- {m.Options.Rounds} rounds per process, samples of about {m.Options.SampleMs} ms of CPU time, " +
                          $"{Inputs.Count} input pairs per query ({m.Options.Distribution}: half apart, half overlapping, shuffled).");
            if (reproduced != null)
            {
                md.AppendLine("- Reproducibility: every case's median against an earlier run of the same command on the same machine, relative " +
                              "difference per runtime:");
                foreach (var line in reproduced.Split('\n', StringSplitOptions.RemoveEmptyEntries))
                {
                    int colon = line.IndexOf(':');
                    md.AppendLine("  - " + Mode.Parse(line.Substring(0, colon)).Title + Targets.Label(line.Substring(colon)));
                }
            }
            md.AppendLine();
            md.AppendLine("## What holds where");
            md.AppendLine();
            foreach (var line in Summary(m)) md.AppendLine("- " + line);
            md.AppendLine();
            md.AppendLine("![speed against error](performance.png)");
            md.AppendLine();
            foreach (var line in RaycastSection(m, accuracy)) md.AppendLine(line);
            foreach (var mode in modes)
            {
                var rows = Targets.For(m, mode);
                md.AppendLine($"## Targets: {mode.Title}");
                md.AppendLine();
                md.AppendLine($"{rows.Count(r => r.Verdict == "met")} met, {rows.Count(r => r.Verdict == "within noise")} within noise, " +
                              $"{rows.Count(r => r.Verdict == "missed")} missed, {rows.Count(r => r.Verdict == "n/a")} not measurable. " +
                              "Ratios are the median over rounds of the two cases' times in the same round, then the median across processes " +
                              "(± the farthest process); \"within noise\" is a ratio above 1 by less than 10%, the size of the run-to-run differences " +
                              "on this machine (Reproducibility, above).");
                md.AppendLine();
                md.AppendLine("| target | limit | measured | |");
                md.AppendLine("| --- | --- | --- | --- |");
                foreach (var r in rows) md.AppendLine($"| {r.What} | {r.Target} | {r.Measured} | {r.Verdict} |");
                md.AppendLine();
            }

            md.AppendLine("## Every case");
            md.AppendLine();
            md.AppendLine("ns per query (± the farthest process from the median); × baseline: the ratio to the hand-written baseline of the same " +
                          "answer in the same group (Between to Between, Distance and batch to Distance, Overlaps to Overlaps). Max E: the largest " +
                          "error the accuracy run measured ([accuracy.md](accuracy.md)), in units of the method's own precision. B/query: the most " +
                          "any round allocated, in any runtime. Issue 12's pairs take max E from the fuzz against the exact reference " +
                          "([accuracy-fuzz.md](accuracy-fuzz.md)) when that page exists, ray casts the E of T from its ray-cast section; \"—\" where no error was measured.");
            md.AppendLine();
            md.AppendLine("| group | case | " + string.Join(" | ", modes.Select(x => $"{x.Title} ns | × baseline")) + " | B/query | max E |");
            md.AppendLine("| --- | --- | " + string.Join(" | ", modes.Select(_ => "--- | ---")) + " | --- | --- |");
            foreach (var key in AllKeys(m))
            {
                var (group, name) = Split(key);
                var cells = new List<string>();
                foreach (var mode in modes)
                {
                    var t = m.Time(mode, key);
                    cells.Add(t == null ? "—" : Text.Ns(t.Value));
                    string? baseline = Baseline(m, mode, group, name);
                    var r = baseline == null ? null : m.Ratio(mode, key, Measurement.Key(group, baseline));
                    cells.Add(r == null ? "" : $"{r.Value.Median:0.00}");
                }
                double bytes = modes.Max(x => m.Has(x, key) ? m.MaxBytesPerQuery(x, key) : 0);
                double? e = accuracy.MaxE(group, name);
                md.AppendLine($"| {group} | {name} | {string.Join(" | ", cells)} | {bytes:0.##} | {(e.HasValue ? Accuracy.Format(e.Value) : "—")} |");
            }
            md.AppendLine();
            md.AppendLine("## How this is measured");
            md.AppendLine();
            md.AppendLine("- Every case runs in one process per measurement, interleaved: each round times one short sample of every case, the groups " +
                          "in random order and a group's cases (library, baseline, batch) back to back in random order, so load changes fall on " +
                          "all of them alike. A case's time is the median over rounds, then the median across processes; the thread's CPU time is " +
                          "the clock, so time spent descheduled by other processes is not counted.");
            md.AppendLine("- Now and then a whole process runs about 1.4 times as long on this shared VM, every case alike, for its lifetime. " +
                          "Each process's slowdown (the median over cases of its time ÷ the case's median across processes, relative to the " +
                          "fastest process; listed above) is divided out of its times before the median across processes, so the times are " +
                          "the fastest process's speed. Ratios within a process (library ÷ baseline, batch ÷ scalar, now ÷ old) are not " +
                          "scaled; the no-PGO ÷ default ratio compares two modes' scaled times.");
            md.AppendLine("- Before timing, every case runs repeatedly with pauses until the runtime stops compiling (tiering, OSR and PGO's " +
                          "instrumented code otherwise leave loops in unoptimised code); Mono compiles once.");
            md.AppendLine("- The baselines (tests/ProximityLib.Speed.Cases/Baselines.cs) are the simplest correct C# for the same answer, written " +
                          "from the formula: System.Numerics in float, scalar arithmetic in double. On Mono the same baselines are compiled into " +
                          "the same program as the library (Roslyn from the .NET SDK against Mono's class libraries, run by `mono`).");
            md.AppendLine($"- Batch rows are per pair; their \"old batch\" twins are the same cases compiled against the library at {Program.BatchReference}, " +
                          "measured in the same processes.");
            md.AppendLine("- Reproduce a subset: `dotnet run --project tests/ProximityLib.Speed -c Release -- run --modes pgo,nopgo,mono --filter \"3D OBB–OBB\"`; " +
                          "an A/B against another commit: `-- ab --against <ref>` (.NET with and without PGO; `--modes mono`: both libraries compiled into one Mono program).");
            File.WriteAllText(Path.Combine(dir, "performance.md"), md.ToString().Replace("\r\n", "\n"));
            Plot(m, accuracy, Path.Combine(dir, "performance.png"));
        }

        /// <summary>
        /// Ray casts (issue 12): the library's Raycast against the textbook forms, per target and precision, in every
        /// runtime, and the batch casts per target against the scalar cast.
        /// </summary>
        private static IEnumerable<string> RaycastSection(Measurement m, Accuracy accuracy)
        {
            var groups = m.Modes.SelectMany(m.Keys).Select(k => Split(k).Group).Where(g => g.Contains(" ray cast–")).Distinct()
                .OrderBy(g => g.Substring(g.IndexOf(' ') + 1), StringComparer.Ordinal).ThenBy(g => g, StringComparer.Ordinal).ToList();
            if (groups.Count == 0) yield break;
            var modes = m.Modes.ToList();
            yield return "## Ray casts";
            yield return "";
            yield return "The library's `Raycast.Cast` (T and hit; it also fills the hit point and normal, left unused here) against the textbook " +
                         "forms a game engine would write (tests/ProximityLib.Speed.Cases/Raycasts.cs): ray–sphere by the quadratic with an early " +
                         "out (Ericson §5.3.2), ray–AABB by the branch-free slab test, ray–triangle by Möller–Trumbore, ray–half-space by the plane " +
                         "equation. The inputs are 40% hits, 40% misses and 20% near-grazing rays (0.1% off a tangent or an edge); the quick check " +
                         "requires every baseline to agree with the library on hit or miss and on T pair by pair. The float API computes in double " +
                         "and rounds. Cells: library ÷ baseline (time ÷ time, below 1 the library is faster), and the library's ns per cast; " +
                         "batch rows: one ray against all 1024 targets, per target, ÷ the scalar library cast.";
            yield return "";
            yield return "| ray cast | " + string.Join(" | ", modes.Select(x => $"{x.Title}: library ns | ÷ baseline")) + " | max E of T |";
            yield return "| --- | " + string.Join(" | ", modes.Select(_ => "--- | ---")) + " | --- |";
            foreach (var g in groups)
            {
                var cells = new List<string>();
                foreach (var mode in modes)
                {
                    var t = m.Time(mode, Measurement.Key(g, "library Cast"));
                    var r = m.Ratio(mode, Measurement.Key(g, "library Cast"), Measurement.Key(g, "baseline Cast"));
                    cells.Add(t == null ? "—" : Text.Ns(t.Value.Median));
                    cells.Add(r == null ? "" : Text.Ratio(r.Value));
                }
                double? e = accuracy.MaxE(g, "library Cast");
                yield return $"| {g} | {string.Join(" | ", cells)} | {(e.HasValue ? Accuracy.Format(e.Value) : "—")} |";
                string batch = Measurement.Key(g, "batch one-to-many Raycasts");
                if (modes.Any(x => m.Has(x, batch)))
                {
                    var b = new List<string>();
                    foreach (var mode in modes)
                    {
                        var t = m.Time(mode, batch);
                        var r = m.Ratio(mode, batch, Measurement.Key(g, "library Cast"));
                        b.Add(t == null ? "—" : Text.Ns(t.Value.Median));
                        b.Add(r == null ? "" : Text.Ratio(r.Value) + " of the scalar cast");
                    }
                    yield return $"| {g}: batch one-to-many | {string.Join(" | ", b)} | |";
                }
            }
            yield return "";
            foreach (var mode in modes)
            {
                var r = groups.Select(g => (Group: g, Ratio: m.Ratio(mode, Measurement.Key(g, "library Cast"), Measurement.Key(g, "baseline Cast"))))
                    .Where(x => x.Ratio != null).Select(x => (x.Group, Ratio: x.Ratio!.Value.Median)).ToList();
                if (r.Count == 0) continue;
                var faster = r.Where(x => x.Ratio < 1).Select(x => x.Group).ToList();
                yield return $"- {mode.Title}: the library's cast takes {Range(r.Select(x => x.Ratio))} of the textbook form's time on the {r.Count} " +
                             $"targets with one; {(faster.Count == 0 ? "it is faster on none" : "faster on " + string.Join(", ", faster))}.";
            }
            if (m.Runs.ContainsKey(Mode.Pgo) && m.Runs.ContainsKey(Mode.NoPgo))
            {
                var r = m.Keys(Mode.NoPgo).Where(k => k.Contains(" ray cast–") && k.EndsWith(" | library Cast", StringComparison.Ordinal) && m.Has(Mode.Pgo, k))
                    .Select(k => m.Time(Mode.NoPgo, k)!.Value.Median / m.Time(Mode.Pgo, k)!.Value.Median).ToList();
                if (r.Count > 0) yield return $"- Without PGO the library's casts take {Range(r)} of their default time.";
            }
            yield return "- Max E of T: the ray-cast fuzz against the exact first hit ([accuracy-fuzz.md](accuracy-fuzz.md#ray-casts)), " +
                         "E = |T − t*| / (u·S) over the well-conditioned hits it measured (a grazing hit's T is not well conditioned; there the " +
                         "fuzz checks the first-hit interval instead). The baselines agree with the library within 1e-3·(1 + T) in float and " +
                         "1e-9·(1 + T) in double on every input pair; their own error is not measured.";
            yield return "";
        }

        /// <summary>Plain sentences: which speed-ups hold on which runtime.</summary>
        private static IEnumerable<string> Summary(Measurement m)
        {
            foreach (var mode in m.Modes)
            {
                // Batch against the scalar API per pair (time ÷ time: below 1 is a speed-up).
                var batch = m.Keys(mode).Where(k => k.Contains(" | batch ")).OrderBy(k => k, StringComparer.Ordinal)
                    .Select(k => (Key: k, Scalar: Targets.Scalar(m, mode, k)))
                    .Select(x => (x.Key, x.Scalar, Ratio: m.Ratio(mode, x.Key, Measurement.Key(Split(x.Key).Group, x.Scalar))))
                    .Where(x => x.Ratio != null).Select(x => (x.Key, x.Scalar, Ratio: x.Ratio!.Value.Median)).ToList();
                if (batch.Count > 0)
                {
                    var slower = batch.Where(x => x.Ratio > 1).ToList();
                    var speedUps = batch.Select(x => 1 / x.Ratio).ToList();
                    yield return $"{mode.Title}, batch: per pair, the {batch.Count} batch queries run {speedUps.Min():0.0}–{speedUps.Max():0.0}× " +
                                 $"(median {Stats.Median(speedUps):0.0}×) as fast as the scalar API answering the same question " +
                                 "(`Distance`, or `Overlaps`) on the same pairs (one-to-many against the scalar API looped over its pairs); " +
                                 (slower.Count == 0 ? "the speed-up holds for every one."
                                  : $"the speed-up does not hold for {slower.Count}, which are slower than the scalar API here: " +
                                    string.Join(", ", slower.Select(x => $"{Targets.Label(x.Key)} ({x.Ratio:0.00}× its time)")) + ".");
                }
                foreach (var op in new[] { "Distance", "Between", "Overlaps" })
                {
                    var r = m.Keys(mode).Select(Split).Where(x => x.Name == "baseline " + op).Select(x => x.Group).Distinct()
                        .Select(g => m.Ratio(mode, Measurement.Key(g, "library " + op), Measurement.Key(g, "baseline " + op)))
                        .Where(x => x != null).Select(x => x!.Value.Median).ToList();
                    if (r.Count > 0)
                        yield return $"{mode.Title}, against the hand-written baselines: the library's `{op}` takes {Range(r)} of their time on the " +
                                     $"{r.Count} groups that have one.";
                }
            }
            if (m.Runs.ContainsKey(Mode.Pgo) && m.Runs.ContainsKey(Mode.Mono))
            {
                // The batch's speed-up on each runtime, per batch query (scalar time ÷ batch time).
                double SpeedUp(Mode mode, string key)
                {
                    var r = m.Ratio(mode, key, Measurement.Key(Split(key).Group, Targets.Scalar(m, mode, key)));
                    return r == null ? double.NaN : 1 / r.Value.Median;
                }
                var both = m.Keys(Mode.Mono).Where(k => k.Contains(" | batch ") && m.Has(Mode.Pgo, k))
                    .Select(k => (Net: SpeedUp(Mode.Pgo, k), Mono: SpeedUp(Mode.Mono, k))).Where(x => !double.IsNaN(x.Net) && !double.IsNaN(x.Mono)).ToList();
                if (both.Count > 0)
                    yield return $"The batch speed-ups of .NET 10 (Vector<T> {m.Runs[Mode.Pgo][0].Vector}) " +
                                 $"{(both.All(x => x.Mono >= x.Net * 0.9) ? "carry over" : "do not carry over")} to Mono (Vector<T> {m.Runs[Mode.Mono][0].Vector}): " +
                                 $"the median speed-up over the scalar API is {Stats.Median(both.Select(x => x.Net).ToList()):0.0}× on " +
                                 $".NET 10 and {Stats.Median(both.Select(x => x.Mono).ToList()):0.0}× on Mono, and it is smaller on Mono for " +
                                 $"{both.Count(x => x.Mono < x.Net)} of the {both.Count} batch queries.";
            }
            if (m.Runs.ContainsKey(Mode.Pgo) && m.Runs.ContainsKey(Mode.NoPgo))
            {
                var r = m.Keys(Mode.NoPgo).Where(k => k.Contains(" | library ") && m.Has(Mode.Pgo, k))
                    .Select(k => m.Time(Mode.NoPgo, k)!.Value.Median / m.Time(Mode.Pgo, k)!.Value.Median).ToList();
                if (r.Count > 0)
                    yield return $"Without PGO the scalar queries take {Range(r)} of their default time; {r.Count(x => x > 1.3)} of {r.Count} above 1.3×.";
            }
        }

        private static string Range(IEnumerable<double> ratios)
        {
            var list = ratios.ToList();
            return $"{list.Min():0.00}–{list.Max():0.00}× (median {Stats.Median(list):0.00}×)";
        }

        /// <summary>The baseline a case is compared with in the table, if its group has one.</summary>
        private static string? Baseline(Measurement m, Mode mode, string group, string name)
        {
            if (name.StartsWith("baseline", StringComparison.Ordinal) || name.StartsWith("old ", StringComparison.Ordinal)) return null;
            string? b = name.EndsWith("Between", StringComparison.Ordinal) ? "baseline Between"
                : name.EndsWith("Overlaps", StringComparison.Ordinal) ? "baseline Overlaps"
                : name.EndsWith("Distance", StringComparison.Ordinal) || name.EndsWith("Distances", StringComparison.Ordinal) ? "baseline Distance"
                : name.EndsWith("Cast", StringComparison.Ordinal) || name.EndsWith("Raycasts", StringComparison.Ordinal) ? "baseline Cast" : null;
            return b != null && m.Has(mode, Measurement.Key(group, b)) ? b : null;
        }

        private static IEnumerable<string> AllKeys(Measurement m) => m.Modes.SelectMany(m.Keys).Distinct()
            .OrderBy(k => Split(k).Group.Contains("scene") ? 1 : 0)
            .ThenBy(k => Split(k).Group.Substring(Split(k).Group.IndexOf(' ') + 1), StringComparer.Ordinal)
            .ThenBy(k => Split(k).Group, StringComparer.Ordinal)
            .ThenBy(k => Order(Split(k).Name)).ThenBy(k => k, StringComparer.Ordinal);

        private static int Order(string name) =>
            name.StartsWith("library", StringComparison.Ordinal) ? 0 : name.StartsWith("baseline", StringComparison.Ordinal) ? 1
            : name.StartsWith("batch", StringComparison.Ordinal) ? 2 : name.StartsWith("old", StringComparison.Ordinal) ? 3 : 4;

        public static (string Group, string Name) Split(string key)
        {
            int cut = key.IndexOf(" | ", StringComparison.Ordinal);
            return (key.Substring(0, cut), key.Substring(cut + 3));
        }

        private static string Cpu()
        {
            try
            {
                var line = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name", StringComparison.Ordinal));
                return line?.Split(':', 2)[1].Trim() ?? RuntimeInformation.ProcessArchitecture.ToString();
            }
            catch (IOException) { return RuntimeInformation.ProcessArchitecture.ToString(); }
        }

        /// <summary>
        /// Time against error on log axes, .NET 10 default: the library's distance queries (Distance) in float and double,
        /// the paired batch queries and the paper's formulas, each at its max E from the accuracy run times its unit roundoff.
        /// </summary>
        private static void Plot(Measurement m, Accuracy accuracy, string file)
        {
            const string Paper = "paper formulas (double; largest finite E, ∞ at the range limits)";
            var mode = m.Runs.ContainsKey(Mode.Pgo) ? Mode.Pgo : m.Modes.First();
            var series = new Dictionary<string, List<(double X, double Y)>>
            {
                ["library, float API"] = new List<(double, double)>(), ["library, double API"] = new List<(double, double)>(),
                ["library, SIMD batch (float)"] = new List<(double, double)>(), [Paper] = new List<(double, double)>(),
            };
            foreach (var key in m.Keys(mode))
            {
                var (group, name) = Split(key);
                if (!group.EndsWith(" distance", StringComparison.Ordinal)) continue;
                // The distance-only entry point where the library has it (the same number as Between's, without the witnesses).
                string distance = m.Has(mode, Measurement.Key(group, "library Distance")) ? "library Distance" : "library Between";
                string? s = name == distance ? (group.StartsWith("float", StringComparison.Ordinal) ? "library, float API" : "library, double API")
                    : name == "batch paired Distances" ? "library, SIMD batch (float)" : name == "paper formula Distance" ? Paper : null;
                double? e = accuracy.MaxE(group, name, finite: true);
                if (s == null || e == null) continue;
                double u = group.StartsWith("float", StringComparison.Ordinal) ? Math.Pow(2, -24) : Math.Pow(2, -53);
                series[s].Add((Math.Log10(Math.Max(e.Value, 0.01) * u), Math.Log10(m.Time(mode, key)!.Value.Median)));
            }
            var plt = new ScottPlot.Plot();
            foreach (var (label, points) in series.Where(x => x.Value.Count > 0))
            {
                var sc = plt.Add.ScatterPoints(points.Select(p => p.X).ToArray(), points.Select(p => p.Y).ToArray());
                sc.LegendText = label;
                sc.MarkerSize = 8;
            }
            // Log axes drawn as linear axes of log10 values, so the ticks are set by hand: every decade of error, and
            // 1-2-5 steps of time.
            var all = series.Values.SelectMany(v => v).ToList();
            if (all.Count > 0)
            {
                var xs = Enumerable.Range((int)Math.Floor(all.Min(p => p.X)), (int)Math.Ceiling(all.Max(p => p.X)) - (int)Math.Floor(all.Min(p => p.X)) + 1)
                    .Select(d => (double)d).ToArray();
                plt.Axes.Bottom.SetTicks(xs, xs.Select(d => $"1e{d:0}").ToArray());
                var ys = Enumerable.Range(-2, 8).SelectMany(d => new[] { 1.0, 2, 5 }.Select(k => k * Math.Pow(10, d)))
                    .Where(t => Math.Log10(t) >= all.Min(p => p.Y) - 0.2 && Math.Log10(t) <= all.Max(p => p.Y) + 0.2).ToArray();
                plt.Axes.Left.SetTicks(ys.Select(Math.Log10).ToArray(), ys.Select(t => $"{t:0.##} ns").ToArray());
            }
            plt.XLabel("max relative error E·u (log; accuracy.md)");
            plt.YLabel($"time per distance query, {mode.Title} (log)");
            plt.Title("ProximityLib: speed against error, one point per method per query");
            // Beside the axes: inside them, the legend hid points.
            plt.ShowLegend(ScottPlot.Edge.Right);
            plt.SavePng(file, 1200, 600);
        }
    }

    /// <summary>The largest errors docs/accuracy.md reports: per query and precision, for the batch, and for the paper's formulas.</summary>
    public sealed class Accuracy
    {
        private readonly Dictionary<string, double> _max = new Dictionary<string, double>(StringComparer.Ordinal);
        private readonly Dictionary<string, double> _maxFinite = new Dictionary<string, double>(StringComparer.Ordinal);

        public static Accuracy Read(string path)
        {
            var a = new Accuracy();
            if (!File.Exists(path)) return a;
            string section = "";
            foreach (var line in File.ReadLines(path))
            {
                if (line.StartsWith("## ", StringComparison.Ordinal)) section = line;
                if (!line.StartsWith("| ", StringComparison.Ordinal) || line.StartsWith("| ---", StringComparison.Ordinal)
                    || line.StartsWith("| query", StringComparison.Ordinal) || line.StartsWith("| family", StringComparison.Ordinal)) continue;
                var c = line.Split('|').Select(x => x.Trim()).ToArray();
                if (section.StartsWith("## Per query", StringComparison.Ordinal))
                {
                    a.Set($"double {c[1]}", Parse(c[3]));
                    a.Set($"float {c[1]}", Parse(c[5]));
                    a.Set($"batch {c[1]}", Parse(c[7]));
                }
                else if (section.StartsWith("## What the robust", StringComparison.Ordinal))
                    a.Set($"paper {c[2]}", Parse(c[4]));
            }
            return a;
        }

        /// <summary>
        /// The fuzz's measured errors (docs/accuracy-fuzz.md: "| pair | precision | cases … | max E | bound | worst case |"), for the
        /// pairs accuracy.md does not cover; absent file: nothing.
        /// </summary>
        public void ReadFuzz(string path)
        {
            if (!File.Exists(path)) return;
            foreach (var line in File.ReadLines(path))
            {
                if (!line.StartsWith("| ", StringComparison.Ordinal) || line.StartsWith("| ---", StringComparison.Ordinal) || line.StartsWith("| pair", StringComparison.Ordinal)) continue;
                var c = line.Split('|').Select(x => x.Trim()).ToArray();
                if (c.Length < 6 || (c[2] != "double" && c[2] != "float")) continue;
                string key = $"{c[2]} {c[1]}";
                if (!_max.ContainsKey(key)) Set(key, Parse(c[4]));
            }
        }

        private void Set(string key, double value)
        {
            if (double.IsNaN(value)) return;
            _max[key] = _max.TryGetValue(key, out var v) ? Math.Max(v, value) : value;
            if (!double.IsInfinity(value)) _maxFinite[key] = _maxFinite.TryGetValue(key, out var f) ? Math.Max(f, value) : value;
        }

        private static double Parse(string s) =>
            s == "Infinity" ? double.PositiveInfinity : double.TryParse(s, NumberStyles.Float, CultureInfo.InvariantCulture, out var v) ? v : double.NaN;

        public static string Format(double e) => double.IsInfinity(e) ? "∞" : e >= 1000 ? e.ToString("0.0e0", CultureInfo.InvariantCulture) : e.ToString("0.00", CultureInfo.InvariantCulture);

        /// <summary>
        /// Max E of a distance case ("float 3D sphere–sphere distance", "library Between"); null for overlaps and baselines.
        /// <paramref name="finite"/>: the largest finite one (the paper's formulas overflow to ∞ at the range limits).
        /// </summary>
        public double? MaxE(string group, string name, bool finite = false)
        {
            int cast = group.IndexOf(" ray cast–", StringComparison.Ordinal);
            if (cast > 0)
            {
                // "double 3D ray cast–sphere", library Cast → the fuzz's "double 3D sphere" (E of T); casts stay out of the plot.
                if (finite || !name.StartsWith("library", StringComparison.Ordinal)) return null;
                string target = group.Substring(0, cast) + " " + group.Substring(cast + " ray cast–".Length);
                return _max.TryGetValue(target, out var ce) ? ce : null;
            }
            if (!group.EndsWith(" distance", StringComparison.Ordinal)) return null;
            string query = group.Substring(group.IndexOf(' ') + 1, group.Length - group.IndexOf(' ') - 1 - " distance".Length);
            string? key = name.StartsWith("library", StringComparison.Ordinal) ? group.Substring(0, group.IndexOf(' ')) + " " + query
                : name.StartsWith("batch", StringComparison.Ordinal) ? "batch " + query
                : name.StartsWith("paper", StringComparison.Ordinal) ? "paper " + query : null;
            return key != null && (finite ? _maxFinite : _max).TryGetValue(key, out var e) ? e : null;
        }
    }
}
