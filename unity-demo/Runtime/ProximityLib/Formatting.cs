// Copied from src/ProximityLib/Formatting.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Globalization;
using System.Numerics;
using ProximityLib.Double;

namespace ProximityLib
{
    /// <summary>
    /// How shapes and results print (their <c>ToString</c> and <see cref="IFormattable"/> forms): each number in the
    /// given format, "R" (round-trip on every runtime, Unity's Mono included, where "G" is not) when none is given, and
    /// in the given culture, the invariant one when none is given. Vectors print as System.Numerics prints them:
    /// &lt;x, y, z&gt;, the components separated by the culture's group separator and a space.
    /// </summary>
    internal static class Formatting
    {
        private static string Format(string? format) => string.IsNullOrEmpty(format) ? "R" : format!;
        private static IFormatProvider Provider(IFormatProvider? provider) => provider ?? CultureInfo.InvariantCulture;
        private static string Separator(IFormatProvider? provider) => NumberFormatInfo.GetInstance(Provider(provider)).NumberGroupSeparator + " ";

        public static string Of(bool v) => v ? "True" : "False";
        public static string Of(double v, string? format, IFormatProvider? provider) => v.ToString(Format(format), Provider(provider));
        public static string Of(float v, string? format, IFormatProvider? provider) => v.ToString(Format(format), Provider(provider));

        public static string Of(Vector2 v, string? format, IFormatProvider? provider) =>
            $"<{Of(v.X, format, provider)}{Separator(provider)}{Of(v.Y, format, provider)}>";
        public static string Of(Vector3 v, string? format, IFormatProvider? provider) =>
            $"<{Of(v.X, format, provider)}{Separator(provider)}{Of(v.Y, format, provider)}{Separator(provider)}{Of(v.Z, format, provider)}>";
        public static string Of(Vector2D v, string? format, IFormatProvider? provider) =>
            $"<{Of(v.X, format, provider)}{Separator(provider)}{Of(v.Y, format, provider)}>";
        public static string Of(Vector3D v, string? format, IFormatProvider? provider) =>
            $"<{Of(v.X, format, provider)}{Separator(provider)}{Of(v.Y, format, provider)}{Separator(provider)}{Of(v.Z, format, provider)}>";
    }
}
