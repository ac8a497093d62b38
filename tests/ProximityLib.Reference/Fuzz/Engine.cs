using System;
using System.Collections.Generic;
using System.Diagnostics;
using System.Linq;
using System.Text;
using System.Threading;
using System.Threading.Tasks;

namespace ProximityReference.Fuzz
{
    public sealed class FuzzOptions
    {
        public long Seed { get; set; } = 1;
        public long Start { get; set; }
        public long Count { get; set; } = 6000;
        /// <summary>Cases of the second index space (issue 12's pairs): FuzzCase.NewBase + NewStart, … (0: none).</summary>
        public long NewStart { get; set; }
        public long NewCount { get; set; }
        /// <summary>Cases of the third index space (exact tiny gaps, every pair in double): FuzzCase.GapBase + GapStart, … (0: none).</summary>
        public long GapStart { get; set; }
        public long GapCount { get; set; }
        /// <summary>Cases of the fourth index space (nearly touching cores, every pair in both precisions): FuzzCase.NearBase + NearStart, … (0: none).</summary>
        public long NearStart { get; set; }
        public long NearCount { get; set; }
        /// <summary>Cases of the fifth index space (edges crossing at shallow angles, both precisions): FuzzCase.ShallowBase + ShallowStart, … (0: none).</summary>
        public long ShallowStart { get; set; }
        public long ShallowCount { get; set; }
        public int Threads { get; set; } = Environment.ProcessorCount;
        /// <summary>Called every few seconds with a progress line.</summary>
        public Action<string>? Progress { get; set; }
        public TimeSpan ProgressEvery { get; set; } = TimeSpan.FromSeconds(10);
    }

    /// <summary>Failure counts per (pair, precision, invariant, generator), the first failure of each, and case counts.</summary>
    public sealed class FuzzReport
    {
        public long Seed { get; init; }
        public long Start { get; init; }
        /// <summary>The index ranges run, as text (set by <see cref="Engine.Run"/>).</summary>
        public string Ranges { get; set; } = "";
        public long Cases { get; set; }
        /// <summary>Cases of pairs the library has no public overloads for yet (not generated, not checked).</summary>
        public long Skipped { get; set; }
        public SortedSet<string> SkippedPairs { get; } = new SortedSet<string>(StringComparer.Ordinal);
        public long ExactCases { get; set; }
        public long FailedCases { get; set; }
        public TimeSpan Elapsed { get; set; }
        public Dictionary<(string Pair, string Precision), long> CasesPerPair { get; } = new Dictionary<(string, string), long>();
        /// <summary>How many cases ran each optional check (translation and scaling need an exact transform, the batch a float 3D pair in its range).</summary>
        public Dictionary<string, long> Ran { get; } = new Dictionary<string, long>();
        public Dictionary<(string Pair, string Precision, string Invariant, string Generator), (long Count, Failure First)> Failures { get; } =
            new Dictionary<(string, string, string, string), (long, Failure)>();

        /// <summary>Per pair and precision: the largest E against the exact reference, the cases it was measured on and the first case reaching it.</summary>
        public Dictionary<(string Pair, string Precision), (double E, long Count, long Index, double Bound)> WorstE { get; } =
            new Dictionary<(string, string), (double, long, long, double)>();

        public void Add(FuzzCase c, List<Failure> fails, bool exact, IEnumerable<string> ran, double worstE = -1)
        {
            if (worstE >= 0)
            {
                var p = (c.Pair, c.PrecisionName);
                WorstE[p] = WorstE.TryGetValue(p, out var w)
                    ? (worstE > w.E ? worstE : w.E, w.Count + 1, worstE > w.E || (worstE == w.E && c.Index < w.Index) ? c.Index : w.Index, w.Bound)
                    : (worstE, 1, c.Index, c.Float ? 2 : Checker.Bound(c.A.Kind, c.B.Kind));
            }
            foreach (var r in ran) Ran[r] = Ran.GetValueOrDefault(r) + 1;
            Cases++;
            if (exact) ExactCases++;
            var key = (c.Pair, c.PrecisionName);
            CasesPerPair[key] = CasesPerPair.GetValueOrDefault(key) + 1;
            if (fails.Count > 0) FailedCases++;
            foreach (var f in fails)
            {
                var k = (c.Pair, c.PrecisionName, f.Invariant, c.Generator);
                if (Failures.TryGetValue(k, out var e))
                    Failures[k] = (e.Count + 1, f.Case.Index < e.First.Case.Index ? f : e.First);
                else
                    Failures[k] = (1, f);
            }
        }

        public void Merge(FuzzReport o)
        {
            Cases += o.Cases;
            Skipped += o.Skipped;
            SkippedPairs.UnionWith(o.SkippedPairs);
            ExactCases += o.ExactCases;
            FailedCases += o.FailedCases;
            foreach (var kv in o.Ran) Ran[kv.Key] = Ran.GetValueOrDefault(kv.Key) + kv.Value;
            foreach (var kv in o.CasesPerPair) CasesPerPair[kv.Key] = CasesPerPair.GetValueOrDefault(kv.Key) + kv.Value;
            foreach (var kv in o.WorstE)
                WorstE[kv.Key] = WorstE.TryGetValue(kv.Key, out var w)
                    ? (Math.Max(w.E, kv.Value.E), w.Count + kv.Value.Count,
                       kv.Value.E > w.E || (kv.Value.E == w.E && kv.Value.Index < w.Index) ? kv.Value.Index : w.Index, w.Bound)
                    : kv.Value;
            foreach (var kv in o.Failures)
            {
                if (Failures.TryGetValue(kv.Key, out var e))
                    Failures[kv.Key] = (e.Count + kv.Value.Count, kv.Value.First.Case.Index < e.First.Case.Index ? kv.Value.First : e.First);
                else
                    Failures[kv.Key] = kv.Value;
            }
        }

        public long FailureCount => Failures.Values.Sum(v => v.Count);

        /// <summary>
        /// The measured error table: per pair and precision, the cases checked against the exact reference, the largest E
        /// over both argument orders, the promised bound and the case that reached it (replayable).
        /// </summary>
        public string FormatErrors()
        {
            var sb = new StringBuilder();
            sb.AppendLine("| pair | precision | cases against the exact reference | max E | bound | worst case |");
            sb.AppendLine("| --- | --- | --- | --- | --- | --- |");
            foreach (var kv in WorstE.OrderBy(kv => kv.Key.Pair, StringComparer.Ordinal).ThenBy(kv => kv.Key.Precision, StringComparer.Ordinal))
                sb.AppendLine($"| {kv.Key.Pair} | {kv.Key.Precision} | {kv.Value.Count} | {kv.Value.E.ToString("0.00", System.Globalization.CultureInfo.InvariantCulture)} | " +
                              $"{kv.Value.Bound} | {Seed}:{kv.Value.Index} |");
            return sb.ToString();
        }

        /// <summary>The summary table (at most <paramref name="rows"/> rows, most frequent first) and the first <paramref name="repros"/> repros (one per row).</summary>
        public string Format(int repros, int rows = int.MaxValue)
        {
            var sb = new StringBuilder();
            string ranges = Ranges.Length > 0 ? Ranges : $"{Start}..{Start + Cases - 1}";
            sb.AppendLine($"Fuzz: seed {Seed}, cases {ranges} ({Cases} cases, {ExactCases} against the exact reference) " +
                          $"in {Elapsed.TotalSeconds:F1} s; {CasesPerPair.Values.DefaultIfEmpty().Min()}–{CasesPerPair.Values.DefaultIfEmpty().Max()} cases per pair and precision " +
                          $"({CasesPerPair.Count} pairs and precisions).");
            if (Skipped > 0)
                sb.AppendLine($"Skipped {Skipped} cases of {SkippedPairs.Count} pairs and precisions the library has no overloads for yet: {string.Join(", ", SkippedPairs)}.");
            sb.AppendLine("Cases per optional check: " + string.Join(", ", Ran.OrderBy(kv => kv.Key).Select(kv => $"{kv.Key} {kv.Value}")) + ".");
            if (Failures.Count == 0)
            {
                sb.AppendLine("No invariant violated.");
                return sb.ToString();
            }
            sb.AppendLine($"{FailureCount} violations in {FailedCases} cases.");
            sb.AppendLine();
            var all = Failures.OrderByDescending(kv => kv.Value.Count).ThenBy(kv => kv.Key.Pair, StringComparer.Ordinal)
                .ThenBy(kv => kv.Key.Precision, StringComparer.Ordinal).ThenBy(kv => kv.Key.Invariant, StringComparer.Ordinal)
                .ThenBy(kv => kv.Key.Generator, StringComparer.Ordinal).ToList();
            sb.AppendLine("| pair | precision | invariant | generator | failures | of cases | first case |");
            sb.AppendLine("| --- | --- | --- | --- | --- | --- | --- |");
            foreach (var kv in all.Take(rows))
                sb.AppendLine($"| {kv.Key.Pair} | {kv.Key.Precision} | {kv.Key.Invariant} | {kv.Key.Generator} | {kv.Value.Count} | " +
                              $"{CasesPerPair.GetValueOrDefault((kv.Key.Pair, kv.Key.Precision))} | {kv.Value.First.Case.Seed}:{kv.Value.First.Case.Index} |");
            if (all.Count > rows) sb.AppendLine($"| … {all.Count - rows} more rows | | | | {all.Skip(rows).Sum(kv => kv.Value.Count)} | | |");
            sb.AppendLine();
            sb.AppendLine("Per invariant: " + string.Join(", ", all.GroupBy(r => r.Key.Invariant).OrderBy(g => g.Key)
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
    /// The differential fuzz: case i of seed s is drawn by <see cref="FuzzCase.Create"/> and checked by
    /// <see cref="Checker.Run"/>; cases run in parallel chunks and the report does not depend on the thread count.
    /// </summary>
    public static class Engine
    {
        /// <summary>
        /// The exact reference runs on one case in ExactEvery (it is rational arithmetic over BigInteger, and box pairs
        /// enumerate hundreds of feature pairs): every case without a box, one in 8 with one box, one in 40 with two.
        /// </summary>
        public static int ExactEvery(FuzzCase c)
        {
            static bool Polytope(Kind k) => k == Kind.Aabb || k == Kind.Obb || k == Kind.Triangle;
            int boxes = (Polytope(c.A.Kind) ? 1 : 0) + (Polytope(c.B.Kind) ? 1 : 0);
            return boxes == 0 ? 1 : boxes == 1 ? 8 : 40;
        }

        public static bool IsExact(FuzzCase c) => Rng.Mix((ulong)c.Seed * 31 + (ulong)c.Index) % (ulong)ExactEvery(c) == 0;

        public static FuzzReport Run(FuzzOptions o)
        {
            var total = new FuzzReport { Seed = o.Seed, Start = o.Start };
            // The index spaces run, each as (first index, count): the original, the new pairs', the tiny gaps', the near cores',
            // the shallow crossings'.
            var spaces = new[] { (o.Start, o.Count), (FuzzCase.NewBase + o.NewStart, o.NewCount), (FuzzCase.GapBase + o.GapStart, o.GapCount), (FuzzCase.NearBase + o.NearStart, o.NearCount), (FuzzCase.ShallowBase + o.ShallowStart, o.ShallowCount) };
            total.Ranges = string.Join(" and ", spaces.Where(x => x.Item2 > 0).Select(x => $"{x.Item1}..{x.Item1 + x.Item2 - 1}"));
            var clock = Stopwatch.StartNew();
            const int chunk = 60;
            // Chunks of each space in turn: chunk k belongs to the first space whose cumulative chunk count exceeds k.
            var ends = new long[spaces.Length];
            long chunks = 0, next = -1, done = 0, all = 0;
            for (int j = 0; j < spaces.Length; j++) { chunks += (spaces[j].Item2 + chunk - 1) / chunk; ends[j] = chunks; all += spaces[j].Item2; }
            var gate = new object();
            var lastProgress = clock.Elapsed;
            var workers = Enumerable.Range(0, Math.Max(1, o.Threads)).Select(_ => Task.Factory.StartNew(() =>
            {
                var local = new FuzzReport { Seed = o.Seed, Start = o.Start };
                while (true)
                {
                    long k = Interlocked.Increment(ref next);
                    if (k >= chunks) break;
                    int space = 0;
                    while (k >= ends[space]) space++;
                    var (first, count) = spaces[space];
                    long from = first + (k - (space == 0 ? 0 : ends[space - 1])) * chunk;
                    long to = Math.Min(first + count, from + chunk);
                    for (long i = from; i < to; i++)
                    {
                        if (!FuzzCase.Available(i))
                        {
                            var (dim, ka, kb, isFloat, _) = FuzzCase.Slot(i);
                            local.Skipped++;
                            local.SkippedPairs.Add($"{dim}D {ka}–{kb} {(isFloat ? "float" : "double")}");
                            continue;
                        }
                        var c = FuzzCase.Create(o.Seed, i);
                        bool exact = IsExact(c);
                        List<Failure> fails;
                        var ran = new HashSet<string>();
                        double worstE;
                        try { fails = Checker.Run(c, exact, ran, out worstE); }
                        catch (Exception e) { throw new InvalidOperationException($"case {o.Seed}:{i} ({c.Pair} {c.PrecisionName}, {c.Generator}): {e.Message}", e); }
                        local.Add(c, fails, exact, ran, worstE);
                    }
                    long d = Interlocked.Add(ref done, to - from);
                    if (o.Progress != null && clock.Elapsed - lastProgress > o.ProgressEvery)
                        lock (gate)
                        {
                            if (clock.Elapsed - lastProgress > o.ProgressEvery)
                            {
                                lastProgress = clock.Elapsed;
                                double rate = d / clock.Elapsed.TotalSeconds;
                                lock (total) o.Progress($"{d}/{all} cases ({100.0 * d / all:F1}%), {rate:F0} cases/s, " +
                                    $"about {(all - d) / Math.Max(rate, 1e-9):F0} s left; {total.FailedCases + local.FailedCases}+ failing cases so far");
                            }
                        }
                }
                lock (total) total.Merge(local);
            }, TaskCreationOptions.LongRunning)).ToArray();
            Task.WaitAll(workers);
            total.Elapsed = clock.Elapsed;
            return total;
        }

        /// <summary>Everything about one case: the shapes as C#, both results, and every failure with its repro.</summary>
        public static string Replay(long seed, long index)
        {
            var c = FuzzCase.Create(seed, index);
            var fails = Checker.Run(c, exact: true);
            var sb = new StringBuilder();
            sb.AppendLine($"case {seed}:{index}: {c.Pair} ({c.PrecisionName}), generator \"{c.Generator}\"");
            sb.AppendLine($"var a = {c.A.ToCSharp()};");
            sb.AppendLine($"var b = {c.B.ToCSharp()};");
            sb.AppendLine(fails.Count == 0 ? "every invariant holds (exact reference included)" : $"{fails.Count} violations:");
            foreach (var f in fails)
            {
                sb.AppendLine();
                sb.Append(f.Repro());
            }
            return sb.ToString();
        }
    }
}
