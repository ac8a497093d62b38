// Copied from src/ProximityLib/Shapes.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using Dbl = ProximityLib.Double;

// The float shapes hold their validated double form, so a float query runs the one double algorithm with no
// conversion or re-validation per call; the public members read back in float.
namespace ProximityLib
{
    /// <summary>A closed 3D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Segment3 : IEquatable<Segment3>, IFormattable
    {
        internal readonly Dbl.Segment3 Inner;
        /// <summary>Creates a segment; throws <see cref="ArgumentException"/> on non-finite endpoints.</summary>
        public Segment3(Vector3 start, Vector3 end) { Inner = new Dbl.Segment3(start, end); }
        /// <summary>The endpoint at parameter 0.</summary>
        public Vector3 Start => (Vector3)Inner.Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public Vector3 End => (Vector3)Inner.End;
        /// <summary>The point at parameter t (0 = Start, 1 = End).</summary>
        public Vector3 PointAt(float t) => (Vector3)Inner.PointAt(t);
        /// <summary>The same segment in double precision.</summary>
        public static implicit operator Dbl.Segment3(Segment3 s) => s.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Segment3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Segment3"/>.</summary>
        public override bool Equals(object? obj) => obj is Segment3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Segment3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Segment3)"/>.</summary>
        public static bool operator ==(Segment3 a, Segment3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Segment3)"/>.</summary>
        public static bool operator !=(Segment3 a, Segment3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Segment3 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Segment3 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)} }}";
    }

    /// <summary>A closed 2D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Segment2 : IEquatable<Segment2>, IFormattable
    {
        internal readonly Dbl.Segment2 Inner;
        /// <summary>Creates a segment; throws <see cref="ArgumentException"/> on non-finite endpoints.</summary>
        public Segment2(Vector2 start, Vector2 end) { Inner = new Dbl.Segment2(start, end); }
        /// <summary>The endpoint at parameter 0.</summary>
        public Vector2 Start => (Vector2)Inner.Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public Vector2 End => (Vector2)Inner.End;
        /// <summary>The point at parameter t (0 = Start, 1 = End).</summary>
        public Vector2 PointAt(float t) => (Vector2)Inner.PointAt(t);
        /// <summary>The same segment in double precision.</summary>
        public static implicit operator Dbl.Segment2(Segment2 s) => s.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Segment2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Segment2"/>.</summary>
        public override bool Equals(object? obj) => obj is Segment2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Segment2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Segment2)"/>.</summary>
        public static bool operator ==(Segment2 a, Segment2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Segment2)"/>.</summary>
        public static bool operator !=(Segment2 a, Segment2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Segment2 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Segment2 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)} }}";
    }

    /// <summary>A closed solid sphere; radius 0 is a point.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Sphere : IEquatable<Sphere>, IFormattable
    {
        internal readonly Dbl.Sphere Inner;
        /// <summary>Creates a sphere; throws <see cref="ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Sphere(Vector3 center, float radius) { Inner = new Dbl.Sphere(center, radius); }
        /// <summary>The center.</summary>
        public Vector3 Center => (Vector3)Inner.Center;
        /// <summary>The radius.</summary>
        public float Radius => (float)Inner.Radius;
        /// <summary>The same sphere in double precision.</summary>
        public static implicit operator Dbl.Sphere(Sphere s) => s.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Sphere other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Sphere"/>.</summary>
        public override bool Equals(object? obj) => obj is Sphere other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Sphere)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Sphere)"/>.</summary>
        public static bool operator ==(Sphere a, Sphere b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Sphere)"/>.</summary>
        public static bool operator !=(Sphere a, Sphere b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Sphere { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Sphere {{ Center = {Formatting.Of(Center, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }

    /// <summary>A closed solid disc (the paper's circle); radius 0 is a point.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Circle : IEquatable<Circle>, IFormattable
    {
        internal readonly Dbl.Circle Inner;
        /// <summary>Creates a circle; throws <see cref="ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Circle(Vector2 center, float radius) { Inner = new Dbl.Circle(center, radius); }
        /// <summary>The center.</summary>
        public Vector2 Center => (Vector2)Inner.Center;
        /// <summary>The radius.</summary>
        public float Radius => (float)Inner.Radius;
        /// <summary>The same circle in double precision.</summary>
        public static implicit operator Dbl.Circle(Circle c) => c.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: every stored field equal under IEEE == (so −0 equals 0).</summary>
        public bool Equals(Circle other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Circle"/>.</summary>
        public override bool Equals(object? obj) => obj is Circle other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Circle)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Circle)"/>.</summary>
        public static bool operator ==(Circle a, Circle b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Circle)"/>.</summary>
        public static bool operator !=(Circle a, Circle b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Circle { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Circle {{ Center = {Formatting.Of(Center, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }

    /// <summary>A closed solid axis-aligned box [Min, Max]; zero extents are allowed.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Aabb3 : IEquatable<Aabb3>, IFormattable
    {
        internal readonly Dbl.Aabb3 Inner;
        private Aabb3(Dbl.Aabb3 inner) { Inner = inner; }
        /// <summary>Creates a box; throws <see cref="ArgumentException"/> on non-finite corners or Min greater than Max on any axis.</summary>
        public Aabb3(Vector3 min, Vector3 max) { Inner = new Dbl.Aabb3(min, max); }
        /// <summary>The paper's form: minimum corner plus length (X), height (Y) and width (Z), all non-negative.</summary>
        public static Aabb3 FromOrigin(Vector3 origin, float length, float height, float width) =>
            new Aabb3(Dbl.Aabb3.FromOrigin(origin, length, height, width));
        /// <summary>A box from its center and non-negative half-extents.</summary>
        public static Aabb3 FromCenter(Vector3 center, Vector3 halfExtents) => new Aabb3(Dbl.Aabb3.FromCenter(center, halfExtents));
        /// <summary>The minimum corner.</summary>
        public Vector3 Min => (Vector3)Inner.Min;
        /// <summary>The maximum corner.</summary>
        public Vector3 Max => (Vector3)Inner.Max;
        /// <summary>The same box in double precision.</summary>
        public static implicit operator Dbl.Aabb3(Aabb3 b) => b.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision corners, which the queries use (IEEE ==, so −0 equals 0): FromOrigin and FromCenter can keep corners between floats, so two boxes that print alike can differ.</summary>
        public bool Equals(Aabb3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Aabb3"/>.</summary>
        public override bool Equals(object? obj) => obj is Aabb3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Aabb3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
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

    /// <summary>A closed solid axis-aligned rectangle [Min, Max]; zero extents are allowed.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Aabb2 : IEquatable<Aabb2>, IFormattable
    {
        internal readonly Dbl.Aabb2 Inner;
        private Aabb2(Dbl.Aabb2 inner) { Inner = inner; }
        /// <summary>Creates a rectangle; throws <see cref="ArgumentException"/> on non-finite corners or Min greater than Max on any axis.</summary>
        public Aabb2(Vector2 min, Vector2 max) { Inner = new Dbl.Aabb2(min, max); }
        /// <summary>The paper's form: minimum corner plus length (X) and height (Y), both non-negative.</summary>
        public static Aabb2 FromOrigin(Vector2 origin, float length, float height) => new Aabb2(Dbl.Aabb2.FromOrigin(origin, length, height));
        /// <summary>A rectangle from its center and non-negative half-extents.</summary>
        public static Aabb2 FromCenter(Vector2 center, Vector2 halfExtents) => new Aabb2(Dbl.Aabb2.FromCenter(center, halfExtents));
        /// <summary>The minimum corner.</summary>
        public Vector2 Min => (Vector2)Inner.Min;
        /// <summary>The maximum corner.</summary>
        public Vector2 Max => (Vector2)Inner.Max;
        /// <summary>The same rectangle in double precision.</summary>
        public static implicit operator Dbl.Aabb2(Aabb2 b) => b.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision corners, which the queries use (IEEE ==, so −0 equals 0): FromOrigin and FromCenter can keep corners between floats, so two boxes that print alike can differ.</summary>
        public bool Equals(Aabb2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Aabb2"/>.</summary>
        public override bool Equals(object? obj) => obj is Aabb2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Aabb2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
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

    /// <summary>A closed solid oriented box; see <see cref="Dbl.Obb3"/>. Axes are kept orthonormal in double.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Obb3 : IEquatable<Obb3>, IFormattable
    {
        internal readonly Dbl.Obb3 Inner;
        private Obb3(Dbl.Obb3 inner) { Inner = inner; }
        /// <summary>Creates a box rotated by a quaternion (normalised here); throws <see cref="ArgumentException"/> naming <paramref name="rotation"/> when it is zero or not finite.</summary>
        public Obb3(Vector3 center, Quaternion rotation, Vector3 halfExtents) { Inner = new Dbl.Obb3(center, rotation, halfExtents); }
        /// <summary>Creates a box from three axes of any finite, non-zero length whose directions are orthogonal within <see cref="Dbl.Obb3.AxisTolerance"/>; re-orthonormalised in double.</summary>
        public Obb3(Vector3 center, Vector3 axisX, Vector3 axisY, Vector3 axisZ, Vector3 halfExtents)
        {
            Inner = new Dbl.Obb3(center, axisX, axisY, axisZ, halfExtents);
        }
        /// <summary>The paper's form: eight corners and the three face normals; the smallest such box containing the corners.</summary>
        public static Obb3 FromCorners(ReadOnlySpan<Vector3> corners, Vector3 axisX, Vector3 axisY, Vector3 axisZ)
        {
            if (corners.Length != 8) throw new ArgumentException($"a box has 8 corners (got {corners.Length}).", nameof(corners));
            Span<Dbl.Vector3D> wide = stackalloc Dbl.Vector3D[8];
            for (int i = 0; i < 8; i++) wide[i] = Spans.At(corners, i);
            return new Obb3(Dbl.Obb3.FromCorners(wide, axisX, axisY, axisZ));
        }
        /// <summary>The center.</summary>
        public Vector3 Center => (Vector3)Inner.Center;
        /// <summary>The first box axis.</summary>
        public Vector3 AxisX => (Vector3)Inner.AxisX;
        /// <summary>The second box axis.</summary>
        public Vector3 AxisY => (Vector3)Inner.AxisY;
        /// <summary>The third box axis.</summary>
        public Vector3 AxisZ => (Vector3)Inner.AxisZ;
        /// <summary>The half-extents along the three axes.</summary>
        public Vector3 HalfExtents => (Vector3)Inner.HalfExtents;
        /// <summary>The same box in double precision.</summary>
        public static implicit operator Dbl.Obb3(Obb3 b) => b.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision box, which the queries use (see <see cref="Dbl.Obb3.Equals(Dbl.Obb3)"/>): its axes can differ below float precision, so two boxes that print alike can differ.</summary>
        public bool Equals(Obb3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Obb3"/>.</summary>
        public override bool Equals(object? obj) => obj is Obb3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Obb3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Obb3)"/>.</summary>
        public static bool operator ==(Obb3 a, Obb3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Obb3)"/>.</summary>
        public static bool operator !=(Obb3 a, Obb3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Obb3 { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Obb3 {{ Center = {Formatting.Of(Center, format, formatProvider)}, AxisX = {Formatting.Of(AxisX, format, formatProvider)}, AxisY = {Formatting.Of(AxisY, format, formatProvider)}, AxisZ = {Formatting.Of(AxisZ, format, formatProvider)}, HalfExtents = {Formatting.Of(HalfExtents, format, formatProvider)} }}";
    }

    /// <summary>A closed solid oriented rectangle; see <see cref="Dbl.Obb2"/>.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Obb2 : IEquatable<Obb2>, IFormattable
    {
        internal readonly Dbl.Obb2 Inner;
        private Obb2(Dbl.Obb2 inner) { Inner = inner; }
        /// <summary>Creates a box from its first axis, of any finite, non-zero length (normalised here).</summary>
        public Obb2(Vector2 center, Vector2 axisX, Vector2 halfExtents) { Inner = new Dbl.Obb2(center, axisX, halfExtents); }
        /// <summary>Creates a box rotated counter-clockwise by <paramref name="angle"/> radians.</summary>
        public Obb2(Vector2 center, float angle, Vector2 halfExtents) { Inner = new Dbl.Obb2(center, (double)angle, halfExtents); }
        /// <summary>The paper's form: four corners and the two edge normals; the smallest such box containing the corners.</summary>
        public static Obb2 FromCorners(ReadOnlySpan<Vector2> corners, Vector2 axisX, Vector2 axisY)
        {
            if (corners.Length != 4) throw new ArgumentException($"a rectangle has 4 corners (got {corners.Length}).", nameof(corners));
            Span<Dbl.Vector2D> wide = stackalloc Dbl.Vector2D[4];
            for (int i = 0; i < 4; i++) wide[i] = Spans.At(corners, i);
            return new Obb2(Dbl.Obb2.FromCorners(wide, axisX, axisY));
        }
        /// <summary>The center.</summary>
        public Vector2 Center => (Vector2)Inner.Center;
        /// <summary>The first box axis.</summary>
        public Vector2 AxisX => (Vector2)Inner.AxisX;
        /// <summary>The second box axis (AxisX turned +90°).</summary>
        public Vector2 AxisY => (Vector2)Inner.AxisY;
        /// <summary>The half-extents along the two axes.</summary>
        public Vector2 HalfExtents => (Vector2)Inner.HalfExtents;
        /// <summary>The same box in double precision.</summary>
        public static implicit operator Dbl.Obb2(Obb2 b) => b.Inner;

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision box, which the queries use (see <see cref="Dbl.Obb2.Equals(Dbl.Obb2)"/>): its axes can differ below float precision, so two boxes that print alike can differ.</summary>
        public bool Equals(Obb2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Obb2"/>.</summary>
        public override bool Equals(object? obj) => obj is Obb2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Obb2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Obb2)"/>.</summary>
        public static bool operator ==(Obb2 a, Obb2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Obb2)"/>.</summary>
        public static bool operator !=(Obb2 a, Obb2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Obb2 { Center = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Obb2 {{ Center = {Formatting.Of(Center, format, formatProvider)}, AxisX = {Formatting.Of(AxisX, format, formatProvider)}, HalfExtents = {Formatting.Of(HalfExtents, format, formatProvider)} }}";
    }
}
