// Copied from src/ProximityLib/Double/Vector2D.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>An immutable 2D vector of doubles: the point type of the double-precision 2D API.</summary>
    public readonly struct Vector2D : IEquatable<Vector2D>, IFormattable, IScalable<Vector2D>
    {
        /// <summary>The X component.</summary>
        public readonly double X;
        /// <summary>The Y component.</summary>
        public readonly double Y;

        /// <summary>Creates a vector from its components.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector2D(double x, double y) { X = x; Y = y; }

        /// <summary>The zero vector.</summary>
        public static Vector2D Zero { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => default; }
        /// <summary>The unit vector along X.</summary>
        public static Vector2D UnitX { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new Vector2D(1, 0); }
        /// <summary>The unit vector along Y.</summary>
        public static Vector2D UnitY { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new Vector2D(0, 1); }

        /// <summary>The squared Euclidean length.</summary>
        public double LengthSquared { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => X * X + Y * Y; }
        /// <summary>The Euclidean length.</summary>
        public double Length { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => Math.Sqrt(LengthSquared); }
        /// <summary>True when every component is finite.</summary>
        public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y);

        /// <summary>The dot product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(Vector2D a, Vector2D b) => a.X * b.X + a.Y * b.Y;
        /// <summary>The scalar cross product a.X*b.Y - a.Y*b.X.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Cross(Vector2D a, Vector2D b) => a.X * b.Y - a.Y * b.X;
        /// <summary>The Euclidean distance between two points.</summary>
        public static double Distance(Vector2D a, Vector2D b) => (a - b).Length;

        /// <summary>Component-wise sum.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator +(Vector2D a, Vector2D b) => new Vector2D(a.X + b.X, a.Y + b.Y);
        /// <summary>Component-wise difference.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator -(Vector2D a, Vector2D b) => new Vector2D(a.X - b.X, a.Y - b.Y);
        /// <summary>Negation.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator -(Vector2D a) => new Vector2D(-a.X, -a.Y);
        /// <summary>Scaling by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator *(Vector2D a, double s) => new Vector2D(a.X * s, a.Y * s);
        /// <summary>Scaling by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator *(double s, Vector2D a) => new Vector2D(a.X * s, a.Y * s);
        /// <summary>Division by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D operator /(Vector2D a, double s) => new Vector2D(a.X / s, a.Y / s);
        /// <summary>Exact component-wise equality.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool operator ==(Vector2D a, Vector2D b) => a.X == b.X && a.Y == b.Y;
        /// <summary>Exact component-wise inequality.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool operator !=(Vector2D a, Vector2D b) => !(a == b);

        /// <summary>Widens a float vector exactly.</summary>
        public static implicit operator Vector2D(System.Numerics.Vector2 v) => new Vector2D(v.X, v.Y);
        /// <summary>Rounds to the nearest float vector.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // the float API's results: without PGO the inlining budget ran out before it (2x slower)
        public static explicit operator System.Numerics.Vector2(Vector2D v) => new System.Numerics.Vector2((float)v.X, (float)v.Y);

        // The 2D API runs on the 3D kernels in the z = 0 plane; z stays exactly 0 through them.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal Vector3D To3() => new Vector3D(X, Y, 0);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Vector2D From3(Vector3D v) => new Vector2D(v.X, v.Y);

        void IScalable<Vector2D>.Measure(ref Rescale s) => s.Point(this);
        Vector2D IScalable<Vector2D>.Rescaled(in Rescale s) => s.Apply(this);

        /// <summary>Exact component-wise equality.</summary>
        public bool Equals(Vector2D other) => this == other;
        /// <summary>Exact component-wise equality.</summary>
        public override bool Equals(object? obj) => obj is Vector2D v && this == v;
        /// <summary>A hash of the components.</summary>
        public override int GetHashCode() => HashCode.Combine(X, Y);
        /// <summary>Formats as &lt;X, Y&gt; with round-trip precision.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>Formats as &lt;X, Y&gt;, each component in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null), separated as System.Numerics does.</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) => Formatting.Of(this, format, formatProvider);
    }
}
