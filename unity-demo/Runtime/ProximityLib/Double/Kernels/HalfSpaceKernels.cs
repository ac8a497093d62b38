// Copied from src/ProximityLib/Double/Kernels/HalfSpaceKernels.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        // A half-space {x : n·(x − p) ≤ 0} (n unit, p a stored boundary point) against another shape. Every height above the
        // boundary is measured as n·(x − p) from the stored point, never through the offset n·p: its rounding would be at
        // the scale of the boundary's distance from the origin instead of the configuration's.
        //
        // inRange: the relative coordinates lie in [2^-450, 2^450] (or are 0), so no product of a height underflows or
        // overflows, and a positive distance's square lies in [2^-960, 2^960] (see Range).

        /// <summary>
        /// A ball (center c, radius r ≥ 0; a point when r = 0) against the half-space: its lowest point c − n·r and that
        /// point's foot on the boundary, as the pair (ball, half-space). <paramref name="t"/> is reported as ParameterA.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 BallHalfSpace(Vector3D c, double r, Vector3D n, Vector3D p, double t, out bool inRange)
        {
            var d = c - p;
            double s = Vector3D.Dot(n, d), dist = s - r;
            inRange = Range.Box(Num.Max(Range.MaxAbs(d), r)) & (dist <= 0 | Range.In(dist * dist));
            return new DistanceResult3(dist, dist > 0 ? dist * dist : 0, c - n * r, c - n * s, t, 0);
        }

        /// <summary>The distance of <see cref="BallHalfSpace"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double BallHalfSpaceDistance(Vector3D c, double r, Vector3D n, Vector3D p, out bool inRange)
        {
            var d = c - p;
            double dist = Vector3D.Dot(n, d) - r;
            inRange = Range.Box(Num.Max(Range.MaxAbs(d), r)) & (dist <= 0 | Range.In(dist * dist));
            return dist;
        }

        /// <summary>
        /// A capsule (axis [a, b], radius r; a segment when r = 0) against the half-space: the lower axis end, as a ball
        /// (<see cref="BallHalfSpace"/>). The signed distance is linear along the axis, so an end attains its minimum; when
        /// both ends are equally high (the axis parallel to the boundary), Start (parameter 0).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 CapsuleHalfSpace(Vector3D a, Vector3D b, double r, Vector3D n, Vector3D p, out bool inRange)
        {
            var da = a - p;
            var db = b - p;
            bool end = Vector3D.Dot(n, db) < Vector3D.Dot(n, da);
            // The ends' magnitudes are checked too: an overflowed height would have made the choice meaningless.
            var r1 = BallHalfSpace(end ? b : a, r, n, p, end ? 1 : 0, out inRange);
            inRange &= Range.Box(Num.Max(Range.MaxAbs(da), Range.MaxAbs(db)));
            return r1;
        }

        /// <summary>The distance of <see cref="CapsuleHalfSpace"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double CapsuleHalfSpaceDistance(Vector3D a, Vector3D b, double r, Vector3D n, Vector3D p, out bool inRange)
        {
            var da = a - p;
            var db = b - p;
            double sa = Vector3D.Dot(n, da), sb = Vector3D.Dot(n, db);
            // BallHalfSpaceDistance on the lower end, spelled out on the scalars it would form (its d is da or db, its dot
            // sa or sb, bit for bit): selecting the end as a vector made a stack copy without dynamic PGO, 2x slower.
            bool upper = sb < sa;
            double dist = (upper ? sb : sa) - r;
            inRange = Range.Box(Num.Max(upper ? Range.MaxAbs(db) : Range.MaxAbs(da), r)) & (dist <= 0 | Range.In(dist * dist))
                & Range.Box(Num.Max(Range.MaxAbs(da), Range.MaxAbs(db)));
            return dist;
        }

        /// <summary>
        /// The vertices a, b, c against the half-space: the lowest vertex (the first of A, B, C among equally low ones) and
        /// its foot on the boundary, as the pair (triangle, half-space). The signed distance is linear over the triangle, so
        /// a vertex attains its minimum whether the triangle is a solid (2D) or not (3D).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 TriangleHalfSpace(Vector3D a, Vector3D b, Vector3D c, Vector3D n, Vector3D p, out bool inRange)
        {
            var r = BallHalfSpace(LowestVertex(a, b, c, n, p, out bool vertices), 0, n, p, 0, out inRange);
            inRange &= vertices;
            return r;
        }

        /// <summary>The distance of <see cref="TriangleHalfSpace"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double TriangleHalfSpaceDistance(Vector3D a, Vector3D b, Vector3D c, Vector3D n, Vector3D p, out bool inRange)
        {
            double d = BallHalfSpaceDistance(LowestVertex(a, b, c, n, p, out bool vertices), 0, n, p, out inRange);
            inRange &= vertices;
            return d;
        }

        /// <summary>The lowest of a, b, c along n (the first on ties); <paramref name="inRange"/>: their offsets from p are in the box range.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D LowestVertex(Vector3D a, Vector3D b, Vector3D c, Vector3D n, Vector3D p, out bool inRange)
        {
            var da = a - p;
            var db = b - p;
            var dc = c - p;
            double sa = Vector3D.Dot(n, da), sb = Vector3D.Dot(n, db), sc = Vector3D.Dot(n, dc);
            inRange = Range.Box(Range.MaxAbs(da, db, dc));
            var low = a;
            if (sb < sa) { low = b; sa = sb; }
            return sc < sa ? c : low;
        }

        /// <summary>
        /// A line (origin o, unit direction u; a ray when <paramref name="ray"/>) against the half-space. Not parallel to
        /// the boundary (a line), or heading inward (a ray), by the exact sign of n·u (<see cref="AccurateDot"/>): the
        /// penetration is unbounded, −∞, and both witnesses are the origin when it lies inside, else the crossing point
        /// o + t·u, t = −n·(o − p)/n·u; should the crossing or t lie beyond <paramref name="range"/> (the float API passes
        /// float.MaxValue), or t beyond 2^1022·M (M the largest coordinate magnitude of o and p, to its power of two), the origin. Otherwise the minimum is at every point of a line (parallel) or at a ray's origin,
        /// which is returned with its foot on the boundary.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 LineHalfSpace(Vector3D o, Vector3D u, bool ray, Vector3D n, Vector3D p, double range, out bool inRange)
        {
            var d = o - p;
            double s = Vector3D.Dot(n, d), k = AccurateDot(n, u, Vector3D.Dot(n, u));
            inRange = Range.Box(Range.MaxAbs(d));
            if (ray ? k < 0 : k != 0)
            {
                double t = 0;
                if (s > 0)
                {
                    t = -s / k + 0.0; // + 0.0: a crossing at the origin is t = +0 whatever the signs
                    var x = o + u * t;
                    // Past 2^1022·M (M the inputs' magnitude to its power of two) as for two lines (Unbounded): the
                    // rescaled slow path could not form the point, so neither path takes it.
                    if (!Within(x, range) || !(Math.Abs(t) <= range) || !(Math.Abs(t) <= NoReachBelow || WithinReach(t, t, o, p))) t = 0;
                }
                var common = t == 0 ? o : o + u * t;
                return new DistanceResult3(double.NegativeInfinity, 0, common, common, t, 0);
            }
            inRange &= s <= 0 | Range.In(s * s);
            return new DistanceResult3(s, s > 0 ? s * s : 0, o, o - n * s, 0, 0);
        }

        /// <summary>The distance of <see cref="LineHalfSpace"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double LineHalfSpaceDistance(Vector3D o, Vector3D u, bool ray, Vector3D n, Vector3D p, out bool inRange)
        {
            var d = o - p;
            double s = Vector3D.Dot(n, d);
            inRange = Range.Box(Range.MaxAbs(d));
            double k = AccurateDot(n, u, Vector3D.Dot(n, u));
            if (ray ? k < 0 : k != 0) return double.NegativeInfinity;
            inRange &= s <= 0 | Range.In(s * s);
            return s;
        }

        /// <summary>Whether a line or ray meets the half-space: it is not parallel to the boundary (a line) or heads inward (a ray), or its origin is inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool LineHalfSpaceOverlaps(Vector3D o, Vector3D u, bool ray, Vector3D n, Vector3D p, out bool inRange)
        {
            var d = o - p;
            double k = AccurateDot(n, u, Vector3D.Dot(n, u));
            inRange = Range.Box(Range.MaxAbs(d));
            return (ray ? k < 0 : k != 0) || Vector3D.Dot(n, d) <= 0;
        }

        /// <summary>
        /// a·b with its exact sign (0 exactly when a ⊥ b): the rounded <paramref name="dot"/> when it clears its rounding
        /// bound 8u·Σ|aᵢbᵢ|, else the exact sum of the three products (each split exactly in two, Dekker; summed without
        /// error, Shewchuk), rounded once. Why: whether a line is parallel to a boundary decides between a finite
        /// distance and −∞, a rounded dot product of exactly perpendicular vectors is rarely exactly 0, and a nearly
        /// parallel line's crossing t = −s/(n·u) needs n·u to more than its sign.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double AccurateDot(Vector3D a, Vector3D b, double dot)
        {
            double bound = (Math.Abs(a.X * b.X) + Math.Abs(a.Y * b.Y) + Math.Abs(a.Z * b.Z)) * 8.881784197001252e-16;
            return Math.Abs(dot) > bound ? dot : ExactDot(a, b);
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double ExactDot(Vector3D a, Vector3D b)
        {
            Span<double> e = stackalloc double[12];
            int m = 0;
            AddProduct(e, ref m, a.X, b.X);
            AddProduct(e, ref m, a.Y, b.Y);
            AddProduct(e, ref m, a.Z, b.Z);
            // The components are non-overlapping and increasing: summed from the smallest, the result is the exact
            // value rounded (to within an ulp) and has its sign; no components, an exact 0.
            double sum = 0;
            for (int i = 0; i < m; i++) sum += e[i];
            return sum;
        }

        /// <summary>
        /// Half-space A (na, pa) against half-space B (nb, pb), symmetric by construction (swapping the arguments swaps the
        /// witnesses, bit for bit). Exactly opposite normals: the signed gap na·(pb − pa) between the parallel boundaries,
        /// witnessed by the feet on both boundaries of the midpoint of the stored points. Otherwise the intersection is
        /// unbounded: −∞, with a common point: the midpoint of the stored points if each lies in the other half-space, else
        /// the stored point that does, else a point of both near where the boundaries meet (<see cref="BoundaryMeet"/>;
        /// should that lie beyond <paramref name="range"/>, the midpoint: the float API passes float.MaxValue, as its
        /// result could not hold the point, the double one double.MaxValue). Inlined: without dynamic PGO the JIT kept it a call,
        /// and copying the shapes into its arguments and reading back its result stalled (3D Between 22 → 7 ns).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 HalfSpaceHalfSpace(Vector3D na, Vector3D pa, Vector3D nb, Vector3D pb, double range, out bool inRange)
        {
            inRange = Range.Box(Range.MaxAbs(pb - pa));
            // Halves first: pa + pb can overflow. Addition commutes, so either order gives this midpoint.
            var m = pa * 0.5 + pb * 0.5;
            if (na == -nb)
            {
                // Swapped: (−na)·(−(pb − pa)), the same products up to the signs of zero terms; + 0.0 makes a zero gap +0.
                double gap = Vector3D.Dot(na, pb - pa) + 0.0;
                inRange &= gap <= 0 | Range.In(gap * gap);
                return new DistanceResult3(gap, gap > 0 ? gap * gap : 0, m - na * Vector3D.Dot(na, m - pa), m - nb * Vector3D.Dot(nb, m - pb), 0, 0);
            }
            // Each stored point's height above the other boundary, written the same way in both argument orders.
            bool aInB = Vector3D.Dot(nb, pa - pb) <= 0, bInA = Vector3D.Dot(na, pb - pa) <= 0;
            Vector3D common;
            if (aInB && bInA) common = m;
            else if (aInB) common = pa;
            else if (bInA) common = pb;
            else common = BoundaryMeet(na, pa, nb, pb, m, range);
            return new DistanceResult3(double.NegativeInfinity, 0, common, common, 0, 0);
        }

        /// <summary>
        /// A point inside both half-spaces near where their boundaries meet: the point of both boundaries nearest m,
        /// m + α·na + γ·q with q = L × na and L = na × nb the direction of the meeting line, so na·q = 0 and nb·q = |L|²;
        /// then moved inward along −L × (na − nb), which lowers both heights at the rate |L|², should rounding have left
        /// it outside either. Why this basis: for nearly parallel normals 1 − (na·nb)² cancels to noise (and, with normals
        /// unit only to rounding, so do na·(na + nb) and the like), while L from <see cref="AccurateCross"/> keeps its full
        /// relative precision however small it is, and so does every coefficient built from it. L is scaled by a power of
        /// two so |L|² neither underflows nor overflows. The arguments are taken in a canonical order
        /// (<see cref="Order.Swap(Vector3D, Vector3D, Vector3D, Vector3D)"/>), so swapping them gives the same point bit
        /// for bit; m when the point is not finite or lies beyond <paramref name="range"/> (in magnitude).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static Vector3D BoundaryMeet(Vector3D na, Vector3D pa, Vector3D nb, Vector3D pb, Vector3D m, double range)
        {
            if (Order.Swap(na, pa, nb, pb)) { var n = na; na = nb; nb = n; var p = pa; pa = pb; pb = p; }
            var l = AccurateCross(na, nb);
            double big = Range.MaxAbs(l);
            if (!(big > 0)) return m;
            double k = Num.InversePowerOfTwo(big); // big ≤ 2: the clamp never applies
            l *= k;
            double l2 = l.LengthSquared;
            double ea = Vector3D.Dot(na, pa - m), eb = Vector3D.Dot(nb, pb - m);
            double alpha = ea / na.LengthSquared;
            // q = L × na at scale k: x − m = α·na + q·(eb − α·c)/|L|², the /k folded into the factor.
            var x = m + (na * alpha + Vector3D.Cross(l, na) * ((eb - alpha * Vector3D.Dot(na, nb)) / l2 * k));
            if (!Within(x, range)) return m;
            double high = Math.Max(Vector3D.Dot(na, x - pa), Vector3D.Dot(nb, x - pb));
            if (high > 0)
            {
                // −L × (na − nb) at scale k lowers each height at the rate |L|²/k.
                var inside = x - Vector3D.Cross(l, na - nb) * (2 * high / l2 * k);
                if (Within(inside, range)) x = inside;
            }
            return x;
        }

        /// <summary>Whether every coordinate of v is at most <paramref name="range"/> in magnitude (false for NaN and ±∞).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Within(Vector3D v, double range) => Math.Abs(v.X) <= range && Math.Abs(v.Y) <= range && Math.Abs(v.Z) <= range;

        /// <summary>The distance of <see cref="HalfSpaceHalfSpace"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double HalfSpaceHalfSpaceDistance(Vector3D na, Vector3D pa, Vector3D nb, Vector3D pb, out bool inRange)
        {
            var d = pb - pa;
            inRange = Range.Box(Range.MaxAbs(d));
            if (!(na == -nb)) return double.NegativeInfinity;
            double gap = Vector3D.Dot(na, d) + 0.0;
            inRange &= gap <= 0 | Range.In(gap * gap);
            return gap;
        }

        /// <summary>
        /// Half-space (n, p) against a box, as the pair (half-space, box): the signed height of the box's lowest point,
        /// n·(origin − p) + Σ k_i·q_i with k = n in the box frame and q the lowest corner (box-local), from differences
        /// only. Witnesses: that point of the box and its foot on the boundary; where an axis is level (k_i = 0: a face or
        /// edge parallel to the boundary) the middle of the box along it, so the middle of the lowest face or edge.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 HalfSpaceBox(Vector3D n, Vector3D p, in Box box, out bool inRange)
        {
            var q = LowestCorner(n, p, box, out double s, out inRange);
            var onBox = box.Origin + box.ToWorldOffset(q);
            return new DistanceResult3(s, s > 0 ? s * s : 0, onBox - n * s, onBox, 0, 0);
        }

        /// <summary>The distance of <see cref="HalfSpaceBox"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double HalfSpaceBoxDistance(Vector3D n, Vector3D p, in Box box, out bool inRange)
        {
            LowestCorner(n, p, box, out double s, out inRange);
            return s;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D LowestCorner(Vector3D n, Vector3D p, in Box box, out double s, out bool inRange)
        {
            var d = box.Origin - p;
            var k = box.ToLocal(n);
            var q = new Vector3D(Lowest(k.X, box.Lo.X, box.Hi.X), Lowest(k.Y, box.Lo.Y, box.Hi.Y), Lowest(k.Z, box.Lo.Z, box.Hi.Z));
            s = Vector3D.Dot(n, d) + Vector3D.Dot(k, q);
            inRange = Range.Box(Num.Max(Range.MaxAbs(d), Range.MaxAbs(box.Hi - box.Lo))) & (s <= 0 | Range.In(s * s));
            return q;
        }

        /// <summary>The lowest coordinate of [lo, hi] along an axis rising at rate k: lo, hi, or the middle when level.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Lowest(double k, double lo, double hi) => k > 0 ? lo : (k < 0 ? hi : 0.5 * lo + 0.5 * hi);
    }
}
