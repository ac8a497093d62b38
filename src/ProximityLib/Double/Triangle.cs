namespace ProximityLib.Double
{
    /// <summary>A 3D triangle: the planar, two-sided set of convex combinations of A, B and C; not a solid (nothing is inside it). Degenerate triangles (collinear or coincident vertices) are valid and answered as the segment or point they are.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Triangle3 : System.IEquatable<Triangle3>, System.IFormattable, IScalable<Triangle3>
    {
        /// <summary>The first vertex.</summary>
        public readonly Vector3D A;
        /// <summary>The second vertex.</summary>
        public readonly Vector3D B;
        /// <summary>The third vertex.</summary>
        public readonly Vector3D C;

        /// <summary>Creates a triangle; throws <see cref="System.ArgumentException"/> on a non-finite vertex.</summary>
        public Triangle3(Vector3D a, Vector3D b, Vector3D c)
        {
            Num.Finite(a, nameof(a));
            Num.Finite(b, nameof(b));
            Num.Finite(c, nameof(c));
            A = Num.NoNegativeZero(a); B = Num.NoNegativeZero(b); C = Num.NoNegativeZero(c);
        }

        void IScalable<Triangle3>.Measure(ref Rescale s) { s.Point(A); s.Point(B); s.Point(C); }
        Triangle3 IScalable<Triangle3>.Rescaled(in Rescale s) => new Triangle3(s.Apply(A), s.Apply(B), s.Apply(C));

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Triangle3 other) => A == other.A && B == other.B && C == other.C;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Triangle3"/>.</summary>
        public override bool Equals(object? obj) => obj is Triangle3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Triangle3)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(A, B, C);
        /// <summary>Value equality, as <see cref="Equals(Triangle3)"/>.</summary>
        public static bool operator ==(Triangle3 a, Triangle3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Triangle3)"/>.</summary>
        public static bool operator !=(Triangle3 a, Triangle3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Triangle3 { A = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Triangle3 {{ A = {Formatting.Of(A, format, formatProvider)}, B = {Formatting.Of(B, format, formatProvider)}, C = {Formatting.Of(C, format, formatProvider)} }}";
    }

    /// <summary>A closed solid 2D triangle: the convex hull of A, B and C. Degenerate triangles (collinear or coincident vertices) are valid and answered as the segment or point they are.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Triangle2 : System.IEquatable<Triangle2>, System.IFormattable, IScalable<Triangle2>
    {
        /// <summary>The first vertex.</summary>
        public readonly Vector2D A;
        /// <summary>The second vertex.</summary>
        public readonly Vector2D B;
        /// <summary>The third vertex.</summary>
        public readonly Vector2D C;

        /// <summary>Creates a triangle; throws <see cref="System.ArgumentException"/> on a non-finite vertex.</summary>
        public Triangle2(Vector2D a, Vector2D b, Vector2D c)
        {
            Num.Finite(a, nameof(a));
            Num.Finite(b, nameof(b));
            Num.Finite(c, nameof(c));
            A = Num.NoNegativeZero(a); B = Num.NoNegativeZero(b); C = Num.NoNegativeZero(c);
        }

        void IScalable<Triangle2>.Measure(ref Rescale s) { s.Point(A); s.Point(B); s.Point(C); }
        Triangle2 IScalable<Triangle2>.Rescaled(in Rescale s) => new Triangle2(s.Apply(A), s.Apply(B), s.Apply(C));

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Triangle2 other) => A == other.A && B == other.B && C == other.C;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Triangle2"/>.</summary>
        public override bool Equals(object? obj) => obj is Triangle2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Triangle2)"/>.</summary>
        public override int GetHashCode() => System.HashCode.Combine(A, B, C);
        /// <summary>Value equality, as <see cref="Equals(Triangle2)"/>.</summary>
        public static bool operator ==(Triangle2 a, Triangle2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Triangle2)"/>.</summary>
        public static bool operator !=(Triangle2 a, Triangle2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Triangle2 { A = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, System.IFormatProvider? formatProvider) =>
            $"Triangle2 {{ A = {Formatting.Of(A, format, formatProvider)}, B = {Formatting.Of(B, format, formatProvider)}, C = {Formatting.Of(C, format, formatProvider)} }}";
    }
}
