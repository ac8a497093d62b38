using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace ProximityLib.Batch
{
    // The first argument of a batch query is either a whole set (paired, lane by lane) or one shape broadcast to every
    // lane (one against many). These sources give the kernels both with one code path; as struct type arguments they
    // inline away.

    internal interface ISpheres
    {
        Vector<float> X(int i);
        Vector<float> Y(int i);
        Vector<float> Z(int i);
        Vector<float> R(int i);
    }

    internal readonly struct SphereLanes : ISpheres
    {
        private readonly SphereSet _s;
        public SphereLanes(SphereSet s) { _s = s; }
        public Vector<float> X(int i) => new Vector<float>(_s.X, i);
        public Vector<float> Y(int i) => new Vector<float>(_s.Y, i);
        public Vector<float> Z(int i) => new Vector<float>(_s.Z, i);
        public Vector<float> R(int i) => new Vector<float>(_s.R, i);
    }

    /// <summary>Points are spheres of radius 0 to the kernels.</summary>
    internal readonly struct PointLanes : ISpheres
    {
        private readonly PointSet _s;
        public PointLanes(PointSet s) { _s = s; }
        public Vector<float> X(int i) => new Vector<float>(_s.X, i);
        public Vector<float> Y(int i) => new Vector<float>(_s.Y, i);
        public Vector<float> Z(int i) => new Vector<float>(_s.Z, i);
        public Vector<float> R(int i) => Vector<float>.Zero;
    }

    internal readonly struct SphereBroadcast : ISpheres
    {
        private readonly Vector<float> _x, _y, _z, _r;
        public SphereBroadcast(Vector3 c, float r) { _x = new Vector<float>(c.X); _y = new Vector<float>(c.Y); _z = new Vector<float>(c.Z); _r = new Vector<float>(r); }
        public Vector<float> X(int i) => _x;
        public Vector<float> Y(int i) => _y;
        public Vector<float> Z(int i) => _z;
        public Vector<float> R(int i) => _r;
    }

    internal interface IAabbs
    {
        Vector<float> MinX(int i);
        Vector<float> MinY(int i);
        Vector<float> MinZ(int i);
        Vector<float> MaxX(int i);
        Vector<float> MaxY(int i);
        Vector<float> MaxZ(int i);
    }

    internal readonly struct AabbLanes : IAabbs
    {
        private readonly AabbSet _s;
        public AabbLanes(AabbSet s) { _s = s; }
        public Vector<float> MinX(int i) => new Vector<float>(_s.MinX, i);
        public Vector<float> MinY(int i) => new Vector<float>(_s.MinY, i);
        public Vector<float> MinZ(int i) => new Vector<float>(_s.MinZ, i);
        public Vector<float> MaxX(int i) => new Vector<float>(_s.MaxX, i);
        public Vector<float> MaxY(int i) => new Vector<float>(_s.MaxY, i);
        public Vector<float> MaxZ(int i) => new Vector<float>(_s.MaxZ, i);
    }

    internal readonly struct AabbBroadcast : IAabbs
    {
        private readonly Vector<float> _minX, _minY, _minZ, _maxX, _maxY, _maxZ;
        public AabbBroadcast(Vector3 min, Vector3 max)
        {
            _minX = new Vector<float>(min.X); _minY = new Vector<float>(min.Y); _minZ = new Vector<float>(min.Z);
            _maxX = new Vector<float>(max.X); _maxY = new Vector<float>(max.Y); _maxZ = new Vector<float>(max.Z);
        }
        public Vector<float> MinX(int i) => _minX;
        public Vector<float> MinY(int i) => _minY;
        public Vector<float> MinZ(int i) => _minZ;
        public Vector<float> MaxX(int i) => _maxX;
        public Vector<float> MaxY(int i) => _maxY;
        public Vector<float> MaxZ(int i) => _maxZ;
    }

    internal interface ISegments
    {
        Vector<float> AX(int i);
        Vector<float> AY(int i);
        Vector<float> AZ(int i);
        Vector<float> BX(int i);
        Vector<float> BY(int i);
        Vector<float> BZ(int i);
    }

    internal readonly struct SegmentLanes : ISegments
    {
        private readonly SegmentSet _s;
        public SegmentLanes(SegmentSet s) { _s = s; }
        public Vector<float> AX(int i) => new Vector<float>(_s.AX, i);
        public Vector<float> AY(int i) => new Vector<float>(_s.AY, i);
        public Vector<float> AZ(int i) => new Vector<float>(_s.AZ, i);
        public Vector<float> BX(int i) => new Vector<float>(_s.BX, i);
        public Vector<float> BY(int i) => new Vector<float>(_s.BY, i);
        public Vector<float> BZ(int i) => new Vector<float>(_s.BZ, i);
    }

    internal readonly struct SegmentBroadcast : ISegments
    {
        private readonly Vector<float> _ax, _ay, _az, _bx, _by, _bz;
        public SegmentBroadcast(Vector3 a, Vector3 b)
        {
            _ax = new Vector<float>(a.X); _ay = new Vector<float>(a.Y); _az = new Vector<float>(a.Z);
            _bx = new Vector<float>(b.X); _by = new Vector<float>(b.Y); _bz = new Vector<float>(b.Z);
        }
        public Vector<float> AX(int i) => _ax;
        public Vector<float> AY(int i) => _ay;
        public Vector<float> AZ(int i) => _az;
        public Vector<float> BX(int i) => _bx;
        public Vector<float> BY(int i) => _by;
        public Vector<float> BZ(int i) => _bz;
    }

    /// <summary>Oriented boxes lane by lane: center, axes (row-wise: X axis, Y axis, Z axis) and half-extents.</summary>
    internal interface IObbs
    {
        void Load(int i, out V3 center, out V3 x, out V3 y, out V3 z, out V3 half);
    }

    /// <summary>Three lanes of coordinates.</summary>
    internal struct V3
    {
        public Vector<float> X, Y, Z;
        public V3(Vector<float> x, Vector<float> y, Vector<float> z) { X = x; Y = y; Z = z; }
        public static V3 Broadcast(Vector3 v) => new V3(new Vector<float>(v.X), new Vector<float>(v.Y), new Vector<float>(v.Z));
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Dot(in V3 a, in V3 b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
    }

    internal readonly struct ObbLanes : IObbs
    {
        private readonly ObbSet _s;
        public ObbLanes(ObbSet s) { _s = s; }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Load(int i, out V3 center, out V3 x, out V3 y, out V3 z, out V3 half)
        {
            center = new V3(new Vector<float>(_s.CX, i), new Vector<float>(_s.CY, i), new Vector<float>(_s.CZ, i));
            x = new V3(new Vector<float>(_s.XX, i), new Vector<float>(_s.XY, i), new Vector<float>(_s.XZ, i));
            y = new V3(new Vector<float>(_s.YX, i), new Vector<float>(_s.YY, i), new Vector<float>(_s.YZ, i));
            z = new V3(new Vector<float>(_s.ZX, i), new Vector<float>(_s.ZY, i), new Vector<float>(_s.ZZ, i));
            half = new V3(new Vector<float>(_s.HX, i), new Vector<float>(_s.HY, i), new Vector<float>(_s.HZ, i));
        }
    }

    internal readonly struct ObbBroadcast : IObbs
    {
        private readonly V3 _c, _x, _y, _z, _h;
        public ObbBroadcast(Obb3 b)
        {
            _c = V3.Broadcast(b.Center); _x = V3.Broadcast(b.AxisX); _y = V3.Broadcast(b.AxisY); _z = V3.Broadcast(b.AxisZ);
            _h = V3.Broadcast(b.HalfExtents);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Load(int i, out V3 center, out V3 x, out V3 y, out V3 z, out V3 half)
        {
            center = _c; x = _x; y = _y; z = _z; half = _h;
        }
    }

    /// <summary>A per-lane computation over a batch: values to report (distances) or to test (≤ 0 means overlap).</summary>
    internal interface IKernel
    {
        Vector<float> Compute(int i);
    }

    internal static class Runner
    {
        public static void Values<TK>(in TK kernel, int count, System.Span<float> result) where TK : struct, IKernel
        {
            if (result.Length < count) throw new System.ArgumentException($"result needs room for {count} values (has {result.Length}).", nameof(result));
            int w = Vector<float>.Count, i = 0;
            // Vector<T>.CopyTo(Span<T>) is missing from netstandard2.1; a reinterpreting store does the same.
            for (; i + w <= count; i += w) MemoryMarshal.Cast<float, Vector<float>>(result.Slice(i, w))[0] = kernel.Compute(i);
            if (i < count)
            {
                System.Span<float> tail = stackalloc float[w];
                MemoryMarshal.Cast<float, Vector<float>>(tail)[0] = kernel.Compute(i);
                tail.Slice(0, count - i).CopyTo(result.Slice(i));
            }
        }

        public static void NonPositive<TK>(in TK kernel, int count, System.Span<bool> result) where TK : struct, IKernel
        {
            if (result.Length < count) throw new System.ArgumentException($"result needs room for {count} values (has {result.Length}).", nameof(result));
            int w = Vector<float>.Count;
            // Lanes go through a stack buffer: indexing a Vector<T> by a variable lane is slow on every target.
            System.Span<float> lanes = stackalloc float[w];
            var asVector = MemoryMarshal.Cast<float, Vector<float>>(lanes);
            for (int i = 0; i < count; i += w)
            {
                asVector[0] = kernel.Compute(i);
                int n = System.Math.Min(w, count - i);
                for (int j = 0; j < n; j++) result[i + j] = lanes[j] <= 0;
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Clamp(Vector<float> x, Vector<float> lo, Vector<float> hi) => Vector.Min(Vector.Max(x, lo), hi);

        /// <summary>−x by flipping the sign bit, as .NET's unary minus does: Mono's Vector&lt;T&gt; negation computes 0 − x, which keeps +0 positive, so unary minus would give Mono and .NET results of different sign at 0.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Negate(Vector<float> x) => Vector.AsVectorSingle(Vector.Xor(Vector.AsVectorUInt32(x), new Vector<uint>(0x80000000u)));
    }
}
