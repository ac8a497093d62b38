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
    }
}
