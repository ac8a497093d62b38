// Copied from src/ProximityLib/Batch/BatchQuery.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace ProximityLib.Batch
{
    /// <summary>
    /// SIMD batch queries over <see cref="ShapeSet"/>s, one against many or paired (many against many, lane by lane),
    /// with no allocation. Results are the scalar queries' signed distances (gap apart, 0 touching, −depth overlapping)
    /// or touch-or-overlap verdicts, computed in float across <see cref="Vector{T}"/> lanes; witness points are the scalar
    /// API's job. The lanes compute in float: the error bound (E ≤ 8, measured in docs/accuracy.md) holds for
    /// configurations whose size lies within 2^±28, where squares stay normal floats (segment–segment scales its fourth
    /// powers down to squares).
    /// </summary>
    public static partial class BatchQuery
    {
        /// <summary>
        /// The most threads one batch call uses, the calling thread included; default <see cref="Environment.ProcessorCount"/>.
        /// Calls of at least 65,536 shapes are split over the thread pool (same results, no allocation on .NET); 1 keeps
        /// every call on the calling thread, for callers that already run batches in parallel or must not use the pool.
        /// Process-wide; <see cref="ArgumentException"/> below 1.
        /// </summary>
        public static int MaxDegreeOfParallelism
        {
            get => Workers.MaxThreads;
            set => Workers.MaxThreads = value >= 1 ? value : throw new ArgumentException("the degree of parallelism must be at least 1.", nameof(value));
        }

        /// <summary>Signed distances between spheres a[i] and b[i].</summary>
        public static void Distances(SphereSet a, SphereSet b, Span<float> result) =>
            Runner.Values(new SphereSphere<SphereLanes>(new SphereLanes(a), Paired(a, b), false), b.Count, result);

        /// <summary>Signed distances between sphere a and every sphere of b.</summary>
        public static void Distances(Sphere a, SphereSet b, Span<float> result) =>
            Runner.Values(new SphereSphere<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, false), b.Count, result);

        /// <summary>Whether spheres a[i] and b[i] touch or overlap.</summary>
        public static void Overlaps(SphereSet a, SphereSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereSphere<SphereLanes>(new SphereLanes(a), Paired(a, b), true), b.Count, result);

        /// <summary>Whether sphere a touches or overlaps each sphere of b.</summary>
        public static void Overlaps(Sphere a, SphereSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereSphere<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, true), b.Count, result);

        /// <summary>Signed distances between points a[i] and boxes b[i] (negative inside).</summary>
        public static void Distances(PointSet a, AabbSet b, Span<float> result) =>
            Runner.Values(new SphereAabb<PointLanes>(new PointLanes(a), Paired(a, b), false), b.Count, result);

        /// <summary>Signed distances between point a and every box of b (negative inside).</summary>
        public static void Distances(Vector3 a, AabbSet b, Span<float> result) =>
            Runner.Values(new SphereAabb<SphereBroadcast>(new SphereBroadcast(a, 0), b, false), b.Count, result);

        /// <summary>Whether points a[i] lie in boxes b[i].</summary>
        public static void Overlaps(PointSet a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereAabb<PointLanes>(new PointLanes(a), Paired(a, b), true), b.Count, result);

        /// <summary>Whether point a lies in each box of b.</summary>
        public static void Overlaps(Vector3 a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereAabb<SphereBroadcast>(new SphereBroadcast(a, 0), b, true), b.Count, result);

        /// <summary>Signed distances between spheres a[i] and boxes b[i].</summary>
        public static void Distances(SphereSet a, AabbSet b, Span<float> result) =>
            Runner.Values(new SphereAabb<SphereLanes>(new SphereLanes(a), Paired(a, b), false), b.Count, result);

        /// <summary>Signed distances between sphere a and every box of b.</summary>
        public static void Distances(Sphere a, AabbSet b, Span<float> result) =>
            Runner.Values(new SphereAabb<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, false), b.Count, result);

        /// <summary>Whether spheres a[i] and boxes b[i] touch or overlap.</summary>
        public static void Overlaps(SphereSet a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereAabb<SphereLanes>(new SphereLanes(a), Paired(a, b), true), b.Count, result);

        /// <summary>Whether sphere a touches or overlaps each box of b.</summary>
        public static void Overlaps(Sphere a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereAabb<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, true), b.Count, result);

        /// <summary>Whether boxes a[i] and b[i] touch or overlap.</summary>
        public static void Overlaps(AabbSet a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new AabbAabb<AabbLanes>(new AabbLanes(a), Paired(a, b)), b.Count, result);

        /// <summary>Whether box a touches or overlaps each box of b.</summary>
        public static void Overlaps(Aabb3 a, AabbSet b, Span<bool> result) =>
            Runner.NonPositive(new AabbAabb<AabbBroadcast>(new AabbBroadcast(a.Min, a.Max), b), b.Count, result);

        /// <summary>Signed distances between spheres a[i] and oriented boxes b[i].</summary>
        public static void Distances(SphereSet a, ObbSet b, Span<float> result) =>
            Runner.Values(new SphereObb<SphereLanes>(new SphereLanes(a), Paired(a, b), false), b.Count, result);

        /// <summary>Signed distances between sphere a and every oriented box of b.</summary>
        public static void Distances(Sphere a, ObbSet b, Span<float> result) =>
            Runner.Values(new SphereObb<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, false), b.Count, result);

        /// <summary>Whether spheres a[i] and oriented boxes b[i] touch or overlap.</summary>
        public static void Overlaps(SphereSet a, ObbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereObb<SphereLanes>(new SphereLanes(a), Paired(a, b), true), b.Count, result);

        /// <summary>Whether sphere a touches or overlaps each oriented box of b.</summary>
        public static void Overlaps(Sphere a, ObbSet b, Span<bool> result) =>
            Runner.NonPositive(new SphereObb<SphereBroadcast>(new SphereBroadcast(a.Center, a.Radius), b, true), b.Count, result);

        /// <summary>Distances between segments a[i] and b[i].</summary>
        public static void Distances(SegmentSet a, SegmentSet b, Span<float> result) =>
            Runner.Values(new SegmentSegment<SegmentLanes>(new SegmentLanes(a), Paired(a, b)), b.Count, result);

        /// <summary>Distances between segment a and every segment of b.</summary>
        public static void Distances(Segment3 a, SegmentSet b, Span<float> result) =>
            Runner.Values(new SegmentSegment<SegmentBroadcast>(new SegmentBroadcast(a.Start, a.End), b), b.Count, result);

        /// <summary>Whether oriented boxes a[i] and b[i] touch or overlap (15-axis SAT).</summary>
        public static void Overlaps(ObbSet a, ObbSet b, Span<bool> result) =>
            Runner.NonPositive(new ObbObb<ObbLanes>(new ObbLanes(a), Paired(a, b)), b.Count, result);

        /// <summary>Whether oriented box a touches or overlaps each box of b (15-axis SAT).</summary>
        public static void Overlaps(Obb3 a, ObbSet b, Span<bool> result) =>
            Runner.NonPositive(new ObbObb<ObbBroadcast>(new ObbBroadcast(a), b), b.Count, result);

        private static TB Paired<TB>(ShapeSet a, TB b) where TB : ShapeSet =>
            a.Count == b.Count ? b : throw new ArgumentException($"paired queries need sets of equal size ({a.Count} and {b.Count}).", nameof(b));

        /// <summary>
        /// Signed distance from points to boxes [lo, hi], per lane: the clamped gap outside, minus the nearest face's
        /// depth inside; or, for a margin, the squared gap less r² (≤ 0 exactly when a sphere of radius r meets the box).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<float> PointBox(Vector<float> px, Vector<float> py, Vector<float> pz, Vector<float> r,
            Vector<float> lox, Vector<float> loy, Vector<float> loz, Vector<float> hix, Vector<float> hiy, Vector<float> hiz, bool margin)
        {
            var dx = px - Runner.Clamp(px, lox, hix);
            var dy = py - Runner.Clamp(py, loy, hiy);
            var dz = pz - Runner.Clamp(pz, loz, hiz);
            var d2 = dx * dx + dy * dy + dz * dz;
            if (margin) return d2 - r * r;
            var depth = Vector.Min(Vector.Min(Vector.Min(px - lox, hix - px), Vector.Min(py - loy, hiy - py)), Vector.Min(pz - loz, hiz - pz));
            return Vector.ConditionalSelect(Vector.GreaterThan(d2, Vector<float>.Zero), Vector.SquareRoot(d2), Runner.Negate(depth)) - r;
        }

        /// <summary>One lane of <see cref="PointBox(Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, Vector{float}, bool)"/>; the depth only inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static float PointBox(float px, float py, float pz, float r, float lox, float loy, float loz, float hix, float hiy, float hiz, bool margin)
        {
            var dx = px - Runner.Clamp(px, lox, hix);
            var dy = py - Runner.Clamp(py, loy, hiy);
            var dz = pz - Runner.Clamp(pz, loz, hiz);
            var d2 = dx * dx + dy * dy + dz * dz;
            if (margin) return d2 - r * r;
            if (d2 > 0) return Runner.Sqrt(d2) - r;
            var depth = Runner.Min(Runner.Min(Runner.Min(px - lox, hix - px), Runner.Min(py - loy, hiy - py)), Runner.Min(pz - loz, hiz - pz));
            return -depth - r;
        }

        /// <summary>
        /// The scalar lanes' squared gap less r², the vector lanes' bits without a branch: each axis's p − clamp(p, lo, hi)
        /// is ±(p − hi) above the box, ±(p − lo) below it and 0 inside, so its square is that of (p − hi)⁺ + (lo − p)⁺
        /// (at most one term is nonzero; negation is exact). On Mono the clamps' branches mispredicted on mixed inputs
        /// and made the one-to-many queries slower than the scalar API.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static float Margin(float px, float py, float pz, float r, float lox, float loy, float loz, float hix, float hiy, float hiz)
        {
            float dx = Positive(px - hix) + Positive(lox - px);
            float dy = Positive(py - hiy) + Positive(loy - py);
            float dz = Positive(pz - hiz) + Positive(loz - pz);
            return dx * dx + dy * dy + dz * dz - r * r;
        }

        /// <summary>max(t, 0) from the sign bit (−0 and negatives give +0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static float Positive(float t)
        {
            int bits = BitConverter.SingleToInt32Bits(t);
            return BitConverter.Int32BitsToSingle(bits & ~(bits >> 31));
        }

        private struct SphereSphere<TS> : IKernel where TS : struct, ISpheres
        {
            private TS _a;
            private readonly SphereSet _b;
            private readonly bool _margin;
            public SphereSphere(TS a, SphereSet b, bool margin) { _a = a; _b = b; _margin = margin; }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var dx = _a.X(i) - new Vector<float>(_b.X, i);
                var dy = _a.Y(i) - new Vector<float>(_b.Y, i);
                var dz = _a.Z(i) - new Vector<float>(_b.Z, i);
                var d2 = dx * dx + dy * dy + dz * dz;
                var r = _a.R(i) + new Vector<float>(_b.R, i);
                return _margin ? d2 - r * r : Vector.SquareRoot(d2) - r;
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i) => Value(_a.XAt(i) - _b.X[i], _a.YAt(i) - _b.Y[i], _a.ZAt(i) - _b.Z[i], _a.RAt(i) + _b.R[i], _margin);

            // The scalar lanes over pinned arrays, one loop for paired spheres and one for a broadcast sphere: through
            // Lane (a field and a bounds check per coordinate) they ran slower on Mono than the scalar API. The loops call
            // Gap or Margin, not Value: Mono 6.8 keeps the arguments of an inlined method that branches (on margin) in
            // stack slots, a store and a load each per pair, and did not fold the constant margin.

            public unsafe void Values(int start, int end, Span<float> result)
            {
                fixed (float* bx = _b.X, by = _b.Y, bz = _b.Z, br = _b.R, ax = _a.Xs, ay = _a.Ys, az = _a.Zs, ar = _a.Rs)
                fixed (float* v = result)
                {
                    if (ax == null)
                    {
                        float x = _a.XAt(0), y = _a.YAt(0), z = _a.ZAt(0), r = _a.RAt(0);
                        for (int i = start; i < end; i++) v[i] = Gap(x - bx[i], y - by[i], z - bz[i], r + br[i]);
                    }
                    else
                        for (int i = start; i < end; i++) v[i] = Gap(ax[i] - bx[i], ay[i] - by[i], az[i] - bz[i], ar[i] + br[i]);
                }
            }

            public unsafe void Verdicts(int start, int end, Span<bool> result)
            {
                fixed (float* bx = _b.X, by = _b.Y, bz = _b.Z, br = _b.R, ax = _a.Xs, ay = _a.Ys, az = _a.Zs, ar = _a.Rs)
                fixed (bool* v = result)
                {
                    if (ax == null)
                    {
                        float x = _a.XAt(0), y = _a.YAt(0), z = _a.ZAt(0), r = _a.RAt(0);
                        for (int i = start; i < end; i++) v[i] = Margin(x - bx[i], y - by[i], z - bz[i], r + br[i]) <= 0;
                    }
                    else
                        for (int i = start; i < end; i++) v[i] = Margin(ax[i] - bx[i], ay[i] - by[i], az[i] - bz[i], ar[i] + br[i]) <= 0;
                }
            }

            /// <summary>One lane of <see cref="Compute"/> from the center offset and the radii's sum.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Value(float dx, float dy, float dz, float r, bool margin) => margin ? Margin(dx, dy, dz, r) : Gap(dx, dy, dz, r);

            /// <summary>The distance lane: |d| − r.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Gap(float dx, float dy, float dz, float r) => Runner.Sqrt(dx * dx + dy * dy + dz * dz) - r;

            /// <summary>The overlap lane: |d|² − r², ≤ 0 exactly when the spheres touch or overlap.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Margin(float dx, float dy, float dz, float r) => dx * dx + dy * dy + dz * dz - r * r;
        }

        private struct SphereAabb<TS> : IKernel where TS : struct, ISpheres
        {
            private TS _a;
            private readonly AabbSet _b;
            private readonly bool _margin;
            public SphereAabb(TS a, AabbSet b, bool margin) { _a = a; _b = b; _margin = margin; }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i) => PointBox(_a.X(i), _a.Y(i), _a.Z(i), _a.R(i),
                new Vector<float>(_b.MinX, i), new Vector<float>(_b.MinY, i), new Vector<float>(_b.MinZ, i),
                new Vector<float>(_b.MaxX, i), new Vector<float>(_b.MaxY, i), new Vector<float>(_b.MaxZ, i), _margin);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i) =>
                PointBox(_a.XAt(i), _a.YAt(i), _a.ZAt(i), _a.RAt(i), _b.MinX[i], _b.MinY[i], _b.MinZ[i], _b.MaxX[i], _b.MaxY[i], _b.MaxZ[i], _margin);

            // The scalar lanes over pinned arrays: one loop each for paired spheres, paired points and one shape
            // broadcast. Through Lane (a field and a bounds check per coordinate) the one-to-many queries ran slower on
            // Mono than the scalar API.

            public unsafe void Values(int start, int end, Span<float> result)
            {
                fixed (float* lx = _b.MinX, ly = _b.MinY, lz = _b.MinZ, hx = _b.MaxX, hy = _b.MaxY, hz = _b.MaxZ, px = _a.Xs, py = _a.Ys, pz = _a.Zs, pr = _a.Rs)
                fixed (float* v = result)
                {
                    if (px == null)
                    {
                        float x = _a.XAt(0), y = _a.YAt(0), z = _a.ZAt(0), r = _a.RAt(0);
                        for (int i = start; i < end; i++) v[i] = PointBox(x, y, z, r, lx[i], ly[i], lz[i], hx[i], hy[i], hz[i], false);
                    }
                    else if (pr == null)
                        for (int i = start; i < end; i++) v[i] = PointBox(px[i], py[i], pz[i], 0, lx[i], ly[i], lz[i], hx[i], hy[i], hz[i], false);
                    else
                        for (int i = start; i < end; i++) v[i] = PointBox(px[i], py[i], pz[i], pr[i], lx[i], ly[i], lz[i], hx[i], hy[i], hz[i], false);
                }
            }

            /// <summary>
            /// Whether the margin d2 − r² is ≤ 0 (only overlap queries ask): points by <see cref="Inside"/> (six sign bits,
            /// measured several times faster on Mono than squaring the gaps), spheres by <see cref="Margin"/>.
            /// </summary>
            public unsafe void Verdicts(int start, int end, Span<bool> result)
            {
                fixed (float* lx = _b.MinX, ly = _b.MinY, lz = _b.MinZ, hx = _b.MaxX, hy = _b.MaxY, hz = _b.MaxZ, px = _a.Xs, py = _a.Ys, pz = _a.Zs, pr = _a.Rs)
                fixed (bool* v = result)
                {
                    if (px == null)
                    {
                        float x = _a.XAt(0), y = _a.YAt(0), z = _a.ZAt(0), r = _a.RAt(0);
                        if (r * r == 0)
                            for (int i = start; i < end; i++) v[i] = Inside(x, y, z, lx[i], ly[i], lz[i], hx[i], hy[i], hz[i]);
                        else
                            for (int i = start; i < end; i++) v[i] = Margin(x, y, z, r, lx[i], ly[i], lz[i], hx[i], hy[i], hz[i]) <= 0;
                    }
                    else if (pr == null)
                        for (int i = start; i < end; i++) v[i] = Inside(px[i], py[i], pz[i], lx[i], ly[i], lz[i], hx[i], hy[i], hz[i]);
                    else
                        for (int i = start; i < end; i++) v[i] = Margin(px[i], py[i], pz[i], pr[i], lx[i], ly[i], lz[i], hx[i], hy[i], hz[i]) <= 0;
                }
            }

            /// <summary>
            /// Whether p − clamp(p, lo, hi) squares to 0 in float on every axis, so d2 = 0 (a point's margin ≤ 0): the
            /// difference is at most 2^-75 in magnitude (its square is then at most 2^-150, which rounds to 0, ties to
            /// even; any larger float difference squares to 2^-149 or more). Each bound is read from a sign bit, without
            /// a branch: (p − lo) + 2^-75 is ≥ 0 exactly when p − lo ≥ −2^-75, since a nonzero exact sum of floats does
            /// not round to 0 and an exact 0 is +0.
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static bool Inside(float px, float py, float pz, float lx, float ly, float lz, float hx, float hy, float hz) =>
                (BitConverter.SingleToInt32Bits(px - lx + SquaresToZero) | BitConverter.SingleToInt32Bits(SquaresToZero - (px - hx))
                | BitConverter.SingleToInt32Bits(py - ly + SquaresToZero) | BitConverter.SingleToInt32Bits(SquaresToZero - (py - hy))
                | BitConverter.SingleToInt32Bits(pz - lz + SquaresToZero) | BitConverter.SingleToInt32Bits(SquaresToZero - (pz - hz))) >= 0;

            private const float SquaresToZero = 1f / (1L << 62) / (1 << 13);
        }

        private struct SphereObb<TS> : IKernel where TS : struct, ISpheres
        {
            private TS _a;
            private readonly ObbSet _b;
            private readonly bool _margin;
            public SphereObb(TS a, ObbSet b, bool margin) { _a = a; _b = b; _margin = margin; }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            public void Verdicts(int start, int end, Span<bool> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                // The center in the box frame (subtract first), then the AABB kernel on [−h, h].
                var wx = _a.X(i) - new Vector<float>(_b.CX, i);
                var wy = _a.Y(i) - new Vector<float>(_b.CY, i);
                var wz = _a.Z(i) - new Vector<float>(_b.CZ, i);
                var qx = wx * new Vector<float>(_b.XX, i) + wy * new Vector<float>(_b.XY, i) + wz * new Vector<float>(_b.XZ, i);
                var qy = wx * new Vector<float>(_b.YX, i) + wy * new Vector<float>(_b.YY, i) + wz * new Vector<float>(_b.YZ, i);
                var qz = wx * new Vector<float>(_b.ZX, i) + wy * new Vector<float>(_b.ZY, i) + wz * new Vector<float>(_b.ZZ, i);
                var hx = new Vector<float>(_b.HX, i);
                var hy = new Vector<float>(_b.HY, i);
                var hz = new Vector<float>(_b.HZ, i);
                return PointBox(qx, qy, qz, _a.R(i), Runner.Negate(hx), Runner.Negate(hy), Runner.Negate(hz), hx, hy, hz, _margin);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                var wx = _a.XAt(i) - _b.CX[i];
                var wy = _a.YAt(i) - _b.CY[i];
                var wz = _a.ZAt(i) - _b.CZ[i];
                var qx = wx * _b.XX[i] + wy * _b.XY[i] + wz * _b.XZ[i];
                var qy = wx * _b.YX[i] + wy * _b.YY[i] + wz * _b.YZ[i];
                var qz = wx * _b.ZX[i] + wy * _b.ZY[i] + wz * _b.ZZ[i];
                float hx = _b.HX[i], hy = _b.HY[i], hz = _b.HZ[i];
                return PointBox(qx, qy, qz, _a.RAt(i), -hx, -hy, -hz, hx, hy, hz, _margin);
            }
        }

        /// <summary>
        /// Segment–segment without branches: the best of five candidate pairs, every one a pair of real points, so a
        /// noisy candidate can only lose: a point of a against segment b, where the point is the clamped stationary
        /// point of the lines (from the Lagrange-identity determinant |d0 × d1|²), and each endpoint against the other
        /// segment. That point's partner is its closest point on b, not the lines' own stationary t: for nearly parallel
        /// segments both stationary parameters are off by up to ~u·S/sin²θ along the lines, and two independent errors
        /// leave the pair about that far apart (E in the thousands), while a point of a off by δ along the lines, with
        /// its partner following, misses the distance by at most δ·sin θ, and by far less when the lines do not meet;
        /// where even that is too much, an endpoint candidate is closer.
        /// </summary>
        private struct SegmentSegment<TA> : IKernel where TA : struct, ISegments
        {
            private TA _a;
            private readonly SegmentSet _b;
            public SegmentSegment(TA a, SegmentSet b) { _a = a; _b = b; }

            public void Verdicts(int start, int end, Span<bool> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var a0 = new V3(_a.AX(i), _a.AY(i), _a.AZ(i));
                var b0 = new V3(new Vector<float>(_b.AX, i), new Vector<float>(_b.AY, i), new Vector<float>(_b.AZ, i));
                var d0 = new V3(_a.BX(i) - a0.X, _a.BY(i) - a0.Y, _a.BZ(i) - a0.Z);
                var d1 = new V3(new Vector<float>(_b.BX, i) - b0.X, new Vector<float>(_b.BY, i) - b0.Y, new Vector<float>(_b.BZ, i) - b0.Z);
                var w = new V3(b0.X - a0.X, b0.Y - a0.Y, b0.Z - a0.Z);
                var dd0 = V3.Dot(d0, d0);
                var dd1 = V3.Dot(d1, d1);

                // s = ((w × d1)·n)/|n|² with n = d0 × d1: the quotient of two fourth powers of the lengths, subnormal
                // (imprecise) for short segments inside the safe range. Dividing both by about the larger squared length
                // (g, a power of two: exact) leaves squares. Where |n|²·g still underflows, the shorter segment times
                // sin θ is below 2^−63, and the endpoint candidates are that close to the answer.
                var n = Cross(d0, d1);
                var g = PowerOfTwoInverse(Runner.MaxNative(dd0, dd1));
                var ng = new V3(n.X * g, n.Y * g, n.Z * g);
                var nng = V3.Dot(n, ng);
                var s = Vector.ConditionalSelect(Vector.GreaterThan(nng, Vector<float>.Zero),
                    Runner.Clamp(V3.Dot(Cross(w, d1), ng) / nng, Vector<float>.Zero, Vector<float>.One), Vector<float>.Zero);

                // a(s) against segment b (offset a0 + s·d0 − b0 = s·d0 − w), a0 against b (−w), a1 against b (d0 − w),
                // b0 against a (w), b1 against a (w + d1).
                var inv0 = Reciprocal(dd0);
                var inv1 = Reciprocal(dd1);
                var best = PointSegment2(d0.X * s - w.X, d0.Y * s - w.Y, d0.Z * s - w.Z, d1, inv1);
                best = Runner.MinNative(best, PointSegment2(Runner.Negate(w.X), Runner.Negate(w.Y), Runner.Negate(w.Z), d1, inv1));
                best = Runner.MinNative(best, PointSegment2(d0.X - w.X, d0.Y - w.Y, d0.Z - w.Z, d1, inv1));
                best = Runner.MinNative(best, PointSegment2(w.X, w.Y, w.Z, d0, inv0));
                best = Runner.MinNative(best, PointSegment2(w.X + d1.X, w.Y + d1.Y, w.Z + d1.Z, d0, inv0));
                return Vector.SquareRoot(best);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                _a.EndsAt(i, out var a);
                return Distance(a, _b.AX[i], _b.AY[i], _b.AZ[i], _b.BX[i], _b.BY[i], _b.BZ[i]);
            }

            /// <summary>The scalar lanes over pinned arrays (through <see cref="Lane"/>, one-to-many ran slower on Mono than the scalar API).</summary>
            public unsafe void Values(int start, int end, Span<float> result)
            {
                var set = _a.Set;
                _a.EndsAt(0, out var a);
                fixed (float* b0x = _b.AX, b0y = _b.AY, b0z = _b.AZ, b1x = _b.BX, b1y = _b.BY, b1z = _b.BZ)
                fixed (float* a0x = set?.AX, a0y = set?.AY, a0z = set?.AZ, a1x = set?.BX, a1y = set?.BY, a1z = set?.BZ)
                fixed (float* v = result)
                {
                    for (int i = start; i < end; i++)
                    {
                        if (a0x != null)
                        {
                            a.AX = a0x[i]; a.AY = a0y[i]; a.AZ = a0z[i]; a.BX = a1x[i]; a.BY = a1y[i]; a.BZ = a1z[i];
                        }
                        v[i] = Distance(a, b0x[i], b0y[i], b0z[i], b1x[i], b1y[i], b1z[i]);
                    }
                }
            }

            /// <summary>One lane of <see cref="Compute"/>: segment a against the segment from b0 to b1.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Distance(in SegmentLane a, float b0x, float b0y, float b0z, float b1x, float b1y, float b1z)
            {
                float d0x = a.BX - a.AX, d0y = a.BY - a.AY, d0z = a.BZ - a.AZ;
                float d1x = b1x - b0x, d1y = b1y - b0y, d1z = b1z - b0z;
                float wx = b0x - a.AX, wy = b0y - a.AY, wz = b0z - a.AZ;
                var dd0 = d0x * d0x + d0y * d0y + d0z * d0z;
                var dd1 = d1x * d1x + d1y * d1y + d1z * d1z;

                float nx = d0y * d1z - d0z * d1y, ny = d0z * d1x - d0x * d1z, nz = d0x * d1y - d0y * d1x;
                var g = PowerOfTwoInverse(dd0 > dd1 ? dd0 : dd1);
                float ngx = nx * g, ngy = ny * g, ngz = nz * g;
                var nng = nx * ngx + ny * ngy + nz * ngz;
                float s = 0;
                if (nng > 0)
                {
                    float cx = wy * d1z - wz * d1y, cy = wz * d1x - wx * d1z, cz = wx * d1y - wy * d1x;
                    s = Runner.Clamp((cx * ngx + cy * ngy + cz * ngz) / nng, 0, 1);
                }

                var inv0 = Reciprocal(dd0);
                var inv1 = Reciprocal(dd1);
                var best = PointSegment2(d0x * s - wx, d0y * s - wy, d0z * s - wz, d1x, d1y, d1z, inv1);
                best = Min(best, PointSegment2(-wx, -wy, -wz, d1x, d1y, d1z, inv1));
                best = Min(best, PointSegment2(d0x - wx, d0y - wy, d0z - wz, d1x, d1y, d1z, inv1));
                best = Min(best, PointSegment2(wx, wy, wz, d0x, d0y, d0z, inv0));
                best = Min(best, PointSegment2(wx + d1x, wy + d1y, wz + d1z, d0x, d0y, d0z, inv0));
                return Runner.Sqrt(best);
            }

            /// <summary>The scalar lanes' minimum of two squared distances (never −0): minps's rule, as the vector lanes' <see cref="Runner.MinNative"/>.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Min(float a, float b) => a < b ? a : b;

            /// <summary>
            /// 1/dd for a squared length dd, or 0 below 2^−126, where 1/dd could overflow: such a segment is shorter than
            /// 2^−63, and as a point at its start it is off by far less than u·S in the safe range.
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Vector<float> Reciprocal(Vector<float> dd) =>
                Vector.ConditionalSelect(Vector.GreaterThanOrEqual(dd, new Vector<float>(MinNormal)), Vector<float>.One / dd, Vector<float>.Zero);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Reciprocal(float dd) => dd >= MinNormal ? 1 / dd : 0;

            /// <summary>The smallest normal float, 2^−126.</summary>
            private const float MinNormal = 1.17549435E-38f;

            /// <summary>
            /// 2^−e for x in [2^e, 2^(e+1)), from the exponent bits alone (exact, no division). x below 2^−126 (zero or
            /// subnormal) gives 2^127; x from 2^127 up (outside any safe range) gives 0 or a non-finite factor, whose lane
            /// the determinant test then rejects.
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Vector<float> PowerOfTwoInverse(Vector<float> x) =>
                Vector.AsVectorSingle(new Vector<int>(0x7F000000) - (Vector.AsVectorInt32(x) & new Vector<int>(0x7F800000)));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float PowerOfTwoInverse(float x) => BitConverter.Int32BitsToSingle(0x7F000000 - (BitConverter.SingleToInt32Bits(x) & 0x7F800000));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static V3 Cross(in V3 a, in V3 b) => new V3(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Vector<float> Residual2(Vector<float> x, Vector<float> y, Vector<float> z) => x * x + y * y + z * z;

            /// <summary>
            /// Squared distance from a point at offset (px, py, pz) from a segment's start to the segment d, given
            /// <see cref="Reciprocal(Vector{float})"/> of its squared length (one division per segment, not per candidate).
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Vector<float> PointSegment2(Vector<float> px, Vector<float> py, Vector<float> pz, in V3 d, Vector<float> inv)
            {
                var t = Runner.Clamp((px * d.X + py * d.Y + pz * d.Z) * inv, Vector<float>.Zero, Vector<float>.One);
                return Residual2(px - d.X * t, py - d.Y * t, pz - d.Z * t);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float PointSegment2(float px, float py, float pz, float dx, float dy, float dz, float inv)
            {
                var t = Runner.Clamp((px * dx + py * dy + pz * dz) * inv, 0, 1);
                float rx = px - dx * t, ry = py - dy * t, rz = pz - dz * t;
                return rx * rx + ry * ry + rz * rz;
            }
        }

        /// <summary>
        /// OBB–OBB separating-axis test without branches: the largest separation over the 15 axes (≤ 0 exactly when no
        /// axis separates). Cross axes project B through the minors of R, as the scalar test does.
        /// </summary>
        private struct ObbObb<TA> : IKernel where TA : struct, IObbs
        {
            private TA _a;
            private readonly ObbSet _b;
            public ObbObb(TA a, ObbSet b) { _a = a; _b = b; }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                _a.Load(i, out var ca, out var ax, out var ay, out var az, out var ha);
                new ObbLanes(_b).Load(i, out var cb, out var bx, out var by, out var bz, out var hb);
                var tw = new V3(cb.X - ca.X, cb.Y - ca.Y, cb.Z - ca.Z);
                Vector<float> tx = V3.Dot(tw, ax), ty = V3.Dot(tw, ay), tz = V3.Dot(tw, az);
                Vector<float> r00 = V3.Dot(ax, bx), r01 = V3.Dot(ax, by), r02 = V3.Dot(ax, bz);
                Vector<float> r10 = V3.Dot(ay, bx), r11 = V3.Dot(ay, by), r12 = V3.Dot(ay, bz);
                Vector<float> r20 = V3.Dot(az, bx), r21 = V3.Dot(az, by), r22 = V3.Dot(az, bz);
                Vector<float> q00 = Vector.Abs(r00), q01 = Vector.Abs(r01), q02 = Vector.Abs(r02);
                Vector<float> q10 = Vector.Abs(r10), q11 = Vector.Abs(r11), q12 = Vector.Abs(r12);
                Vector<float> q20 = Vector.Abs(r20), q21 = Vector.Abs(r21), q22 = Vector.Abs(r22);

                var sep = Vector.Abs(tx) - (ha.X + hb.X * q00 + hb.Y * q01 + hb.Z * q02);
                sep = Runner.MaxNative(sep, Vector.Abs(ty) - (ha.Y + hb.X * q10 + hb.Y * q11 + hb.Z * q12));
                sep = Runner.MaxNative(sep, Vector.Abs(tz) - (ha.Z + hb.X * q20 + hb.Y * q21 + hb.Z * q22));
                sep = Runner.MaxNative(sep, Vector.Abs(tx * r00 + ty * r10 + tz * r20) - (ha.X * q00 + ha.Y * q10 + ha.Z * q20 + hb.X));
                sep = Runner.MaxNative(sep, Vector.Abs(tx * r01 + ty * r11 + tz * r21) - (ha.X * q01 + ha.Y * q11 + ha.Z * q21 + hb.Y));
                sep = Runner.MaxNative(sep, Vector.Abs(tx * r02 + ty * r12 + tz * r22) - (ha.X * q02 + ha.Y * q12 + ha.Z * q22 + hb.Z));
                sep = Runner.MaxNative(sep, Cross(tz * r10 - ty * r20, ha.Y * q20 + ha.Z * q10, hb.Y, r11 * r20 - r21 * r10, hb.Z, r12 * r20 - r22 * r10));
                sep = Runner.MaxNative(sep, Cross(tz * r11 - ty * r21, ha.Y * q21 + ha.Z * q11, hb.X, r10 * r21 - r20 * r11, hb.Z, r12 * r21 - r22 * r11));
                sep = Runner.MaxNative(sep, Cross(tz * r12 - ty * r22, ha.Y * q22 + ha.Z * q12, hb.X, r10 * r22 - r20 * r12, hb.Y, r11 * r22 - r21 * r12));
                sep = Runner.MaxNative(sep, Cross(tx * r20 - tz * r00, ha.X * q20 + ha.Z * q00, hb.Y, r01 * r20 - r21 * r00, hb.Z, r02 * r20 - r22 * r00));
                sep = Runner.MaxNative(sep, Cross(tx * r21 - tz * r01, ha.X * q21 + ha.Z * q01, hb.X, r00 * r21 - r20 * r01, hb.Z, r02 * r21 - r22 * r01));
                sep = Runner.MaxNative(sep, Cross(tx * r22 - tz * r02, ha.X * q22 + ha.Z * q02, hb.X, r00 * r22 - r20 * r02, hb.Y, r01 * r22 - r21 * r02));
                sep = Runner.MaxNative(sep, Cross(ty * r00 - tx * r10, ha.X * q10 + ha.Y * q00, hb.Y, r11 * r00 - r01 * r10, hb.Z, r12 * r00 - r02 * r10));
                sep = Runner.MaxNative(sep, Cross(ty * r01 - tx * r11, ha.X * q11 + ha.Y * q01, hb.X, r10 * r01 - r00 * r11, hb.Z, r12 * r01 - r02 * r11));
                return Runner.MaxNative(sep, Cross(ty * r02 - tx * r12, ha.X * q12 + ha.Y * q02, hb.X, r10 * r02 - r00 * r12, hb.Y, r11 * r02 - r01 * r12));
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static Vector<float> Cross(Vector<float> tl, Vector<float> ra, Vector<float> h1, Vector<float> m1, Vector<float> h2, Vector<float> m2) =>
                Vector.Abs(tl) - (ra + h1 * Vector.Abs(m1) + h2 * Vector.Abs(m2));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                _a.LoadAt(i, out var a);
                new ObbLanes(_b).LoadAt(i, out var b);
                return Separation(a, b);
            }

            /// <summary>
            /// The scalar verdicts over pinned arrays: through <see cref="Lane"/> (a field and a bounds check for each of
            /// the 30 floats) the paired verdicts ran slower on Mono than the scalar API.
            /// </summary>
            public unsafe void Verdicts(int start, int end, Span<bool> result)
            {
                var a = _a.Set;
                _a.LoadAt(0, out var one);
                var b = _b;
                fixed (float* bcx = b.CX, bcy = b.CY, bcz = b.CZ, bxx = b.XX, bxy = b.XY, bxz = b.XZ, byx = b.YX, byy = b.YY, byz = b.YZ,
                       bzx = b.ZX, bzy = b.ZY, bzz = b.ZZ, bhx = b.HX, bhy = b.HY, bhz = b.HZ)
                fixed (float* acx = a?.CX, acy = a?.CY, acz = a?.CZ, axx = a?.XX, axy = a?.XY, axz = a?.XZ, ayx = a?.YX, ayy = a?.YY, ayz = a?.YZ,
                       azx = a?.ZX, azy = a?.ZY, azz = a?.ZZ, ahx = a?.HX, ahy = a?.HY, ahz = a?.HZ)
                fixed (bool* v = result)
                {
                    ObbLane bi;
                    for (int i = start; i < end; i++)
                    {
                        bi.CX = bcx[i]; bi.CY = bcy[i]; bi.CZ = bcz[i]; bi.XX = bxx[i]; bi.XY = bxy[i]; bi.XZ = bxz[i];
                        bi.YX = byx[i]; bi.YY = byy[i]; bi.YZ = byz[i]; bi.ZX = bzx[i]; bi.ZY = bzy[i]; bi.ZZ = bzz[i];
                        bi.HX = bhx[i]; bi.HY = bhy[i]; bi.HZ = bhz[i];
                        if (acx != null)
                        {
                            one.CX = acx[i]; one.CY = acy[i]; one.CZ = acz[i]; one.XX = axx[i]; one.XY = axy[i]; one.XZ = axz[i];
                            one.YX = ayx[i]; one.YY = ayy[i]; one.YZ = ayz[i]; one.ZX = azx[i]; one.ZY = azy[i]; one.ZZ = azz[i];
                            one.HX = ahx[i]; one.HY = ahy[i]; one.HZ = ahz[i];
                        }
                        v[i] = Separation(one, bi) <= 0;
                    }
                }
            }

            /// <summary>
            /// The axes' separations as <see cref="Compute"/> forms them, stopping at the first that is not ≤ 0. A's rows of
            /// R are formed as its face axes need them, so a pair that its first face axis separates (most pairs apart)
            /// pays for a third of the products.
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Separation(in ObbLane a, in ObbLane b)
            {
                float twx = b.CX - a.CX, twy = b.CY - a.CY, twz = b.CZ - a.CZ;
                float hax = a.HX, hay = a.HY, haz = a.HZ, hbx = b.HX, hby = b.HY, hbz = b.HZ;
                float tx = twx * a.XX + twy * a.XY + twz * a.XZ;
                float r00 = a.XX * b.XX + a.XY * b.XY + a.XZ * b.XZ, r01 = a.XX * b.YX + a.XY * b.YY + a.XZ * b.YZ, r02 = a.XX * b.ZX + a.XY * b.ZY + a.XZ * b.ZZ;
                float q00 = Runner.Abs(r00), q01 = Runner.Abs(r01), q02 = Runner.Abs(r02);
                float sep;
                if (!((sep = Runner.Abs(tx) - (hax + hbx * q00 + hby * q01 + hbz * q02)) <= 0)) return sep;
                float ty = twx * a.YX + twy * a.YY + twz * a.YZ;
                float r10 = a.YX * b.XX + a.YY * b.XY + a.YZ * b.XZ, r11 = a.YX * b.YX + a.YY * b.YY + a.YZ * b.YZ, r12 = a.YX * b.ZX + a.YY * b.ZY + a.YZ * b.ZZ;
                float q10 = Runner.Abs(r10), q11 = Runner.Abs(r11), q12 = Runner.Abs(r12);
                if (!((sep = Runner.Abs(ty) - (hay + hbx * q10 + hby * q11 + hbz * q12)) <= 0)) return sep;
                float tz = twx * a.ZX + twy * a.ZY + twz * a.ZZ;
                float r20 = a.ZX * b.XX + a.ZY * b.XY + a.ZZ * b.XZ, r21 = a.ZX * b.YX + a.ZY * b.YY + a.ZZ * b.YZ, r22 = a.ZX * b.ZX + a.ZY * b.ZY + a.ZZ * b.ZZ;
                float q20 = Runner.Abs(r20), q21 = Runner.Abs(r21), q22 = Runner.Abs(r22);
                if (!((sep = Runner.Abs(tz) - (haz + hbx * q20 + hby * q21 + hbz * q22)) <= 0)) return sep;
                if (!((sep = Runner.Abs(tx * r00 + ty * r10 + tz * r20) - (hax * q00 + hay * q10 + haz * q20 + hbx)) <= 0)) return sep;
                if (!((sep = Runner.Abs(tx * r01 + ty * r11 + tz * r21) - (hax * q01 + hay * q11 + haz * q21 + hby)) <= 0)) return sep;
                if (!((sep = Runner.Abs(tx * r02 + ty * r12 + tz * r22) - (hax * q02 + hay * q12 + haz * q22 + hbz)) <= 0)) return sep;
                if (!((sep = Cross(tz * r10 - ty * r20, hay * q20 + haz * q10, hby, r11 * r20 - r21 * r10, hbz, r12 * r20 - r22 * r10)) <= 0)) return sep;
                if (!((sep = Cross(tz * r11 - ty * r21, hay * q21 + haz * q11, hbx, r10 * r21 - r20 * r11, hbz, r12 * r21 - r22 * r11)) <= 0)) return sep;
                if (!((sep = Cross(tz * r12 - ty * r22, hay * q22 + haz * q12, hbx, r10 * r22 - r20 * r12, hby, r11 * r22 - r21 * r12)) <= 0)) return sep;
                if (!((sep = Cross(tx * r20 - tz * r00, hax * q20 + haz * q00, hby, r01 * r20 - r21 * r00, hbz, r02 * r20 - r22 * r00)) <= 0)) return sep;
                if (!((sep = Cross(tx * r21 - tz * r01, hax * q21 + haz * q01, hbx, r00 * r21 - r20 * r01, hbz, r02 * r21 - r22 * r01)) <= 0)) return sep;
                if (!((sep = Cross(tx * r22 - tz * r02, hax * q22 + haz * q02, hbx, r00 * r22 - r20 * r02, hby, r01 * r22 - r21 * r02)) <= 0)) return sep;
                if (!((sep = Cross(ty * r00 - tx * r10, hax * q10 + hay * q00, hby, r11 * r00 - r01 * r10, hbz, r12 * r00 - r02 * r10)) <= 0)) return sep;
                if (!((sep = Cross(ty * r01 - tx * r11, hax * q11 + hay * q01, hbx, r10 * r01 - r00 * r11, hbz, r12 * r01 - r02 * r11)) <= 0)) return sep;
                return Cross(ty * r02 - tx * r12, hax * q12 + hay * q02, hbx, r10 * r02 - r00 * r12, hby, r11 * r02 - r01 * r12);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static float Cross(float tl, float ra, float h1, float m1, float h2, float m2) =>
                Runner.Abs(tl) - (ra + h1 * Runner.Abs(m1) + h2 * Runner.Abs(m2));
        }

        private struct AabbAabb<TA> : IKernel where TA : struct, IAabbs
        {
            private TA _a;
            private readonly AabbSet _b;
            public AabbAabb(TA a, AabbSet b) { _a = a; _b = b; }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            /// <summary>The largest per-axis gap: ≤ 0 exactly when the boxes touch or overlap (paper Eq. 18).</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var gx = Runner.MaxNative(new Vector<float>(_b.MinX, i) - _a.MaxX(i), _a.MinX(i) - new Vector<float>(_b.MaxX, i));
                var gy = Runner.MaxNative(new Vector<float>(_b.MinY, i) - _a.MaxY(i), _a.MinY(i) - new Vector<float>(_b.MaxY, i));
                var gz = Runner.MaxNative(new Vector<float>(_b.MinZ, i) - _a.MaxZ(i), _a.MinZ(i) - new Vector<float>(_b.MaxZ, i));
                return Runner.MaxNative(gx, Runner.MaxNative(gy, gz));
            }

            /// <summary>−1 where the boxes touch or overlap, else 1 (<see cref="Touch"/>).</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                _a.CornersAt(i, out var minX, out var minY, out var minZ, out var maxX, out var maxY, out var maxZ);
                return Touch(minX, minY, minZ, maxX, maxY, maxZ, _b.MinX[i], _b.MinY[i], _b.MinZ[i], _b.MaxX[i], _b.MaxY[i], _b.MaxZ[i]) ? -1 : 1;
            }

            /// <summary>
            /// The scalar verdicts over pinned arrays, one loop for paired sets and one for a broadcast box, each written
            /// out in the loop: reading the sets through <see cref="Lane"/> (a field and a bounds check per coordinate) made
            /// them slower on Mono than the scalar API, and so did calling <see cref="Touch"/>, which Mono 6.8 inlines by
            /// loading all twelve coordinates and storing each to the stack first (Mono, ab against that: 0.91× paired,
            /// 0.75× one-to-many). The sign bits of the six differences hi − lo are joined without a branch: comparisons that
            /// stop at the first separating axis took 2.2–3.9 ns a pair on Mono where the benchmark repeats 1024 pairs (the
            /// branch predictor learns the sequence), but 10.5 over 65,536 pairs, where these took 6.4. A difference of
            /// floats is 0 only when they are equal, and never −0 then because the shapes store no −0 (−0 − +0 would be
            /// −0); its sign survives overflow to ±∞.
            /// </summary>
            public unsafe void Verdicts(int start, int end, Span<bool> result)
            {
                fixed (float* bx0 = _b.MinX, by0 = _b.MinY, bz0 = _b.MinZ, bx1 = _b.MaxX, by1 = _b.MaxY, bz1 = _b.MaxZ)
                fixed (bool* r = result)
                {
                    var set = _a.Set;
                    if (set != null)
                    {
                        fixed (float* ax0 = set.MinX, ay0 = set.MinY, az0 = set.MinZ, ax1 = set.MaxX, ay1 = set.MaxY, az1 = set.MaxZ)
                            for (int i = start; i < end; i++)
                                r[i] = (BitConverter.SingleToInt32Bits(ax1[i] - bx0[i]) | BitConverter.SingleToInt32Bits(bx1[i] - ax0[i])
                                    | BitConverter.SingleToInt32Bits(ay1[i] - by0[i]) | BitConverter.SingleToInt32Bits(by1[i] - ay0[i])
                                    | BitConverter.SingleToInt32Bits(az1[i] - bz0[i]) | BitConverter.SingleToInt32Bits(bz1[i] - az0[i])) >= 0;
                    }
                    else
                    {
                        _a.CornersAt(0, out var minX, out var minY, out var minZ, out var maxX, out var maxY, out var maxZ);
                        for (int i = start; i < end; i++)
                            r[i] = (BitConverter.SingleToInt32Bits(maxX - bx0[i]) | BitConverter.SingleToInt32Bits(bx1[i] - minX)
                                | BitConverter.SingleToInt32Bits(maxY - by0[i]) | BitConverter.SingleToInt32Bits(by1[i] - minY)
                                | BitConverter.SingleToInt32Bits(maxZ - bz0[i]) | BitConverter.SingleToInt32Bits(bz1[i] - minZ)) >= 0;
                    }
                }
            }

            /// <summary>
            /// Whether every gap lo − hi of <see cref="Compute"/> is ≤ 0, read from the sign bits of hi − lo without a
            /// branch, as <see cref="Verdicts"/> writes it out (see there): so these are the vector lanes' verdicts.
            /// </summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static bool Touch(float ax0, float ay0, float az0, float ax1, float ay1, float az1, float bx0, float by0, float bz0, float bx1, float by1, float bz1) =>
                (BitConverter.SingleToInt32Bits(ax1 - bx0) | BitConverter.SingleToInt32Bits(bx1 - ax0)
                | BitConverter.SingleToInt32Bits(ay1 - by0) | BitConverter.SingleToInt32Bits(by1 - ay0)
                | BitConverter.SingleToInt32Bits(az1 - bz0) | BitConverter.SingleToInt32Bits(bz1 - az0)) >= 0;
        }
    }
}
