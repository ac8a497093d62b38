// Copied from src/ProximityLib/DistanceResult.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib
{
    /// <summary>The answer of a 3D closest-distance query; the contract of <see cref="Dbl.DistanceResult3"/>, rounded to float.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct DistanceResult3 : System.IEquatable<DistanceResult3>, System.IFormattable
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly float Distance;
        /// <summary>max(Distance, 0)², rounded from the double computation.</summary>
        public readonly float DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector3 PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector3 PointB;
        /// <summary>When A is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointA (a capsule: of the axis point nearest PointA); a line or ray, the t with PointA = Origin + t·Direction; otherwise 0.</summary>
        public readonly float ParameterA;
        /// <summary>When B is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointB (a capsule: of the axis point nearest PointB); a line or ray, the t with PointB = Origin + t·Direction; otherwise 0.</summary>
        public readonly float ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult3(in Dbl.DistanceResult3 r)
        {
            Distance = (float)r.Distance; DistanceSquared = (float)r.DistanceSquared;
            PointA = (Vector3)r.PointA; PointB = (Vector3)r.PointB;
            ParameterA = (float)r.ParameterA; ParameterB = (float)r.ParameterB;
        }

        private DistanceResult3(in DistanceResult3 r, bool swap)
        {
            Distance = r.Distance; DistanceSquared = r.DistanceSquared;
            PointA = swap ? r.PointB : r.PointA; PointB = swap ? r.PointA : r.PointB;
            ParameterA = swap ? r.ParameterB : r.ParameterA; ParameterB = swap ? r.ParameterA : r.ParameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult3 Swapped() => new DistanceResult3(this, true);

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

    /// <summary>The answer of a 2D closest-distance query; the contract of <see cref="Dbl.DistanceResult3"/>, rounded to float.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct DistanceResult2 : System.IEquatable<DistanceResult2>, System.IFormattable
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly float Distance;
        /// <summary>max(Distance, 0)², rounded from the double computation.</summary>
        public readonly float DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector2 PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector2 PointB;
        /// <summary>When A is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointA (a capsule: of the axis point nearest PointA); a line or ray, the t with PointA = Origin + t·Direction; otherwise 0.</summary>
        public readonly float ParameterA;
        /// <summary>When B is a segment or capsule, the parameter along its axis (0 = Start, 1 = End) of PointB (a capsule: of the axis point nearest PointB); a line or ray, the t with PointB = Origin + t·Direction; otherwise 0.</summary>
        public readonly float ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2(in Dbl.DistanceResult2 r)
        {
            Distance = (float)r.Distance; DistanceSquared = (float)r.DistanceSquared;
            PointA = (Vector2)r.PointA; PointB = (Vector2)r.PointB;
            ParameterA = (float)r.ParameterA; ParameterB = (float)r.ParameterB;
        }

        private DistanceResult2(in DistanceResult2 r, bool swap)
        {
            Distance = r.Distance; DistanceSquared = r.DistanceSquared;
            PointA = swap ? r.PointB : r.PointA; PointB = swap ? r.PointA : r.PointB;
            ParameterA = swap ? r.ParameterB : r.ParameterA; ParameterB = swap ? r.ParameterA : r.ParameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult2 Swapped() => new DistanceResult2(this, true);

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
