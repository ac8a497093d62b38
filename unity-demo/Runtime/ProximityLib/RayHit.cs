// Copied from src/ProximityLib/RayHit.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using Dbl = ProximityLib.Double;

namespace ProximityLib
{
    /// <summary>The answer of a 3D ray cast (<see cref="Raycast"/>); the contract of <see cref="Dbl.RayHit3"/>, computed in double and rounded to float (a hit whose T or Point lies past float's range is a miss).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct RayHit3 : IEquatable<RayHit3>, IFormattable
    {
        /// <summary>Whether the ray meets the shape within the maximum distance.</summary>
        public readonly bool Hit;
        /// <summary>The distance along the ray's unit Direction to the hit (0 when the ray starts on or in the shape); +∞ for a miss.</summary>
        public readonly float T;
        /// <summary>The hit point, on the shape (to rounding); zero for a miss.</summary>
        public readonly Vector3 Point;
        /// <summary>The unit outward surface normal at the hit (a triangle: its normal on the side the ray comes from; a point or segment: −Direction); zero for a miss or a ray starting inside.</summary>
        public readonly Vector3 Normal;
        /// <summary>True when the ray's origin lies strictly inside a solid (then T = 0 and Normal is zero).</summary>
        public readonly bool StartsInside;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal RayHit3(in Dbl.RayHit3 h)
        {
            // A hit past float's range is a miss, as the double API's past double's range: no infinite T or Point.
            var p = (Vector3)h.Point;
            Hit = h.Hit && h.T <= float.MaxValue && float.IsFinite(p.X) && float.IsFinite(p.Y) && float.IsFinite(p.Z);
            T = Hit ? (float)h.T : float.PositiveInfinity;
            Point = Hit ? p : default; Normal = Hit ? (Vector3)h.Normal : default; StartsInside = Hit && h.StartsInside;
        }

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(RayHit3 other) => Hit == other.Hit && T == other.T && Point == other.Point && Normal == other.Normal && StartsInside == other.StartsInside;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="RayHit3"/>.</summary>
        public override bool Equals(object? obj) => obj is RayHit3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(RayHit3)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Hit, T, Point, Normal, StartsInside);
        /// <summary>Value equality, as <see cref="Equals(RayHit3)"/>.</summary>
        public static bool operator ==(RayHit3 a, RayHit3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(RayHit3)"/>.</summary>
        public static bool operator !=(RayHit3 a, RayHit3 b) => !a.Equals(b);
        /// <summary>The result as text in the invariant culture with round-trip numbers, e.g. <c>RayHit3 { Hit = True, T = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The result as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"RayHit3 {{ Hit = {Formatting.Of(Hit)}, T = {Formatting.Of(T, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)}, Normal = {Formatting.Of(Normal, format, formatProvider)}, StartsInside = {Formatting.Of(StartsInside)} }}";
    }

    /// <summary>The answer of a 2D ray cast (<see cref="Raycast"/>); the contract of <see cref="Dbl.RayHit3"/>, computed in double and rounded to float (a hit whose T or Point lies past float's range is a miss).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct RayHit2 : IEquatable<RayHit2>, IFormattable
    {
        /// <summary>Whether the ray meets the shape within the maximum distance.</summary>
        public readonly bool Hit;
        /// <summary>The distance along the ray's unit Direction to the hit (0 when the ray starts on or in the shape); +∞ for a miss.</summary>
        public readonly float T;
        /// <summary>The hit point, on the shape (to rounding); zero for a miss.</summary>
        public readonly Vector2 Point;
        /// <summary>The unit outward normal at the hit (a segment, line or ray: its normal on the side the ray comes from, −Direction when the ray runs along it; a point: −Direction); zero for a miss or a ray starting inside.</summary>
        public readonly Vector2 Normal;
        /// <summary>True when the ray's origin lies strictly inside a solid (then T = 0 and Normal is zero).</summary>
        public readonly bool StartsInside;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal RayHit2(in Dbl.RayHit2 h)
        {
            // A hit past float's range is a miss, as the double API's past double's range: no infinite T or Point.
            var p = (Vector2)h.Point;
            Hit = h.Hit && h.T <= float.MaxValue && float.IsFinite(p.X) && float.IsFinite(p.Y);
            T = Hit ? (float)h.T : float.PositiveInfinity;
            Point = Hit ? p : default; Normal = Hit ? (Vector2)h.Normal : default; StartsInside = Hit && h.StartsInside;
        }

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(RayHit2 other) => Hit == other.Hit && T == other.T && Point == other.Point && Normal == other.Normal && StartsInside == other.StartsInside;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="RayHit2"/>.</summary>
        public override bool Equals(object? obj) => obj is RayHit2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(RayHit2)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Hit, T, Point, Normal, StartsInside);
        /// <summary>Value equality, as <see cref="Equals(RayHit2)"/>.</summary>
        public static bool operator ==(RayHit2 a, RayHit2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(RayHit2)"/>.</summary>
        public static bool operator !=(RayHit2 a, RayHit2 b) => !a.Equals(b);
        /// <summary>The result as text in the invariant culture with round-trip numbers, e.g. <c>RayHit2 { Hit = True, T = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The result as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"RayHit2 {{ Hit = {Formatting.Of(Hit)}, T = {Formatting.Of(T, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)}, Normal = {Formatting.Of(Normal, format, formatProvider)}, StartsInside = {Formatting.Of(StartsInside)} }}";
    }
}
