namespace ProximityLib.Double
{
    /// <summary>A 3D line, unbounded both ways: the points Origin + t·Direction for every real t. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Line3 : System.IEquatable<Line3>, System.IFormattable, IScalable<Line3>
    {
        /// <summary>The point at parameter 0.</summary>
        public readonly Vector3D Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public readonly Vector3D Direction;

        /// <summary>Creates a line; throws <see cref="System.ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Line3(Vector3D origin, Vector3D direction)
        {
            Num.Finite(origin, nameof(origin));
            Direction = Num.Unit(direction, nameof(direction), out _, out _);
            Origin = Num.NoNegativeZero(origin);
        }

        // The slow path's rescaled copy: the direction is a unit vector already and is not a length.
        private Line3(Vector3D origin, Vector3D direction, bool _) { Origin = origin; Direction = direction; }

        void IScalable<Line3>.Measure(ref Rescale s) => s.Point(Origin);
        Line3 IScalable<Line3>.Rescaled(in Rescale s) => new Line3(s.Apply(Origin), Direction, true);

        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector3D PointAt(double t) => Origin + Direction * t;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Line3 other) => Origin == other.Origin && Direction == other.Direction;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Line3"/>.</summary>
        public override bool Equals(object? obj) => obj is Line3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Line3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Origin, Direction);
        /// <summary>Value equality, as <see cref="Equals(Line3)"/>.</summary>
        public static bool operator ==(Line3 a, Line3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Line3)"/>.</summary>
        public static bool operator !=(Line3 a, Line3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Line3 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Line3 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }

    /// <summary>A 2D line, unbounded both ways: the points Origin + t·Direction for every real t. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Line2 : System.IEquatable<Line2>, System.IFormattable, IScalable<Line2>
    {
        /// <summary>The point at parameter 0.</summary>
        public readonly Vector2D Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public readonly Vector2D Direction;

        /// <summary>Creates a line; throws <see cref="System.ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Line2(Vector2D origin, Vector2D direction)
        {
            Num.Finite(origin, nameof(origin));
            Direction = Num.Unit(direction, nameof(direction), out _, out _);
            Origin = Num.NoNegativeZero(origin);
        }

        // The slow path's rescaled copy: the direction is a unit vector already and is not a length.
        private Line2(Vector2D origin, Vector2D direction, bool _) { Origin = origin; Direction = direction; }

        void IScalable<Line2>.Measure(ref Rescale s) => s.Point(Origin);
        Line2 IScalable<Line2>.Rescaled(in Rescale s) => new Line2(s.Apply(Origin), Direction, true);

        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector2D PointAt(double t) => Origin + Direction * t;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Line2 other) => Origin == other.Origin && Direction == other.Direction;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Line2"/>.</summary>
        public override bool Equals(object? obj) => obj is Line2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Line2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Origin, Direction);
        /// <summary>Value equality, as <see cref="Equals(Line2)"/>.</summary>
        public static bool operator ==(Line2 a, Line2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Line2)"/>.</summary>
        public static bool operator !=(Line2 a, Line2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Line2 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Line2 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }

    /// <summary>A 3D ray, the points Origin + t·Direction for t ≥ 0. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Ray3 : System.IEquatable<Ray3>, System.IFormattable, IScalable<Ray3>
    {
        /// <summary>The point at parameter 0.</summary>
        public readonly Vector3D Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public readonly Vector3D Direction;

        /// <summary>Creates a ray; throws <see cref="System.ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Ray3(Vector3D origin, Vector3D direction)
        {
            Num.Finite(origin, nameof(origin));
            Direction = Num.Unit(direction, nameof(direction), out _, out _);
            Origin = Num.NoNegativeZero(origin);
        }

        // The slow path's rescaled copy: the direction is a unit vector already and is not a length.
        private Ray3(Vector3D origin, Vector3D direction, bool _) { Origin = origin; Direction = direction; }

        void IScalable<Ray3>.Measure(ref Rescale s) => s.Point(Origin);
        Ray3 IScalable<Ray3>.Rescaled(in Rescale s) => new Ray3(s.Apply(Origin), Direction, true);

        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector3D PointAt(double t) => Origin + Direction * t;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Ray3 other) => Origin == other.Origin && Direction == other.Direction;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Ray3"/>.</summary>
        public override bool Equals(object? obj) => obj is Ray3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Ray3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Origin, Direction);
        /// <summary>Value equality, as <see cref="Equals(Ray3)"/>.</summary>
        public static bool operator ==(Ray3 a, Ray3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Ray3)"/>.</summary>
        public static bool operator !=(Ray3 a, Ray3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Ray3 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Ray3 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }

    /// <summary>A 2D ray, the points Origin + t·Direction for t ≥ 0. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Ray2 : System.IEquatable<Ray2>, System.IFormattable, IScalable<Ray2>
    {
        /// <summary>The point at parameter 0.</summary>
        public readonly Vector2D Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public readonly Vector2D Direction;

        /// <summary>Creates a ray; throws <see cref="System.ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Ray2(Vector2D origin, Vector2D direction)
        {
            Num.Finite(origin, nameof(origin));
            Direction = Num.Unit(direction, nameof(direction), out _, out _);
            Origin = Num.NoNegativeZero(origin);
        }

        // The slow path's rescaled copy: the direction is a unit vector already and is not a length.
        private Ray2(Vector2D origin, Vector2D direction, bool _) { Origin = origin; Direction = direction; }

        void IScalable<Ray2>.Measure(ref Rescale s) => s.Point(Origin);
        Ray2 IScalable<Ray2>.Rescaled(in Rescale s) => new Ray2(s.Apply(Origin), Direction, true);

        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector2D PointAt(double t) => Origin + Direction * t;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Ray2 other) => Origin == other.Origin && Direction == other.Direction;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Ray2"/>.</summary>
        public override bool Equals(object? obj) => obj is Ray2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Ray2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Origin, Direction);
        /// <summary>Value equality, as <see cref="Equals(Ray2)"/>.</summary>
        public static bool operator ==(Ray2 a, Ray2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Ray2)"/>.</summary>
        public static bool operator !=(Ray2 a, Ray2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Ray2 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Ray2 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }
}
