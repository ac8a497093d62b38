using System;
using System.Numerics;
using System.Runtime.CompilerServices;

namespace ProximityLib.Batch
{
    /// <summary>
    /// SIMD batch queries over <see cref="ShapeSet"/>s, one against many or paired (many against many, lane by lane),
    /// with no allocation. Results are the scalar queries' signed distances (gap apart, 0 touching, −depth overlapping)
    /// or touch-or-overlap verdicts, computed in float across <see cref="Vector{T}"/> lanes; witness points are the scalar
    /// API's job. Error bounds are measured in docs/accuracy.md-style tests against the double queries.
    /// </summary>
    public static class BatchQuery
    {
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
            return Vector.ConditionalSelect(Vector.GreaterThan(d2, Vector<float>.Zero), Vector.SquareRoot(d2), -depth) - r;
        }

        private readonly struct SphereSphere<TS> : IKernel where TS : struct, ISpheres
        {
            private readonly TS _a;
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
        }

        private readonly struct SphereAabb<TS> : IKernel where TS : struct, ISpheres
        {
            private readonly TS _a;
            private readonly AabbSet _b;
            private readonly bool _margin;
            public SphereAabb(TS a, AabbSet b, bool margin) { _a = a; _b = b; _margin = margin; }

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i) => PointBox(_a.X(i), _a.Y(i), _a.Z(i), _a.R(i),
                new Vector<float>(_b.MinX, i), new Vector<float>(_b.MinY, i), new Vector<float>(_b.MinZ, i),
                new Vector<float>(_b.MaxX, i), new Vector<float>(_b.MaxY, i), new Vector<float>(_b.MaxZ, i), _margin);
        }

        private readonly struct SphereObb<TS> : IKernel where TS : struct, ISpheres
        {
            private readonly TS _a;
            private readonly ObbSet _b;
            private readonly bool _margin;
            public SphereObb(TS a, ObbSet b, bool margin) { _a = a; _b = b; _margin = margin; }

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
                return PointBox(qx, qy, qz, _a.R(i), -hx, -hy, -hz, hx, hy, hz, _margin);
            }
        }

        private readonly struct AabbAabb<TA> : IKernel where TA : struct, IAabbs
        {
            private readonly TA _a;
            private readonly AabbSet _b;
            public AabbAabb(TA a, AabbSet b) { _a = a; _b = b; }

            /// <summary>The largest per-axis gap: ≤ 0 exactly when the boxes touch or overlap (paper Eq. 18).</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public Vector<float> Compute(int i)
            {
                var gx = Vector.Max(new Vector<float>(_b.MinX, i) - _a.MaxX(i), _a.MinX(i) - new Vector<float>(_b.MaxX, i));
                var gy = Vector.Max(new Vector<float>(_b.MinY, i) - _a.MaxY(i), _a.MinY(i) - new Vector<float>(_b.MaxY, i));
                var gz = Vector.Max(new Vector<float>(_b.MinZ, i) - _a.MaxZ(i), _a.MinZ(i) - new Vector<float>(_b.MaxZ, i));
                return Vector.Max(gx, Vector.Max(gy, gz));
            }
        }
    }
}
