using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using ProximityReference;
using ProximityReference.Fuzz;

// Usage: dotnet run --project tests/ProximityLib.Accuracy -c Release -- [--cases N] [--seed S] [--family NAME] [--out FILE]
//        ... -- --fuzz N [--fuzz-new M] [--fuzz-gaps G] [--fuzz-near H] [--fuzz-shallow X] [--seed S] [--start I] [--start-new J] [--start-gaps K] [--start-near L] [--start-shallow Y] [--threads T] [--repros R] [--out FILE] [--errors FILE]
//        ... -- --fuzz-replay SEED:INDEX
//        ... -- --fuzz-casts N [--casts-start I] [--seed S] [--threads T] [--repros R] [--out FILE] [--errors FILE]
//        ... -- --fuzz-casts-replay SEED:INDEX
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
int cases = 20, seed = 2026;
long fuzz = 0, start = 0, fuzzNew = -1, startNew = 0, fuzzGaps = -1, startGaps = 0, fuzzNear = -1, startNear = 0, fuzzShallow = -1, startShallow = 0, casts = 0, castsStart = 0;
int threads = Environment.ProcessorCount, repros = 20;
string? output = null, replay = null, only = null, errors = null, castReplay = null;
try
{
    for (int i = 0; i < args.Length; i++)
    {
        switch (args[i])
        {
            case "--cases": cases = int.Parse(args[++i]); break;
            case "--seed": seed = int.Parse(args[++i]); break;
            case "--out": output = args[++i]; break;
            case "--family": only = args[++i]; break;
            case "--fuzz": fuzz = long.Parse(args[++i]); break;
            case "--start": start = long.Parse(args[++i]); break;
            case "--fuzz-new": fuzzNew = long.Parse(args[++i]); break;
            case "--start-new": startNew = long.Parse(args[++i]); break;
            case "--fuzz-gaps": fuzzGaps = long.Parse(args[++i]); break;
            case "--start-gaps": startGaps = long.Parse(args[++i]); break;
            case "--fuzz-near": fuzzNear = long.Parse(args[++i]); break;
            case "--start-near": startNear = long.Parse(args[++i]); break;
            case "--fuzz-shallow": fuzzShallow = long.Parse(args[++i]); break;
            case "--start-shallow": startShallow = long.Parse(args[++i]); break;
            case "--threads": threads = int.Parse(args[++i]); break;
            case "--repros": repros = int.Parse(args[++i]); break;
            case "--fuzz-replay": replay = args[++i]; break;
            case "--errors": errors = args[++i]; break;
            case "--fuzz-casts": casts = long.Parse(args[++i]); break;
            case "--casts-start": castsStart = long.Parse(args[++i]); break;
            case "--fuzz-casts-replay": castReplay = args[++i]; break;
            case "--help":
                Console.WriteLine("accuracy [--cases N (per family parameter, default 20)] [--seed S] [--family NAME (one family only)] [--out docs/accuracy.md]");
                Console.WriteLine("accuracy --fuzz N [--seed S] [--start I] [--threads T] [--repros R] [--out FILE]   differential fuzz of N cases");
                Console.WriteLine("         [--fuzz-new M] [--start-new J]   and M cases (default N) of issue 12's pairs, indices 1000000000000 + J …");
                Console.WriteLine("         [--fuzz-gaps G] [--start-gaps K]   and G cases (default N/4) of exact tiny gaps, every pair in double, indices 2000000000000 + K …");
                Console.WriteLine("         [--fuzz-near H] [--start-near L]   and H cases (default N/4) of nearly touching cores, every pair in both precisions, indices 3000000000000 + L …");
                Console.WriteLine("         [--fuzz-shallow X] [--start-shallow Y]   and X cases (default N/4) of edges crossing at shallow angles, both precisions, indices 4000000000000 + Y …");
                Console.WriteLine("         [--errors FILE]   also write the measured E per pair (against the exact reference) as a Markdown page");
                Console.WriteLine("accuracy --fuzz-replay SEED:INDEX                                                 one fuzz case, every check, repros");
                Console.WriteLine("accuracy --fuzz-casts N [--casts-start I] [--seed S] [--threads T] [--repros R] [--out FILE] [--errors FILE]");
                Console.WriteLine("         the ray-cast fuzz: N casts (own index space) against the exact first hit; with --fuzz/--fuzz-new too, both run");
                Console.WriteLine("         and --errors writes both sections");
                Console.WriteLine("accuracy --fuzz-casts-replay SEED:INDEX                                           one ray-cast case, every check, repros");
                return 0;
            default:
                Console.Error.WriteLine($"unknown option '{args[i]}' (try --help)");
                return 2;
        }
    }
}
catch (Exception e) when (e is FormatException || e is OverflowException || e is IndexOutOfRangeException)
{
    Console.Error.WriteLine($"bad option value: {e.Message} (try --help)");
    return 2;
}
if (fuzzNew < 0) fuzzNew = fuzz;
if (fuzzGaps < 0) fuzzGaps = fuzz / 4;
if (fuzzNear < 0) fuzzNear = fuzz / 4;
if (fuzzShallow < 0) fuzzShallow = fuzz / 4;
if (fuzz < 0 || start < 0 || startNew < 0 || startGaps < 0 || startNear < 0 || fuzzShallow < 0 || startShallow < 0 || casts < 0 || castsStart < 0 || threads < 1 || repros < 0)
{
    Console.Error.WriteLine("--fuzz, --fuzz-new, --fuzz-gaps, --fuzz-near, --fuzz-shallow, --fuzz-casts, --start, --start-new, --start-gaps, --start-near, --start-shallow, --casts-start and --repros must not be negative and --threads must be at least 1 (try --help)");
    return 2;
}

if (castReplay != null)
{
    var parts = castReplay.Split(':');
    if (parts.Length != 2 || !long.TryParse(parts[0], out long rs) || !long.TryParse(parts[1], out long ri) || ri < 0)
    {
        Console.Error.WriteLine($"--fuzz-casts-replay needs SEED:INDEX (got '{castReplay}')");
        return 2;
    }
    try { Console.Write(CastEngine.Replay(rs, ri)); }
    catch (Exception e) { Console.Error.WriteLine($"error: ray-cast case {rs}:{ri} could not be checked: {e.Message}"); return 2; }
    return 0;
}

if (replay != null)
{
    var parts = replay.Split(':');
    if (parts.Length != 2 || !long.TryParse(parts[0], out long rs) || !long.TryParse(parts[1], out long ri) || ri < 0)
    {
        Console.Error.WriteLine($"--fuzz-replay needs SEED:INDEX (got '{replay}')");
        return 2;
    }
    try { Console.Write(Engine.Replay(rs, ri)); }
    catch (Exception e) { Console.Error.WriteLine($"error: case {rs}:{ri} could not be checked: {e.Message}"); return 2; }
    return 0;
}

if (fuzz > 0 || fuzzNew > 0 || fuzzGaps > 0 || fuzzNear > 0 || fuzzShallow > 0 || casts > 0)
{
    FuzzReport? report = null;
    CastReport? castReport = null;
    try
    {
        if (fuzz > 0 || fuzzNew > 0 || fuzzGaps > 0 || fuzzNear > 0 || fuzzShallow > 0)
        {
            Console.Error.WriteLine($"fuzz: {fuzz} cases from {start}, {fuzzNew} of issue 12's pairs from {FuzzCase.NewBase + startNew} {fuzzGaps} tiny gaps from {FuzzCase.GapBase + startGaps} {fuzzNear} near cores from {FuzzCase.NearBase + startNear} and {fuzzShallow} shallow crossings from {FuzzCase.ShallowBase + startShallow}, seed {seed}, {threads} threads");
            report = Engine.Run(new FuzzOptions
            {
                Seed = seed, Start = start, Count = fuzz, NewStart = startNew, NewCount = fuzzNew, GapStart = startGaps, GapCount = fuzzGaps, NearStart = startNear, NearCount = fuzzNear, ShallowStart = startShallow, ShallowCount = fuzzShallow, Threads = threads,
                Progress = line => Console.Error.WriteLine("  " + line),
            });
        }
        if (casts > 0)
        {
            Console.Error.WriteLine($"ray-cast fuzz: {casts} casts from {castsStart}, seed {seed}, {threads} threads");
            castReport = CastEngine.Run(new CastFuzzOptions
            {
                Seed = seed, Start = castsStart, Count = casts, Threads = threads,
                Progress = line => Console.Error.WriteLine("  " + line),
            });
        }
    }
    catch (AggregateException e)
    {
        Console.Error.WriteLine($"error: the fuzz engine failed: {e.InnerException?.Message ?? e.Message}");
        return 2;
    }
    string text = (report?.Format(repros) ?? "") + (report != null && castReport != null ? Environment.NewLine : "") + (castReport?.Format(repros) ?? "");
    if (output != null) File.WriteAllText(output, text);
    if (errors != null)
    {
        var command = new StringBuilder("dotnet run --project tests/ProximityLib.Accuracy -c Release --");
        if (report != null) command.Append($" --fuzz {fuzz} --fuzz-new {fuzzNew} --fuzz-gaps {fuzzGaps} --fuzz-near {fuzzNear} --fuzz-shallow {fuzzShallow}");
        if (castReport != null) command.Append($" --fuzz-casts {casts}{(castsStart > 0 ? $" --casts-start {castsStart}" : "")}");
        command.Append($" --seed {seed} --errors {errors}");
        var page = new StringBuilder();
        page.AppendLine("# Measured error of every pair in the fuzz");
        page.AppendLine();
        page.AppendLine($"Generated by `{command}`; do not edit by hand.");
        page.AppendLine();
        if (report != null)
        {
            page.AppendLine("The differential fuzz (tests/ProximityLib.Reference/Fuzz: seeded generators aimed at degeneracies, every public");
            page.AppendLine("overload in both argument orders) checks a sample of its cases against the exact rational reference. E is the");
            page.AppendLine("error of Distance in units of U = u·S + η (docs/accuracy.md; S the configuration's local scale), the largest over");
            page.AppendLine("both argument orders; the bound is the promise the fuzz enforces (32 for issue 12's pairs in double unless stated");
            page.AppendLine("less, 2 for the float API). Replay a worst case with `--fuzz-replay SEED:INDEX`.");
            page.AppendLine();
            page.AppendLine($"{report.ExactCases} of {report.Cases} cases against the exact reference; {report.FailureCount} invariant violations.");
            page.AppendLine();
            page.Append(report.FormatErrors());
        }
        if (castReport != null)
        {
            if (report != null) page.AppendLine();
            page.AppendLine("## Ray casts");
            page.AppendLine();
            page.AppendLine("The ray-cast fuzz (tests/ProximityLib.Reference/Fuzz/Raycast*.cs: every public `Raycast.Cast` overload, 2D and 3D,");
            page.AppendLine("double and float, with and without maxDistance, and the batch `BatchQuery.Raycasts`) checks every cast against the");
            page.AppendLine("exact first hit (dyadic arithmetic; a ball's or capsule's root compared on squares). The first-hit check is");
            page.AppendLine("backward-stable: T must be the exact first hit of the target grown or shrunk by at most B·U, with U = u·S + η");
            page.AppendLine("(S: the largest coordinate difference between the ray's origin and the target's defining points, its radius, or");
            page.AppendLine("the exact hit's distance when larger), plus T's own rounding 2u·T; at a graze that is one-sided. E = |T − t\\*|/U is");
            page.AppendLine("measured on well-conditioned hits only (the grown and shrunk targets' first hits within 4·B·U, i.e. an incidence");
            page.AppendLine("cosine ≥ 1/2), where the check implies E ≤ 2·B + 4. The batch row casts with the direction rounded to float, as");
            page.AppendLine("the batch does. Zero-thickness 3D targets are hit within `PassThroughTolerance` (2^−40 of the local scale) of the");
            page.AppendLine("documented candidates; their E is measured against the first such candidate. Replay a case with");
            page.AppendLine("`--fuzz-casts-replay SEED:INDEX`.");
            page.AppendLine();
            page.AppendLine($"{castReport.Cases} casts; {castReport.WorstE.Values.Sum(v => v.Count)} well-conditioned hits measured; {castReport.FailureCount} invariant violations.");
            page.AppendLine();
            page.Append(castReport.FormatErrors());
        }
        File.WriteAllText(errors, page.ToString());
    }
    Console.Write(text);
    return (report?.Failures.Count ?? 0) + (castReport?.Failures.Count ?? 0) == 0 ? 0 : 1;
}

var all = new List<Measurement>();
foreach (var family in Families.Names.Where(f => only == null || f == only))
{
    var started = DateTime.UtcNow;
    var ms = Families.Get(family, cases, seed).Select(Measure.Run).ToList();
    all.AddRange(ms);
    Console.Error.WriteLine($"{family}: {ms.Count} cases in {(DateTime.UtcNow - started).TotalSeconds:F1} s");
}

static double P99(IEnumerable<double> xs)
{
    var sorted = xs.OrderBy(x => x).ToArray();
    return sorted.Length == 0 ? 0 : sorted[Math.Min(sorted.Length - 1, (int)Math.Ceiling(0.99 * sorted.Length) - 1)];
}

static double Ed(Measurement m) => Math.Max(m.ErrorDouble, m.ErrorDoubleSwapped);
string F(double x) => x < 100 ? x.ToString("0.00") : x.ToString("0.0e0");

var md = new StringBuilder();
md.AppendLine("# Accuracy");
md.AppendLine();
md.AppendLine("Generated by `dotnet run --project tests/ProximityLib.Accuracy -c Release -- " +
              $"--cases {cases} --seed {seed} --out docs/accuracy.md` ({all.Count} configurations); do not edit by hand.");
md.AppendLine();
md.AppendLine("Every result is compared with the exact answer from `tests/ProximityLib.Reference` (rational arithmetic over");
md.AppendLine("`BigInteger`: exact squared distances, an exact separating-axis verdict, square roots to ~2⁻¹⁶⁰). The error is");
md.AppendLine("**E = |d − d\\*| / (u·S)** with u = 2⁻⁵³ for the double API and 2⁻²⁴ for the float API, and S the configuration's");
md.AppendLine("local scale (largest coordinate difference between its defining points, or radius; a common translation is not");
md.AppendLine("part of S). Float results are measured on the inputs rounded to float, against the exact answer for those inputs.");
md.AppendLine("Double E covers both argument orders. Booleans must match the exact verdict whenever |d\\*| > 32·u·S.");
md.AppendLine("The SIMD batch queries (`ProximityLib.Batch`, float lanes) are measured on the same float inputs; they promise E ≤ 8.");
md.AppendLine("The pairs with lines, rays, capsules, triangles and half-spaces (issue 12) are measured by the differential fuzz against");
md.AppendLine("the same exact reference: [accuracy-fuzz.md](accuracy-fuzz.md), every pair's max E against its bound.");
md.AppendLine();
md.AppendLine("## Per query: promised bound and measured error (all families)");
md.AppendLine();
md.AppendLine("| query | bound (double) | max E double | p99 E double | max E float | p99 E float | max E batch (float) | wrong overlap verdicts (double / float) | cases |");
md.AppendLine("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
foreach (var g in all.GroupBy(m => m.Pair).OrderBy(g => g.Key[0]).ThenBy(g => g.Key))
{
    var floats = g.Where(m => m.FloatMeasured).Select(m => m.ErrorFloat).ToList();
    var batch = g.Select(m => m.ErrorBatch).Where(e => !double.IsNaN(e)).ToList();
    md.AppendLine($"| {g.Key} | {Measure.Bound(g.Key)} | {F(g.Max(Ed))} | {F(P99(g.Select(Ed)))} | {F(floats.DefaultIfEmpty().Max())} | {F(P99(floats))} | " +
                  $"{(batch.Count > 0 ? F(batch.Max()) : "–")} | " +
                  $"{g.Count(m => m.WrongOverlapDouble)} / {g.Count(m => m.WrongOverlapFloat)} | {g.Count()} |");
}
md.AppendLine();
md.AppendLine("## Per family");
md.AppendLine();
md.AppendLine("| family | query | cases | max E double | p99 E double | max E float | p99 E float | max E batch (float) |");
md.AppendLine("| --- | --- | --- | --- | --- | --- | --- | --- |");
foreach (var fam in all.GroupBy(m => m.Family))
    foreach (var g in fam.GroupBy(m => m.Pair).OrderBy(g => g.Key))
    {
        var floats = g.Where(m => m.FloatMeasured).Select(m => m.ErrorFloat).ToList();
        var batch = g.Select(m => m.ErrorBatch).Where(e => !double.IsNaN(e)).ToList();
        md.AppendLine($"| {fam.Key} | {g.Key} | {g.Count()} | {F(g.Max(Ed))} | {F(P99(g.Select(Ed)))} | {F(floats.DefaultIfEmpty().Max())} | {F(P99(floats))} | " +
                      $"{(batch.Count > 0 ? F(batch.Max()) : "–")} |");
    }
md.AppendLine();
md.AppendLine("## What the robust forms buy: the paper's formulas on the same cases (double)");
md.AppendLine();
md.AppendLine("| family | query | paper formula | paper max E | paper p99 E | ours max E | ours p99 E | paper wrong verdicts | ours wrong verdicts |");
md.AppendLine("| --- | --- | --- | --- | --- | --- | --- | --- | --- |");
foreach (var g in all.Where(m => m.Baseline != null).GroupBy(m => (m.Family, m.Pair, m.Baseline)).OrderBy(g => g.Key.Pair).ThenBy(g => g.Key.Family))
{
    bool boolean = g.Key.Baseline!.StartsWith("SAT");
    md.AppendLine($"| {g.Key.Family} | {g.Key.Pair} | {g.Key.Baseline} | " +
                  (boolean ? "– | – | " : $"{F(g.Max(m => m.BaselineError))} | {F(P99(g.Select(m => m.BaselineError)))} | ") +
                  $"{F(g.Max(m => m.ErrorDouble))} | {F(P99(g.Select(m => m.ErrorDouble)))} | " +
                  (boolean ? $"{g.Count(m => m.BaselineWrong)} of {g.Count()}" : "–") + " | " +
                  (boolean ? $"{g.Count(m => m.WrongOverlapDouble)} of {g.Count()}" : "–") + " |");
}
md.AppendLine();
md.AppendLine("## Range");
md.AppendLine();
md.AppendLine("- Float API: every finite float input (the double internals square at most ~10⁷⁷).");
md.AppendLine("- Double API: the bounds above hold for configuration scales S from 2⁻¹⁰⁰⁰ to 2¹⁰⁰⁰ at any position (the");
md.AppendLine("  `range-limits` family measures 2^±240 … 2^±1000, `mixed-scales` shapes 2⁴ … 2¹²⁰ apart in size). Each query checks, on");
md.AppendLine("  quantities it forms anyway, that its squares stay within 2^±960 (box queries: relative magnitudes within 2^±450); a");
md.AppendLine("  configuration that fails is rescaled by an exact power of two, so scaling a configuration by 2^k scales every result");
md.AppendLine("  exactly on either path (tested in `WideTests`, `PairMatrixTests`, `FamilyTests` and the fuzz). Beyond 2^±1000 answers");
md.AppendLine("  stay finite where the true answer is representable (the fuzz checks every finite input).");
md.AppendLine("- The SIMD batch queries (float lanes): configuration scales within 2^±28.");

var worst = all.GroupBy(m => m.Pair).Select(g => g.OrderByDescending(Ed).First()).OrderByDescending(Ed);
Console.Error.WriteLine("worst double case per query:");
foreach (var m in worst) Console.Error.WriteLine($"  {m.Pair}: E={Ed(m):0.00} — {m.Case}");
Console.Error.WriteLine("worst batch case per query:");
foreach (var m in all.Where(m => !double.IsNaN(m.ErrorBatch)).GroupBy(m => m.Pair).Select(g => g.OrderByDescending(m => m.ErrorBatch).First()))
    Console.Error.WriteLine($"  {m.Pair}: E={m.ErrorBatch:0.00} — {m.Case}");

if (output != null) File.WriteAllText(output, md.ToString());
else Console.Write(md.ToString());
bool missed = all.Any(m => Ed(m) > Measure.Bound(m.Pair) || m.WrongOverlapDouble || m.WrongOverlapFloat || m.ErrorBatch > 8);
Console.Error.WriteLine(missed ? "SOME BOUND MISSED" : "every query within its bound");
return missed ? 1 : 0;
