// Copied from src/ProximityLib.Scenes/CommandLine.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Collections.Generic;

namespace ProximityLib.Scenes
{
    /// <summary>What the scenes' command-line forms (<see cref="Gait.GaitOptions"/>, <see cref="Picker.PickerOptions"/>) share.</summary>
    internal static class CommandLine
    {
        /// <summary>True when the arguments hold <c>--help</c> or <c>-h</c> anywhere: help is shown even beside a mistake.</summary>
        public static bool AsksForHelp(IReadOnlyList<string> args)
        {
            foreach (var a in args)
                if (a == "--help" || a == "-h") return true;
            return false;
        }
    }
}
