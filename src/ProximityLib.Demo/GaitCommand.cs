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
        public static int Run(GaitOptions options)
        {
            GaitSimulation sim;
            try
            {
                sim = options.CreateSimulation();
            }
            catch (Exception e) when (e is ArgumentException || e is InvalidOperationException)
            {
                return Fail(e.Message);
            }
            // Before any output: a bad folder found after the run would waste it and leave a half-written result.
            string outDir = options.OutputFolder;
            if (CannotWrite(outDir) is string problem) return Fail($"--out '{outDir}': {problem}");
            int frames = sim.FrameCount;

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

        // Null when a file can be created in the folder (made if missing); otherwise why not, in a few words.
        private static string? CannotWrite(string folder)
        {
            if (File.Exists(folder)) return "is a file, not a folder";
            try
            {
                Directory.CreateDirectory(folder);
                using (new FileStream(Path.Combine(folder, $".write-test-{Guid.NewGuid():N}"), FileMode.CreateNew, FileAccess.Write,
                           FileShare.None, 1, FileOptions.DeleteOnClose)) { }
                return null;
            }
            catch (Exception e) when (e is IOException || e is UnauthorizedAccessException || e is ArgumentException || e is NotSupportedException)
            {
                return $"cannot write there ({e.Message})";
            }
        }

        private static int Fail(string message)
        {
            Console.Error.WriteLine($"error: {message}");
            return 2;
        }
    }
}
