// Copied from src/ProximityLib/Double/Segment3.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
namespace ProximityLib.Double
{
    /// <summary>A closed 3D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Segment3 : System.IEquatable<Segment3>, System.IFormattable, IScalable<Segment3>
    {
        /// <summary>The endpoint at parameter 0.</summary>
        public readonly Vector3D Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public readonly Vector3D End;

        /// <summary>Creates a segment; throws <see cref="System.ArgumentException"/> on non-finite endpoints.</summary>
        public Segment3(Vector3D start, Vector3D end)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Start = Num.NoNegativeZero(start); End = Num.NoNegativeZero(end);
        }


        void IScalable<Segment3>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); }
        Segment3 IScalable<Segment3>.Rescaled(in Rescale s) => new Segment3(s.Apply(Start), s.Apply(End));

        /// <summary>The point at parameter t (0 = Start, 1 = End), evaluated from the nearer endpoint.</summary>
        public Vector3D PointAt(double t) => t <= 0.5 ? Start + (End - Start) * t : End - (End - Start) * (1 - t);

        /// <summary>The segment's length.</summary>
        public double Length => (End - Start).Length;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Segment3 other) => Start == other.Start && End == other.End;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Segment3"/>.</summary>
        public override bool Equals(object? obj) => obj is Segment3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Segment3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Start, End);
        /// <summary>Value equality, as <see cref="Equals(Segment3)"/>.</summary>
        public static bool operator ==(Segment3 a, Segment3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Segment3)"/>.</summary>
        public static bool operator !=(Segment3 a, Segment3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Segment3 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Segment3 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)} }}";
    }

    /// <summary>A closed 2D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Segment2 : System.IEquatable<Segment2>, System.IFormattable, IScalable<Segment2>
    {
        /// <summary>The endpoint at parameter 0.</summary>
        public readonly Vector2D Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public readonly Vector2D End;

        /// <summary>Creates a segment; throws <see cref="System.ArgumentException"/> on non-finite endpoints.</summary>
        public Segment2(Vector2D start, Vector2D end)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Start = Num.NoNegativeZero(start); End = Num.NoNegativeZero(end);
        }


        void IScalable<Segment2>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); }
        Segment2 IScalable<Segment2>.Rescaled(in Rescale s) => new Segment2(s.Apply(Start), s.Apply(End));

        /// <summary>The point at parameter t (0 = Start, 1 = End), evaluated from the nearer endpoint.</summary>
        public Vector2D PointAt(double t) => t <= 0.5 ? Start + (End - Start) * t : End - (End - Start) * (1 - t);

        /// <summary>The segment's length.</summary>
        public double Length => (End - Start).Length;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Segment2 other) => Start == other.Start && End == other.End;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Segment2"/>.</summary>
        public override bool Equals(object? obj) => obj is Segment2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Segment2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Start, End);
        /// <summary>Value equality, as <see cref="Equals(Segment2)"/>.</summary>
        public static bool operator ==(Segment2 a, Segment2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Segment2)"/>.</summary>
        public static bool operator !=(Segment2 a, Segment2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Segment2 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Segment2 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)} }}";
    }
}
