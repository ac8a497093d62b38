namespace ProximityLib.Double
{
    /// <summary>A closed solid 3D half-space: the points x with Normal·x ≤ Offset (the solid below a plane whose outward normal is Normal). A point's signed distance is Normal·(x − Point), negative inside.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct HalfSpace : System.IEquatable<HalfSpace>, System.IFormattable, IScalable<HalfSpace>
    {
        /// <summary>The unit outward normal (the given normal normalised).</summary>
        public readonly Vector3D Normal;
        /// <summary>A point on the boundary: the one given to <see cref="FromPointNormal"/>, else Normal·Offset.</summary>
        public readonly Vector3D Point;

        /// <summary>
        /// The solid normal·x ≤ offset for any finite non-zero normal: the normal is normalised and the offset divided by
        /// its length; the boundary is stored as its point nearest the origin (rounded once per coordinate). Throws
        /// <see cref="System.ArgumentException"/> on a zero or non-finite normal, a non-finite offset, or a boundary beyond
        /// the double range.
        /// </summary>
        public HalfSpace(Vector3D normal, double offset)
        {
            Num.Finite(offset, nameof(offset));
            Normal = Num.Unit(normal, nameof(normal), out double k, out double l);
            Point = Num.NoNegativeZero(Normal * (offset * k / l));
            Num.Finite(Point, nameof(offset));
        }

        /// <summary>The solid behind the boundary through <paramref name="point"/> (stored exactly) with outward normal <paramref name="normal"/> (normalised); throws <see cref="System.ArgumentException"/> on non-finite input or a zero normal.</summary>
        public static HalfSpace FromPointNormal(Vector3D point, Vector3D normal)
        {
            Num.Finite(point, nameof(point));
            return new HalfSpace(Num.Unit(normal, nameof(normal), out _, out _), Num.NoNegativeZero(point), true);
        }

        // Queries measure from the stored boundary point, so their rounding is at the scale of the configuration around
        // it, not of the boundary's distance from the origin.
        private HalfSpace(Vector3D unitNormal, Vector3D point, bool _) { Normal = unitNormal; Point = point; }

        void IScalable<HalfSpace>.Measure(ref Rescale s) => s.Point(Point);
        HalfSpace IScalable<HalfSpace>.Rescaled(in Rescale s) => new HalfSpace(Normal, s.Apply(Point), true);

        /// <summary>The signed distance of the boundary from the origin along Normal: Normal·Point.</summary>
        public double Offset => Vector3D.Dot(Normal, Point);

        /// <summary>The signed distance of a point: Normal·(point − Point) (negative inside).</summary>
        public double SignedDistance(Vector3D point) => Vector3D.Dot(Normal, point - Point);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(HalfSpace other) => Normal == other.Normal && Point == other.Point;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="HalfSpace"/>.</summary>
        public override bool Equals(object? obj) => obj is HalfSpace other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(HalfSpace)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Normal, Point);
        /// <summary>Value equality, as <see cref="Equals(HalfSpace)"/>.</summary>
        public static bool operator ==(HalfSpace a, HalfSpace b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(HalfSpace)"/>.</summary>
        public static bool operator !=(HalfSpace a, HalfSpace b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>HalfSpace { Normal = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"HalfSpace {{ Normal = {Formatting.Of(Normal, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)} }}";
    }

    /// <summary>A closed solid 2D half-plane: the points x with Normal·x ≤ Offset (the solid behind a line whose outward normal is Normal). A point's signed distance is Normal·(x − Point), negative inside.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct HalfPlane : System.IEquatable<HalfPlane>, System.IFormattable, IScalable<HalfPlane>
    {
        /// <summary>The unit outward normal (the given normal normalised).</summary>
        public readonly Vector2D Normal;
        /// <summary>A point on the boundary: the one given to <see cref="FromPointNormal"/>, else Normal·Offset.</summary>
        public readonly Vector2D Point;

        /// <summary>
        /// The solid normal·x ≤ offset for any finite non-zero normal: the normal is normalised and the offset divided by
        /// its length; the boundary is stored as its point nearest the origin (rounded once per coordinate). Throws
        /// <see cref="System.ArgumentException"/> on a zero or non-finite normal, a non-finite offset, or a boundary beyond
        /// the double range.
        /// </summary>
        public HalfPlane(Vector2D normal, double offset)
        {
            Num.Finite(offset, nameof(offset));
            Normal = Num.Unit(normal, nameof(normal), out double k, out double l);
            Point = Num.NoNegativeZero(Normal * (offset * k / l));
            Num.Finite(Point, nameof(offset));
        }

        /// <summary>The solid behind the boundary through <paramref name="point"/> (stored exactly) with outward normal <paramref name="normal"/> (normalised); throws <see cref="System.ArgumentException"/> on non-finite input or a zero normal.</summary>
        public static HalfPlane FromPointNormal(Vector2D point, Vector2D normal)
        {
            Num.Finite(point, nameof(point));
            return new HalfPlane(Num.Unit(normal, nameof(normal), out _, out _), Num.NoNegativeZero(point), true);
        }

        // Queries measure from the stored boundary point, so their rounding is at the scale of the configuration around
        // it, not of the boundary's distance from the origin.
        private HalfPlane(Vector2D unitNormal, Vector2D point, bool _) { Normal = unitNormal; Point = point; }

        void IScalable<HalfPlane>.Measure(ref Rescale s) => s.Point(Point);
        HalfPlane IScalable<HalfPlane>.Rescaled(in Rescale s) => new HalfPlane(Normal, s.Apply(Point), true);

        /// <summary>The signed distance of the boundary from the origin along Normal: Normal·Point.</summary>
        public double Offset => Vector2D.Dot(Normal, Point);

        /// <summary>The signed distance of a point: Normal·(point − Point) (negative inside).</summary>
        public double SignedDistance(Vector2D point) => Vector2D.Dot(Normal, point - Point);

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(HalfPlane other) => Normal == other.Normal && Point == other.Point;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="HalfPlane"/>.</summary>
        public override bool Equals(object? obj) => obj is HalfPlane other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(HalfPlane)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(Normal, Point);
        /// <summary>Value equality, as <see cref="Equals(HalfPlane)"/>.</summary>
        public static bool operator ==(HalfPlane a, HalfPlane b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(HalfPlane)"/>.</summary>
        public static bool operator !=(HalfPlane a, HalfPlane b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>HalfPlane { Normal = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"HalfPlane {{ Normal = {Formatting.Of(Normal, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)} }}";
    }
}
