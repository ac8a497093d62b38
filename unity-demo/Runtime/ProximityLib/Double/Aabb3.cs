// Copied from src/ProximityLib/Double/Aabb3.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>A closed solid axis-aligned box [Min, Max]; zero extents (a face, an edge, a point) are allowed.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Aabb3 : IEquatable<Aabb3>, IFormattable, IScalable<Aabb3>
    {
        /// <summary>The minimum corner.</summary>
        public readonly Vector3D Min;
        /// <summary>The maximum corner.</summary>
        public readonly Vector3D Max;

        /// <summary>Creates a box; throws <see cref="ArgumentException"/> on non-finite corners or Min greater than Max on any axis.</summary>
        public Aabb3(Vector3D min, Vector3D max)
        {
            Num.Finite(min, nameof(min));
            Num.Finite(max, nameof(max));
            if (min.X > max.X || min.Y > max.Y || min.Z > max.Z)
                throw new ArgumentException($"min {min} must not exceed max {max} on any axis.", nameof(min));
            Min = Num.NoNegativeZero(min); Max = Num.NoNegativeZero(max);
        }


        void IScalable<Aabb3>.Measure(ref Rescale s) { s.Point(Min); s.Point(Max); }
        Aabb3 IScalable<Aabb3>.Rescaled(in Rescale s) => new Aabb3(s.Apply(Min), s.Apply(Max));

        /// <summary>The paper's form: minimum corner plus length (X), height (Y) and width (Z), all non-negative.</summary>
        public static Aabb3 FromOrigin(Vector3D origin, double length, double height, double width)
        {
            Num.Finite(origin, nameof(origin));
            Num.NonNegative(length, nameof(length));
            Num.NonNegative(height, nameof(height));
            Num.NonNegative(width, nameof(width));
            return new Aabb3(origin, origin + new Vector3D(length, height, width));
        }

        /// <summary>A box from its center and non-negative half-extents.</summary>
        public static Aabb3 FromCenter(Vector3D center, Vector3D halfExtents)
        {
            Num.Finite(center, nameof(center));
            Num.Finite(halfExtents, nameof(halfExtents));
            if (halfExtents.X < 0 || halfExtents.Y < 0 || halfExtents.Z < 0)
                throw new ArgumentException($"halfExtents must be non-negative (got {halfExtents}).", nameof(halfExtents));
            return new Aabb3(center - halfExtents, center + halfExtents);
        }

        /// <summary>The center, (Min + Max) / 2.</summary>
        public Vector3D Center => (Min + Max) * 0.5;

        // Inlined: a call returns the 150-byte box through memory (it cost segment–AABB, before that pair skipped the box,
        // 13% of its time without PGO).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box ToBox() => new Box(Min, Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ, default, Max - Min, false);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Aabb3 other) => Min == other.Min && Max == other.Max;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Aabb3"/>.</summary>
        public override bool Equals(object? obj) => obj is Aabb3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Aabb3)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Min, Max);
        /// <summary>Value equality, as <see cref="Equals(Aabb3)"/>.</summary>
        public static bool operator ==(Aabb3 a, Aabb3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Aabb3)"/>.</summary>
        public static bool operator !=(Aabb3 a, Aabb3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Aabb3 { Min = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Aabb3 {{ Min = {Formatting.Of(Min, format, formatProvider)}, Max = {Formatting.Of(Max, format, formatProvider)} }}";
    }

    /// <summary>A closed solid axis-aligned rectangle [Min, Max]; zero extents (a segment, a point) are allowed.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Aabb2 : IEquatable<Aabb2>, IFormattable, IScalable<Aabb2>
    {
        /// <summary>The minimum corner.</summary>
        public readonly Vector2D Min;
        /// <summary>The maximum corner.</summary>
        public readonly Vector2D Max;

        /// <summary>Creates a rectangle; throws <see cref="ArgumentException"/> on non-finite corners or Min greater than Max on any axis.</summary>
        public Aabb2(Vector2D min, Vector2D max)
        {
            Num.Finite(min, nameof(min));
            Num.Finite(max, nameof(max));
            if (min.X > max.X || min.Y > max.Y)
                throw new ArgumentException($"min {min} must not exceed max {max} on any axis.", nameof(min));
            Min = Num.NoNegativeZero(min); Max = Num.NoNegativeZero(max);
        }


        void IScalable<Aabb2>.Measure(ref Rescale s) { s.Point(Min); s.Point(Max); }
        Aabb2 IScalable<Aabb2>.Rescaled(in Rescale s) => new Aabb2(s.Apply(Min), s.Apply(Max));

        /// <summary>The paper's form: minimum corner plus length (X) and height (Y), both non-negative.</summary>
        public static Aabb2 FromOrigin(Vector2D origin, double length, double height)
        {
            Num.Finite(origin, nameof(origin));
            Num.NonNegative(length, nameof(length));
            Num.NonNegative(height, nameof(height));
            return new Aabb2(origin, origin + new Vector2D(length, height));
        }

        /// <summary>A rectangle from its center and non-negative half-extents.</summary>
        public static Aabb2 FromCenter(Vector2D center, Vector2D halfExtents)
        {
            Num.Finite(center, nameof(center));
            Num.Finite(halfExtents, nameof(halfExtents));
            if (halfExtents.X < 0 || halfExtents.Y < 0)
                throw new ArgumentException($"halfExtents must be non-negative (got {halfExtents}).", nameof(halfExtents));
            return new Aabb2(center - halfExtents, center + halfExtents);
        }

        /// <summary>The center, (Min + Max) / 2.</summary>
        public Vector2D Center => (Min + Max) * 0.5;

        // Inlined, as Aabb3.ToBox is.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box2 ToBox2() => new Box2(Min, Vector2D.UnitX, Vector2D.UnitY, default, Max - Min);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box ToBox()
        {
            var ext = Max - Min;
            return new Box(Min.To3(), Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ, default, new Vector3D(ext.X, ext.Y, 0), true);
        }

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Aabb2 other) => Min == other.Min && Max == other.Max;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Aabb2"/>.</summary>
        public override bool Equals(object? obj) => obj is Aabb2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Aabb2)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Min, Max);
        /// <summary>Value equality, as <see cref="Equals(Aabb2)"/>.</summary>
        public static bool operator ==(Aabb2 a, Aabb2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Aabb2)"/>.</summary>
        public static bool operator !=(Aabb2 a, Aabb2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Aabb2 { Min = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Aabb2 {{ Min = {Formatting.Of(Min, format, formatProvider)}, Max = {Formatting.Of(Max, format, formatProvider)} }}";
    }
}
