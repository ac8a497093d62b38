// Copied from src/ProximityLib/Double/Vector3D.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>An immutable 3D vector of doubles: the point type of the double-precision API.</summary>
    public readonly struct Vector3D : IEquatable<Vector3D>, IFormattable, IScalable<Vector3D>
    {
        /// <summary>The X component.</summary>
        public readonly double X;
        /// <summary>The Y component.</summary>
        public readonly double Y;
        /// <summary>The Z component.</summary>
        public readonly double Z;

        /// <summary>Creates a vector from its components.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3D(double x, double y, double z) { X = x; Y = y; Z = z; }

        /// <summary>The zero vector.</summary>
        public static Vector3D Zero { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => default; }
        /// <summary>The unit vector along X.</summary>
        public static Vector3D UnitX { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new Vector3D(1, 0, 0); }
        /// <summary>The unit vector along Y.</summary>
        public static Vector3D UnitY { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new Vector3D(0, 1, 0); }
        /// <summary>The unit vector along Z.</summary>
        public static Vector3D UnitZ { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => new Vector3D(0, 0, 1); }

        /// <summary>The squared Euclidean length.</summary>
        public double LengthSquared
        {
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            get => X * X + Y * Y + Z * Z;
        }

        /// <summary>The Euclidean length.</summary>
        public double Length { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => Math.Sqrt(LengthSquared); }

        /// <summary>True when every component is finite.</summary>
        public bool IsFinite => double.IsFinite(X) && double.IsFinite(Y) && double.IsFinite(Z);

        /// <summary>The dot product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Dot(Vector3D a, Vector3D b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;

        /// <summary>The cross product.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Cross(Vector3D a, Vector3D b) =>
            new Vector3D(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

        /// <summary>The Euclidean distance between two points.</summary>
        public static double Distance(Vector3D a, Vector3D b) => (a - b).Length;

        /// <summary>Component-wise sum.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator +(Vector3D a, Vector3D b) => new Vector3D(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        /// <summary>Component-wise difference.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator -(Vector3D a, Vector3D b) => new Vector3D(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        /// <summary>Negation.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator -(Vector3D a) => new Vector3D(-a.X, -a.Y, -a.Z);
        /// <summary>Scaling by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator *(Vector3D a, double s) => new Vector3D(a.X * s, a.Y * s, a.Z * s);
        /// <summary>Scaling by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator *(double s, Vector3D a) => new Vector3D(a.X * s, a.Y * s, a.Z * s);
        /// <summary>Division by a scalar.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D operator /(Vector3D a, double s) => new Vector3D(a.X / s, a.Y / s, a.Z / s);
        /// <summary>Exact component-wise equality.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool operator ==(Vector3D a, Vector3D b) => a.X == b.X && a.Y == b.Y && a.Z == b.Z;
        /// <summary>Exact component-wise inequality.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool operator !=(Vector3D a, Vector3D b) => !(a == b);

        /// <summary>Widens a float vector exactly.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static implicit operator Vector3D(System.Numerics.Vector3 v) => new Vector3D(v.X, v.Y, v.Z);
        /// <summary>Rounds to the nearest float vector.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static explicit operator System.Numerics.Vector3(Vector3D v) => new System.Numerics.Vector3((float)v.X, (float)v.Y, (float)v.Z);

        void IScalable<Vector3D>.Measure(ref Rescale s) => s.Point(this);
        Vector3D IScalable<Vector3D>.Rescaled(in Rescale s) => s.Apply(this);

        /// <summary>Exact component-wise equality.</summary>
        public bool Equals(Vector3D other) => this == other;
        /// <summary>Exact component-wise equality.</summary>
        public override bool Equals(object? obj) => obj is Vector3D v && this == v;
        /// <summary>A hash of the components.</summary>
        public override int GetHashCode() => HashCode.Combine(X, Y, Z);
        /// <summary>Formats as &lt;X, Y, Z&gt; with round-trip precision.</summary>
        public override string ToString() => ToString(null, null);
        /// <summary>Formats as &lt;X, Y, Z&gt;, each component in <paramref name="format"/> ("R", round-trip, when null) and <paramref name="formatProvider"/> (invariant when null), separated as System.Numerics does.</summary>
        public string ToString(string? format, IFormatProvider? formatProvider) => Formatting.Of(this, format, formatProvider);
    }
}
