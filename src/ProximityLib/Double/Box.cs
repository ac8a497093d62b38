using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// The one box form the kernels see: Origin + X*u + Y*v + Z*w with (u, v, w) in [Lo, Hi].
    /// An AABB keeps its Min as origin (Lo = 0, Hi = Max - Min) so nothing is rounded at the scale of its
    /// position; an OBB keeps its center (Lo = -Half, Hi = Half). Planar boxes come from the 2D API: they lie
    /// in z = 0 with Lo.Z = Hi.Z = 0, and the kernels then never pick z as a separating or push-out direction.
    /// </summary>
    internal readonly struct Box
    {
        public readonly Vector3D Origin, X, Y, Z, Lo, Hi;
        public readonly bool Planar;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Box(Vector3D origin, Vector3D x, Vector3D y, Vector3D z, Vector3D lo, Vector3D hi, bool planar)
        {
            Origin = origin; X = x; Y = y; Z = z; Lo = lo; Hi = hi; Planar = planar;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3D ToLocal(Vector3D worldOffset) =>
            new Vector3D(Vector3D.Dot(worldOffset, X), Vector3D.Dot(worldOffset, Y), Vector3D.Dot(worldOffset, Z));

        /// <summary>
        /// X·local.X + Y·local.Y + Z·local.Z, in plain doubles, each component as Vector3D's operations form it (the same
        /// bits): Mono keeps every Vector3D temporary in memory.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3D ToWorldOffset(Vector3D local)
        {
            double u = local.X, v = local.Y, w = local.Z;
            return new Vector3D((X.X * u + Y.X * v) + Z.X * w, (X.Y * u + Y.Y * v) + Z.Y * w, (X.Z * u + Y.Z * v) + Z.Z * w);
        }

        public Vector3D Axis(int i) => i == 0 ? X : (i == 1 ? Y : Z);

        /// <summary>Box-local centre and half-extents; exact for both AABB ([0, ext]) and OBB ([−h, h]) forms.</summary>
        public Vector3D LocalCenter { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => (Lo + Hi) * 0.5; }
        public Vector3D Half { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => (Hi - Lo) * 0.5; }

        public Box Translated(Vector3D by) => new Box(Origin + by, X, Y, Z, Lo, Hi, Planar);
    }

    /// <summary>
    /// The planar box form of the 2D box kernels: Origin + X*u + Y*v with (u, v) in [Lo, Hi]; the same values as the
    /// planar <see cref="Box"/> without its z parts (which only ever added exact zeros), so both forms give the same
    /// bits, up to the sign of a zero.
    /// </summary>
    internal readonly struct Box2
    {
        public readonly Vector2D Origin, X, Y, Lo, Hi;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Box2(Vector2D origin, Vector2D x, Vector2D y, Vector2D lo, Vector2D hi)
        {
            Origin = origin; X = x; Y = y; Lo = lo; Hi = hi;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector2D ToLocal(Vector2D worldOffset) => new Vector2D(Vector2D.Dot(worldOffset, X), Vector2D.Dot(worldOffset, Y));

        /// <summary>X·local.X + Y·local.Y in plain doubles (the same bits; see the 3D box's).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector2D ToWorldOffset(Vector2D local) => new Vector2D(X.X * local.X + Y.X * local.Y, X.Y * local.X + Y.Y * local.Y);

        public Vector2D LocalCenter { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => (Lo + Hi) * 0.5; }
        public Vector2D Half { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => (Hi - Lo) * 0.5; }
    }
}
