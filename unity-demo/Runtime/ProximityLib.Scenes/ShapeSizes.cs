// Copied from src/ProximityLib.Scenes/ShapeSizes.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;

namespace ProximityLib.Scenes
{
    /// <summary>
    /// Sizes from a person or a script (Unity's Inspector, ProximityShape's fields) made acceptable to ProximityLib's
    /// constructors, which refuse negative and non-finite sizes: a bad size gives a smaller shape, never an exception.
    /// </summary>
    public static class ShapeSizes
    {
        /// <summary><paramref name="size"/> when positive and finite; 0 when negative, zero or NaN; float.MaxValue for +∞.</summary>
        public static float NonNegative(float size) => size > 0 ? Math.Min(size, float.MaxValue) : 0;

        /// <summary>A size in local units times |<paramref name="scale"/>|, both made acceptable as by <see cref="NonNegative"/> (an overflow gives float.MaxValue, a NaN scale 0).</summary>
        public static float Scaled(float size, float scale) => NonNegative(NonNegative(size) * Math.Abs(scale));
    }
}
