// Copied from src/ProximityLib/Batch/Lanes.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
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
        float XAt(int i);
        float YAt(int i);
        float ZAt(int i);
        float RAt(int i);
        /// <summary>The centers' arrays for paired lanes (null for one shape broadcast), and the radii's (null for points).</summary>
        float[]? Xs { get; }
        float[]? Ys { get; }
        float[]? Zs { get; }
        float[]? Rs { get; }
    }

    internal readonly struct SphereLanes : ISpheres
    {
        private readonly SphereSet _s;
        public SphereLanes(SphereSet s) { _s = s; }
        public float[]? Xs => _s.X;
        public float[]? Ys => _s.Y;
        public float[]? Zs => _s.Z;
        public float[]? Rs => _s.R;
        public Vector<float> X(int i) => new Vector<float>(_s.X, i);
        public Vector<float> Y(int i) => new Vector<float>(_s.Y, i);
        public Vector<float> Z(int i) => new Vector<float>(_s.Z, i);
        public Vector<float> R(int i) => new Vector<float>(_s.R, i);
        public float XAt(int i) => _s.X[i];
        public float YAt(int i) => _s.Y[i];
        public float ZAt(int i) => _s.Z[i];
        public float RAt(int i) => _s.R[i];
    }

    /// <summary>Points are spheres of radius 0 to the kernels.</summary>
    internal readonly struct PointLanes : ISpheres
    {
        private readonly PointSet _s;
        public PointLanes(PointSet s) { _s = s; }
        public float[]? Xs => _s.X;
        public float[]? Ys => _s.Y;
        public float[]? Zs => _s.Z;
        public float[]? Rs => null;
        public Vector<float> X(int i) => new Vector<float>(_s.X, i);
        public Vector<float> Y(int i) => new Vector<float>(_s.Y, i);
        public Vector<float> Z(int i) => new Vector<float>(_s.Z, i);
        public Vector<float> R(int i) => Vector<float>.Zero;
        public float XAt(int i) => _s.X[i];
        public float YAt(int i) => _s.Y[i];
        public float ZAt(int i) => _s.Z[i];
        public float RAt(int i) => 0;
    }

    internal readonly struct SphereBroadcast : ISpheres
    {
        private readonly Vector<float> _x, _y, _z, _r;
        private readonly Vector3 _c;
        private readonly float _radius;
        public SphereBroadcast(Vector3 c, float r)
        {
            _x = new Vector<float>(c.X); _y = new Vector<float>(c.Y); _z = new Vector<float>(c.Z); _r = new Vector<float>(r);
            _c = c; _radius = r;
        }
        public float[]? Xs => null;
        public float[]? Ys => null;
        public float[]? Zs => null;
        public float[]? Rs => null;
        public Vector<float> X(int i) => _x;
        public Vector<float> Y(int i) => _y;
        public Vector<float> Z(int i) => _z;
        public Vector<float> R(int i) => _r;
        public float XAt(int i) => _c.X;
        public float YAt(int i) => _c.Y;
        public float ZAt(int i) => _c.Z;
        public float RAt(int i) => _radius;
    }

    internal interface IAabbs
    {
        Vector<float> MinX(int i);
        Vector<float> MinY(int i);
        Vector<float> MinZ(int i);
        Vector<float> MaxX(int i);
        Vector<float> MaxY(int i);
        Vector<float> MaxZ(int i);
        /// <summary>Box i's corners (min x, y, z, max x, y, z) for the scalar lanes.</summary>
        void CornersAt(int i, out float minX, out float minY, out float minZ, out float maxX, out float maxY, out float maxZ);
        /// <summary>The set for paired lanes, null for one box broadcast.</summary>
        AabbSet? Set { get; }
    }

    internal readonly struct AabbLanes : IAabbs
    {
        private readonly AabbSet _s;
        public AabbLanes(AabbSet s) { _s = s; }
        public AabbSet? Set => _s;
        public Vector<float> MinX(int i) => new Vector<float>(_s.MinX, i);
        public Vector<float> MinY(int i) => new Vector<float>(_s.MinY, i);
        public Vector<float> MinZ(int i) => new Vector<float>(_s.MinZ, i);
        public Vector<float> MaxX(int i) => new Vector<float>(_s.MaxX, i);
        public Vector<float> MaxY(int i) => new Vector<float>(_s.MaxY, i);
        public Vector<float> MaxZ(int i) => new Vector<float>(_s.MaxZ, i);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void CornersAt(int i, out float minX, out float minY, out float minZ, out float maxX, out float maxY, out float maxZ)
        {
            minX = _s.MinX[i]; minY = _s.MinY[i]; minZ = _s.MinZ[i]; maxX = _s.MaxX[i]; maxY = _s.MaxY[i]; maxZ = _s.MaxZ[i];
        }
    }

    internal readonly struct AabbBroadcast : IAabbs
    {
        private readonly Vector<float> _minX, _minY, _minZ, _maxX, _maxY, _maxZ;
        private readonly Vector3 _min, _max;
        public AabbBroadcast(Vector3 min, Vector3 max)
        {
            _minX = new Vector<float>(min.X); _minY = new Vector<float>(min.Y); _minZ = new Vector<float>(min.Z);
            _maxX = new Vector<float>(max.X); _maxY = new Vector<float>(max.Y); _maxZ = new Vector<float>(max.Z);
            _min = min; _max = max;
        }
        public AabbSet? Set => null;
        public Vector<float> MinX(int i) => _minX;
        public Vector<float> MinY(int i) => _minY;
        public Vector<float> MinZ(int i) => _minZ;
        public Vector<float> MaxX(int i) => _maxX;
        public Vector<float> MaxY(int i) => _maxY;
        public Vector<float> MaxZ(int i) => _maxZ;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void CornersAt(int i, out float minX, out float minY, out float minZ, out float maxX, out float maxY, out float maxZ)
        {
            minX = _min.X; minY = _min.Y; minZ = _min.Z; maxX = _max.X; maxY = _max.Y; maxZ = _max.Z;
        }
    }

    internal interface ISegments
    {
        Vector<float> AX(int i);
        Vector<float> AY(int i);
        Vector<float> AZ(int i);
        Vector<float> BX(int i);
        Vector<float> BY(int i);
        Vector<float> BZ(int i);
        /// <summary>Segment i's endpoints for the scalar lanes.</summary>
        void EndsAt(int i, out SegmentLane s);
        /// <summary>The set for paired lanes, null for one segment broadcast.</summary>
        SegmentSet? Set { get; }
    }

    /// <summary>One segment's endpoints in scalar floats, for the scalar lanes.</summary>
    internal struct SegmentLane
    {
        public float AX, AY, AZ, BX, BY, BZ;
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

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void EndsAt(int i, out SegmentLane s)
        {
            s.AX = _s.AX[i]; s.AY = _s.AY[i]; s.AZ = _s.AZ[i]; s.BX = _s.BX[i]; s.BY = _s.BY[i]; s.BZ = _s.BZ[i];
        }

        public SegmentSet? Set => _s;
    }

    internal readonly struct SegmentBroadcast : ISegments
    {
        private readonly Vector<float> _ax, _ay, _az, _bx, _by, _bz;
        private readonly SegmentLane _one;
        public SegmentBroadcast(Vector3 a, Vector3 b)
        {
            _ax = new Vector<float>(a.X); _ay = new Vector<float>(a.Y); _az = new Vector<float>(a.Z);
            _bx = new Vector<float>(b.X); _by = new Vector<float>(b.Y); _bz = new Vector<float>(b.Z);
            _one = new SegmentLane { AX = a.X, AY = a.Y, AZ = a.Z, BX = b.X, BY = b.Y, BZ = b.Z };
        }
        public Vector<float> AX(int i) => _ax;
        public Vector<float> AY(int i) => _ay;
        public Vector<float> AZ(int i) => _az;
        public Vector<float> BX(int i) => _bx;
        public Vector<float> BY(int i) => _by;
        public Vector<float> BZ(int i) => _bz;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void EndsAt(int i, out SegmentLane s) => s = _one;

        public SegmentSet? Set => null;
    }

    /// <summary>Oriented boxes lane by lane: center, axes (row-wise: X axis, Y axis, Z axis) and half-extents.</summary>
    internal interface IObbs
    {
        void Load(int i, out V3 center, out V3 x, out V3 y, out V3 z, out V3 half);
        /// <summary>Box i for the scalar lanes.</summary>
        void LoadAt(int i, out ObbLane box);
        /// <summary>The set for paired lanes, null for one box broadcast.</summary>
        ObbSet? Set { get; }
    }

    /// <summary>One oriented box in scalar floats (center, axes row-wise, half-extents), for the scalar lanes.</summary>
    internal struct ObbLane
    {
        public float CX, CY, CZ, XX, XY, XZ, YX, YY, YZ, ZX, ZY, ZZ, HX, HY, HZ;
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

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void LoadAt(int i, out ObbLane box)
        {
            box.CX = _s.CX[i]; box.CY = _s.CY[i]; box.CZ = _s.CZ[i];
            box.XX = _s.XX[i]; box.XY = _s.XY[i]; box.XZ = _s.XZ[i];
            box.YX = _s.YX[i]; box.YY = _s.YY[i]; box.YZ = _s.YZ[i];
            box.ZX = _s.ZX[i]; box.ZY = _s.ZY[i]; box.ZZ = _s.ZZ[i];
            box.HX = _s.HX[i]; box.HY = _s.HY[i]; box.HZ = _s.HZ[i];
        }

        public ObbSet? Set => _s;
    }

    internal readonly struct ObbBroadcast : IObbs
    {
        private readonly V3 _c, _x, _y, _z, _h;
        private readonly ObbLane _box;
        public ObbBroadcast(Obb3 b)
        {
            Vector3 c = b.Center, x = b.AxisX, y = b.AxisY, z = b.AxisZ, h = b.HalfExtents;
            _c = V3.Broadcast(c); _x = V3.Broadcast(x); _y = V3.Broadcast(y); _z = V3.Broadcast(z); _h = V3.Broadcast(h);
            _box = new ObbLane
            {
                CX = c.X, CY = c.Y, CZ = c.Z, XX = x.X, XY = x.Y, XZ = x.Z, YX = y.X, YY = y.Y, YZ = y.Z,
                ZX = z.X, ZY = z.Y, ZZ = z.Z, HX = h.X, HY = h.Y, HZ = h.Z,
            };
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Load(int i, out V3 center, out V3 x, out V3 y, out V3 z, out V3 half)
        {
            center = _c; x = _x; y = _y; z = _z; half = _h;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void LoadAt(int i, out ObbLane box) => box = _box;

        public ObbSet? Set => null;
    }

    /// <summary>
    /// A per-lane computation over a batch: values to report (distances) or to test (≤ 0 means overlap), on
    /// <see cref="Vector{T}"/> lanes or on one lane in scalar float. Kernels are mutable structs passed by value: a call
    /// on a readonly field (or <c>in</c> parameter) whose type is a type parameter copies the struct first, which Mono
    /// does on every call (a one-against-many source holds its shape broadcast to whole vectors).
    /// </summary>
    internal interface IKernel
    {
        /// <summary>Lanes i to i + <see cref="Vector{T}.Count"/> − 1.</summary>
        Vector<float> Compute(int i);

        /// <summary>
        /// Lane i in scalar float, by the same operations in the same order as <see cref="Compute"/>, so the same bits;
        /// a kernel whose values are only tested (OBB–OBB, AABB–AABB) may stop at the first positive term: then only
        /// whether the value is ≤ 0 agrees.
        /// </summary>
        float Lane(int i);

        /// <summary>
        /// <see cref="Lane"/> for lanes start to end − 1 into result, where <see cref="Vector{T}"/> is not
        /// hardware-accelerated. A kernel whose <see cref="Lane"/> reads its sets through bounds-checked field loads
        /// on every lane (slow on Mono) writes its own loop over pinned arrays; the rest call Runner.EachLane.
        /// </summary>
        void Values(int start, int end, Span<float> result);

        /// <summary>Whether <see cref="Lane"/> is ≤ 0 for lanes start to end − 1, as <see cref="Values"/>.</summary>
        void Verdicts(int start, int end, Span<bool> result);
    }
}
