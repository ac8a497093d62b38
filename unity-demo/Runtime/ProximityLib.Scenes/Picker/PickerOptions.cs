// Copied from src/ProximityLib.Scenes/Picker/PickerOptions.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Collections.Generic;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>
    /// The picker command's arguments: <c>[--proximity] [--svg FILE] A B</c>, where A and B are <see cref="ShapeSpec"/>s
    /// of the same dimension, or <c>--help</c>.
    /// </summary>
    public sealed class PickerOptions
    {
        private PickerOptions(bool help, bool proximity, string? svgFile, object? first, object? second)
        {
            Help = help; Proximity = proximity; SvgFile = svgFile; First = first; Second = second;
        }

        /// <summary>True when <c>--help</c> or <c>-h</c> was given: show <see cref="HelpLines"/> and do nothing else.</summary>
        public bool Help { get; }
        /// <summary>Only the overlap verdict, as the picker's Proximity Queries mode.</summary>
        public bool Proximity { get; }
        /// <summary>Where to draw the two shapes as SVG, or null.</summary>
        public string? SvgFile { get; }
        /// <summary>Shape A (a float-API shape or point), null with <see cref="Help"/>.</summary>
        public object? First { get; }
        /// <summary>Shape B, of the same dimension as A; null with <see cref="Help"/>.</summary>
        public object? Second { get; }

        /// <summary>
        /// Reads the arguments after <c>picker</c>; throws <see cref="FormatException"/> with a one-line message for an
        /// unknown option, a missing value, a bad shape, a shape count other than two or shapes of different dimensions.
        /// </summary>
        public static PickerOptions Parse(IReadOnlyList<string> args)
        {
            if (args is null) throw new ArgumentNullException(nameof(args));
            bool proximity = false;
            string? svg = null;
            var specs = new List<string>();
            if (CommandLine.AsksForHelp(args)) return new PickerOptions(true, false, null, null, null);
            for (int i = 0; i < args.Count; i++)
            {
                string a = args[i];
                if (a == "--proximity") proximity = true;
                else if (a == "--svg")
                {
                    if (i + 1 >= args.Count) throw new FormatException("'--svg' needs a file name (try picker --help)");
                    svg = args[++i];
                }
                // A shape spec always has a kind before its colon, so a leading '-' can only be an option.
                else if (a.StartsWith("-", StringComparison.Ordinal)) throw new FormatException($"unknown option '{a}' (try picker --help)");
                else specs.Add(a);
            }
            if (specs.Count != 2)
                throw new FormatException($"picker needs two shapes (got {specs.Count}), e.g. picker sphere:0,0,0,1 aabb:2,0,0,3,1,1 (try picker --help)");
            object first = ShapeSpec.Parse(specs[0]), second = ShapeSpec.Parse(specs[1]);
            int da = ShapeSpec.Dimension(first), db = ShapeSpec.Dimension(second);
            if (da != db)
                throw new FormatException($"'{specs[0]}' is {da}D and '{specs[1]}' is {db}D: pick two shapes of the same dimension");
            return new PickerOptions(false, proximity, svg, first, second);
        }

        /// <summary>The picker's help: usage, options and every shape form with its units and an example.</summary>
        public static IReadOnlyList<string> HelpLines()
        {
            var lines = new List<string>
            {
                "usage: ProximityLib.Demo picker [--proximity] [--svg FILE] A B",
                "Evaluates two shapes, both 2D or both 3D, as the paper's primitive picker does: the minimum distance",
                "(negative: penetration depth), the closest points on A and B, and whether they collide.",
                "",
                "options:",
                "  --proximity   print only the overlap verdict (Colliding / Not colliding), the picker's Proximity Queries mode",
                "  --svg FILE    also draw the two shapes into FILE as the picker shows them (looking along +z)",
                "  -h, --help    this help",
                "",
                "shapes are kind:numbers, comma-separated without spaces; the count of numbers picks 2D or 3D.",
                "Lengths are in any one unit (the same for both shapes); angles are in radians; quaternions are x,y,z,w.",
            };
            int width = 0;
            foreach (var f in ShapeSpec.Forms) width = Math.Max(width, f.Syntax.Length);
            foreach (var f in ShapeSpec.Forms)
            {
                lines.Add($"  {f.Syntax.PadRight(width)}  {f.Meaning}");
                lines.Add($"  {"".PadRight(width)}  e.g. {f.Example}");
            }
            lines.Add("");
            lines.Add("examples:");
            lines.Add("  ProximityLib.Demo picker sphere:0,0,0,1 obb:3,0,0,0,0,0.3826834,0.9238795,1,1,1");
            lines.Add("  ProximityLib.Demo picker --proximity --svg pick.svg circle:0,0,1 obb:1.2,0.4,0.6,1,0.5");
            return lines;
        }
    }
}
