using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Reflection;
using System.Text;
using System.Threading;

namespace ProximitySpeed
{
    /// <summary>
    /// One measuring process (the driver starts several per mode; on Mono this is the program's entry point). It warms
    /// every case up until the runtime stops compiling, sizes each case's sample to about --sample-ms of CPU time, then
    /// runs rounds: in each round every case takes one sample, groups in random order and a group's cases back to back
    /// in random order. It prints, per case, the time per query of every round and the most it allocated per query.
    /// Keeps to C# 9 and Mono 6.8's class libraries: it is compiled against them for the Mono mode.
    /// </summary>
    public static class ProbeProgram
    {
        private sealed class Case
        {
            public Case(string group, string name, int count, Func<int, double> run) { Group = group; Name = name; Count = count; Run = run; }
            public readonly string Group, Name;
            public readonly int Count;
            public readonly Func<int, double> Run;
            public int Reps = 1;
            public double[] Times = new double[0];
            public double MaxBytesPerQuery;
        }

        private static double _sink;

        public static int Main(string[] args)
        {
            try { return Run(args); }
            catch (Exception e)
            {
                // One line, no stack trace: a case that throws while timing is named by its exception (quick names the case).
                var inner = e is TargetInvocationException t && t.InnerException != null ? t.InnerException : e;
                Console.Error.WriteLine("error: " + (inner is ArgumentException || inner is System.IO.IOException ? "" : inner.GetType().Name + ": ") + inner.Message);
                return 2;
            }
        }

        /// <summary>
        /// Options: --inputs FILE (required), --rounds N, --sample-ms X, --seed N, --filter TEXT (cases whose group or name
        /// contains it), --old ASSEMBLY (the cases compiled against another library version, named "old …"),
        /// --old-filter TEXT (only those old cases whose name contains it), --once (each case twice, no timing).
        /// </summary>
        public static int Run(string[] args)
        {
            CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
            string? inputs = null, old = null, filter = null, oldFilter = null;
            int rounds = 41, seed = 1;
            double sampleMs = 1;
            bool once = false;
            for (int i = 0; i < args.Length; i++)
            {
                string Value() => i + 1 < args.Length ? args[++i] : throw new ArgumentException(args[i] + " needs a value");
                switch (args[i])
                {
                    case "--inputs": inputs = Value(); break;
                    case "--rounds": rounds = int.Parse(Value(), CultureInfo.InvariantCulture); break;
                    case "--sample-ms": sampleMs = double.Parse(Value(), CultureInfo.InvariantCulture); break;
                    case "--seed": seed = int.Parse(Value(), CultureInfo.InvariantCulture); break;
                    case "--filter": filter = Value(); break;
                    case "--old": old = Value(); break;
                    case "--old-filter": oldFilter = Value(); break;
                    case "--once": once = true; break;
                    default: throw new ArgumentException("unknown probe option '" + args[i] + "'");
                }
            }
            if (inputs == null) throw new ArgumentException("--inputs is required");

            var cases = new List<Case>();
            Catalog.Load(inputs, (group, name, count, run) =>
            {
                if (filter == null || group.Contains(filter) || name.Contains(filter)) cases.Add(new Case(group, name, count, run));
            });
            if (old != null) LoadOld(old, inputs, filter, oldFilter, cases);
            if (cases.Count == 0) throw new ArgumentException("no case matches the filter");

            return once ? Once(cases, inputs, filter) : Measure(cases, rounds, sampleMs, seed);
        }

        /// <summary>The same catalog compiled against another library version (the driver's A/B build), by reflection.</summary>
        private static void LoadOld(string path, string inputs, string? filter, string? oldFilter, List<Case> cases)
        {
            var load = Assembly.LoadFrom(path).GetType("ProximitySpeed.Catalog", true)!.GetMethod("Load")!;
            Action<string, string, int, Func<int, double>> add = (group, name, count, run) =>
            {
                if ((filter == null || group.Contains(filter) || name.Contains(filter)) && (oldFilter == null || name.Contains(oldFilter)))
                    cases.Add(new Case(group, "old " + name, count, run));
            };
            load.Invoke(null, new object[] { inputs, add });
        }

        /// <summary>
        /// Every case twice; the second call must not allocate, no call may throw, and every baseline must give the
        /// library's answer (one line per failing case, exit code 1). Proves the cases run; measures nothing.
        /// </summary>
        private static int Once(List<Case> cases, string inputs, string? filter)
        {
            int allocating = 0, throwing = 0;
            foreach (var c in cases)
            {
                try
                {
                    _sink += c.Run(1);
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    _sink += c.Run(1);
                    long bytes = GC.GetAllocatedBytesForCurrentThread() - before;
                    if (bytes != 0)
                    {
                        Console.WriteLine("allocates " + bytes + " bytes per " + c.Count + " queries: " + c.Group + " | " + c.Name);
                        allocating++;
                    }
                }
                catch (Exception e)
                {
                    Console.WriteLine("throws " + e.GetType().Name + " (" + e.Message + "): " + c.Group + " | " + c.Name);
                    throwing++;
                }
            }
            int differing = Agreement(cases) + RaycastAgreement(inputs, filter);
            Console.WriteLine(cases.Count + " cases executed on " + System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription + ", " +
                              allocating + " allocating, " + throwing + " throwing, " + differing + " baselines disagreeing with the library (clock: " + Clock.Kind + ")");
            return allocating == 0 && throwing == 0 && differing == 0 ? 0 : 1;
        }

        /// <summary>
        /// A baseline must give the library's answer: over one pass of a group's pairs, the sum of the distance-only
        /// distances may differ by rounding only (1e-4 per pair: a wrong sign or formula moves it by far more), and the
        /// overlap counts by at most 2 (pairs that touch within rounding). Returns how many baselines disagree.
        /// </summary>
        private static int Agreement(List<Case> cases)
        {
            int differing = 0;
            foreach (var g in cases.GroupBy(c => c.Group))
                foreach (var op in new[] { "Distance", "Overlaps" })
                {
                    var library = g.FirstOrDefault(c => c.Name == "library " + op);
                    var baseline = g.FirstOrDefault(c => c.Name == "baseline " + op);
                    if (library == null || baseline == null) continue;
                    double a, b;
                    try { a = library.Run(1); b = baseline.Run(1); }
                    catch (Exception) { continue; } // already reported as throwing
                    double tolerance = op == "Distance" ? 1e-4 * library.Count : 2;
                    if (Math.Abs(a - b) > tolerance)
                    {
                        Console.WriteLine("disagrees with the library: " + g.Key + " | baseline " + op + " (" + b.ToString("R", CultureInfo.InvariantCulture) +
                                          " against " + a.ToString("R", CultureInfo.InvariantCulture) + " over " + library.Count + " pairs)");
                        differing++;
                    }
                }
            return differing;
        }

        /// <summary>
        /// A ray-cast baseline must give the library's answer pair by pair (Catalog.RaycastAgreement): hit or miss alike
        /// and T within the precision's tolerance, except on at most 2 pairs (as overlap counts may differ by 2; the
        /// inputs' near-grazing rays pass 0.1% off a tangent or edge, so rounding does not decide hit or miss).
        /// </summary>
        private static int RaycastAgreement(string inputs, string? filter)
        {
            int differing = 0;
            foreach (var (group, pairs, disagreeing, worst) in Catalog.RaycastAgreement(inputs))
            {
                if (filter != null && !group.Contains(filter)) continue;
                if (disagreeing <= 2) continue;
                Console.WriteLine("disagrees with the library: " + group + " | baseline Cast on " + disagreeing + " of " + pairs + " pairs (worst " + worst + ")");
                differing++;
            }
            return differing;
        }

        private static int Measure(List<Case> cases, int rounds, double sampleMs, int seed)
        {
            var rng = new Random(seed);
            int passes = WarmUp(cases, rng);
            foreach (var c in cases)
            {
                // Size each sample from the fastest of three single repetitions.
                double best = double.MaxValue;
                for (int k = 0; k < 3; k++) best = Math.Min(best, Time(c, 1));
                c.Reps = Math.Max(1, (int)Math.Round(sampleMs * 1e6 / Math.Max(best, 1)));
                c.Times = new double[rounds];
            }
            GC.Collect();
            GC.WaitForPendingFinalizers();

            var groups = cases.GroupBy(c => c.Group).Select(g => g.ToArray()).ToArray();
            for (int round = 0; round < rounds; round++)
            {
                Shuffle(groups, rng);
                foreach (var g in groups)
                {
                    Shuffle(g, rng);
                    foreach (var c in g)
                    {
                        long bytes = GC.GetAllocatedBytesForCurrentThread();
                        double ns = Time(c, c.Reps);
                        bytes = GC.GetAllocatedBytesForCurrentThread() - bytes;
                        c.Times[round] = ns / ((double)c.Reps * c.Count);
                        c.MaxBytesPerQuery = Math.Max(c.MaxBytesPerQuery, bytes / ((double)c.Reps * c.Count));
                    }
                }
            }

            var output = new StringBuilder();
            output.Append("# runtime\t").Append(System.Runtime.InteropServices.RuntimeInformation.FrameworkDescription).Append('\n');
            output.Append("# clock\t").Append(Clock.Kind).Append('\n');
            output.Append("# vector\t").Append(System.Numerics.Vector.IsHardwareAccelerated ? "accelerated" : "not accelerated")
                .Append(", ").Append(System.Numerics.Vector<float>.Count).Append(" float lanes").Append('\n');
            output.Append("# warm-up passes\t").Append(passes).Append('\n');
            foreach (var c in cases)
            {
                output.Append("case\t").Append(c.Group).Append('\t').Append(c.Name).Append('\t').Append(c.Reps * c.Count).Append('\t')
                    .Append(c.MaxBytesPerQuery.ToString("R", CultureInfo.InvariantCulture)).Append('\t')
                    .Append(string.Join(" ", c.Times.Select(t => t.ToString("0.####", CultureInfo.InvariantCulture)))).Append('\n');
            }
            Console.Out.Write(output.ToString());
            return 0;
        }

        /// <summary>Nanoseconds of CPU time for run(reps).</summary>
        private static double Time(Case c, int reps)
        {
            long start = Clock.Now();
            _sink += c.Run(reps);
            return Clock.Now() - start;
        }

        /// <summary>
        /// Runs every case many times, sleeps so the runtime's background compiler promotes what was called (tiering waits
        /// for a quiet spell), and repeats until a whole pass and its sleep compiled nothing new (.NET); call counting,
        /// the instrumented tier and OSR otherwise leave timed loops in unoptimised code. Mono compiles once: two passes.
        /// </summary>
        private static int WarmUp(List<Case> cases, Random rng)
        {
            var order = cases.ToArray();
            long compiled = CompiledMethods();
            for (int pass = 1; ; pass++)
            {
                Shuffle(order, rng);
                foreach (var c in order)
                    for (int k = 0; k < CallsPerPass; k++) _sink += c.Run(1);
                Thread.Sleep(300);
                long now = CompiledMethods();
                if (pass >= MinPasses && (now == compiled || pass == MaxPasses)) return pass;
                compiled = now;
            }
        }

#if NET
        // Above the runtime's call-count threshold (30) for promotion at each tier.
        private const int CallsPerPass = 40, MinPasses = 3, MaxPasses = 12;
        private static long CompiledMethods() => System.Runtime.JitInfo.GetCompiledMethodCount(false);
#else
        private const int CallsPerPass = 3, MinPasses = 2, MaxPasses = 2;
        private static long CompiledMethods() => 0;
#endif

        private static void Shuffle<T>(T[] items, Random rng)
        {
            for (int i = items.Length - 1; i > 0; i--)
            {
                int j = rng.Next(i + 1);
                var t = items[i];
                items[i] = items[j];
                items[j] = t;
            }
        }
    }
}
