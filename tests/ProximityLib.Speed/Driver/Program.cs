using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;

namespace ProximitySpeed
{
    /// <summary>Options shared by the measuring commands.</summary>
    public sealed class Options
    {
        public List<Mode> Modes { get; set; } = new List<Mode> { Mode.Pgo };
        public int Processes { get; set; } = 5;
        public int Rounds { get; set; } = 41;
        public double SampleMs { get; set; } = 1;
        public string Distribution { get; set; } = "mixed";
        public string? Filter { get; set; }
        public string? Against { get; set; }
        public string Out { get; set; } = "docs";
        public string? Save { get; set; }
        public string? Previous { get; set; }
    }

    public static class Program
    {
        /// <summary>
        /// The library at the commit where the speed issue was filed: the report's batch rows are measured against it
        /// ("no batch row slower than today").
        /// </summary>
        public const string BatchReference = "5a0d5e3";

        private const string Usage = """
            usage: dotnet run --project tests/ProximityLib.Speed -c Release -- <command> [options]
              quick               every case twice, the second call checked for allocation, none may throw; no timing
                                  (CI; --modes pgo,mono also builds and checks the Mono probe)
              run                 measure and print ns per query in each mode (default mode: pgo)
              report              measure in every mode and write <out>/performance.md and performance.png
                                  (modes pgo, nopgo, mono; the batch rows also against the library at 5a0d5e3)
              ab --against <ref>  the library at a git ref against the working tree's, interleaved in one process per
                                  measurement, in both PGO modes unless --modes says (mono: both compiled for Mono
                                  into one program): new ns, old ns, new ÷ old with its spread
              compare A B         two files written by --save: the relative difference of every case's median
                                  between the two measurements, per mode (how well a report reproduces)
            options:
              --modes pgo,nopgo,mono   runtimes (quick, run, ab); pgo = .NET 10 default, nopgo = DOTNET_TieredPGO=0,
                                       mono = the sources compiled against Mono's class libraries, run by mono
              --processes N            processes per mode (default 5)
              --rounds N               rounds per process (default 41)
              --sample-ms X            CPU time per sample (default 1)
              --distribution D         mixed (default), apart or overlapping
              --filter TEXT            only cases whose group or name contains TEXT, e.g. "3D sphere–OBB"
              --out DIR                where report writes (default docs)
              --save FILE              run, report: also write every case's median per mode to FILE (for compare)
              --previous FILE          report: state in the report how far its medians are from FILE's (an earlier --save)
            """;

        public static int Main(string[] args)
        {
            CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;
            if (args.Length > 0 && args[0] == "probe") return ProbeProgram.Main(args[1..]);
            try
            {
                if (args.Length == 0 || args[0] is "-h" or "--help") { Console.WriteLine(Usage); return args.Length == 0 ? 2 : 0; }
                var options = args[0] == "compare" ? new Options() : Parse(args[1..]);
                string work = Path.Combine(Path.GetTempPath(), "proximitylib-speed-" + Environment.ProcessId);
                try
                {
                    switch (args[0])
                    {
                        case "quick":
                            {
                                Directory.CreateDirectory(work);
                                string inputs = Path.Combine(work, "inputs.txt");
                                Inputs.Write(inputs, options.Distribution);
                                var probe = new List<string> { "--inputs", inputs, "--once" };
                                if (options.Filter != null) probe.AddRange(new[] { "--filter", options.Filter });
                                return Quick(options, work, probe);
                            }
                        case "run":
                            {
                                var m = Measurement.Run(options, work, null, null, null);
                                if (options.Save != null) Saved.Write(m, options.Save);
                                Console.Write(Text.Times(m));
                                return 0;
                            }
                        case "report":
                            {
                                options.Modes = Mode.All.ToList();
                                if (options.Previous != null && !File.Exists(options.Previous))
                                    throw new ArgumentException($"--previous: no file '{options.Previous}' (write one with --save)");
                                string load = Measurement.Load();
                                Console.Error.WriteLine($"load before: {load}");
                                string old = Builds.Old(BatchReference, Path.Combine(work, "old"));
                                var m = Measurement.Run(options, work, old, null, "batch");
                                if (options.Save != null) Saved.Write(m, options.Save);
                                Report.Write(m, options.Out, load, options.Previous == null ? null : Saved.Compare(options.Previous, m));
                                Console.WriteLine($"wrote {Path.Combine(options.Out, "performance.md")} and performance.png in {m.Elapsed.TotalMinutes:0.0} min");
                                return 0;
                            }
                        case "ab":
                            {
                                if (options.Against == null) throw new ArgumentException("ab needs --against <git ref>");
                                if (!args.Contains("--modes")) options.Modes = new List<Mode> { Mode.Pgo, Mode.NoPgo };
                                string? old = options.Modes.Any(x => x != Mode.Mono) ? Builds.Old(options.Against, Path.Combine(work, "old")) : null;
                                string? oldMono = options.Modes.Contains(Mode.Mono) ? Builds.OldMono(options.Against, Path.Combine(work, "old-mono")) : null;
                                var m = Measurement.Run(options, work, old, oldMono, null);
                                Console.Write(Text.Ab(m, options.Against));
                                return 0;
                            }
                        case "compare":
                            {
                                if (args.Length != 3) throw new ArgumentException("compare needs two files written by --save");
                                Console.Write(Saved.Compare(args[1], args[2]));
                                return 0;
                            }
                        default:
                            throw new ArgumentException($"unknown command '{args[0]}' (quick, run, report, ab, compare)");
                    }
                }
                finally
                {
                    if (Directory.Exists(work)) Directory.Delete(work, true);
                }
            }
            catch (Exception e)
            {
                // Bad input and failed builds or probes name themselves; anything else is named by its type. No stack trace.
                Console.Error.WriteLine("error: " + (e is ArgumentException || e is IOException || e is FormatException ? "" : e.GetType().Name + ": ") + e.Message);
                return 2;
            }
        }

        /// <summary>
        /// The quick check in each requested mode: .NET default in this process, without PGO and on Mono in a child
        /// process (the Mono probe built first). Fails when any mode fails.
        /// </summary>
        private static int Quick(Options options, string work, List<string> probe)
        {
            int failed = 0;
            foreach (var mode in options.Modes)
            {
                int code;
                if (mode == Mode.Pgo) code = ProbeProgram.Run(probe.ToArray());
                else
                {
                    var env = new Dictionary<string, string?> { ["DOTNET_TieredPGO"] = mode == Mode.NoPgo ? "0" : null };
                    string output;
                    (code, output) = mode == Mode.Mono
                        ? Shell.Run("mono", new[] { Builds.Mono(Path.Combine(work, "mono")) }.Concat(probe), env)
                        : Shell.Run("dotnet", new[] { typeof(Program).Assembly.Location, "probe" }.Concat(probe), env);
                    Console.Write(output);
                }
                if (code != 0) Console.Error.WriteLine($"error: the quick check failed on {mode.Title}");
                failed += code == 0 ? 0 : 1;
            }
            return failed == 0 ? 0 : 1;
        }

        private static Options Parse(string[] args)
        {
            var o = new Options();
            for (int i = 0; i < args.Length; i++)
            {
                string Value() => i + 1 < args.Length ? args[++i] : throw new ArgumentException($"{args[i]} needs a value");
                int Positive() => int.TryParse(Value(), NumberStyles.None, CultureInfo.InvariantCulture, out int n) && n > 0 ? n
                    : throw new ArgumentException($"{args[i - 1]} needs a positive whole number");
                switch (args[i])
                {
                    case "--modes": o.Modes = Value().Split(',').Select(Mode.Parse).Distinct().ToList(); break;
                    case "--processes": o.Processes = Positive(); break;
                    case "--rounds": o.Rounds = Positive(); break;
                    case "--sample-ms":
                        o.SampleMs = double.TryParse(Value(), NumberStyles.Float, CultureInfo.InvariantCulture, out double ms) && ms > 0 ? ms
                            : throw new ArgumentException("--sample-ms needs a positive number");
                        break;
                    case "--distribution":
                        o.Distribution = Value();
                        if (!Inputs.Distributions.Contains(o.Distribution)) throw new ArgumentException($"unknown distribution '{o.Distribution}' (mixed, apart, overlapping)");
                        break;
                    case "--filter": o.Filter = Value(); break;
                    case "--against": o.Against = Value(); break;
                    case "--out": o.Out = Value(); break;
                    case "--save": o.Save = Value(); break;
                    case "--previous": o.Previous = Value(); break;
                    default: throw new ArgumentException($"unknown option '{args[i]}'");
                }
            }
            return o;
        }
    }
}
