using System;
using System.Collections.Generic;
using System.Globalization;

namespace ProximityLib.Scenes.Gait
{
    /// <summary>
    /// The gait command's options as given on the command line. Parsing only checks the syntax; the values are
    /// checked by <see cref="GaitSimulation"/> itself. The help text takes its defaults from the constants the scene
    /// uses, so it cannot drift from them.
    /// </summary>
    public sealed class GaitOptions
    {
        /// <summary>Where the outputs go unless <c>--out</c> says otherwise.</summary>
        public const string DefaultOutputFolder = "gait-output";

        private static readonly string[] ValueOptions = { "--cadence", "--speed", "--foot-length", "--frames", "--tolerance", "--out" };

        private GaitOptions(bool help, double? cadence, double? speed, double? footLength, int frames, double toleranceMm, string outputFolder)
        {
            Help = help; Cadence = cadence; Speed = speed; FootLength = footLength; Frames = frames;
            ToleranceMm = toleranceMm; OutputFolder = outputFolder;
        }

        /// <summary>True when <c>--help</c> or <c>-h</c> was given: show <see cref="HelpLines"/> and do nothing else.</summary>
        public bool Help { get; }
        /// <summary>Steps per minute, or null for the recording's own timing.</summary>
        public double? Cadence { get; }
        /// <summary>Walking speed in m/s, or null.</summary>
        public double? Speed { get; }
        /// <summary>Heel–toe length in m, or null for the recorded foot.</summary>
        public double? FootLength { get; }
        /// <summary>Frames per cycle.</summary>
        public int Frames { get; }
        /// <summary>Contact tolerance in millimetres.</summary>
        public double ToleranceMm { get; }
        /// <summary>The folder that receives gait.csv, gait.png and gait-poses.svg.</summary>
        public string OutputFolder { get; }

        /// <summary>
        /// Reads <c>--name value</c> pairs; throws <see cref="FormatException"/> with a one-line message for an
        /// unknown option, a missing value or a value that is not a number.
        /// </summary>
        public static GaitOptions Parse(IReadOnlyList<string> args)
        {
            if (args is null) throw new ArgumentNullException(nameof(args));
            double? cadence = null, speed = null, footLength = null;
            int frames = GaitSimulation.DefaultFrames;
            double toleranceMm = DefaultToleranceMm;
            string outputFolder = DefaultOutputFolder;
            if (CommandLine.AsksForHelp(args)) return new GaitOptions(true, null, null, null, frames, toleranceMm, outputFolder);
            for (int i = 0; i < args.Count; i++)
            {
                string name = args[i];
                if (Array.IndexOf(ValueOptions, name) < 0)
                    throw new FormatException(name.StartsWith("-", StringComparison.Ordinal)
                        ? $"unknown option '{name}' (try --help)"
                        : $"unexpected argument '{name}': options are --name value (try --help)");
                if (i + 1 >= args.Count) throw new FormatException($"'{name}' needs a value (try --help)");
                string value = args[++i];
                switch (name)
                {
                    case "--cadence": cadence = Number(name, value); break;
                    case "--speed": speed = Number(name, value); break;
                    case "--foot-length": footLength = Number(name, value); break;
                    case "--tolerance": toleranceMm = Number(name, value); break;
                    case "--frames":
                        if (!int.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, out frames))
                            throw new FormatException($"'{name} {value}': '{value}' is not a whole number");
                        break;
                    default: outputFolder = value; break;
                }
            }
            return new GaitOptions(false, cadence, speed, footLength, frames, toleranceMm, outputFolder);
        }

        /// <summary>The scene these options describe; <see cref="ArgumentException"/> or <see cref="InvalidOperationException"/> for values it rejects.</summary>
        public GaitSimulation CreateSimulation() => new GaitSimulation(Cadence, Speed, FootLength, Frames, ToleranceMm / 1000);

        /// <summary>The options' help, one line each, with the defaults the scene actually uses.</summary>
        public static IReadOnlyList<string> HelpLines()
        {
            string footLength = new FootModel().RecordedFootLength.ToString("0.###", CultureInfo.InvariantCulture);
            return new[]
            {
                "--cadence N        steps per minute (default: the recording's)",
                "--speed V          walking speed in m/s instead of cadence (the stride is the recorded one)",
                $"--foot-length M    heel–toe length in m: scales the foot and its path (default: the recorded {footLength})",
                $"--frames N         frames per cycle (default {GaitSimulation.DefaultFrames})",
                $"--tolerance MM     contact tolerance in mm (default {DefaultToleranceMm.ToString("0.###", CultureInfo.InvariantCulture)})",
                $"--out DIR          where gait.csv, gait.png and gait-poses.svg go (default {DefaultOutputFolder})",
                "-h, --help         this help",
            };
        }

        private static double DefaultToleranceMm => GaitSimulation.DefaultContactTolerance * 1000;

        private static double Number(string name, string value) =>
            double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, out double number) && double.IsFinite(number)
                ? number
                : throw new FormatException($"'{name} {value}': '{value}' is not a number");
    }
}
