// Copied from src/ProximityLib/Batch/Raycasts.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace ProximityLib.Batch
{
    // One ray against many shapes. Each lane's value is the distance along the ray's direction (rounded to float) to
    // the first hit, 0 when the origin lies in a solid (sphere, box), +∞ for a miss or a hit beyond maxDistance. The ray
    // is the same in every lane, so whatever depends on it alone (which axis a box slab divides by, the triangle's
    // shear) is chosen once per call and every lane runs the same branch-free code; the scalar lanes run the same
    // operations in the same order, so the same bits.
    public static partial class BatchQuery
    {
        /// <summary>Distance along the ray to its first hit on each sphere of b (0 when it starts inside one), +∞ for a miss or a hit beyond <paramref name="maxDistance"/>; throws <see cref="ArgumentException"/> when maxDistance is negative or NaN.</summary>
        public static void Raycasts(Ray3 ray, SphereSet b, Span<float> result, float maxDistance = float.PositiveInfinity) =>
            Runner.Values(new RaySpheres(new RayLanes(ray, maxDistance), b), b.Count, result);

        /// <summary>Distance along the ray to its first hit on each box of b (slab test; 0 when it starts inside one), +∞ for a miss or a hit beyond <paramref name="maxDistance"/>; throws <see cref="ArgumentException"/> when maxDistance is negative or NaN.</summary>
        public static void Raycasts(Ray3 ray, AabbSet b, Span<float> result, float maxDistance = float.PositiveInfinity) =>
            Runner.Values(new RayAabbs(new RayLanes(ray, maxDistance), b), b.Count, result);

        /// <summary>
        /// Distance along the ray to its first hit on each triangle of b (two-sided, watertight in float: a ray through a
        /// shared edge hits at least one of its triangles), +∞ for a miss or a hit beyond <paramref name="maxDistance"/>. A
        /// lane the float test hits whose determinant is within 2^-11 of its edge functions' first products (a degenerate or sliver triangle,
        /// a ray in or nearly in the triangle's plane: its T would be rounding) is answered as the scalar
        /// <see cref="Raycast"/> answers it, edge-on hits included. Throws <see cref="ArgumentException"/> when
        /// maxDistance is negative or NaN.
        /// </summary>
        public static void Raycasts(Ray3 ray, TriangleSet b, Span<float> result, float maxDistance = float.PositiveInfinity) =>
            Runner.Values(new RayTriangles(new RayLanes(ray, maxDistance), ray, b), b.Count, result);

        /// <summary>The ray in float, broadcast, with the maximum distance.</summary>
        private readonly struct RayLanes
        {
            public readonly float OX, OY, OZ, DX, DY, DZ, Max;

            public RayLanes(Ray3 ray, float maxDistance)
            {
                if (!(maxDistance >= 0))
                    throw new ArgumentException($"maxDistance must be non-negative and not NaN (got {maxDistance}).", nameof(maxDistance));
                var o = ray.Origin;
                var d = ray.Direction;
                OX = o.X; OY = o.Y; OZ = o.Z; DX = d.X; DY = d.Y; DZ = d.Z; Max = maxDistance;
            }

            public float O(int k) => k == 0 ? OX : k == 1 ? OY : OZ;
            public float D(int k) => k == 0 ? DX : k == 1 ? DY : DZ;

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Limit(Vector<int> hit, Vector<float> t) =>
                Vector.ConditionalSelect(hit & Vector.LessThanOrEqual(t, new Vector<float>(Max)), t, new Vector<float>(float.PositiveInfinity));

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Limit(bool hit, float t) => hit && t <= Max ? t : float.PositiveInfinity;
        }

        /// <summary>
        /// Ray–sphere as the scalar kernel computes it: inside (|w| ≤ r) gives 0; else a hit needs b = w·d &lt; 0 and the
        /// perpendicular distance h ≤ r, at (|w| − r)(|w| + r) / (√((r − h)(r + h)) − b), the root that does not cancel.
        /// </summary>
        private struct RaySpheres : IKernel
        {
            private readonly RayLanes _r;
            private readonly SphereSet _b;
            public RaySpheres(RayLanes r, SphereSet b) { _r = r; _b = b; }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            public void Verdicts(int start, int end, Span<bool> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var wx = new Vector<float>(_r.OX) - new Vector<float>(_b.X, i);
                var wy = new Vector<float>(_r.OY) - new Vector<float>(_b.Y, i);
                var wz = new Vector<float>(_r.OZ) - new Vector<float>(_b.Z, i);
                var r = new Vector<float>(_b.R, i);
                Vector<float> dx = new Vector<float>(_r.DX), dy = new Vector<float>(_r.DY), dz = new Vector<float>(_r.DZ);
                var wl = Vector.SquareRoot(wx * wx + wy * wy + wz * wz);
                var b = wx * dx + wy * dy + wz * dz;
                Vector<float> qx = wx - dx * b, qy = wy - dy * b, qz = wz - dz * b;
                var h = Vector.SquareRoot(qx * qx + qy * qy + qz * qz);
                var t = (wl - r) * (wl + r) / (Vector.SquareRoot((r - h) * (r + h)) - b);
                var inside = Vector.LessThanOrEqual(wl, r);
                var hit = inside | (Vector.LessThan(b, Vector<float>.Zero) & Vector.LessThanOrEqual(h, r));
                return _r.Limit(hit, Vector.ConditionalSelect(inside, Vector<float>.Zero, t));
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                float wx = _r.OX - _b.X[i], wy = _r.OY - _b.Y[i], wz = _r.OZ - _b.Z[i], r = _b.R[i];
                float dx = _r.DX, dy = _r.DY, dz = _r.DZ;
                var wl = Runner.Sqrt(wx * wx + wy * wy + wz * wz);
                if (wl <= r) return _r.Limit(true, 0);
                var b = wx * dx + wy * dy + wz * dz;
                float qx = wx - dx * b, qy = wy - dy * b, qz = wz - dz * b;
                var h = Runner.Sqrt(qx * qx + qy * qy + qz * qz);
                if (!(b < 0 && h <= r)) return float.PositiveInfinity;
                return _r.Limit(true, (wl - r) * (wl + r) / (Runner.Sqrt((r - h) * (r + h)) - b));
            }
        }

        /// <summary>
        /// Slab test. Per axis the ray fixes which face is near (d &gt; 0: Min) and whether the axis is a containment test
        /// instead (d = 0: no division, so no 0·∞); entry = largest near-face time, exit = smallest far-face time, both by
        /// compare-and-select (no NaN can arise, and the scalar lanes pick the same bits).
        /// </summary>
        private struct RayAabbs : IKernel
        {
            private readonly RayLanes _r;
            private readonly float[] _nearX, _nearY, _nearZ, _farX, _farY, _farZ;

            public RayAabbs(RayLanes r, AabbSet b)
            {
                _r = r;
                _nearX = r.DX < 0 ? b.MaxX : b.MinX; _farX = r.DX < 0 ? b.MinX : b.MaxX;
                _nearY = r.DY < 0 ? b.MaxY : b.MinY; _farY = r.DY < 0 ? b.MinY : b.MaxY;
                _nearZ = r.DZ < 0 ? b.MaxZ : b.MinZ; _farZ = r.DZ < 0 ? b.MinZ : b.MaxZ;
            }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            public void Verdicts(int start, int end, Span<bool> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var enter = new Vector<float>(float.NegativeInfinity);
                var exit = new Vector<float>(float.PositiveInfinity);
                var ok = new Vector<int>(-1);
                Axis(_r.OX, _r.DX, new Vector<float>(_nearX, i), new Vector<float>(_farX, i), ref enter, ref exit, ref ok);
                Axis(_r.OY, _r.DY, new Vector<float>(_nearY, i), new Vector<float>(_farY, i), ref enter, ref exit, ref ok);
                Axis(_r.OZ, _r.DZ, new Vector<float>(_nearZ, i), new Vector<float>(_farZ, i), ref enter, ref exit, ref ok);
                var hit = ok & Vector.LessThanOrEqual(enter, exit) & Vector.GreaterThanOrEqual(exit, Vector<float>.Zero);
                return _r.Limit(hit, Vector.ConditionalSelect(Vector.GreaterThan(enter, Vector<float>.Zero), enter, Vector<float>.Zero));
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static void Axis(float o, float d, Vector<float> near, Vector<float> far, ref Vector<float> enter, ref Vector<float> exit, ref Vector<int> ok)
            {
                var vo = new Vector<float>(o);
                if (d == 0)
                {
                    // near is Min and far is Max here.
                    ok &= Vector.LessThanOrEqual(near, vo) & Vector.LessThanOrEqual(vo, far);
                    return;
                }
                var vd = new Vector<float>(d);
                var tn = (near - vo) / vd;
                var tf = (far - vo) / vd;
                enter = Vector.ConditionalSelect(Vector.GreaterThan(tn, enter), tn, enter);
                exit = Vector.ConditionalSelect(Vector.LessThan(tf, exit), tf, exit);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                float enter = float.NegativeInfinity, exit = float.PositiveInfinity;
                bool ok = Axis(_r.OX, _r.DX, _nearX[i], _farX[i], ref enter, ref exit)
                    & Axis(_r.OY, _r.DY, _nearY[i], _farY[i], ref enter, ref exit)
                    & Axis(_r.OZ, _r.DZ, _nearZ[i], _farZ[i], ref enter, ref exit);
                return _r.Limit(ok && enter <= exit && exit >= 0, enter > 0 ? enter : 0);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            private static bool Axis(float o, float d, float near, float far, ref float enter, ref float exit)
            {
                if (d == 0) return near <= o && o <= far;
                float tn = (near - o) / d, tf = (far - o) / d;
                enter = tn > enter ? tn : enter;
                exit = tf < exit ? tf : exit;
                return true;
            }
        }

        /// <summary>
        /// Watertight ray–triangle (Woop, Benthin and Wald 2013) in float: the vertices relative to the origin, sheared
        /// so the ray runs along its dominant axis kz (the arrays are picked in that axis order once per call); edge
        /// functions U, V, W of one sign (zeros included) make a hit. T is U, V, W's weighted mean of the vertices' depths
        /// over the determinant U + V + W, so where that is near the rounding of its terms (a sliver, a ray nearly in the
        /// plane) the weights are noise and T can land anywhere on the triangle's span along the ray (fuzz 12:54466:
        /// 6e-6 off a needle, 38 U): those lanes, rare in a scene, go to the scalar cast.
        /// </summary>
        private struct RayTriangles : IKernel
        {
            /// <summary>
            /// 2^-11: a determinant at most this share of |U|'s, |V|'s and |W|'s first products is ill-conditioned. Where U
            /// cancels, its two products are about equal, so the first stands for both; where it does not, its rounding
            /// is a rounding of |U| ≤ |det| (a hit's U, V, W share a sign).
            /// </summary>
            private const float Ill = 1f / 2048;

            private readonly RayLanes _r;
            private readonly Ray3 _ray;
            private readonly TriangleSet _set;
            private readonly float[] _ax, _ay, _az, _bx, _by, _bz, _cx, _cy, _cz;
            private readonly float _ox, _oy, _oz, _sx, _sy, _dz;

            public RayTriangles(RayLanes r, Ray3 ray, TriangleSet b)
            {
                _r = r; _ray = ray; _set = b;
                float adx = Math.Abs(r.DX), ady = Math.Abs(r.DY), adz = Math.Abs(r.DZ);
                int kz = adx >= ady ? (adx >= adz ? 0 : 2) : (ady >= adz ? 1 : 2);
                int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
                _ax = b.Coordinate(0, kx); _ay = b.Coordinate(0, ky); _az = b.Coordinate(0, kz);
                _bx = b.Coordinate(1, kx); _by = b.Coordinate(1, ky); _bz = b.Coordinate(1, kz);
                _cx = b.Coordinate(2, kx); _cy = b.Coordinate(2, ky); _cz = b.Coordinate(2, kz);
                _ox = r.O(kx); _oy = r.O(ky); _oz = r.O(kz);
                _dz = r.D(kz); _sx = r.D(kx) / _dz; _sy = r.D(ky) / _dz;
            }

            public void Values(int start, int end, Span<float> result) => Runner.EachLane(ref this, start, end, result);

            public void Verdicts(int start, int end, Span<bool> result) => Runner.EachLane(ref this, start, end, result);

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                Vector<float> ox = new Vector<float>(_ox), oy = new Vector<float>(_oy), oz = new Vector<float>(_oz);
                Vector<float> sx = new Vector<float>(_sx), sy = new Vector<float>(_sy);
                var az = new Vector<float>(_az, i) - oz;
                var bz = new Vector<float>(_bz, i) - oz;
                var cz = new Vector<float>(_cz, i) - oz;
                var ax = new Vector<float>(_ax, i) - ox - sx * az;
                var ay = new Vector<float>(_ay, i) - oy - sy * az;
                var bx = new Vector<float>(_bx, i) - ox - sx * bz;
                var by = new Vector<float>(_by, i) - oy - sy * bz;
                var cx = new Vector<float>(_cx, i) - ox - sx * cz;
                var cy = new Vector<float>(_cy, i) - oy - sy * cz;
                Vector<float> u1 = cx * by, u2 = cy * bx, v1 = ax * cy, v2 = ay * cx, w1 = bx * ay, w2 = by * ax;
                var u = u1 - u2;
                var v = v1 - v2;
                var w = w1 - w2;
                var det = u + v + w;
                var zero = Vector<float>.Zero;
                var negative = Vector.LessThan(u, zero) | Vector.LessThan(v, zero) | Vector.LessThan(w, zero);
                var positive = Vector.GreaterThan(u, zero) | Vector.GreaterThan(v, zero) | Vector.GreaterThan(w, zero);
                var inside = ~(negative & positive);
                var size = Vector.Abs(u1) + Vector.Abs(v1) + Vector.Abs(w1);
                var ill = inside & Vector.LessThanOrEqual(Vector.Abs(det), size * new Vector<float>(Ill));
                var t = (u * az + v * bz + w * cz) / (det * new Vector<float>(_dz)) + zero;
                var hit = inside & ~Vector.Equals(det, zero) & Vector.GreaterThanOrEqual(t, zero);
                var result = _r.Limit(hit, t);
                return Vector.EqualsAll(ill, Vector<int>.Zero) ? result : Rescue(i, result, ill);
            }

            /// <summary>
            /// The lanes of <paramref name="ill"/> replaced by the scalar cast (rare: not inlined into the loop). The set's
            /// padding lanes are point triangles (zeros), always flagged: they are skipped, so a set whose size is not a
            /// whole number of vectors costs one call here, not a scalar cast per padding lane.
            /// </summary>
            [MethodImpl(MethodImplOptions.NoInlining)]
            private Vector<float> Rescue(int i, Vector<float> result, Vector<int> ill)
            {
                Span<float> lanes = stackalloc float[Vector<float>.Count];
                System.Runtime.InteropServices.MemoryMarshal.Cast<float, Vector<float>>(lanes)[0] = result;
                int n = Math.Min(lanes.Length, _set.Count - i);
                for (int k = 0; k < n; k++)
                    if (ill[k] != 0) lanes[k] = Scalar(i + k);
                return System.Runtime.InteropServices.MemoryMarshal.Cast<float, Vector<float>>(lanes)[0];
            }

            /// <summary>Lane i by the scalar <see cref="Raycast"/> (computed in double, rounded once), within maxDistance.</summary>
            private float Scalar(int i)
            {
                var s = _set;
                var h = Raycast.Cast(_ray, new Triangle3(new Vector3(s.AX[i], s.AY[i], s.AZ[i]), new Vector3(s.BX[i], s.BY[i], s.BZ[i]), new Vector3(s.CX[i], s.CY[i], s.CZ[i])));
                return _r.Limit(h.Hit, h.T);
            }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public float Lane(int i)
            {
                float az = _az[i] - _oz, bz = _bz[i] - _oz, cz = _cz[i] - _oz;
                float ax = _ax[i] - _ox - _sx * az, ay = _ay[i] - _oy - _sy * az;
                float bx = _bx[i] - _ox - _sx * bz, by = _by[i] - _oy - _sy * bz;
                float cx = _cx[i] - _ox - _sx * cz, cy = _cy[i] - _oy - _sy * cz;
                float u1 = cx * by, u2 = cy * bx, v1 = ax * cy, v2 = ay * cx, w1 = bx * ay, w2 = by * ax;
                float u = u1 - u2, v = v1 - v2, w = w1 - w2;
                float det = u + v + w;
                if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return float.PositiveInfinity;
                float size = Runner.Abs(u1) + Runner.Abs(v1) + Runner.Abs(w1);
                if (Runner.Abs(det) <= size * Ill) return Scalar(i);
                float t = (u * az + v * bz + w * cz) / (det * _dz) + 0f;
                return _r.Limit(t >= 0, t);
            }
        }
    }
}
