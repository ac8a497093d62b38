namespace ProximityLib.Double
{
    /// <summary>A closed solid sphere; radius 0 is a point.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Sphere : System.IEquatable<Sphere>, System.IFormattable, IScalable<Sphere>
    {
        /// <summary>The center.</summary>
        public readonly Vector3D Center;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a sphere; throws <see cref="System.ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Sphere(Vector3D center, double radius)
        {
            Num.Finite(center, nameof(center));
            Num.NonNegative(radius, nameof(radius));
            Center = Num.NoNegativeZero(center); Radius = Num.NoNegativeZero(radius);
        }


        void IScalable<Sphere>.Measure(ref Rescale s) { s.Point(Center); s.Length(Radius); }
        Sphere IScalable<Sphere>.Rescaled(in Rescale s) => new Sphere(s.Apply(Center), s.Apply(Radius));

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Sphere other) => Center == other.Center && Radius == other.Radius;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Sphere"/>.</summary>
        public override bool Equals(object? obj) => obj is Sphere other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Sphere)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Center, Radius);
        /// <summary>Value equality, as <see cref="Equals(Sphere)"/>.</summary>
        public static bool operator ==(Sphere a, Sphere b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Sphere)"/>.</summary>
        public static bool operator !=(Sphere a, Sphere b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Sphere { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Sphere {{ Center = {Formatting.Of(Center, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }

    /// <summary>A closed solid disc (the paper's circle); radius 0 is a point.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Circle : System.IEquatable<Circle>, System.IFormattable, IScalable<Circle>
    {
        /// <summary>The center.</summary>
        public readonly Vector2D Center;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a circle; throws <see cref="System.ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Circle(Vector2D center, double radius)
        {
            Num.Finite(center, nameof(center));
            Num.NonNegative(radius, nameof(radius));
            Center = Num.NoNegativeZero(center); Radius = Num.NoNegativeZero(radius);
        }


        void IScalable<Circle>.Measure(ref Rescale s) { s.Point(Center); s.Length(Radius); }
        Circle IScalable<Circle>.Rescaled(in Rescale s) => new Circle(s.Apply(Center), s.Apply(Radius));

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Circle other) => Center == other.Center && Radius == other.Radius;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Circle"/>.</summary>
        public override bool Equals(object? obj) => obj is Circle other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Circle)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Center, Radius);
        /// <summary>Value equality, as <see cref="Equals(Circle)"/>.</summary>
        public static bool operator ==(Circle a, Circle b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Circle)"/>.</summary>
        public static bool operator !=(Circle a, Circle b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Circle { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Circle {{ Center = {Formatting.Of(Center, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }
}
