// Copied from src/ProximityLib/Double/Obb2.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A closed solid oriented rectangle: Center + AxisX*u + AxisY*v with |u|, |v| bounded by HalfExtents, where
    /// AxisY is AxisX turned +90°. <c>default</c> is the axis-aligned point box at the origin.
    /// </summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Obb2 : IEquatable<Obb2>, IFormattable, IScalable<Obb2>
    {
        private readonly double _cos, _sin;
        // default(Obb2) must be valid: without this flag its axis would be zero.
        private readonly bool _hasAxis;
        // Beside the other flag, so the struct does not grow: some stored value is outside the fast path's range.
        private readonly bool _extreme;

        /// <summary>The center.</summary>
        public readonly Vector2D Center;
        /// <summary>The non-negative half-extents along AxisX and AxisY.</summary>
        public readonly Vector2D HalfExtents;

        /// <summary>The first box axis (unit).</summary>
        public Vector2D AxisX { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => _hasAxis ? new Vector2D(_cos, _sin) : Vector2D.UnitX; }
        /// <summary>The second box axis: AxisX turned +90°.</summary>
        public Vector2D AxisY { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => _hasAxis ? new Vector2D(-_sin, _cos) : Vector2D.UnitY; }

        /// <summary>Creates a box from its first axis, of any finite, non-zero length (normalised here); throws <see cref="ArgumentException"/> on non-finite input, a zero axis or negative half-extents.</summary>
        public Obb2(Vector2D center, Vector2D axisX, Vector2D halfExtents)
        {
            Num.Finite(center, nameof(center));
            CheckHalfExtents(halfExtents);
            var x = Obb3.Direction(axisX.To3(), nameof(axisX));
            Center = Num.NoNegativeZero(center); HalfExtents = Num.NoNegativeZero(halfExtents);
            _cos = x.X; _sin = x.Y; _hasAxis = true;
            _extreme = !(Range.Moderate(center) && Range.Moderate(halfExtents));
        }

        /// <summary>Creates a box rotated counter-clockwise by <paramref name="angle"/> radians.</summary>
        public Obb2(Vector2D center, double angle, Vector2D halfExtents)
        {
            Num.Finite(center, nameof(center));
            CheckHalfExtents(halfExtents);
            Num.Finite(angle, nameof(angle));
            Center = Num.NoNegativeZero(center); HalfExtents = Num.NoNegativeZero(halfExtents);
            _cos = Math.Cos(angle); _sin = Math.Sin(angle); _hasAxis = true;
            _extreme = !(Range.Moderate(center) && Range.Moderate(halfExtents));
        }

        private Obb2(in Obb2 frame, Vector2D center, Vector2D halfExtents)
        {
            Center = Num.NoNegativeZero(center); HalfExtents = Num.NoNegativeZero(halfExtents);
            _cos = frame._cos; _sin = frame._sin; _hasAxis = frame._hasAxis;
            _extreme = !(Range.Moderate(center) && Range.Moderate(halfExtents));
        }

        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Obb2>.Measure(ref Rescale s) { s.Point(Center); s.Length(Math.Max(HalfExtents.X, HalfExtents.Y)); }
        Obb2 IScalable<Obb2>.Rescaled(in Rescale s) => new Obb2(this, s.Apply(Center), new Vector2D(s.Apply(HalfExtents.X), s.Apply(HalfExtents.Y)));

        /// <summary>
        /// The paper's form: the box's four corners and its two edge normals (<paramref name="axisX"/>, <paramref name="axisY"/>). The result is the smallest box with
        /// those axes containing every corner, which is the box itself when the corners are a box's corners. The normals
        /// are validated as by <see cref="Obb3"/>'s axes constructor: any length, directions orthogonal within <see cref="Obb3.AxisTolerance"/>.
        /// </summary>
        public static Obb2 FromCorners(ReadOnlySpan<Vector2D> corners, Vector2D axisX, Vector2D axisY)
        {
            if (corners.Length != 4) throw new ArgumentException($"a rectangle has 4 corners (got {corners.Length}).", nameof(corners));
            var axes = new Obb3(default, axisX.To3(), axisY.To3(), Vector3D.UnitZ, default);
            var sum = default(Vector2D);
            for (int i = 0; i < 4; i++)
            {
                var c = Spans.At(corners, i);
                Num.Finite(c, nameof(corners));
                sum += c;
            }
            var center = sum * 0.25;
            var ax = Vector2D.From3(axes.AxisX);
            double hx = 0, hy = 0;
            for (int i = 0; i < 4; i++)
            {
                var d = Spans.At(corners, i) - center;
                hx = Math.Max(hx, Math.Abs(Vector2D.Dot(d, ax)));
                hy = Math.Max(hy, Math.Abs(Vector2D.Cross(ax, d)));
            }
            return new Obb2(center, ax, new Vector2D(hx, hy));
        }

        // Inlined, as Aabb3.ToBox is.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box2 ToBox2()
        {
            var x = AxisX;
            return new Box2(Center, x, new Vector2D(-x.Y, x.X), -HalfExtents, HalfExtents);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box ToBox()
        {
            var x = AxisX;
            return new Box(Center.To3(), new Vector3D(x.X, x.Y, 0), new Vector3D(-x.Y, x.X, 0), Vector3D.UnitZ,
                new Vector3D(-HalfExtents.X, -HalfExtents.Y, 0), new Vector3D(HalfExtents.X, HalfExtents.Y, 0), true);
        }

        private static void CheckHalfExtents(Vector2D h)
        {
            Num.Finite(h, "halfExtents");
            if (h.X < 0 || h.Y < 0)
                throw new ArgumentException($"halfExtents must be non-negative (got {h}).", "halfExtents");
        }

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: Center, half-extents and the stored, normalised AxisX equal under IEEE == (so −0 equals 0): boxes built from the same rotation by different routes (angle, axis, corners) can differ in the last bits of their axis.</summary>
        public bool Equals(Obb2 other) => Center == other.Center && AxisX == other.AxisX && HalfExtents == other.HalfExtents;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Obb2"/>.</summary>
        public override bool Equals(object? obj) => obj is Obb2 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Obb2)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Center, AxisX, HalfExtents);
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
