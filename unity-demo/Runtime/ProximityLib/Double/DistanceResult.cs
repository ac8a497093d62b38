// Copied from src/ProximityLib/Double/DistanceResult.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
namespace ProximityLib.Double
{
    /// <summary>
    /// The answer of a 3D closest-distance query between shape A (first argument) and shape B (second argument).
    /// Distance &gt; 0: separated, and PointA, PointB are closest points with |PointA − PointB| = Distance.
    /// Distance = 0: touching. Distance &lt; 0 (only when a solid is involved): overlapping by the penetration depth
    /// −Distance; PointA lies in A, PointB in B, and moving A by PointB − PointA (length −Distance) makes the shapes
    /// just touch: that is the minimum translation.
    /// </summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct DistanceResult3 : System.IEquatable<DistanceResult3>, System.IFormattable
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly double Distance;
        /// <summary>max(Distance, 0)², formed before the square root where the pair allows (point, segment and box pairs).</summary>
        public readonly double DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector3D PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector3D PointB;
        /// <summary>When A is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointA (a capsule: of the axis point nearest PointA); a line or ray, the t with PointA = Origin + t·Direction; otherwise 0.</summary>
        public readonly double ParameterA;
        /// <summary>When B is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointB (a capsule: of the axis point nearest PointB); a line or ray, the t with PointB = Origin + t·Direction; otherwise 0.</summary>
        public readonly double ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult3(double distance, double distanceSquared, Vector3D pointA, Vector3D pointB, double parameterA, double parameterB)
        {
            Distance = distance; DistanceSquared = distanceSquared; PointA = pointA; PointB = pointB;
            ParameterA = parameterA; ParameterB = parameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult3 Swapped() => new DistanceResult3(Distance, DistanceSquared, PointB, PointA, ParameterB, ParameterA);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2 To2() =>
            new DistanceResult2(Distance, DistanceSquared, Vector2D.From3(PointA), Vector2D.From3(PointB), ParameterA, ParameterB);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(DistanceResult3 other) => Distance == other.Distance && DistanceSquared == other.DistanceSquared && PointA == other.PointA && PointB == other.PointB && ParameterA == other.ParameterA && ParameterB == other.ParameterB;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="DistanceResult3"/>.</summary>
        public override bool Equals(object? obj) => obj is DistanceResult3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(DistanceResult3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Distance, DistanceSquared, PointA, PointB, ParameterA, ParameterB);
        /// <summary>Value equality, as <see cref="Equals(DistanceResult3)"/>.</summary>
        public static bool operator ==(DistanceResult3 a, DistanceResult3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(DistanceResult3)"/>.</summary>
        public static bool operator !=(DistanceResult3 a, DistanceResult3 b) => !a.Equals(b);
        /// <summary>The result as text in the invariant culture with round-trip numbers, e.g. <c>DistanceResult3 { Distance = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The result as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"DistanceResult3 {{ Distance = {Formatting.Of(Distance, format, formatProvider)}, DistanceSquared = {Formatting.Of(DistanceSquared, format, formatProvider)}, PointA = {Formatting.Of(PointA, format, formatProvider)}, PointB = {Formatting.Of(PointB, format, formatProvider)}, ParameterA = {Formatting.Of(ParameterA, format, formatProvider)}, ParameterB = {Formatting.Of(ParameterB, format, formatProvider)} }}";
    }

    /// <summary>The answer of a 2D closest-distance query; same contract as <see cref="DistanceResult3"/>.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct DistanceResult2 : System.IEquatable<DistanceResult2>, System.IFormattable
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly double Distance;
        /// <summary>max(Distance, 0)², formed before the square root where the pair allows (point, segment and box pairs).</summary>
        public readonly double DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector2D PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector2D PointB;
        /// <summary>When A is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointA (a capsule: of the axis point nearest PointA); a line or ray, the t with PointA = Origin + t·Direction; otherwise 0.</summary>
        public readonly double ParameterA;
        /// <summary>When B is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointB (a capsule: of the axis point nearest PointB); a line or ray, the t with PointB = Origin + t·Direction; otherwise 0.</summary>
        public readonly double ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2(double distance, double distanceSquared, Vector2D pointA, Vector2D pointB, double parameterA, double parameterB)
        {
            Distance = distance; DistanceSquared = distanceSquared; PointA = pointA; PointB = pointB;
            ParameterA = parameterA; ParameterB = parameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult2 Swapped() => new DistanceResult2(Distance, DistanceSquared, PointB, PointA, ParameterB, ParameterA);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(DistanceResult2 other) => Distance == other.Distance && DistanceSquared == other.DistanceSquared && PointA == other.PointA && PointB == other.PointB && ParameterA == other.ParameterA && ParameterB == other.ParameterB;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="DistanceResult2"/>.</summary>
        public override bool Equals(object? obj) => obj is DistanceResult2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(DistanceResult2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Distance, DistanceSquared, PointA, PointB, ParameterA, ParameterB);
        /// <summary>Value equality, as <see cref="Equals(DistanceResult2)"/>.</summary>
        public static bool operator ==(DistanceResult2 a, DistanceResult2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(DistanceResult2)"/>.</summary>
        public static bool operator !=(DistanceResult2 a, DistanceResult2 b) => !a.Equals(b);
        /// <summary>The result as text in the invariant culture with round-trip numbers, e.g. <c>DistanceResult2 { Distance = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The result as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"DistanceResult2 {{ Distance = {Formatting.Of(Distance, format, formatProvider)}, DistanceSquared = {Formatting.Of(DistanceSquared, format, formatProvider)}, PointA = {Formatting.Of(PointA, format, formatProvider)}, PointB = {Formatting.Of(PointB, format, formatProvider)}, ParameterA = {Formatting.Of(ParameterA, format, formatProvider)}, ParameterB = {Formatting.Of(ParameterB, format, formatProvider)} }}";
    }
}
