using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // Ray casts (src/ProximityLib/Raycasts). Every kernel works on differences from the ray's origin (or the shape's own
    // stored point), so a common translation adds no error, and is homogeneous in lengths (the direction is a unit
    // vector, no absolute constants), so 2^k-scaled inputs give 2^k-scaled answers. inRange: the largest relative
    // magnitude lies where the squares (triangles: fourth powers) the kernel forms stay far from underflow and overflow.
    internal static partial class Kernels
    {
        /// <summary>2^-40: a point or segment (3D) is hit when the ray passes within this much of the local scale of it.</summary>
        public const double PassThrough = 9.094947017729282e-13;

        /// <summary>2^-90: |e × d|² of two unit directions below this is rounding: they are parallel (see <see cref="RayLinear"/>).</summary>
        private const double ParallelNoise = 8.077935669463161e-28;

        /// <summary>2^-20: |(B − A) × (C − A)|² below this times the longer edge at A to the fourth makes a sliver (see <see cref="RaySliver"/>).</summary>
        private const double Sliver2 = 9.5367431640625E-07;

        /// <summary>2^-46: a ray–triangle determinant below this times m and its sheared coordinates' sum is rounding (see <see cref="RayTriangle"/>).</summary>
        private const double DetNoise = 1.4210854715202004e-14;

        /// <summary>
        /// Ray against a closed ball. The perpendicular distance h of the center from the line gives the half-chord
        /// √((r − h)(r + h)) without the cancellation of b² − c, and the entry is (|w|² − r²)/(−b + half-chord), the
        /// root of the quadratic that does not cancel (Press et al., Numerical Recipes §5.6). Inlined: without dynamic PGO
        /// the JIT kept it a call, and reading back the struct it wrote cost half the cast (55 → 26 ns).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit3 RaySphere(Vector3D o, Vector3D d, Vector3D center, double r, out bool inRange)
        {
            var w = o - center;
            inRange = Range.Box(Num.Max(Range.MaxAbs(w), r));
            double wl = w.Length;
            // On the surface; a zero radius (w zero, or so small its length underflows) has only −Direction (docs).
            if (wl <= r) return wl < r ? RayHit3.Inside(o) : new RayHit3(0, o, r == 0 ? -d : Unit(w, -d), false);
            double b = Vector3D.Dot(w, d);
            if (!(b < 0)) return RayHit3.Miss; // outside and not approaching the center: never enters a ball
            var across = w - d * b; // the centre's offset across the ray, length h
            double h = across.Length;
            if (!(h <= r)) return RayHit3.Miss;
            double t = (wl - r) * (wl + r) / (Math.Sqrt((r - h) * (r + h)) - b);
            // The hit's offset from the centre, w + d·t = across + d·(b + t): its part along the ray is −half-chord at an
            // entry, so a positive b + t is rounding (all there is at a zero radius) and is clamped to 0: the normal never
            // points along the ray, and every term scales by 2^k exactly. The point from the centre is on the surface to
            // rounding at the sphere's scale, however far the origin.
            var n = Unit(across + d * Math.Min(b + t, 0), -d);
            return new RayHit3(t, center + n * r, n, false);
        }

        /// <summary><see cref="RaySphere"/> as a call: inlined twice, it made the capsule's cast 10–15% slower.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static RayHit3 RaySphereCall(Vector3D o, Vector3D d, Vector3D center, double r) => RaySphere(o, d, center, r, out _);

        /// <summary>
        /// Ray against a closed capsule: the origin inside (point–segment distance), else the earliest of the two end
        /// balls and the side of the cylinder where the hit's axis parameter lies in [0, 1] (the capsule is their union,
        /// and a flat cap's points lie in a ball, so the first entry into the union is the first of these).
        /// Inlined: without dynamic PGO, kept a call, it ran 1.4× slower than with PGO (reading back its result).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit3 RayCapsule(Vector3D o, Vector3D d, Vector3D a, Vector3D b, double r, out bool inRange)
        {
            var w = o - a;
            var e = b - a;
            inRange = Range.Box(Num.Max(Num.Max(Range.MaxAbs(w), Range.MaxAbs(e)), r));
            var res = PointSegmentResidual(o, a, b, out _, out double ee);
            double rl = res.Length;
            if (rl <= r) return rl < r ? RayHit3.Inside(o) : new RayHit3(0, o, r == 0 ? -d : Unit(res, -d), false);
            var best = RaySphereCall(o, d, a, r);
            var other = RaySphereCall(o, d, b, r);
            if (other.T < best.T) best = other;
            if (ee > 0)
            {
                // The cylinder's side in the plane across the axis: the 2D ray–circle problem of the sphere above.
                double dp = Vector3D.Dot(d, e) / ee, wp = Vector3D.Dot(w, e) / ee;
                var dn = d - e * dp;
                var wn = w - e * wp;
                double aa = dn.LengthSquared, bq = Vector3D.Dot(wn, dn), wl = wn.Length;
                if (aa > 0 && bq < 0 && wl > r)
                {
                    double q = bq / aa;
                    var across = wn - dn * q;
                    double h = across.Length;
                    if (h <= r)
                    {
                        double t = (wl - r) * (wl + r) / (Math.Sqrt(aa) * Math.Sqrt((r - h) * (r + h)) - bq);
                        double u = wp + dp * t;
                        if (u >= 0 && u <= 1 && t < best.T)
                        {
                            // As for the ball, in the plane across the axis: wn + dn·t = across + dn·(q + t), q + t ≤ 0
                            // for the normal. The point follows the ray across the axis unclamped: at a graze by a ray
                            // nearly along the axis T is ill-conditioned, and a point on the tangent line would sit
                            // |dn|·(q + t) off the ray (fuzz 1:548925: 8e-11), where the ray's own point is on the side to
                            // second order.
                            double s = q + t;
                            var n = Unit(across + dn * Math.Min(s, 0), -d);
                            var toward = s > 0 ? Unit(across + dn * s, n) : n;
                            best = new RayHit3(t, SegmentPoint(a, b, u) + toward * r, n, false);
                        }
                    }
                }
                if (r == 0 && best.Hit)
                {
                    // A zero radius is the segment: any normal across it is outward at an interior point, so take the one
                    // facing the ray (in the outward cone at an end too). A ray along the axis that meets an end exactly
                    // runs along the segment: an origin between the ends is on it (its residual was rounding), else it
                    // meets the near end first (whose own offset across the ray may have rounded away from 0).
                    if (aa > 0) best = new RayHit3(best.T, best.Point, Unit(-dn, -d), false);
                    else if (wp >= 0 && wp <= 1) best = new RayHit3(0, o, -d, false);
                    else if (wp < 0 == dp > 0)
                    {
                        var near = dp > 0 ? a : b;
                        double tn = Vector3D.Dot(near - o, d);
                        if (tn >= 0 && tn < best.T) best = new RayHit3(tn, near, -d, false);
                    }
                }
            }
            return best;
        }

        /// <summary>Ray against a closed half-space {x : n·(x − p) ≤ 0}: from the origin's signed distance and the approach rate −n·d.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit3 RayHalfSpace(Vector3D o, Vector3D d, Vector3D n, Vector3D p, out bool inRange)
        {
            var w = o - p;
            inRange = Range.Box(Range.MaxAbs(w));
            double s = Vector3D.Dot(n, w);
            if (s <= 0) return s < 0 ? RayHit3.Inside(o) : new RayHit3(0, o, n, false);
            double rate = -Vector3D.Dot(n, d);
            if (!(rate > 0)) return RayHit3.Miss;
            double t = s / rate; // may exceed the double range at grazing angles: the public Cast turns that into a miss
            return new RayHit3(t, o + d * t, n, false);
        }

        /// <summary>
        /// Ray against a closed box (slab test, Kay and Kajiya 1986) in the box's frame (<see cref="SlabCast"/>); the hit
        /// point and the entry face's normal mapped back to world.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit3 RayBox(Vector3D o, Vector3D d, in Box box, out bool inRange)
        {
            var w = o - box.Origin;
            inRange = Range.Box(Range.MaxAbs(w, box.Lo, box.Hi));
            int how = SlabCast(box.ToLocal(w), box.ToLocal(d), box.Lo, box.Hi, box.Planar, out double enter, out var q, out int face, out bool up);
            if (how < 0) return RayHit3.Miss;
            if (how == 0) return RayHit3.Inside(o);
            var n = up ? box.Axis(face) : -box.Axis(face);
            return how == 1 ? new RayHit3(0, o, n, false) : new RayHit3(enter, box.Origin + box.ToWorldOffset(q), n, false);
        }

        /// <summary>
        /// <see cref="RayBox"/> for an AABB given by its corners: its frame is the world's shifted to min, where a dot
        /// product with a unit axis, and the map back, are exact, so the answer is the one through Aabb3.ToBox and
        /// Aabb2.ToBox (up to the sign of a zero coordinate) without forming the 150-byte box or rotating by identities
        /// (ab against the box form, 3D: 18 → 14 ns, and 41 → 15 ns without dynamic PGO, inlined as it now is).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit3 RayAabb(Vector3D o, Vector3D d, Vector3D min, Vector3D max, bool planar, out bool inRange)
        {
            var p = o - min;
            var hi = max - min;
            inRange = Range.Box(Num.Max(Range.MaxAbs(p), Range.MaxAbs(hi))); // the box form's Lo is 0 here
            int how = SlabCast(p, d, default, hi, planar, out double enter, out var q, out int face, out bool up);
            if (how < 0) return RayHit3.Miss;
            if (how == 0) return RayHit3.Inside(o);
            var axis = face == 0 ? Vector3D.UnitX : face == 1 ? Vector3D.UnitY : Vector3D.UnitZ;
            var n = up ? axis : -axis;
            return how == 1 ? new RayHit3(0, o, n, false) : new RayHit3(enter, min + q, n, false);
        }

        /// <summary>
        /// The slab test in a box's frame: the ray p + T·v against [lo, hi] (planar: x and y only). −1: a miss; 0: p
        /// inside; 1: p on the surface, a hit at T = 0 on the first axis whose coordinate sits on a face (a flat axis
        /// faces the ray); 2: an entry at T = <paramref name="enter"/>, at the box-local point <paramref name="q"/>,
        /// snapped onto the entry face and clamped into the box. An axis the ray does not move along is a containment
        /// test, never a division by zero; the other axes divide a finite difference by a non-zero component, so no
        /// 0·∞ or NaN. The entry axis (the first of equal ones) is <paramref name="face"/>; <paramref name="up"/>: its
        /// normal is +axis. Written out per axis: a loop over the axes ran twice as slowly without dynamic PGO.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static int SlabCast(Vector3D p, Vector3D v, Vector3D lo, Vector3D hi, bool planar,
            out double enter, out Vector3D q, out int face, out bool up)
        {
            enter = 0;
            q = default;
            bool z = !planar;
            if ((p.X > lo.X & p.X < hi.X) & (p.Y > lo.Y & p.Y < hi.Y) & (!z | (p.Z > lo.Z & p.Z < hi.Z)))
            {
                face = 0; up = false;
                return 0;
            }
            if ((p.X >= lo.X & p.X <= hi.X) & (p.Y >= lo.Y & p.Y <= hi.Y) & (!z | (p.Z >= lo.Z & p.Z <= hi.Z)))
            {
                if (p.X == lo.X || p.X == hi.X) { face = 0; up = lo.X == hi.X ? v.X < 0 : p.X == hi.X; }
                else if (p.Y == lo.Y || p.Y == hi.Y) { face = 1; up = lo.Y == hi.Y ? v.Y < 0 : p.Y == hi.Y; }
                else { face = 2; up = lo.Z == hi.Z ? v.Z < 0 : p.Z == hi.Z; }
                return 1;
            }
            double exit = double.PositiveInfinity;
            enter = double.NegativeInfinity;
            face = 0;
            up = false;
            if (!Slab(p.X, v.X, lo.X, hi.X, 0, ref enter, ref exit, ref face)
                | !Slab(p.Y, v.Y, lo.Y, hi.Y, 1, ref enter, ref exit, ref face)
                | (z && !Slab(p.Z, v.Z, lo.Z, hi.Z, 2, ref enter, ref exit, ref face))
                || !(enter <= exit) || !(enter >= 0))
                return -1;
            double va = Vec.Get(v, face);
            q = p + v * enter;
            q = new Vector3D(Num.Clamp(q.X, lo.X, hi.X), Num.Clamp(q.Y, lo.Y, hi.Y), Num.Clamp(q.Z, lo.Z, hi.Z));
            q = Vec.With(q, face, va > 0 ? Vec.Get(lo, face) : Vec.Get(hi, face));
            up = !(va > 0);
            return 2;
        }

        /// <summary>
        /// One slab of <see cref="SlabCast"/>: false when the ray does not move along the axis and lies outside the
        /// slab; else the slab's entry and exit narrow [enter, exit] (an entry beyond the current one makes this axis
        /// the entry face).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Slab(double x, double vi, double lo, double hi, int i, ref double enter, ref double exit, ref int face)
        {
            if (vi == 0) return !(x < lo || x > hi);
            double t1 = (lo - x) / vi, t2 = (hi - x) / vi;
            double near = vi > 0 ? t1 : t2, far = vi > 0 ? t2 : t1;
            if (near > enter) { enter = near; face = i; }
            if (far < exit) exit = far;
            return true;
        }

        /// <summary>
        /// Ray against a point (zero thickness): hit when the point lies within <see cref="PassThrough"/>·|p − o|∞ of the
        /// ray; T is its distance along the ray, Point the point itself, Normal −d.
        /// </summary>
        public static RayHit3 RayPoint(Vector3D o, Vector3D d, Vector3D p, out bool inRange)
        {
            var w = p - o;
            double m = Range.MaxAbs(w);
            inRange = Range.Box(m);
            return PassesThrough(w, d, m, out double t) ? new RayHit3(t, p, -d, false) : RayHit3.Miss;
        }

        /// <summary>Whether the offset w from the origin lies on the ray within the tolerance tol·m; t its distance along d (≥ 0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool PassesThrough(Vector3D w, Vector3D d, double m, out double t)
        {
            t = Vector3D.Dot(w, d);
            double tol = PassThrough * m;
            bool hit = t >= -tol && (w - d * t).Length <= tol;
            t = t > 0 ? t : 0;
            return hit;
        }

        /// <summary>
        /// Ray against a segment (3D, zero thickness): hit when the ray passes within <see cref="PassThrough"/> of the
        /// local scale (the larger endpoint offset from the origin) of it. The earliest of: the origin on the segment
        /// (T = 0), an endpoint on the ray, and the lines' closest approach inside both (parameters from the cross
        /// products (w × d)·(e × d) / |e × d|², Lagrange's identity, no cancellation of the normal equations).
        /// </summary>
        public static RayHit3 RaySegment(Vector3D o, Vector3D d, Vector3D a, Vector3D b, out bool inRange)
        {
            var wa = a - o;
            var wb = b - o;
            double m = Num.Max(Range.MaxAbs(wa), Range.MaxAbs(wb));
            inRange = Range.Box(m);
            double tol = PassThrough * m;
            var res = PointSegmentResidual(o, a, b, out double u);
            if (res.Length <= tol) return new RayHit3(0, SegmentPoint(a, b, u), -d, false);
            var best = RayHit3.Miss;
            if (PassesThrough(wa, d, m, out double ta)) best = new RayHit3(ta, a, -d, false);
            if (PassesThrough(wb, d, m, out double tb) && tb < best.T) best = new RayHit3(tb, b, -d, false);
            var e = b - a;
            var ed = Vector3D.Cross(e, d);
            double den = ed.LengthSquared;
            if (den > 0)
            {
                double s = -Vector3D.Dot(Vector3D.Cross(wa, d), ed) / den;
                if (s > 0 && s < 1)
                {
                    var w = s <= 0.5 ? wa + e * s : wb - e * (1 - s);
                    if (PassesThrough(w, d, m, out double t) && t < best.T) best = new RayHit3(t, SegmentPoint(a, b, s), -d, false);
                }
            }
            return best;
        }

        /// <summary>
        /// Ray against a line or, when <paramref name="targetRay"/>, a ray (3D, zero thickness; p its origin, e its unit
        /// direction): hit when the ray passes within <see cref="PassThrough"/> of the local scale (the larger of |p − o|
        /// and the closest approach's offset from o, largest coordinate) of it. The earliest of: the origin on the target
        /// (T = 0), the lines' closest approach (the target's parameter from cross products, as in
        /// <see cref="RaySegment"/>) when it lies on the target, else a target ray's origin on the ray. Parallel (to
        /// rounding: |e × d| below 2^-45): only the origin on the target, or a target ray's origin ahead on the ray.
        /// </summary>
        public static RayHit3 RayLinear(Vector3D o, Vector3D d, Vector3D p, Vector3D e, bool targetRay, out bool inRange)
        {
            var w = p - o;
            double m = Range.MaxAbs(w);
            // The target's parameter at the closest approach; e and d are unit, so |e × d|² neither over- nor underflows.
            // Each of its components is within about 5u of exact: below 2^−45 the lines are parallel to rounding, and the
            // approach's place (hence the local scale m and the tolerance) would be that rounding magnified.
            var ed = Vector3D.Cross(e, d);
            double den = ed.LengthSquared, s = 0;
            bool skew = den > ParallelNoise;
            if (skew)
            {
                s = -Vector3D.Dot(Vector3D.Cross(w, d), ed) / den;
                if (targetRay && s < 0) s = 0;
                skew = Math.Abs(s) <= double.MaxValue / 4;
            }
            var q = skew && s != 0 ? w + e * s : w; // the approach's offset from o
            m = Num.Max(m, Range.MaxAbs(q));
            inRange = Range.Box(m);
            double tol = PassThrough * m;
            // The origin on the target: its residual from the target, by the point–line kernel.
            var c = PointLinear(o, p, e, targetRay, out _);
            if (c.Distance <= tol) return new RayHit3(0, c.Closest, -d, false);
            if (skew && PassesThrough(q, d, m, out double t)) return new RayHit3(t, s != 0 ? p + e * s : p, -d, false);
            if (!skew && targetRay && PassesThrough(w, d, m, out double tp)) return new RayHit3(tp, p, -d, false);
            return RayHit3.Miss;
        }

        /// <summary>
        /// Ray against a two-sided triangle, watertight (Woop, Benthin and Wald, "Watertight Ray/Triangle Intersection",
        /// JCGT 2013): the vertices relative to the origin are sheared so the ray runs along the dominant axis, and the
        /// edge functions are 2D cross products of per-vertex values, so a shared edge gives both triangles the same value
        /// of opposite sign: a ray through it hits at least one. A determinant at rounding level (the ray parallel to the
        /// plane, or the triangle degenerate, to rounding) answers the triangle as the segments it is seen as
        /// (<see cref="RayEdgeOn"/>).
        /// </summary>
        public static RayHit3 RayTriangle(Vector3D o, Vector3D d, Vector3D A, Vector3D B, Vector3D C, out bool inRange)
        {
            var a = A - o;
            var b = B - o;
            var c = C - o;
            double m = Range.MaxAbs(a, b, c), m2 = m * m;
            inRange = Range.In(m2 * m2) || m == 0;
            double adx = Math.Abs(d.X), ady = Math.Abs(d.Y), adz = Math.Abs(d.Z);
            int kz = adx >= ady ? (adx >= adz ? 0 : 2) : (ady >= adz ? 1 : 2);
            int kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
            double dz = Vec.Get(d, kz), sx = Vec.Get(d, kx) / dz, sy = Vec.Get(d, ky) / dz;
            double az = Vec.Get(a, kz), bz = Vec.Get(b, kz), cz = Vec.Get(c, kz);
            double ax = Vec.Get(a, kx) - sx * az, ay = Vec.Get(a, ky) - sy * az;
            double bx = Vec.Get(b, kx) - sx * bz, by = Vec.Get(b, ky) - sy * bz;
            double cx = Vec.Get(c, kx) - sx * cz, cy = Vec.Get(c, ky) - sy * cz;
            double U = cx * by - cy * bx, V = ax * cy - ay * cx, W = bx * ay - by * ax;
            double det = U + V + W;
            // Each sheared coordinate is within 5u·m of its exact value, so det within about 70u·m times their sum: a det
            // below 2^−46·m·that sum is rounding (the ray in the plane, or the triangle degenerate, to rounding), and its
            // sign, U, V, W and t would be noise; the edge-on answer is the one within the pass-through tolerance.
            double sheared = Math.Abs(ax) + Math.Abs(ay) + Math.Abs(bx) + Math.Abs(by) + Math.Abs(cx) + Math.Abs(cy);
            if (!(Math.Abs(det) > DetNoise * m * sheared)) return RayEdgeOn(o, d, A, B, C, m);
            if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return RayHit3.Miss;
            var e1 = B - A;
            var e2 = C - A;
            var N = Vector3D.Cross(e1, e2);
            if (N == default) return RayEdgeOn(o, d, A, B, C, m); // degenerate after all: the segment or point it is
            double l2 = Math.Max(e1.LengthSquared, e2.LengthSquared), l4 = l2 * l2;
            if (l4 >= 1e-270 ? N.LengthSquared < Sliver2 * l4 : TinySliver(N, l2, m)) return RaySliver(o, d, A, B, C);
            double t = (U * az + V * bz + W * cz) / (det * dz);
            if (!(t >= 0)) return RayHit3.Miss;
            var n = Unit(N, -d);
            return new RayHit3(t + 0.0, A + e1 * (V / det) + e2 * (W / det), Vector3D.Dot(n, d) > 0 ? -n : n, false);
        }

        /// <summary>
        /// The sliver test where the fourth powers of the edges underflow (the fast range's small end, m down to 2^-240):
        /// at the scale of m (powers of two, exact), so 2^k-scaled inputs take the same path as at scale 1.
        /// </summary>
        private static bool TinySliver(Vector3D n, double l2, double m)
        {
            double s2 = Num.InversePowerOfTwo(m);
            s2 *= s2;
            l2 *= s2;
            return (n * s2).LengthSquared < Sliver2 * (l2 * l2);
        }

        /// <summary>
        /// The hit on a sliver or needle the watertight test says the ray crosses (twice its area below 2^-10 of its longer
        /// edge at A squared: tilt factor F above about 2^10). There the
        /// edge functions' weights are rounding over the sliver's tiny area, so their mean of the vertices' depths moves T
        /// by about u·m·F (tilt factor F: fuzz 12:750646, F = 7e8, T off by 4e-8 at a square-on hit), and the rounded
        /// edges' cross product turns by u·F as well. The plane from the exact edge differences (<see cref="FacetAxis"/>)
        /// has its normal to about u, so T = ((A − O)·N)/(D·N), with A − O exact too, is within about u·m/cos.
        /// </summary>
        private static RayHit3 RaySliver(Vector3D o, Vector3D d, Vector3D A, Vector3D B, Vector3D C)
        {
            ExactDiff(B, A, 1, out var eh, out var el);
            ExactDiff(C, A, 1, out var fh, out var fl);
            var N = FacetAxis(eh, el, fh, fl);
            ExactDiff(A, o, 1, out var ah, out var al);
            double t = (Vector3D.Dot(ah, N) + Vector3D.Dot(al, N)) / Vector3D.Dot(d, N);
            if (!(t >= 0)) return RayHit3.Miss;
            var n = Unit(N, -d);
            // From A: the offset to the hit is short, so only the final sum rounds at A's magnitude.
            return new RayHit3(t + 0.0, A + ((d * t - ah) - al), Vector3D.Dot(n, d) > 0 ? -n : n, false);
        }

        /// <summary>
        /// A triangle the ray sees edge-on (zero determinant): the origin inside it in its plane is a hit at T = 0 (normal:
        /// the triangle's, (B − A) × (C − A) turned against the ray when it is not parallel); otherwise the earliest hit
        /// of its three edges as segments (a degenerate triangle is the segment or point it is).
        /// </summary>
        private static RayHit3 RayEdgeOn(Vector3D o, Vector3D d, Vector3D A, Vector3D B, Vector3D C, double m)
        {
            var n = Vector3D.Cross(B - A, C - A);
            if (n != default)
            {
                var u = Unit(n, -d);
                var pa = A - o;
                if (Math.Abs(Vector3D.Dot(u, pa)) <= PassThrough * m
                    && Vector3D.Dot(Vector3D.Cross(B - A, o - A), n) >= 0
                    && Vector3D.Dot(Vector3D.Cross(C - B, o - B), n) >= 0
                    && Vector3D.Dot(Vector3D.Cross(A - C, o - C), n) >= 0)
                    return new RayHit3(0, o, Vector3D.Dot(u, d) > 0 ? -u : u, false);
            }
            var best = RaySegment(o, d, A, B, out _);
            var next = RaySegment(o, d, B, C, out _);
            if (next.T < best.T) best = next;
            next = RaySegment(o, d, C, A, out _);
            return next.T < best.T ? next : best;
        }
    }
}
