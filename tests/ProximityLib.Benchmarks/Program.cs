using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using BenchmarkDotNet.Configs;
using BenchmarkDotNet.Jobs;
using BenchmarkDotNet.Reports;
using BenchmarkDotNet.Running;
using BenchmarkDotNet.Toolchains.InProcess.NoEmit;
using ProximityBenchmarks;

// dotnet run --project tests/ProximityLib.Benchmarks -c Release -- [--quick] [--report docs] [BenchmarkDotNet args, e.g. --filter '*Sphere*']
//   --quick   every benchmark once, in process (CI: proves they all run; measures nothing)
//   --report  after a full run, write docs/performance.md and docs/performance.png from its results
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
bool quick = args.Contains("--quick");
int reportAt = Array.IndexOf(args, "--report");
string? reportDir = reportAt >= 0 && reportAt + 1 < args.Length ? args[reportAt + 1] : null;
var rest = args.Where((a, i) => a != "--quick" && (reportAt < 0 || (i != reportAt && i != reportAt + 1))).ToArray();

// In process with no overhead stage: each invocation is already 1024 queries, so the loop overhead is a small, shared
// constant, and the ratios between methods in one run are what the report is about. 15 iterations of 100 ms keep the
// full suite (~400 benchmarks) to ~25 minutes on a 2-core machine; with 5 × 50 ms, medians moved by up to ±40% between
// runs on this shared VM.
var job = quick
    ? Job.Dry.WithToolchain(InProcessNoEmitToolchain.Instance)
    : Job.Default.WithEvaluateOverhead(false).WithIterationTime(Perfolizer.Horology.TimeInterval.FromMilliseconds(100))
        .WithWarmupCount(5).WithIterationCount(15).WithToolchain(InProcessNoEmitToolchain.Instance).WithId("InProcess-tiered-15x100ms");
var config = ManualConfig.Create(DefaultConfig.Instance).AddJob(job).WithOptions(ConfigOptions.DisableLogFile);

var pairTypes = typeof(PairBenchmarks<,,>).GetCustomAttributes(typeof(BenchmarkDotNet.Attributes.GenericTypeArgumentsAttribute), false)
    .Cast<BenchmarkDotNet.Attributes.GenericTypeArgumentsAttribute>()
    .Select(a => typeof(PairBenchmarks<,,>).MakeGenericType(a.GenericTypeArguments)).ToList();
var all = pairTypes.Append(typeof(Baselines)).Append(typeof(BatchBenchmarks)).Append(typeof(GaitFrameBenchmark)).ToArray();

var summaries = rest.Length > 0
    ? BenchmarkSwitcher.FromTypes(new[] { typeof(PairBenchmarks<,,>), typeof(Baselines), typeof(BatchBenchmarks), typeof(GaitFrameBenchmark) }).Run(rest, config).ToArray()
    : all.Select(t => BenchmarkRunner.Run(t, config)).ToArray();

int ran = summaries.Sum(s => s.Reports.Count(r => r.Success));
// Non-critical validation messages (e.g. "assembly located in temp" for a clone under /tmp) do not stop a run.
int failed = summaries.Sum(s => s.Reports.Count(r => !r.Success)) + summaries.Sum(s => s.ValidationErrors.Count(v => v.IsCritical));
foreach (var s in summaries)
{
    foreach (var r in s.Reports.Where(r => !r.Success)) Console.WriteLine($"failed: {r.BenchmarkCase.DisplayInfo}");
    foreach (var v in s.ValidationErrors.Where(v => v.IsCritical)) Console.WriteLine($"invalid: {v.Message}");
}
Console.WriteLine($"{ran} passed, {failed} failed (benchmarks executed)");
if (reportDir != null && !quick) Report.Write(summaries, reportDir, job.DisplayInfo);
return failed == 0 && ran > 0 ? 0 : 1;
