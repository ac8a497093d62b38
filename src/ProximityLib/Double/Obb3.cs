using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A closed solid oriented box: Center + AxisX*u + AxisY*v + AxisZ*w with |u|, |v|, |w| bounded by HalfExtents.
    /// Axes are stored orthonormal to double precision (given axes are normalised, their directions checked against
    /// <see cref="AxisTolerance"/>, then re-orthonormalised); <c>default</c> is the axis-aligned point box at the origin.
    /// </summary>
    [System.Diagnostics.DebuggerDisplay("{ToString(),nq}")]
    public readonly struct Obb3 : IEquatable<Obb3>, IFormattable, IScalable<Obb3>
    {
        /// <summary>How far the directions of given axes may be from orthogonal: |â·b̂| at most this, â and b̂ the axes scaled to unit length.</summary>
        public const double AxisTolerance = 1e-4;

        private readonly Vector3D _x, _y, _z;
        // default(Obb3) must be valid: without this flag its axes would be zero.
        private readonly bool _hasAxes;
        // Beside the other flag, so the struct does not grow: some stored value is outside the fast path's range.
        private readonly bool _extreme;

        /// <summary>The center.</summary>
        public readonly Vector3D Center;
        /// <summary>The non-negative half-extents along AxisX, AxisY, AxisZ.</summary>
        public readonly Vector3D HalfExtents;

#if NET
        /// <summary>Whether the axes are stored (every box but default(Obb3), whose axes are the world's).</summary>
        internal bool HasStoredAxes => _hasAxes;
        /// <summary>The stored axes, in place, for the AVX2 kernels' loads of four doubles: each is followed by the next, the third by the flags' padding.</summary>
        internal static unsafe double* StoredAxes(Obb3* box) => &box->_x.X;
#endif

        /// <summary>The first box axis (unit).</summary>
        public Vector3D AxisX { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => _hasAxes ? _x : Vector3D.UnitX; }
        /// <summary>The second box axis (unit).</summary>
        public Vector3D AxisY { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => _hasAxes ? _y : Vector3D.UnitY; }
        /// <summary>The third box axis (unit).</summary>
        public Vector3D AxisZ { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => _hasAxes ? _z : Vector3D.UnitZ; }

        /// <summary>
        /// Creates a box from three axes of any finite, non-zero length: each is normalised first, and the unit directions
        /// must be orthogonal within <see cref="AxisTolerance"/> (so axes from a quaternion whose norm has drifted are
        /// fine). Throws <see cref="ArgumentException"/> on non-finite input, a zero axis, negative half-extents, or
        /// directions further from orthogonal.
        /// </summary>
        public Obb3(Vector3D center, Vector3D axisX, Vector3D axisY, Vector3D axisZ, Vector3D halfExtents)
        {
            Num.Finite(center, nameof(center));
            CheckHalfExtents(halfExtents);
            var x = Direction(axisX, nameof(axisX));
            var y = Direction(axisY, nameof(axisY));
            var z = Direction(axisZ, nameof(axisZ));
            CheckOrthogonal(x, y, nameof(axisY));
            CheckOrthogonal(x, z, nameof(axisZ));
            CheckOrthogonal(y, z, nameof(axisZ));
            // Gram–Schmidt in double: the stored frame is orthonormal to rounding, which the kernels rely on.
            y -= x * Vector3D.Dot(x, y);
            y /= y.Length;
            z = z - x * Vector3D.Dot(x, z) - y * Vector3D.Dot(y, z);
            z /= z.Length;
            Center = Num.NoNegativeZero(center); HalfExtents = Num.NoNegativeZero(halfExtents); _x = x; _y = y; _z = z; _hasAxes = true;
            _extreme = !(Range.Moderate(center) && Range.Moderate(halfExtents));
        }

        /// <summary>Creates a box rotated by a quaternion (normalised here); throws <see cref="ArgumentException"/> naming <paramref name="rotation"/> when it is zero or not finite.</summary>
        public Obb3(Vector3D center, System.Numerics.Quaternion rotation, Vector3D halfExtents)
            : this(Rotated(center, rotation.X, rotation.Y, rotation.Z, rotation.W, halfExtents, nameof(rotation))) { }

        private Obb3(Obb3 other) { this = other; }

        private Obb3(Vector3D center, Vector3D x, Vector3D y, Vector3D z, Vector3D halfExtents, bool trusted)
        {
            Center = Num.NoNegativeZero(center); HalfExtents = Num.NoNegativeZero(halfExtents); _x = x; _y = y; _z = z; _hasAxes = trusted;
            _extreme = !(Range.Moderate(center) && Range.Moderate(halfExtents));
        }

        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Obb3>.Measure(ref Rescale s)
        {
            s.Point(Center);
            s.Length(Math.Max(HalfExtents.X, Math.Max(HalfExtents.Y, HalfExtents.Z)));
        }

        Obb3 IScalable<Obb3>.Rescaled(in Rescale s) =>
            new Obb3(s.Apply(Center), AxisX, AxisY, AxisZ, new Vector3D(s.Apply(HalfExtents.X), s.Apply(HalfExtents.Y), s.Apply(HalfExtents.Z)), true);

        /// <summary>
        /// Creates a box rotated by the quaternion (x, y, z, w), normalised here: any finite, non-zero size works, 1e-200
        /// and 1e200 included. Throws <see cref="ArgumentException"/> naming the first non-finite component, or
        /// <paramref name="w"/> when all four are zero.
        /// </summary>
        public static Obb3 FromQuaternion(Vector3D center, double x, double y, double z, double w, Vector3D halfExtents) =>
            Rotated(center, x, y, z, w, halfExtents, null);

        /// <summary><see cref="FromQuaternion"/>, reporting a bad quaternion as <paramref name="rotation"/> when given (else by component).</summary>
        private static Obb3 Rotated(Vector3D center, double x, double y, double z, double w, Vector3D halfExtents, string? rotation)
        {
            Num.Finite(center, nameof(center));
            CheckHalfExtents(halfExtents);
            CheckComponent(x, nameof(x), rotation);
            CheckComponent(y, nameof(y), rotation);
            CheckComponent(z, nameof(z), rotation);
            CheckComponent(w, nameof(w), rotation);
            double m = Math.Max(Math.Max(Math.Abs(x), Math.Abs(y)), Math.Max(Math.Abs(z), Math.Abs(w)));
            if (m == 0) throw new ArgumentException("the rotation quaternion must be non-zero (x = y = z = w = 0).", rotation ?? nameof(w));
            // Scaling by a power of two is exact, so the result keeps its bits wherever |q|² was in range already; it keeps
            // |q|² from overflowing or underflowing for quaternions far from unit size.
            double k = Num.InversePowerOfTwo(m);
            x *= k; y *= k; z *= k; w *= k;
            double s = 2 / (x * x + y * y + z * z + w * w); // folds the normalisation into the usual 2·q·q products
            double xx = x * x * s, yy = y * y * s, zz = z * z * s;
            double xy = x * y * s, xz = x * z * s, yz = y * z * s;
            double wx = w * x * s, wy = w * y * s, wz = w * z * s;
            return new Obb3(center,
                new Vector3D(1 - yy - zz, xy + wz, xz - wy),
                new Vector3D(xy - wz, 1 - xx - zz, yz + wx),
                new Vector3D(xz + wy, yz - wx, 1 - xx - yy),
                halfExtents, true);
        }

        /// <summary>
        /// The paper's form: the box's corners and its three face normals (<paramref name="axisX"/>, <paramref name="axisY"/>, <paramref name="axisZ"/>). The result is the smallest box with
        /// those axes containing every corner, which is the box itself when the corners are a box's corners. The normals
        /// are validated and re-orthonormalised as by the axes constructor.
        /// </summary>
        public static Obb3 FromCorners(ReadOnlySpan<Vector3D> corners, Vector3D axisX, Vector3D axisY, Vector3D axisZ)
        {
            if (corners.Length != 8) throw new ArgumentException($"a box has 8 corners (got {corners.Length}).", nameof(corners));
            var frame = new Obb3(default, axisX, axisY, axisZ, default);
            var sum = default(Vector3D);
            for (int i = 0; i < 8; i++)
            {
                var c = Spans.At(corners, i);
                Num.Finite(c, nameof(corners));
                sum += c;
            }
            var center = sum * 0.125;
            double hx = 0, hy = 0, hz = 0;
            for (int i = 0; i < 8; i++)
            {
                var d = Spans.At(corners, i) - center;
                hx = Math.Max(hx, Math.Abs(Vector3D.Dot(d, frame._x)));
                hy = Math.Max(hy, Math.Abs(Vector3D.Dot(d, frame._y)));
                hz = Math.Max(hz, Math.Abs(Vector3D.Dot(d, frame._z)));
            }
            return new Obb3(center, frame._x, frame._y, frame._z, new Vector3D(hx, hy, hz), true);
        }

        // Inlined, as Aabb3.ToBox is.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Box ToBox() => new Box(Center, AxisX, AxisY, AxisZ, -HalfExtents, HalfExtents, false);

        internal static void CheckHalfExtents(Vector3D h)
        {
            Num.Finite(h, "halfExtents");
            if (h.X < 0 || h.Y < 0 || h.Z < 0)
                throw new ArgumentException($"halfExtents must be non-negative (got {h}).", "halfExtents");
        }

        /// <summary>a / |a| for a finite, non-zero a of any size (scaled by a power of two first, so |a|² stays in range).</summary>
        internal static Vector3D Direction(Vector3D a, string name)
        {
            Num.Finite(a, name);
            double m = Math.Max(Math.Abs(a.X), Math.Max(Math.Abs(a.Y), Math.Abs(a.Z)));
            if (m == 0) throw new ArgumentException($"{name} must be non-zero.", name);
            a *= Num.InversePowerOfTwo(m);
            return a / a.Length;
        }

        private static void CheckComponent(double value, string component, string? rotation)
        {
            if (!double.IsFinite(value))
                throw new ArgumentException($"the rotation quaternion's {component} must be finite (got {value}).", rotation ?? component);
        }

        private static void CheckOrthogonal(Vector3D a, Vector3D b, string name)
        {
            if (!(Math.Abs(Vector3D.Dot(a, b)) <= AxisTolerance))
                throw new ArgumentException($"{name} must be orthogonal to the other axes within {AxisTolerance} (after normalising).", name);
        }

        // Printing and comparing (docs/api.md): invariant text with round-trip numbers by default, value equality.
        /// <summary>Value equality: Center, half-extents and the stored, re-orthonormalised axes equal under IEEE == (so −0 equals 0): boxes built from the same rotation by different routes (quaternion, axes, corners) can differ in the last bits of their axes.</summary>
        public bool Equals(Obb3 other) => Center == other.Center && AxisX == other.AxisX && AxisY == other.AxisY && AxisZ == other.AxisZ && HalfExtents == other.HalfExtents;
        /// <summary>True when <paramref name="obj"/> is an equal <see cref="Obb3"/>.</summary>
        public override bool Equals(object? obj) => obj is Obb3 other && Equals(other);
        /// <summary>A hash consistent with <see cref="Equals(Obb3)"/>.</summary>
        public override int GetHashCode() => HashCode.Combine(Center, AxisX, AxisY, AxisZ, HalfExtents);
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
}
