using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;

namespace ProximitySpeed
{
    /// <summary>What the run and ab commands print.</summary>
    public static class Text
    {
        public static string Ns(double ns) => ns >= 100 ? ns.ToString("0") : ns >= 10 ? ns.ToString("0.0") : ns.ToString("0.00");

        /// <summary>"6.50 ±3%": the median across processes and the farthest process from it.</summary>
        public static string Ns(Spread s) => $"{Ns(s.Median)} ±{s.Relative * 100:0}%";

        public static string Ratio(Spread s) => $"{s.Median:0.00} ±{s.Relative * 100:0}%";

        /// <summary>Every case, ns per query in each mode.</summary>
        public static string Times(Measurement m)
        {
            var modes = m.Modes.ToList();
            var text = new StringBuilder();
            text.AppendLine($"ns per query, median over {m.Options.Rounds} rounds, then across {m.Options.Processes} processes (±: farthest process); {m.Options.Distribution} inputs; {m.Elapsed.TotalSeconds:0} s");
            text.AppendLine($"{"case",-78}" + string.Concat(modes.Select(x => $"{x.Name,16}")));
            foreach (var key in modes.SelectMany(m.Keys).Distinct().OrderBy(k => k, StringComparer.Ordinal))
                text.AppendLine($"{key,-78}" + string.Concat(modes.Select(x => $"{(m.Time(x, key) is Spread s ? Ns(s) : "—"),16}")));
            return text.ToString();
        }

        /// <summary>
        /// Every case that has an "old" twin (the same case compiled against the library at the ref): new ns, old ns and
        /// new ÷ old per mode, flagged when the median ratio is above 1.05. The baselines are the same code in both
        /// builds: their ratios show the noise floor.
        /// </summary>
        public static string Ab(Measurement m, string against)
        {
            var modes = m.Modes.ToList();
            var text = new StringBuilder();
            text.AppendLine($"A/B: working tree (new) against {against} (old), one process per measurement, {m.Options.Processes} processes per mode, " +
                            $"{m.Options.Rounds} rounds, {m.Options.Distribution} inputs; {m.Elapsed.TotalSeconds:0} s");
            text.AppendLine("ratio = median over rounds of new ÷ old (run back to back), median across processes [min–max]; * = median above 1.05");
            var keys = m.Keys(modes[0]).Where(k => k.Contains(" | old ")).Select(k => k.Replace(" | old ", " | ")).Where(k => m.Has(modes[0], k))
                .OrderBy(k => k.Contains("baseline") ? 2 : k.Contains("batch") ? 1 : 0).ThenBy(k => k, StringComparer.Ordinal).ToList();
            text.AppendLine($"{"query",-72}" + string.Concat(modes.Select(x => $" | {x.Name + " new",9} {"old",8} {"new ÷ old",-22}")));
            foreach (var key in keys)
            {
                string old = key.Replace(" | ", " | old ");
                text.Append($"{key,-72}");
                foreach (var mode in modes)
                {
                    var r = m.Ratio(mode, key, old)!.Value;
                    text.Append($" | {Ns(m.Time(mode, key)!.Value.Median),9} {Ns(m.Time(mode, old)!.Value.Median),8} {$"{r.Median:0.000} [{r.Min:0.000}–{r.Max:0.000}]{(r.Median > 1.05 ? " *" : "")}",-22}");
                }
                text.AppendLine();
            }
            foreach (var mode in modes)
            {
                var library = keys.Where(k => !k.Contains("baseline")).Select(k => m.Ratio(mode, k, k.Replace(" | ", " | old "))!.Value.Median).ToList();
                var control = keys.Where(k => k.Contains("baseline")).Select(k => m.Ratio(mode, k, k.Replace(" | ", " | old "))!.Value.Median).ToList();
                text.AppendLine($"{mode.Title}: {library.Count} library and batch queries, median new ÷ old {Stats.Median(library):0.000}, " +
                                $"{library.Count(r => r > 1.05)} above 1.05 (worst {library.Max():0.000}); identical baseline code in both builds: " +
                                (control.Count > 0 ? $"{control.Min():0.000}–{control.Max():0.000}" : "none"));
            }
            return text.ToString();
        }
    }

    /// <summary>
    /// Every case's median per mode, written by --save (mode, case, median across processes with each process's
    /// slowdown divided out, each process's own median over rounds; tab-separated), and the comparison of two such
    /// files (compare).
    /// </summary>
    public static class Saved
    {
        public static void Write(Measurement m, string path)
        {
            var text = new StringBuilder();
            foreach (var mode in m.Modes)
                foreach (var key in m.Keys(mode).OrderBy(k => k, StringComparer.Ordinal))
                    if (m.Time(mode, key) is Spread s)
                        text.Append(mode.Name).Append('\t').Append(key).Append('\t').Append(s.Median.ToString("R", CultureInfo.InvariantCulture)).Append('\t')
                            .Append(string.Join(" ", m.Runs[mode].Select(r => r.Cases[key].Median.ToString("R", CultureInfo.InvariantCulture)))).Append('\n');
            File.WriteAllText(path, text.ToString());
        }

        private static Dictionary<(string Mode, string Key), double> Read(string path) =>
            File.ReadAllLines(path).Where(l => l.Length > 0).Select(l => l.Split('\t'))
                .ToDictionary(f => (f[0], f[1]), f => double.Parse(f[2], CultureInfo.InvariantCulture));

        /// <summary>
        /// Per mode: how many cases both files have, the largest, 90th-percentile and median relative difference |b − a| / a
        /// of their medians, how many differ by more than 10%, and the ten that differ most.
        /// </summary>
        public static string Compare(string a, string b) => Format(Differences(Read(a), Read(b)), 10);

        /// <summary>The same comparison between a saved file and a measurement (report --previous); one line per mode.</summary>
        public static string Compare(string previous, Measurement m)
        {
            var now = new Dictionary<(string Mode, string Key), double>();
            foreach (var mode in m.Modes)
                foreach (var key in m.Keys(mode))
                    if (m.Time(mode, key) is Spread s) now[(mode.Name, key)] = s.Median;
            return Format(Differences(Read(previous), now), 1);
        }

        private static List<(string Mode, List<(string Key, double Diff)> Diffs)> Differences(
            Dictionary<(string Mode, string Key), double> x, Dictionary<(string Mode, string Key), double> y) =>
            x.Keys.Select(k => k.Mode).Distinct()
                .Select(mode => (mode, x.Where(kv => kv.Key.Mode == mode && y.ContainsKey(kv.Key))
                    .Select(kv => (kv.Key.Key, Diff: (y[kv.Key] - kv.Value) / kv.Value)).OrderByDescending(t => Math.Abs(t.Diff)).ToList()))
                .Where(t => t.Item2.Count > 0).ToList();

        private static string Format(List<(string Mode, List<(string Key, double Diff)> Diffs)> all, int worst)
        {
            var text = new StringBuilder();
            foreach (var (mode, d) in all)
            {
                var abs = d.Select(t => Math.Abs(t.Diff)).OrderBy(v => v).ToList();
                text.AppendLine($"{mode}: {d.Count} cases, max |difference| {abs[^1] * 100:0.0}%, 90th percentile {abs[(int)(0.9 * (abs.Count - 1))] * 100:0.0}%, " +
                                $"median {Stats.Median(abs) * 100:0.0}%, {abs.Count(v => v > 0.10)} above 10%; largest: " +
                                string.Join(", ", d.Take(worst).Select(t => $"{t.Diff * 100:+0.0;-0.0}% {t.Key}")));
            }
            return text.ToString();
        }
    }
}
