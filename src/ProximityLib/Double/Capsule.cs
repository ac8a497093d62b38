namespace ProximityLib.Double
{
    /// <summary>A closed solid 3D capsule: the points within Radius of the segment Start–End (a sphere when the segment has zero length, the segment when Radius is 0).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Capsule3 : System.IEquatable<Capsule3>, System.IFormattable, IScalable<Capsule3>
    {
        /// <summary>The axis endpoint at parameter 0.</summary>
        public readonly Vector3D Start;
        /// <summary>The axis endpoint at parameter 1.</summary>
        public readonly Vector3D End;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a capsule; throws <see cref="System.ArgumentException"/> on non-finite endpoints or a negative or non-finite radius.</summary>
        public Capsule3(Vector3D start, Vector3D end, double radius)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Num.NonNegative(radius, nameof(radius));
            Start = Num.NoNegativeZero(start); End = Num.NoNegativeZero(end); Radius = Num.NoNegativeZero(radius);
        }

        void IScalable<Capsule3>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); s.Length(Radius); }
        Capsule3 IScalable<Capsule3>.Rescaled(in Rescale s) => new Capsule3(s.Apply(Start), s.Apply(End), s.Apply(Radius));

        /// <summary>The axis: the segment Start–End.</summary>
        public Segment3 Axis => new Segment3(Start, End);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Capsule3 other) => Start == other.Start && End == other.End && Radius == other.Radius;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Capsule3"/>.</summary>
        public override bool Equals(object? obj) => obj is Capsule3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Capsule3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Start, End, Radius);
        /// <summary>Value equality, as <see cref="Equals(Capsule3)"/>.</summary>
        public static bool operator ==(Capsule3 a, Capsule3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Capsule3)"/>.</summary>
        public static bool operator !=(Capsule3 a, Capsule3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Capsule3 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Capsule3 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }

    /// <summary>A closed solid 2D capsule (a stadium): the points within Radius of the segment Start–End (a circle when the segment has zero length, the segment when Radius is 0).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Capsule2 : System.IEquatable<Capsule2>, System.IFormattable, IScalable<Capsule2>
    {
        /// <summary>The axis endpoint at parameter 0.</summary>
        public readonly Vector2D Start;
        /// <summary>The axis endpoint at parameter 1.</summary>
        public readonly Vector2D End;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a capsule; throws <see cref="System.ArgumentException"/> on non-finite endpoints or a negative or non-finite radius.</summary>
        public Capsule2(Vector2D start, Vector2D end, double radius)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Num.NonNegative(radius, nameof(radius));
            Start = Num.NoNegativeZero(start); End = Num.NoNegativeZero(end); Radius = Num.NoNegativeZero(radius);
        }

        void IScalable<Capsule2>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); s.Length(Radius); }
        Capsule2 IScalable<Capsule2>.Rescaled(in Rescale s) => new Capsule2(s.Apply(Start), s.Apply(End), s.Apply(Radius));

        /// <summary>The axis: the segment Start–End.</summary>
        public Segment2 Axis => new Segment2(Start, End);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Capsule2 other) => Start == other.Start && End == other.End && Radius == other.Radius;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Capsule2"/>.</summary>
        public override bool Equals(object? obj) => obj is Capsule2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Capsule2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Start, End, Radius);
        /// <summary>Value equality, as <see cref="Equals(Capsule2)"/>.</summary>
        public static bool operator ==(Capsule2 a, Capsule2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Capsule2)"/>.</summary>
        public static bool operator !=(Capsule2 a, Capsule2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Capsule2 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Capsule2 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }
}
