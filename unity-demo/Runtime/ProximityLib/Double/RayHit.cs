// Copied from src/ProximityLib/Double/RayHit.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// The answer of a 3D ray cast (<see cref="Raycast"/>): the first point of the ray on the shape. A miss has Hit false,
    /// T = +∞ and zero Point and Normal. A ray whose origin lies strictly inside a solid has T = 0, Point = Origin,
    /// StartsInside true and a zero Normal; an origin on a solid's surface is an ordinary hit at T = 0.
    /// </summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct RayHit3 : IEquatable<RayHit3>, IFormattable
    {
        /// <summary>Whether the ray meets the shape within the maximum distance.</summary>
        public readonly bool Hit;
        /// <summary>The distance along the ray's unit Direction to the hit (0 when the ray starts on or in the shape); +∞ for a miss.</summary>
        public readonly double T;
        /// <summary>The hit point, on the shape (to rounding); zero for a miss.</summary>
        public readonly Vector3D Point;
        /// <summary>The unit outward surface normal at the hit (a triangle: its normal on the side the ray comes from; a point or segment: −Direction); zero for a miss or a ray starting inside.</summary>
        public readonly Vector3D Normal;
        /// <summary>True when the ray's origin lies strictly inside a solid (then T = 0 and Normal is zero).</summary>
        public readonly bool StartsInside;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal RayHit3(double t, Vector3D point, Vector3D normal, bool startsInside)
        {
            Hit = true; T = t; Point = point; Normal = normal; StartsInside = startsInside;
        }

        /// <summary>No hit: Hit false, T = +∞, zero Point and Normal.</summary>
        internal static RayHit3 Miss => new RayHit3(false);

        private RayHit3(bool _) { Hit = false; T = double.PositiveInfinity; Point = default; Normal = default; StartsInside = false; }

        /// <summary>A ray starting strictly inside a solid at <paramref name="origin"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Inside(Vector3D origin) => new RayHit3(0, origin, default, true);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal RayHit2 To2() => Hit ? new RayHit2(T, Vector2D.From3(Point), Vector2D.From3(Normal), StartsInside) : RayHit2.Miss;

        /// <summary>
        /// The public answer: h when it is a hit no farther than maxDistance whose T and Point are finite (a hit beyond the
        /// double range is a miss), else a miss. Throws <see cref="ArgumentException"/> on a negative or NaN maxDistance.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit3 Within(in RayHit3 h, double maxDistance)
        {
            if (!(maxDistance >= 0)) Limits.Throw(maxDistance);
            return h.T <= maxDistance && h.T <= double.MaxValue && h.Point.IsFinite ? h : Miss;
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

    /// <summary>The answer of a 2D ray cast (<see cref="Raycast"/>); same contract as <see cref="RayHit3"/>.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct RayHit2 : IEquatable<RayHit2>, IFormattable
    {
        /// <summary>Whether the ray meets the shape within the maximum distance.</summary>
        public readonly bool Hit;
        /// <summary>The distance along the ray's unit Direction to the hit (0 when the ray starts on or in the shape); +∞ for a miss.</summary>
        public readonly double T;
        /// <summary>The hit point, on the shape (to rounding); zero for a miss.</summary>
        public readonly Vector2D Point;
        /// <summary>The unit outward normal at the hit (a segment, line or ray: its normal on the side the ray comes from, −Direction when the ray runs along it; a point: −Direction); zero for a miss or a ray starting inside.</summary>
        public readonly Vector2D Normal;
        /// <summary>True when the ray's origin lies strictly inside a solid (then T = 0 and Normal is zero).</summary>
        public readonly bool StartsInside;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal RayHit2(double t, Vector2D point, Vector2D normal, bool startsInside)
        {
            Hit = true; T = t; Point = point; Normal = normal; StartsInside = startsInside;
        }

        /// <summary>No hit: Hit false, T = +∞, zero Point and Normal.</summary>
        internal static RayHit2 Miss => new RayHit2(false);

        private RayHit2(bool _) { Hit = false; T = double.PositiveInfinity; Point = default; Normal = default; StartsInside = false; }

        /// <summary>A ray starting strictly inside a solid at <paramref name="origin"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Inside(Vector2D origin) => new RayHit2(0, origin, default, true);

        /// <summary>As <see cref="RayHit3.Within"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static RayHit2 Within(in RayHit2 h, double maxDistance)
        {
            if (!(maxDistance >= 0)) Limits.Throw(maxDistance);
            return h.T <= maxDistance && h.T <= double.MaxValue && h.Point.IsFinite ? h : Miss;
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

    internal static class Limits
    {
        // Out of line: the throw keeps the inlined check small.
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static void Throw(double maxDistance) =>
            throw new ArgumentException($"maxDistance must be non-negative and not NaN (got {maxDistance}).", nameof(maxDistance));
    }
}
