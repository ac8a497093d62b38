using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Globalization;
using System.Linq;
using System.Text;
using System.Threading;
using System.Threading.Tasks;

namespace ProximityReference.Fuzz
{
    public sealed class CastFuzzOptions
    {
        public long Seed { get; set; } = 1;
        public long Start { get; set; }
        public long Count { get; set; } = 40_000;
        public int Threads { get; set; } = Environment.ProcessorCount;
        /// <summary>Called every few seconds with a progress line.</summary>
        public Action<string>? Progress { get; set; }
        public TimeSpan ProgressEvery { get; set; } = TimeSpan.FromSeconds(10);
    }

    /// <summary>Failure counts per (target, precision, invariant, generator), the first failure of each, case counts and the worst E per target and precision.</summary>
    public sealed class CastReport
    {
        public long Seed { get; init; }
        public long Start { get; init; }
        public long Cases { get; set; }
        public long FailedCases { get; set; }
        public TimeSpan Elapsed { get; set; }
        public Dictionary<(string Target, string Precision), long> CasesPer { get; } = new Dictionary<(string, string), long>();
        /// <summary>How many cases ran each optional check (maxDistance, scaling, translation, batch).</summary>
        public Dictionary<string, long> Ran { get; } = new Dictionary<string, long>();
        public Dictionary<(string Target, string Precision, string Invariant, string Generator), (long Count, CastFailure First)> Failures { get; } =
            new Dictionary<(string, string, string, string), (long, CastFailure)>();
        /// <summary>Per target and precision ("double", "float", "batch"): the largest E on well-conditioned hits, how many were measured, the first case reaching it.</summary>
        public Dictionary<(string Target, string Precision), (double E, long Count, long Index)> WorstE { get; } =
            new Dictionary<(string, string), (double, long, long)>();

        public void Add(CastCase c, List<CastFailure> fails, IEnumerable<string> ran, IEnumerable<(string Precision, double E)> errors)
        {
            Cases++;
            var key = (c.TargetName, c.PrecisionName);
            CasesPer[key] = CasesPer.GetValueOrDefault(key) + 1;
            foreach (var r in ran) Ran[r] = Ran.GetValueOrDefault(r) + 1;
            foreach (var (precision, e) in errors) AddE((c.TargetName, precision), (e, 1, c.Index));
            if (fails.Count > 0) FailedCases++;
            foreach (var f in fails)
            {
                var k = (c.TargetName, c.PrecisionName, f.Invariant, c.Generator);
                Failures[k] = Failures.TryGetValue(k, out var e) ? (e.Count + 1, f.Case.Index < e.First.Case.Index ? f : e.First) : (1, f);
            }
        }

        private void AddE((string, string) key, (double E, long Count, long Index) v)
        {
            if (!WorstE.TryGetValue(key, out var w)) { WorstE[key] = v; return; }
            bool worse = v.E > w.E || (v.E == w.E && v.Index < w.Index);
            WorstE[key] = (worse ? v.E : w.E, w.Count + v.Count, worse ? v.Index : w.Index);
        }

        public void Merge(CastReport o)
        {
            Cases += o.Cases;
            FailedCases += o.FailedCases;
            foreach (var kv in o.CasesPer) CasesPer[kv.Key] = CasesPer.GetValueOrDefault(kv.Key) + kv.Value;
            foreach (var kv in o.Ran) Ran[kv.Key] = Ran.GetValueOrDefault(kv.Key) + kv.Value;
            foreach (var kv in o.WorstE) AddE(kv.Key, kv.Value);
            foreach (var kv in o.Failures)
                Failures[kv.Key] = Failures.TryGetValue(kv.Key, out var e)
                    ? (e.Count + kv.Value.Count, kv.Value.First.Case.Index < e.First.Case.Index ? kv.Value.First : e.First)
                    : kv.Value;
        }

        public long FailureCount => Failures.Values.Sum(v => v.Count);

        /// <summary>The bound of a precision's first-hit check (the interval's B).</summary>
        public static double Bound(string precision) =>
            precision == "double" ? CastChecker.DoubleBound : precision == "float" ? CastChecker.FloatBound : CastChecker.BatchBound;

        /// <summary>The worst E per target and precision as a Markdown table (replayable worst cases).</summary>
        public string FormatErrors()
        {
            var sb = new StringBuilder();
            sb.AppendLine("| target | precision | well-conditioned hits measured | max E | B (first-hit check) | E implied by it | worst case |");
            sb.AppendLine("| --- | --- | --- | --- | --- | --- | --- |");
            foreach (var kv in WorstE.OrderBy(kv => kv.Key.Target[0]).ThenBy(kv => kv.Key.Target, StringComparer.Ordinal)
                         .ThenBy(kv => kv.Key.Precision == "double" ? 0 : kv.Key.Precision == "float" ? 1 : 2))
            {
                double b = Bound(kv.Key.Precision);
                sb.AppendLine($"| {kv.Key.Target} | {kv.Key.Precision} | {kv.Value.Count} | {kv.Value.E.ToString("0.00", CultureInfo.InvariantCulture)} | {b} | " +
                              $"{2 * b + 4} | {Seed}:{kv.Value.Index} |");
            }
            return sb.ToString();
        }

        /// <summary>The summary (at most <paramref name="rows"/> failure rows, most frequent first) and the first <paramref name="repros"/> repros.</summary>
        public string Format(int repros, int rows = int.MaxValue)
        {
            var sb = new StringBuilder();
            sb.AppendLine($"Ray-cast fuzz: seed {Seed}, cases {Start}..{Start + Cases - 1} ({Cases} cases) in {Elapsed.TotalSeconds:F1} s; " +
                          $"{CasesPer.Values.DefaultIfEmpty().Min()}–{CasesPer.Values.DefaultIfEmpty().Max()} cases per target and precision ({CasesPer.Count} of them); " +
                          $"{WorstE.Values.Sum(v => v.Count)} well-conditioned hits measured against the exact first hit.");
            sb.AppendLine("Cases per optional check: " + string.Join(", ", Ran.Where(kv => !kv.Key.StartsWith("note: ")).OrderBy(kv => kv.Key, StringComparer.Ordinal).Select(kv => $"{kv.Key} {kv.Value}")) + ".");
            foreach (var kv in Ran.Where(kv => kv.Key.StartsWith("note: ")).OrderBy(kv => kv.Key, StringComparer.Ordinal))
                sb.AppendLine($"Note ({kv.Value} cases): {kv.Key.Substring(6)}.");
            if (Failures.Count == 0)
            {
                sb.AppendLine("No invariant violated.");
                return sb.ToString();
            }
            sb.AppendLine($"{FailureCount} violations in {FailedCases} cases.");
            sb.AppendLine();
            var all = Failures.OrderByDescending(kv => kv.Value.Count).ThenBy(kv => kv.Key.Target, StringComparer.Ordinal)
                .ThenBy(kv => kv.Key.Precision, StringComparer.Ordinal).ThenBy(kv => kv.Key.Invariant, StringComparer.Ordinal)
                .ThenBy(kv => kv.Key.Generator, StringComparer.Ordinal).ToList();
            sb.AppendLine("| target | precision | invariant | generator | failures | of cases | first case |");
            sb.AppendLine("| --- | --- | --- | --- | --- | --- | --- |");
            foreach (var kv in all.Take(rows))
                sb.AppendLine($"| {kv.Key.Target} | {kv.Key.Precision} | {kv.Key.Invariant} | {kv.Key.Generator} | {kv.Value.Count} | " +
                              $"{CasesPer.GetValueOrDefault((kv.Key.Target, kv.Key.Precision))} | {kv.Value.First.Case.Seed}:{kv.Value.First.Case.Index} |");
            if (all.Count > rows) sb.AppendLine($"| … {all.Count - rows} more rows | | | | {all.Skip(rows).Sum(kv => kv.Value.Count)} | | |");
            sb.AppendLine();
            sb.AppendLine("Per invariant: " + string.Join(", ", all.GroupBy(r => r.Key.Invariant).OrderBy(g => g.Key, StringComparer.Ordinal)
                .Select(g => $"{g.Key} {g.Sum(r => r.Value.Count)}")));
            int shown = 0;
            foreach (var kv in all)
            {
                if (shown++ >= repros) break;
                sb.AppendLine();
                sb.AppendLine($"---- repro {shown} ----");
                sb.Append(kv.Value.First.Repro());
            }
            return sb.ToString();
        }
    }

    /// <summary>
    /// The ray-cast differential fuzz: case i of seed s is drawn by <see cref="CastCase.Create"/> and checked by
    /// <see cref="CastChecker"/>; cases run in parallel chunks and the report does not depend on the thread count.
    /// </summary>
    public static class CastEngine
    {
        public static CastReport Run(CastFuzzOptions o)
        {
            var total = new CastReport { Seed = o.Seed, Start = o.Start };
            var clock = Stopwatch.StartNew();
            const int chunk = 40;
            long chunks = (o.Count + chunk - 1) / chunk, next = -1, done = 0;
            var gate = new object();
            var lastProgress = clock.Elapsed;
            var workers = Enumerable.Range(0, Math.Max(1, o.Threads)).Select(_ => Task.Factory.StartNew(() =>
            {
                var local = new CastReport { Seed = o.Seed, Start = o.Start };
                while (true)
                {
                    long k = Interlocked.Increment(ref next);
                    if (k >= chunks) break;
                    long from = o.Start + k * chunk, to = Math.Min(o.Start + o.Count, from + chunk);
                    for (long i = from; i < to; i++)
                    {
                        var c = CastCase.Create(o.Seed, i);
                        var ran = new HashSet<string>();
                        var errors = new List<(string, double)>();
                        List<CastFailure> fails;
                        try { fails = CastChecker.Run(c, ran, errors); }
                        catch (Exception e) { throw new InvalidOperationException($"case {o.Seed}:{i} ({c.TargetName} {c.PrecisionName}, {c.Generator}): {e.Message}", e); }
                        local.Add(c, fails, ran, errors);
                    }
                    long d = Interlocked.Add(ref done, to - from);
                    if (o.Progress != null && clock.Elapsed - lastProgress > o.ProgressEvery)
                        lock (gate)
                        {
                            if (clock.Elapsed - lastProgress > o.ProgressEvery)
                            {
                                lastProgress = clock.Elapsed;
                                double rate = d / clock.Elapsed.TotalSeconds;
                                lock (total) o.Progress($"{d}/{o.Count} casts ({100.0 * d / Math.Max(1, o.Count):F1}%), {rate:F0} cases/s, " +
                                    $"about {(o.Count - d) / Math.Max(rate, 1e-9):F0} s left; {total.FailedCases + local.FailedCases}+ failing cases so far");
                            }
                        }
                }
                lock (total) total.Merge(local);
            }, TaskCreationOptions.LongRunning)).ToArray();
            Task.WaitAll(workers);
            total.Elapsed = clock.Elapsed;
            return total;
        }

        /// <summary>Everything about one case: the ray and target as C#, the answer, the exact reference, every failure with its repro.</summary>
        public static string Replay(long seed, long index)
        {
            var c = CastCase.Create(seed, index);
            var errors = new List<(string, double)>();
            var fails = CastChecker.Run(c, new HashSet<string>(), errors);
            var sb = new StringBuilder();
            sb.AppendLine($"ray-cast case {seed}:{index}: a {c.TargetName} ({c.PrecisionName}), generator \"{c.Generator}\"");
            sb.AppendLine(Spec.Usings(c.Float));
            sb.AppendLine($"var ray = {c.Ray.ToCSharp()};");
            sb.AppendLine($"var target = {c.Target.ToCSharp()};");
            sb.AppendLine("var h = Raycast.Cast(ray, target);");
            try
            {
                var h = HitRes.From(c.Float
                    ? (object)ProximityLib.Raycast.Cast((dynamic)c.Ray.Build(), (dynamic)c.Target.Build())
                    : (object)ProximityLib.Double.Raycast.Cast((dynamic)c.Ray.Build(), (dynamic)c.Target.Build()));
                sb.AppendLine($"// got {h.Show(c.Float, c.Dim)}");
            }
            catch (Exception e) when (!(e is Microsoft.CSharp.RuntimeBinder.RuntimeBinderException)) { sb.AppendLine($"// threw {e.GetType().Name}: {e.Message}"); }
            foreach (var (p, e) in errors) sb.AppendLine($"// E ({p}) = {e.ToString("0.000", CultureInfo.InvariantCulture)} (a well-conditioned hit)");
            sb.AppendLine(fails.Count == 0 ? "every invariant holds" : $"{fails.Count} violations:");
            foreach (var f in fails)
            {
                sb.AppendLine();
                sb.Append(f.Repro());
            }
            return sb.ToString();
        }
    }
}
