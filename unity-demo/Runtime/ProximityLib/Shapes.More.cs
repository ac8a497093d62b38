// Copied from src/ProximityLib/Shapes.More.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using Dbl = ProximityLib.Double;

// The float forms of the lines, rays, capsules, half-spaces and triangles: as in Shapes.cs, each holds its validated
// double form, so a query runs the double algorithm with no conversion or re-validation per call.
namespace ProximityLib
{
    /// <summary>A 3D line, unbounded both ways: the points Origin + t·Direction for every real t. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Line3 : IEquatable<Line3>, IFormattable
    {
        internal readonly Dbl.Line3 Inner;
        /// <summary>Creates a line; throws <see cref="ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Line3(Vector3 origin, Vector3 direction) { Inner = new Dbl.Line3(origin, direction); }
        /// <summary>The point at parameter 0.</summary>
        public Vector3 Origin => (Vector3)Inner.Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public Vector3 Direction => (Vector3)Inner.Direction;
        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector3 PointAt(float t) => (Vector3)Inner.PointAt(t);
        /// <summary>The same line in double precision.</summary>
        public static implicit operator Dbl.Line3(Line3 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Line3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Line3"/>.</summary>
        public override bool Equals(object? obj) => obj is Line3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Line3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Line3)"/>.</summary>
        public static bool operator ==(Line3 a, Line3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Line3)"/>.</summary>
        public static bool operator !=(Line3 a, Line3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Line3 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Line3 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }


    /// <summary>A 2D line, unbounded both ways: the points Origin + t·Direction for every real t. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Line2 : IEquatable<Line2>, IFormattable
    {
        internal readonly Dbl.Line2 Inner;
        /// <summary>Creates a line; throws <see cref="ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Line2(Vector2 origin, Vector2 direction) { Inner = new Dbl.Line2(origin, direction); }
        /// <summary>The point at parameter 0.</summary>
        public Vector2 Origin => (Vector2)Inner.Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public Vector2 Direction => (Vector2)Inner.Direction;
        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector2 PointAt(float t) => (Vector2)Inner.PointAt(t);
        /// <summary>The same line in double precision.</summary>
        public static implicit operator Dbl.Line2(Line2 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Line2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Line2"/>.</summary>
        public override bool Equals(object? obj) => obj is Line2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Line2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Line2)"/>.</summary>
        public static bool operator ==(Line2 a, Line2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Line2)"/>.</summary>
        public static bool operator !=(Line2 a, Line2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Line2 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Line2 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }


    /// <summary>A 3D ray, the points Origin + t·Direction for t ≥ 0. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Ray3 : IEquatable<Ray3>, IFormattable
    {
        internal readonly Dbl.Ray3 Inner;
        /// <summary>Creates a ray; throws <see cref="ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Ray3(Vector3 origin, Vector3 direction) { Inner = new Dbl.Ray3(origin, direction); }
        /// <summary>The point at parameter 0.</summary>
        public Vector3 Origin => (Vector3)Inner.Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public Vector3 Direction => (Vector3)Inner.Direction;
        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector3 PointAt(float t) => (Vector3)Inner.PointAt(t);
        /// <summary>The same ray in double precision.</summary>
        public static implicit operator Dbl.Ray3(Ray3 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Ray3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Ray3"/>.</summary>
        public override bool Equals(object? obj) => obj is Ray3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Ray3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Ray3)"/>.</summary>
        public static bool operator ==(Ray3 a, Ray3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Ray3)"/>.</summary>
        public static bool operator !=(Ray3 a, Ray3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Ray3 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Ray3 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }


    /// <summary>A 2D ray, the points Origin + t·Direction for t ≥ 0. Direction is normalised at construction, so t is the distance from Origin (to rounding).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Ray2 : IEquatable<Ray2>, IFormattable
    {
        internal readonly Dbl.Ray2 Inner;
        /// <summary>Creates a ray; throws <see cref="ArgumentException"/> on a non-finite origin or a zero or non-finite direction.</summary>
        public Ray2(Vector2 origin, Vector2 direction) { Inner = new Dbl.Ray2(origin, direction); }
        /// <summary>The point at parameter 0.</summary>
        public Vector2 Origin => (Vector2)Inner.Origin;
        /// <summary>The unit direction (the given direction normalised).</summary>
        public Vector2 Direction => (Vector2)Inner.Direction;
        /// <summary>The point at parameter t: Origin + t·Direction.</summary>
        public Vector2 PointAt(float t) => (Vector2)Inner.PointAt(t);
        /// <summary>The same ray in double precision.</summary>
        public static implicit operator Dbl.Ray2(Ray2 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Ray2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Ray2"/>.</summary>
        public override bool Equals(object? obj) => obj is Ray2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Ray2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Ray2)"/>.</summary>
        public static bool operator ==(Ray2 a, Ray2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Ray2)"/>.</summary>
        public static bool operator !=(Ray2 a, Ray2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Ray2 { Origin = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Ray2 {{ Origin = {Formatting.Of(Origin, format, formatProvider)}, Direction = {Formatting.Of(Direction, format, formatProvider)} }}";
    }


    /// <summary>A closed solid 3D capsule: the points within Radius of the segment Start–End (a sphere when the segment has zero length, the segment when Radius is 0).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Capsule3 : IEquatable<Capsule3>, IFormattable
    {
        internal readonly Dbl.Capsule3 Inner;
        /// <summary>Creates a capsule; throws <see cref="ArgumentException"/> on non-finite endpoints or a negative or non-finite radius.</summary>
        public Capsule3(Vector3 start, Vector3 end, float radius) { Inner = new Dbl.Capsule3(start, end, radius); }
        /// <summary>The axis endpoint at parameter 0.</summary>
        public Vector3 Start => (Vector3)Inner.Start;
        /// <summary>The axis endpoint at parameter 1.</summary>
        public Vector3 End => (Vector3)Inner.End;
        /// <summary>The radius.</summary>
        public float Radius => (float)Inner.Radius;
        /// <summary>The same capsule in double precision.</summary>
        public static implicit operator Dbl.Capsule3(Capsule3 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Capsule3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Capsule3"/>.</summary>
        public override bool Equals(object? obj) => obj is Capsule3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Capsule3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Capsule3)"/>.</summary>
        public static bool operator ==(Capsule3 a, Capsule3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Capsule3)"/>.</summary>
        public static bool operator !=(Capsule3 a, Capsule3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Capsule3 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Capsule3 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }


    /// <summary>A closed solid 2D capsule (a stadium): the points within Radius of the segment Start–End (a circle when the segment has zero length, the segment when Radius is 0).</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Capsule2 : IEquatable<Capsule2>, IFormattable
    {
        internal readonly Dbl.Capsule2 Inner;
        /// <summary>Creates a capsule; throws <see cref="ArgumentException"/> on non-finite endpoints or a negative or non-finite radius.</summary>
        public Capsule2(Vector2 start, Vector2 end, float radius) { Inner = new Dbl.Capsule2(start, end, radius); }
        /// <summary>The axis endpoint at parameter 0.</summary>
        public Vector2 Start => (Vector2)Inner.Start;
        /// <summary>The axis endpoint at parameter 1.</summary>
        public Vector2 End => (Vector2)Inner.End;
        /// <summary>The radius.</summary>
        public float Radius => (float)Inner.Radius;
        /// <summary>The same capsule in double precision.</summary>
        public static implicit operator Dbl.Capsule2(Capsule2 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Capsule2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Capsule2"/>.</summary>
        public override bool Equals(object? obj) => obj is Capsule2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Capsule2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Capsule2)"/>.</summary>
        public static bool operator ==(Capsule2 a, Capsule2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Capsule2)"/>.</summary>
        public static bool operator !=(Capsule2 a, Capsule2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Capsule2 { Start = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Capsule2 {{ Start = {Formatting.Of(Start, format, formatProvider)}, End = {Formatting.Of(End, format, formatProvider)}, Radius = {Formatting.Of(Radius, format, formatProvider)} }}";
    }


    /// <summary>A 3D triangle: the planar, two-sided set of convex combinations of A, B and C; not a solid (nothing is inside it). Degenerate triangles (collinear or coincident vertices) are valid and answered as the segment or point they are.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Triangle3 : IEquatable<Triangle3>, IFormattable
    {
        internal readonly Dbl.Triangle3 Inner;
        /// <summary>Creates a triangle; throws <see cref="ArgumentException"/> on a non-finite vertex.</summary>
        public Triangle3(Vector3 a, Vector3 b, Vector3 c) { Inner = new Dbl.Triangle3(a, b, c); }
        /// <summary>The first vertex.</summary>
        public Vector3 A => (Vector3)Inner.A;
        /// <summary>The second vertex.</summary>
        public Vector3 B => (Vector3)Inner.B;
        /// <summary>The third vertex.</summary>
        public Vector3 C => (Vector3)Inner.C;
        /// <summary>The same triangle in double precision.</summary>
        public static implicit operator Dbl.Triangle3(Triangle3 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Triangle3 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Triangle3"/>.</summary>
        public override bool Equals(object? obj) => obj is Triangle3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Triangle3)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Triangle3)"/>.</summary>
        public static bool operator ==(Triangle3 a, Triangle3 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Triangle3)"/>.</summary>
        public static bool operator !=(Triangle3 a, Triangle3 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Triangle3 { A = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Triangle3 {{ A = {Formatting.Of(A, format, formatProvider)}, B = {Formatting.Of(B, format, formatProvider)}, C = {Formatting.Of(C, format, formatProvider)} }}";
    }


    /// <summary>A closed solid 2D triangle: the convex hull of A, B and C. Degenerate triangles (collinear or coincident vertices) are valid and answered as the segment or point they are.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Triangle2 : IEquatable<Triangle2>, IFormattable
    {
        internal readonly Dbl.Triangle2 Inner;
        /// <summary>Creates a triangle; throws <see cref="ArgumentException"/> on a non-finite vertex.</summary>
        public Triangle2(Vector2 a, Vector2 b, Vector2 c) { Inner = new Dbl.Triangle2(a, b, c); }
        /// <summary>The first vertex.</summary>
        public Vector2 A => (Vector2)Inner.A;
        /// <summary>The second vertex.</summary>
        public Vector2 B => (Vector2)Inner.B;
        /// <summary>The third vertex.</summary>
        public Vector2 C => (Vector2)Inner.C;
        /// <summary>The same triangle in double precision.</summary>
        public static implicit operator Dbl.Triangle2(Triangle2 s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(Triangle2 other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Triangle2"/>.</summary>
        public override bool Equals(object? obj) => obj is Triangle2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Triangle2)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(Triangle2)"/>.</summary>
        public static bool operator ==(Triangle2 a, Triangle2 b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(Triangle2)"/>.</summary>
        public static bool operator !=(Triangle2 a, Triangle2 b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>Triangle2 { A = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"Triangle2 {{ A = {Formatting.Of(A, format, formatProvider)}, B = {Formatting.Of(B, format, formatProvider)}, C = {Formatting.Of(C, format, formatProvider)} }}";
    }


    /// <summary>A closed solid 3D half-space: the points x with Normal·x ≤ Offset (the solid below a plane whose outward normal is Normal). A point's signed distance is Normal·(x − Point), negative inside.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct HalfSpace : IEquatable<HalfSpace>, IFormattable
    {
        internal readonly Dbl.HalfSpace Inner;
        private HalfSpace(Dbl.HalfSpace inner) { Inner = inner; }
        /// <summary>The solid normal·x ≤ offset, the normal normalised and the offset divided by its length (computed in double); throws <see cref="ArgumentException"/> on non-finite input or a zero normal.</summary>
        public HalfSpace(Vector3 normal, float offset) { Inner = new Dbl.HalfSpace(normal, offset); }
        /// <summary>The solid behind the boundary through <paramref name="point"/> with outward normal <paramref name="normal"/> (normalised, in double).</summary>
        public static HalfSpace FromPointNormal(Vector3 point, Vector3 normal) => new HalfSpace(Dbl.HalfSpace.FromPointNormal(point, normal));
        /// <summary>The unit outward normal.</summary>
        public Vector3 Normal => (Vector3)Inner.Normal;
        /// <summary>A point on the boundary (see the double form's <c>Point</c>).</summary>
        public Vector3 Point => (Vector3)Inner.Point;
        /// <summary>The signed distance of the boundary from the origin along Normal.</summary>
        public float Offset => (float)Inner.Offset;
        /// <summary>The signed distance of a point: Normal·(point − Point) (negative inside), computed in double.</summary>
        public float SignedDistance(Vector3 point) => (float)Inner.SignedDistance(point);
        /// <summary>The same half-space in double precision.</summary>
        public static implicit operator Dbl.HalfSpace(HalfSpace s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(HalfSpace other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="HalfSpace"/>.</summary>
        public override bool Equals(object? obj) => obj is HalfSpace other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(HalfSpace)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(HalfSpace)"/>.</summary>
        public static bool operator ==(HalfSpace a, HalfSpace b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(HalfSpace)"/>.</summary>
        public static bool operator !=(HalfSpace a, HalfSpace b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>HalfSpace { Normal = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"HalfSpace {{ Normal = {Formatting.Of(Normal, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)} }}";
    }


    /// <summary>A closed solid 2D half-plane: the points x with Normal·x ≤ Offset (the solid behind a line whose outward normal is Normal). A point's signed distance is Normal·(x − Point), negative inside.</summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct HalfPlane : IEquatable<HalfPlane>, IFormattable
    {
        internal readonly Dbl.HalfPlane Inner;
        private HalfPlane(Dbl.HalfPlane inner) { Inner = inner; }
        /// <summary>The solid normal·x ≤ offset, the normal normalised and the offset divided by its length (computed in double); throws <see cref="ArgumentException"/> on non-finite input or a zero normal.</summary>
        public HalfPlane(Vector2 normal, float offset) { Inner = new Dbl.HalfPlane(normal, offset); }
        /// <summary>The solid behind the boundary through <paramref name="point"/> with outward normal <paramref name="normal"/> (normalised, in double).</summary>
        public static HalfPlane FromPointNormal(Vector2 point, Vector2 normal) => new HalfPlane(Dbl.HalfPlane.FromPointNormal(point, normal));
        /// <summary>The unit outward normal.</summary>
        public Vector2 Normal => (Vector2)Inner.Normal;
        /// <summary>A point on the boundary (see the double form's <c>Point</c>).</summary>
        public Vector2 Point => (Vector2)Inner.Point;
        /// <summary>The signed distance of the boundary from the origin along Normal.</summary>
        public float Offset => (float)Inner.Offset;
        /// <summary>The signed distance of a point: Normal·(point − Point) (negative inside), computed in double.</summary>
        public float SignedDistance(Vector2 point) => (float)Inner.SignedDistance(point);
        /// <summary>The same half-space in double precision.</summary>
        public static implicit operator Dbl.HalfPlane(HalfPlane s) => s.Inner;
        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality of the stored double-precision fields, which the queries use (IEEE ==, so −0 equals 0).</summary>
        public bool Equals(HalfPlane other) => Inner.Equals(other.Inner);
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="HalfPlane"/>.</summary>
        public override bool Equals(object? obj) => obj is HalfPlane other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(HalfPlane)"/>.</summary>
        public override int GetHashCode() => Inner.GetHashCode();
        /// <summary>Value equality, as <see cref="Equals(HalfPlane)"/>.</summary>
        public static bool operator ==(HalfPlane a, HalfPlane b) => a.Equals(b);
        /// <summary>Value inequality, as not <see cref="Equals(HalfPlane)"/>.</summary>
        public static bool operator !=(HalfPlane a, HalfPlane b) => !a.Equals(b);
        /// <summary>The shape as text in the invariant culture with round-trip numbers, e.g. <c>HalfPlane { Normal = …, … }</c>.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>The shape as text, each number in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null).</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) =>
            $"HalfPlane {{ Normal = {Formatting.Of(Normal, format, formatProvider)}, Point = {Formatting.Of(Point, format, formatProvider)} }}";
    }


}
