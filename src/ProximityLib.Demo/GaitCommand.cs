using System;
using System.Diagnostics;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using ProximityLib.Scenes.Gait;

namespace ProximityLib.Demo
{
    /// <summary>The main command: runs the gait scene, prints its summary, writes the per-frame CSV and the plot.</summary>
    internal static class GaitCommand
    {
        public static void PrintOptions()
        {
            Console.WriteLine("         --cadence N        steps per minute (default: the recording's)");
            Console.WriteLine("         --speed V          walking speed in m/s instead of cadence (the stride is the recorded one)");
            Console.WriteLine("         --foot-length M    heel–toe length in m: scales the foot and its path (default: the recorded 0.288)");
            Console.WriteLine("         --frames N         frames per cycle (default 200)");
            Console.WriteLine("         --tolerance MM     contact tolerance in mm (default 5)");
            Console.WriteLine("         --out DIR          where gait.csv and gait.png go (default gait-output)");
        }

        public static int Run(string[] args)
        {
            double? cadence = null, speed = null, footLength = null;
            int frames = 200;
            double toleranceMm = GaitSimulation.DefaultContactTolerance * 1000;
            string outDir = "gait-output";
            for (int i = 0; i < args.Length; i++)
            {
                string name = args[i];
                if (i + 1 >= args.Length) return Fail($"'{name}' needs a value (try --help)");
                string value = args[++i];
                bool ok = double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out double number) && double.IsFinite(number);
                switch (name)
                {
                    case "--cadence" when ok: cadence = number; break;
                    case "--speed" when ok: speed = number; break;
                    case "--foot-length" when ok: footLength = number; break;
                    case "--tolerance" when ok: toleranceMm = number; break;
                    case "--frames" when int.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, out int n): frames = n; break;
                    case "--out": outDir = value; break;
                    case "--cadence": case "--speed": case "--foot-length": case "--tolerance": case "--frames":
                        return Fail($"'{name} {value}': '{value}' is not a number");
                    default: return Fail($"unknown option '{name}' (try --help)");
                }
            }

            GaitSimulation sim;
            try
            {
                sim = new GaitSimulation(cadence, speed, footLength, frames, toleranceMm / 1000);
            }
            catch (Exception e) when (e is ArgumentException || e is InvalidOperationException)
            {
                return Fail(e.Message);
            }

            var ev = sim.Events;
            var w = Console.Out;
            w.WriteLine("ProximityLib foot–ground gait simulation");
            w.WriteLine($"  kinematics: the recorded right stride of OpenSim's subject01_walk1 (Delp et al. 2007), heel and toe markers at 60 Hz");
            w.WriteLine($"  foot: heel sphere r {FootModel.HeelRadius * 1000 * sim.Foot.Scale:0.#} mm, sole OBB, toe sphere r {FootModel.ToeRadius * 1000 * sim.Foot.Scale:0.#} mm; " +
                        $"ground AABB; contact within {sim.ContactTolerance * 1000:0.#} mm");
            w.WriteLine($"  cadence {sim.Cadence:0.0} steps/min, speed {sim.Speed:0.00} m/s, stride {sim.StrideLength:0.00} m in {sim.StrideDuration:0.000} s, " +
                        $"foot {sim.Foot.FootLength:0.000} m, {sim.FrameCount} frames");
            w.WriteLine();
            w.WriteLine("  event         ours      normative (Perry & Burnfield 2010)   within ±5 points");
            w.WriteLine($"  heel strike    0.0 %    0 %                                  (defines the cycle)");
            Row(w, "foot flat", ev.FootFlat, $"by {GaitNorms.FootFlatLatest} % (end of loading response)", 0, GaitNorms.FootFlatLatest);
            Row(w, "heel off", ev.HeelOff, $"{GaitNorms.HeelOff} % (heel rise)", GaitNorms.HeelOff, GaitNorms.HeelOff);
            Row(w, "toe off", ev.ToeOff, $"{GaitNorms.ToeOff} %", GaitNorms.ToeOff, GaitNorms.ToeOff);
            w.WriteLine();
            w.WriteLine($"  minimum toe clearance in mid swing ({GaitNorms.MidSwingStart}–{GaitNorms.MidSwingEnd} %): {ev.MinToeClearance * 1000:0.0} mm at {ev.MinToeClearancePercent:0.0} %");

            Directory.CreateDirectory(outDir);
            var csv = new StringBuilder("frame,percent,time_s,heel_x_m,heel_y_m,pitch_deg,heel_dist_mm,sole_dist_mm,toe_dist_mm,heel_contact,sole_contact,toe_contact\n");
            var percent = new double[frames];
            var dist = new double[3][] { new double[frames], new double[frames], new double[frames] };
            var contact = new bool[3][] { new bool[frames], new bool[frames], new bool[frames] };
            var progress = Stopwatch.StartNew();
            bool reported = false;
            for (int k = 0; k < frames; k++)
            {
                var f = sim.Frame(k);
                percent[k] = f.Percent;
                for (int p = 0; p < 3; p++)
                {
                    dist[p][k] = f.Distance((FootPart)p) * 1000;
                    contact[p][k] = f.Contact((FootPart)p);
                }
                csv.Append(string.Create(CultureInfo.InvariantCulture,
                    $"{k},{f.Percent:0.###},{f.Time:0.#####},{f.Pose.Heel.Center.X:0.#####},{f.Pose.Heel.Center.Y:0.#####},{f.Pose.Pitch * 180 / Math.PI:0.###}," +
                    $"{dist[0][k]:0.###},{dist[1][k]:0.###},{dist[2][k]:0.###},{(f.HeelContact ? 1 : 0)},{(f.SoleContact ? 1 : 0)},{(f.ToeContact ? 1 : 0)}\n"));
                if (progress.ElapsedMilliseconds > 1000)
                {
                    Console.Error.Write($"\r  frames: {k + 1}/{frames}");
                    progress.Restart();
                    reported = true;
                }
            }
            if (reported) Console.Error.WriteLine($"\r  frames: {frames}/{frames}");

            w.WriteLine($"  cost per frame: {FrameCost(sim):0} ns (placing the foot, 3 distance and 3 overlap queries; measured here over repeated cycles)");
#if DEBUG
            w.WriteLine("  (this is a Debug build, which is unoptimised: run with -c Release for representative timings)");
#endif
            string csvPath = Path.Combine(outDir, "gait.csv"), pngPath = Path.Combine(outDir, "gait.png"), svgPath = Path.Combine(outDir, "gait-poses.svg");
            try
            {
                File.WriteAllText(csvPath, csv.ToString());
                GaitPlot.Save(pngPath, percent, dist, contact, ev);
                File.WriteAllText(svgPath, GaitSvg.Render(sim));
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
            {
                return Fail($"cannot write to '{outDir}': {e.Message}");
            }
            w.WriteLine($"  wrote {csvPath} ({frames} frames), {pngPath} and {svgPath}");
            return 0;
        }

        private static void Row(TextWriter w, string name, double ours, string norm, double low, double high) =>
            w.WriteLine($"  {name,-12} {ours,5:0.0} %    {norm,-36} {(GaitNorms.Agrees(ours, low, high) ? "yes" : "NO")}");

        // Whole cycles for ~0.3 s, after ~0.3 s of warm-up so the tiered JIT has promoted the queries to optimised code.
        private static double FrameCost(GaitSimulation sim)
        {
            float sink = 0;
            var warm = Stopwatch.StartNew();
            while (warm.ElapsedMilliseconds < 300)
                for (int k = 0; k < sim.FrameCount; k++) sink += sim.Frame(k).Distances.X;
            long frames = 0;
            var clock = Stopwatch.StartNew();
            while (clock.ElapsedMilliseconds < 300)
            {
                for (int k = 0; k < sim.FrameCount; k++) sink += sim.Frame(k).Distances.X;
                frames += sim.FrameCount;
            }
            GC.KeepAlive(sink);
            return clock.Elapsed.TotalMilliseconds * 1e6 / frames;
        }

        private static int Fail(string message)
        {
            Console.Error.WriteLine($"error: {message}");
            return 2;
        }
    }
}
