// Copied from src/ProximityLib/Double/Kernels/LinearKernels.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A linear component: a segment (Start + s·(End − Start), s in [0, 1]), a ray (Start + s·Dir, s ≥ 0) or a line (all
    /// s); rays and lines have a unit Dir. 2D shapes are passed with z = 0.
    /// </summary>
    internal readonly struct Linear
    {
        public readonly Vector3D Start, End, Dir;
        public readonly double Lo, Hi;

        // Inlined (all of them): without dynamic PGO the JIT kept Segment and PointAt calls inside LinearCapsule, and
        // read back the 88-byte struct Segment returned with a stall (2D line–capsule 1.4× slower than with PGO).
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private Linear(Vector3D start, Vector3D end, Vector3D dir, double lo, double hi) { Start = start; End = end; Dir = dir; Lo = lo; Hi = hi; }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Linear Segment(Vector3D start, Vector3D end) => new Linear(start, end, end - start, 0, 1);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Linear Ray(Vector3D origin, Vector3D dir) => new Linear(origin, origin, dir, 0, double.PositiveInfinity);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Linear Line(Vector3D origin, Vector3D dir) => new Linear(origin, origin, dir, double.NegativeInfinity, double.PositiveInfinity);

        public bool IsSegment { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => Hi == 1; }
        public bool IsRay { [MethodImpl(MethodImplOptions.AggressiveInlining)] get => Lo == 0 && Hi != 1; }

        /// <summary>The point at parameter s (a segment's from its nearer endpoint; a line's or ray's Start + Dir·s, in plain doubles for Mono).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public Vector3D PointAt(double s) => IsSegment ? Kernels.SegmentPoint(Start, End, s) : new Vector3D(Start.X + Dir.X * s, Start.Y + Dir.Y * s, Start.Z + Dir.Z * s);
    }

    internal static partial class Kernels
    {
        /// <summary>
        /// Point against a line (or a ray when <paramref name="ray"/>) through o with unit direction d: the projection
        /// parameter t = d·(p − o) (clamped at 0 for a ray) and the residual (p − o) − t·d, formed from differences, so a
        /// point far along the line loses only u·|p − o| (<paramref name="w"/> = p − o). <paramref name="inRange"/>: the
        /// squared residual lies in the fast range or the residual is exactly zero.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D LinearResidual(Vector3D p, Vector3D o, Vector3D d, bool ray, out double t, out Vector3D w, out double r2, out bool inRange)
        {
            w = p - o;
            t = Vector3D.Dot(w, d);
            if (ray && t <= 0) t = 0;
            var r = t == 0 ? w : w - d * t;
            r2 = r.LengthSquared;
            inRange = Range.Length2(r, r2);
            return r;
        }

        /// <summary>Point against a line or ray (<see cref="LinearResidual"/>): the distance, the line's point and t; no normal.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static PointContact PointLinear(Vector3D p, Vector3D o, Vector3D d, bool ray, out bool inRange)
        {
            LinearResidual(p, o, d, ray, out double t, out _, out double r2, out inRange);
            return new PointContact(Math.Sqrt(r2), r2, o + d * t, default, t);
        }

        /// <summary>
        /// A sphere (centre p, radius <paramref name="ra"/>) against a line or ray, sphere first: the point's contact less
        /// the radius, the sphere's witness pushed in by ra along the push-out normal. That normal is the residual's
        /// direction; below 2^-26 of |p − o| without its part along d (t's rounding), which is all that matters (see
        /// <see cref="SegmentContact"/>); within 2^-50 (on the line as far as anything can tell) <see cref="AnyPerpendicular"/>
        /// of d, which pushes out to within twice that.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 SphereLinear(Vector3D p, double ra, Vector3D o, Vector3D d, bool ray, out bool inRange)
        {
            var c = LinearContact(p, o, d, ray, out inRange);
            double g = c.Distance - ra;
            return new DistanceResult3(g, g > 0 ? g * g : 0, p - c.Normal * ra, c.Closest, 0, c.Parameter);
        }

        /// <summary>
        /// <see cref="PointLinear"/> with <see cref="SphereLinear"/>'s push-out normal. Compared without squares: |w|² can
        /// overflow where the residual's cannot (a line whose origin lies far along it). With t = 0 the residual is w
        /// itself, rounded once. Near the line the direction is Across's (a ray's origin cannot hold the pair there: the
        /// foot lies |w| along, so no feature is in doubt).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static PointContact LinearContact(Vector3D p, Vector3D o, Vector3D d, bool ray, out bool inRange)
        {
            var r = LinearResidual(p, o, d, ray, out double t, out var w, out double r2, out inRange);
            double dist = Math.Sqrt(r2), mr = Range.MaxAbs(r), mw = Range.MaxAbs(w);
            Vector3D n;
            if (t != 0 && mr <= mw * 8.8817841970012523e-16) n = AnyPerpendicular(d);
            else if (t != 0 && mr < mw * NearTouch) n = Across(r, d, 1);
            else n = dist > 0 ? r * (1 / dist) : AnyPerpendicular(d);
            return new PointContact(dist, r2, o + d * t, n, t);
        }

        /// <summary>The distance of <see cref="PointLinear"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointLinearDistance(Vector3D p, Vector3D o, Vector3D d, bool ray, out bool inRange)
        {
            var w = p - o;
            double t = Vector3D.Dot(w, d);
            if (ray && t <= 0) t = 0;
            var r = t == 0 ? w : w - d * t;
            double r2 = r.LengthSquared;
            inRange = Range.Length2(r, r2);
            return Math.Sqrt(r2);
        }

        /// <summary>Whether p lies on the line or ray: its residual is exactly zero (the test <see cref="PointLinear"/>'s distance makes).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointOnLinear(Vector3D p, Vector3D o, Vector3D d, bool ray)
        {
            var w = p - o;
            double t = Vector3D.Dot(w, d);
            if (ray && t <= 0) t = 0;
            return (t == 0 ? w : w - d * t) == default;
        }

        /// <summary>
        /// A point (or sphere of radius <paramref name="ra"/> centred at p) against a capsule of radius
        /// <paramref name="rb"/> (or, rb = 0, a segment): the point–segment contact of p with the axis, less the radii;
        /// B's witness is pushed out of the axis by rb along the push-out normal, A's pushed in by ra. That normal is the
        /// residual's direction; below 2^-26 of the length without its part along the segment (t's rounding); near an end,
        /// below 2^-28 (NearPoint), formed from the exact inputs (<see cref="NearSegmentNormal"/>: which feature holds the
        /// pair is uncertain there, a foot within u·length of the end); within 2^-49 of an interior point, and for a point
        /// on the segment, <see cref="AnyPerpendicular"/> of it (any perpendicular pushes out to within twice the gap).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 PointCapsule(Vector3D p, double ra, Vector3D b0, Vector3D b1, double rb, out bool inRange)
        {
            var c = SegmentContact(p, b0, b1, out inRange);
            double r = ra + rb, d = c.Distance - r;
            inRange &= r <= double.MaxValue;
            var pb = c.Closest;
            if (rb != 0) pb += c.Normal * rb; // a segment's witness as it is (adding n·0 would turn a −0 into +0)
            return new DistanceResult3(d, d > 0 ? d * d : 0, p - c.Normal * ra, pb, 0, c.Parameter);
        }

        /// <summary>
        /// <see cref="PointSegment"/> with <see cref="PointCapsule"/>'s push-out normal. The gap test first: it is almost
        /// always false and predictable. Off the interior the residual less its part along the segment (Across) is all the
        /// normal needs, in 3D as in the plane: the push-out puts the point at the foot plus (ra + rb)·n, whose distance
        /// from the axis is ra + rb whatever n's direction across the axis, to the foot's rounding; only a tilt along the
        /// axis leaves overlap (r·θ²/2), and Across removes that. Near an end the feature itself is in doubt: the exact
        /// normal, out of line and returned in tail position with the whole contact (a call whose result is used here
        /// made the callers keep their inputs in memory, SysV having no callee-saved vector registers; a call returning
        /// the callers' result made them keep that in memory: 1.7x slower on every query without PGO).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static PointContact SegmentContact(Vector3D p, Vector3D b0, Vector3D b1, out bool inRange)
        {
            var v = PointSegmentResidual(p, b0, b1, out double t, out double dd);
            double v2 = v.LengthSquared, dist = Math.Sqrt(v2);
            inRange = Range.Length2(v, v2) && (Range.In(dd) || b0 == b1);
            bool near = v2 < dd * NearPoint2;
            Vector3D n;
            if (near && (v2 > dd * 3.1554436208840472e-30 || !(t > 0 && t < 1)))
            {
                if (!Clear(t, 0, 1, 1)) return SegmentContactNear(p, b0, b1, t, dist, v2);
                n = Across(v, b1 - b0, dd);
            }
            else if (near || !(dist > 0)) n = AnyPerpendicular(b1 - b0);
            else if (v2 < dd * NearTouch2 && t > 0 && t < 1) n = Across(v, b1 - b0, dd); // at an end v is p − end itself
            else n = v * (1 / dist);
            return new PointContact(dist, v2, SegmentPoint(b0, b1, t), n, t);
        }

        /// <summary><see cref="SegmentContact"/> with <see cref="NearSegmentNormal"/>, out of line (rare).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static PointContact SegmentContactNear(Vector3D p, Vector3D b0, Vector3D b1, double t, double dist, double v2) =>
            new PointContact(dist, v2, SegmentPoint(b0, b1, t), NearSegmentNormal(p, b0, b1, t), t);

        /// <summary>
        /// Two lines or rays (o, unit d). Not exactly parallel: the lines' closest parameters from cross products of an
        /// accurately formed normal n = dA × dB (<see cref="AccurateCross"/>: the plain cross product cancels to noise
        /// for nearly parallel directions, and the gap w·n/|n| and the parameters ((w × dB)·n, (w × dA)·n)/|n|² then
        /// carry only u·|w|); when both lie on their shapes, the gap between the lines is the answer however far away
        /// they meet, and the witnesses are refined by projection. Otherwise the minimum lies where a ray starts: each
        /// ray's origin against the other shape (<see cref="FromOrigins"/>). Parallel lines: A's origin against B.
        /// Parameters beyond 2^1022·M, M the origins' largest coordinate magnitude to its power of two (lines within about
        /// 2^-1022 of parallel), come back NaN: their points cannot be formed in the rescaled frame, and
        /// <see cref="UnboundedPair"/> then picks other witnesses.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // each query has one call site; called, its three outs cost 2x without PGO
        public static double Unbounded(Vector3D oA, Vector3D dA, bool rayA, Vector3D oB, Vector3D dB, bool rayB, out double s, out double t, out bool inRange)
        {
            var w = oB - oA;
            bool sized = Range.Length2(w, w.LengthSquared);
            var n = AccurateCross(dA, dB);
            double m = Range.MaxAbs(n);
            double nn, si, ti;
            Vector3D nk;
            if (m >= TinyNormal)
            {
                // n scaled by a power of two so its largest component lies in [1, 2): |n|² stays normal however close
                // the directions are, and the scaling is exact.
                double k = Num.InversePowerOfTwo(m);
                nk = n * k;
                nn = nk.LengthSquared;
                si = Vector3D.Dot(Vector3D.Cross(w, dB), nk) / nn * k;
                ti = Vector3D.Dot(Vector3D.Cross(w, dA), nk) / nn * k;
            }
            else if (m > 0)
            {
                // A value, not out parameters: an address taken here would keep the hot path's locals in memory.
                var c = LiftedCrossing(w, dA, dB);
                nk = c.Nk; nn = c.Nn; si = c.Si; ti = c.Ti;
            }
            else { nk = default; nn = si = ti = 0; }
            if (m > 0 && (!rayA || si >= 0) && (!rayB || ti >= 0))
            {
                double gap = Vector3D.Dot(w, nk) / Math.Sqrt(nn), g2 = gap * gap;
                inRange = sized && (gap == 0 || Range.In(g2));
                // Parameters are measured against the origins' magnitude M: past 2^1022·M (to M's power of two) the
                // rescaled slow path, which brings M to 1, could not form the points, so neither path does (2^k-scaled
                // inputs get 2^k-scaled answers on both sides of the paths' boundary). Up to 2^541 no M matters: the fast
                // path's answer is kept only for |w| ≥ 2^-480.
                if ((Math.Abs(si) <= NoReachBelow && Math.Abs(ti) <= NoReachBelow) || WithinReach(si, ti, oA, oB))
                {
                    // The parameters are known to u·|w|/θ along nearly parallel lines, each on its own: a projection
                    // of A's point onto B and back makes the pair consistent (each projection is well conditioned), so
                    // the returned points realise the gap to within their own rounding.
                    t = Vector3D.Dot(dB, dA * si - w);
                    if (rayB && t < 0) t = 0;
                    s = Vector3D.Dot(dA, w + dB * t);
                    if (rayA && s < 0) s = 0;
                }
                else { s = double.NaN; t = double.NaN; }
                return g2;
            }
            double best = FromOrigins(w, dA, rayA, dB, rayB, out s, out t, out var v);
            inRange = sized && Range.Length2(v, best);
            return best;
        }

        /// <summary>2^-900: a cross product of unit directions this small is formed again, lifted (<see cref="LiftedCrossing"/>).</summary>
        private const double TinyNormal = 1.1830521861667747e-271;

        /// <summary>2^541: parameters up to this are within reach of any origins the fast path answers for (|w| ≥ 2^-480; a line and a half-space: |o − p| ≥ 2^-450).</summary>
        private const double NoReachBelow = 7.198262071269114e+162;

        /// <summary>2^1022: parameters up to this (times the origins' magnitude) keep every product and sum of the witness refinement finite.</summary>
        private const double Reach = 4.49423283715579e307;

        /// <summary>
        /// The lines' crossing for directions within 2^-900 of parallel: dA × dB formed from the directions times 2^500
        /// each (a subnormal product would have lost its direction; there they are exact), scaled into [1, 2); the
        /// parameters take back the lifting's 2^1000 after the division, so a zero stays 0.
        /// Rare, so out of line.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static LiftedLines LiftedCrossing(Vector3D w, Vector3D dA, Vector3D dB)
        {
            const double up = 3.273390607896142e150; // 2^500
            var n = AccurateCross(dA * up, dB * up);
            double k = Num.InversePowerOfTwo(Range.MaxAbs(n));
            var nk = n * k;
            double nn = nk.LengthSquared;
            return new LiftedLines
            {
                Nk = nk,
                Nn = nn,
                Si = Vector3D.Dot(Vector3D.Cross(w, dB), nk) / nn * k * (up * up),
                Ti = Vector3D.Dot(Vector3D.Cross(w, dA), nk) / nn * k * (up * up),
            };
        }

        /// <summary><see cref="LiftedCrossing"/>'s answer: the scaled normal, its squared length and the two parameters.</summary>
        private struct LiftedLines
        {
            public Vector3D Nk;
            public double Nn, Si, Ti;
        }

        /// <summary>Whether both parameters lie within 2^1022·M, M the origins' largest coordinate magnitude to its power of two (<see cref="Unbounded"/>).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool WithinReach(double si, double ti, Vector3D oA, Vector3D oB)
        {
            double perM = Num.InversePowerOfTwo(Num.Max(Range.MaxAbs(oA), Range.MaxAbs(oB)));
            return Math.Abs(si) * perM <= Reach && Math.Abs(ti) * perM <= Reach;
        }

        /// <summary>
        /// The minimum over the rays' origins: each ray's origin against the other shape (a line's origin only when both
        /// are lines), the smaller residual, ties to A; <paramref name="v"/> the residual PointB − PointA or its negation.
        /// The answer when the lines' closest points fall outside a ray, and for parallel shapes.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double FromOrigins(Vector3D w, Vector3D dA, bool rayA, Vector3D dB, bool rayB, out double s, out double t, out Vector3D v)
        {
            double best = double.PositiveInfinity;
            s = 0; t = 0;
            v = default;
            if (rayA || !rayB)
            {
                // A's origin against B.
                double tc = -Vector3D.Dot(dB, w);
                if (rayB && tc <= 0) tc = 0;
                v = tc == 0 ? -w : -w - dB * tc;
                best = v.LengthSquared;
                t = tc;
            }
            if (rayB)
            {
                double sc = Vector3D.Dot(dA, w);
                if (rayA && sc <= 0) sc = 0;
                var r = sc == 0 ? w : w - dA * sc;
                double r2 = r.LengthSquared;
                if (r2 < best) { best = r2; v = r; s = sc; t = 0; }
            }
            return best;
        }

        /// <summary>
        /// A linear component against segment [b0, b1]: the squared distance, the parameters and the residual v = PointB −
        /// PointA formed from differences. A segment goes to <see cref="SegmentSegmentCore"/> as it is. A line or ray is
        /// first cut to the stretch that holds its closest point: the point of the line nearest a point of the segment is
        /// that point's projection, whose parameter lies between the endpoints' (for a ray, clamped at 0), so the segment
        /// kernel (with its nearly-parallel care) answers on that stretch, in the frame of the line's origin.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double LinearSegment(in Linear a, Vector3D b0, Vector3D b1, out double s, out double t, out Vector3D v, out bool inRange)
        {
            if (a.IsSegment)
            {
                double r2 = SegmentSegmentCore(a.Start, a.End, b0, b1, out s, out t, out inRange);
                v = (b0 - a.Start) - (a.Dir * s - (b1 - b0) * t);
                return r2;
            }
            return CutLinearSegment(a, b0, b1, out s, out t, out v, out inRange);
        }

        /// <summary><see cref="LinearSegment"/> for a line or ray (not a segment): the cut, then the segment kernel.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double CutLinearSegment(in Linear a, Vector3D b0, Vector3D b1, out double s, out double t, out Vector3D v, out bool inRange)
        {
            var q0 = b0 - a.Start;
            var q1 = b1 - a.Start;
            double t0 = Vector3D.Dot(a.Dir, q0), t1 = Vector3D.Dot(a.Dir, q1);
            double lo = Math.Min(t0, t1), hi = Math.Max(t0, t1);
            if (a.IsRay) { lo = Math.Max(lo, 0); hi = Math.Max(hi, 0); }
            var c0 = a.Dir * lo;
            var c1 = a.Dir * hi;
            double r2 = SegmentSegmentCore(c0, c1, q0, q1, out double sc, out t, out inRange);
            s = sc <= 0.5 ? lo + (hi - lo) * sc : hi - (hi - lo) * (1 - sc);
            v = (q0 - c0) - ((c1 - c0) * sc - (q1 - q0) * t);
            return r2;
        }

        /// <summary>
        /// Whether a line or ray meets segment [b0, b1]: <see cref="LinearCapsule"/>'s distance is 0. Not LinearSegment
        /// inlined here: the JIT's inlining budget grows with the calling method's own size, and from a method this small
        /// it ran out inside the segment kernel, leaving even Vector3D's operators as calls (half the speed of this).
        /// </summary>
        public static bool LinearSegmentMeet(in Linear a, Vector3D b0, Vector3D b1, out bool inRange) =>
            LinearCapsule(a, 0, b0, b1, 0, false, false, out inRange).DistanceSquared == 0;

        /// <summary>
        /// <see cref="LinearCapsule"/> for two segment axes (capsules, or a segment of radius 0 against a capsule), with
        /// its common case inline: axes more than 2^-26 of their reach apart push along the unit residual, which is what
        /// LinearCapsule does there, by the same operations (the same bits). Anything else (axes meeting, nearly touching,
        /// crossing in the plane) is LinearCapsule itself, called in tail position. Through Linear and the segment
        /// kernel as a call with three out parameters, the common case cost 2–3x the segment–segment query.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 CapsuleCapsule(Vector3D a0, Vector3D a1, double ra, Vector3D b0, Vector3D b1, double rb, bool planar, out bool inRange)
        {
            double r2 = SegmentSegmentInline(a0, a1, b0, b1, out double s, out double t, out inRange);
            double dist = Math.Sqrt(r2);
            double reach = Range.MaxAbs(b0 - a0, b1 - a0, a1 - a0);
            if (!(dist > reach * NearTouch)) return LinearCapsule(Linear.Segment(a0, a1), ra, b0, b1, rb, planar, true, out inRange);
            var v = (b0 - a0) - ((a1 - a0) * s - (b1 - b0) * t); // as LinearSegment forms it, before the zeros' signs are normalised
            s += 0; t += 0; // −0 + 0 = 0
            double r = ra + rb;
            inRange &= r <= double.MaxValue;
            var n = v * (1 / v.Length);
            double d = dist - r;
            return new DistanceResult3(d, d > 0 ? d * d : 0, SegmentPoint(a0, a1, s) + n * ra, SegmentPoint(b0, b1, t) - n * rb, s, t);
        }

        /// <summary>
        /// The distance of <see cref="LinearCapsule"/>(a, 0, b0, b1, rb, false, <paramref name="solid"/>) alone, from the
        /// same operations and with its range verdict: in 3D the Minkowski difference of the two axes is flat, so that is
        /// the axes' distance less rb in every case (meeting axes only choose another push), or for a segment
        /// (!<paramref name="solid"/>) the axes' distance.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double LinearCapsuleDistance(in Linear a, Vector3D b0, Vector3D b1, double rb, bool solid, out bool inRange)
        {
            double dist = Math.Sqrt(LinearSegment(a, b0, b1, out _, out _, out _, out inRange));
            if (!solid) return dist;
            double r = 0 + rb; // LinearCapsule's ra + rb
            inRange &= r <= double.MaxValue;
            return dist - r;
        }

        /// <summary>
        /// The overlap verdict of <see cref="CapsuleCapsule"/> (planar; in either argument order) from the axes' distance
        /// <paramref name="dist"/> (the segment kernel's, the same bits in both orders) and the radii's sum r, where it
        /// follows without the crossing depth: 1 (overlap) when dist − r ≤ 0, because Between's distance is then dist − r or,
        /// for crossing axes, −(r + depth) &lt; 0; −1 (apart) when dist − r &gt; 0 and the axes are clear of each other
        /// (<see cref="AxesClear"/>: Between is dist − r there); 0 otherwise, axes nearly touching beyond the radii, where
        /// rounding may make them cross and only Between's distance tells. <paramref name="inRange"/> gains r's check.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static int OverlapsByAxes(double dist, double r, Vector3D a0, Vector3D a1, Vector3D b0, Vector3D b1, ref bool inRange)
        {
            inRange &= r <= double.MaxValue;
            if (dist - r <= 0) return 1;
            return AxesClear(dist, a0, a1, b0, b1) ? -1 : 0;
        }

        /// <summary>
        /// Whether axes [a0, a1] and [b0, b1] at distance <paramref name="dist"/> take <see cref="CapsuleCapsule"/>'s fast path
        /// in both argument orders: its reach is the largest coordinate of b0 − a0, b1 − a0, a1 − a0 in one order and of
        /// a0 − b0, a1 − b0, b1 − b0 in the other, and the largest of all five differences' magnitudes bounds both.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AxesClear(double dist, Vector3D a0, Vector3D a1, Vector3D b0, Vector3D b1) =>
            dist > Num.Max(Range.MaxAbs(b0 - a0, b1 - a0, a1 - a0), Num.Max(Range.MaxAbs(a1 - b0), Range.MaxAbs(b1 - b0))) * NearTouch;

        /// <summary>
        /// A linear component a, thickened by ra when it is a capsule's axis, against the capsule (or, for rb = 0 and
        /// !<paramref name="solid"/>, the segment) [b0, b1] of radius rb. 3D, or 2D separated: the axes' distance less
        /// ra + rb, the witnesses pushed along the unit residual; axes that meet (to within 2^-49 of their extent, the
        /// rounding of the residual) push along the common normal dA × dB, or
        /// for parallel axes along <see cref="AnyPerpendicular"/> of A's direction (a zero-length axis: of B's). 2D
        /// <paramref name="planar"/> solids whose axes cross: the Minkowski difference of the axes has an interior, and its
        /// depth (<see cref="Separation2"/>) adds to the radii.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 LinearCapsule(in Linear a, double ra, Vector3D b0, Vector3D b1, double rb, bool planar, bool solid, out bool inRange)
        {
            double r2 = LinearSegment(a, b0, b1, out double s, out double t, out var v, out inRange);
            s += 0; t += 0; // −0 + 0 = 0
            var pa = a.PointAt(s);
            var pb = SegmentPoint(b0, b1, t);
            if (!solid) return new DistanceResult3(Math.Sqrt(r2), r2, pa, r2 == 0 ? pa : pb, s, t); // meeting: one common point

            double r = ra + rb, dist = Math.Sqrt(r2);
            inRange &= r <= double.MaxValue;
            // A residual within 2^-49 of the axes' extent (from A's start) is rounding: its direction is noise (it can
            // point along an axis), so the axes count as meeting.
            double reach = Range.MaxAbs(b0 - a.Start, b1 - a.Start, a.End - a.Start);
            bool meet = dist <= reach * 1.7763568394002505e-15;
            Vector3D n;
            if (planar)
            {
                var b = Linear.Segment(b0, b1);
                double g = Separation2(a, b, out var axis, out bool aFlat);
                if (g < 0) return Crossing2(a, ra, b, rb, g, axis, aFlat, reach);
                // Touching axes have no residual: the separating axis orients the push (A lies on its + side).
                n = !meet ? v * (1 / v.Length) : (axis != default ? -axis : Vector3D.UnitX);
                if (!meet && dist < reach * NearTouch) n = NearAxesNormal(a, b0, b1, s, t, true, Num.InversePowerOfTwo(reach), n);
            }
            else if (!meet)
            {
                n = v * (1 / v.Length);
                if (dist < reach * NearTouch) n = NearAxesNormal(a, b0, b1, s, t, false, Num.InversePowerOfTwo(reach), n);
            }
            else
            {
                // Meeting axes: the common normal separates them whether they meet at interior points or endpoints
                // (it is perpendicular to both), turned to agree with what residual there is.
                // Directions scaled by powers of two first: the cross product of tiny or huge ones would underflow or
                // overflow.
                var dA = a.Dir;
                var dB = b1 - b0;
                double mA = Range.MaxAbs(dA), mB = Range.MaxAbs(dB);
                var c = mA > 0 && mB > 0 ? AccurateCross(dA * Num.InversePowerOfTwo(mA), dB * Num.InversePowerOfTwo(mB)) : default;
                n = Unit(c, AnyPerpendicular(mA > 0 ? dA : dB));
                if (Vector3D.Dot(n, v) < 0) n = -n;
            }
            double d = dist - r;
            return new DistanceResult3(d, d > 0 ? d * d : 0, pa + n * ra, pb - n * rb, s, t);
        }

        /// <summary>
        /// The unit normal from axis A to segment [b0, b1] when they nearly touch. The rounded
        /// residual turns by about u·reach/dist there, and a radius pushed out along it leaves radius·angle²/2 of overlap
        /// (axes 1e-12 apart: 5e-8); which features hold the pair is as uncertain (a foot within u·reach of an end). So
        /// every feature pair's normal is formed from the exact inputs: each end's vector from the other axis (its
        /// perpendicular, or the difference to the nearer end, <see cref="EdgeVector"/>), and in 3D the common normal of
        /// the directions; and the one whose plane leaves the whole Minkowski difference of the axes farthest on its far
        /// side (the support of its vertices, each by a compensated dot product) is taken: the exact normal's support is
        /// the distance itself, and a direction whose support is within δ of it pushes out to within δ. A line's or
        /// ray's unbounded side admits only directions that do not lead back along it. <paramref name="fallback"/> when
        /// every candidate is zero or leads along a line or ray. Differences are scaled by k (a power of two near
        /// 1/reach), so the products' error terms stay clear of underflow and 2^j-scaled inputs give the same direction,
        /// bit for bit. Axes within 2^-49 of the reach count as meeting and are not asked here: any direction
        /// perpendicular to both pushes them out to within twice that.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static Vector3D NearAxesNormal(in Linear a, Vector3D b0, Vector3D b1, double s, double t, bool planar, double k, Vector3D fallback)
        {
            Vector3D eh, el;
            if (a.IsSegment) ExactDiff(a.End, a.Start, k, out eh, out el);
            else { eh = a.Dir * Num.InversePowerOfTwo(Range.MaxAbs(a.Dir)); el = default; }
            double best = double.NegativeInfinity;
            var n = fallback;
            var common = default(Vector3D);
            if (!planar)
            {
                ExactDiff(b1, b0, k, out var gh, out var gl);
                common = FacetAxis(eh, el, gh, gl);
                // Interior points far from every end (the rounded parameters are off by far less) and directions not
                // nearly parallel (sin² above 2^-30): the pair is the interiors', its normal the common one (the usual
                // case, kept cheap).
                if (Clear(s, a.Lo, a.Hi, a.IsSegment ? 1 : 1 / (k * Range.MaxAbs(a.Dir))) && Clear(t, 0, 1, 1)
                    && common.LengthSquared > 9.313225746154785E-10 * (eh.LengthSquared * gh.LengthSquared))
                {
                    ExactDiff(b0, a.Start, k, out var wh, out var wl);
                    return Unit(OffsetFrom(common, wh, wl, 0) < 0 ? -common : common, fallback);
                }
            }
            if (a.IsSegment || a.IsRay) Consider(-EdgeVector(a.Start, b0, b1, k), a, b0, b1, eh, k, ref best, ref n); // a line has no end
            if (a.IsSegment) Consider(-EdgeVector(a.End, b0, b1, k), a, b0, b1, eh, k, ref best, ref n);
            Consider(LinearVector(b0, a, eh, el, k), a, b0, b1, eh, k, ref best, ref n);
            Consider(LinearVector(b1, a, eh, el, k), a, b0, b1, eh, k, ref best, ref n);
            Consider(common, a, b0, b1, eh, k, ref best, ref n);
            Consider(-common, a, b0, b1, eh, k, ref best, ref n);
            return n;
        }

        /// <summary>
        /// Whether parameter x lies at least 2^-16·<paramref name="width"/> inside both ends of [lo, hi] (an infinite end
        /// is never near; a segment's width is 1, a line's or ray's the parameter span of the configuration's reach).
        /// </summary>
        internal static bool Clear(double x, double lo, double hi, double width) =>
            x - lo > 1.52587890625E-05 * width && hi - x > 1.52587890625E-05 * width;

        /// <summary>(q − its nearest point on A)·k, to about a rounding of itself (<see cref="EdgeVector"/> for a segment).</summary>
        private static Vector3D LinearVector(Vector3D q, in Linear a, Vector3D eh, Vector3D el, double k)
        {
            if (a.IsSegment) return EdgeVector(q, a.Start, a.End, k);
            ExactDiff(q, a.Start, k, out var wh, out var wl);
            if (a.IsRay && !(OffsetFrom(eh, wh, wl, 0) > 0)) return wh + wl;
            return PerpOfDifference(wh, wl, eh, el);
        }

        /// <summary>
        /// Takes direction v (from A toward B) if its support, the least of (B's end − A's end)·v̂ over the Minkowski
        /// difference's vertices, beats <paramref name="best"/> (whatever its sign: the supports carry the rounding of
        /// v̂ times the size). A ray or line extends it without bound unless v̂ does not lead along A's unbounded side
        /// (to 2^-40).
        /// </summary>
        private static void Consider(Vector3D v, in Linear a, Vector3D b0, Vector3D b1, Vector3D eh, double k, ref double best, ref Vector3D n)
        {
            if (v == default) return;
            var u = Unit(v, default);
            if (!a.IsSegment)
            {
                double along = Vector3D.Dot(u, eh) / eh.Length;
                if (a.IsRay ? along > 9.094947017729282E-13 : Math.Abs(along) > 9.094947017729282E-13) return;
            }
            double h = Math.Min(Support(u, b0, a.Start, k), Support(u, b1, a.Start, k));
            if (a.IsSegment) h = Math.Min(h, Math.Min(Support(u, b0, a.End, k), Support(u, b1, a.End, k)));
            if (h > best) { best = h; n = u; }
        }

        /// <summary>(q − p)·k·u to about a rounding of itself (compensated).</summary>
        private static double Support(Vector3D u, Vector3D q, Vector3D p, double k)
        {
            ExactDiff(q, p, k, out var wh, out var wl);
            return OffsetFrom(u, wh, wl, 0);
        }

        /// <summary>
        /// (p minus its projection onto the line q + τ·(eh + el))·k, for eh + el exact and k a power of two, to about a
        /// rounding of itself: (p − q)·k split exactly, eh·τ with its exact rounding error, and what τ's own rounding
        /// leaves along the line removed at the end (it moves the foot along the line only).
        /// </summary>
        private static Vector3D AccuratePerp(Vector3D p, Vector3D q, double k, Vector3D eh, Vector3D el)
        {
            ExactDiff(p, q, k, out var wh, out var wl);
            return PerpOfDifference(wh, wl, eh, el);
        }

        /// <summary>
        /// <see cref="AccuratePerp"/> from the difference wh + wl (to about u² of itself) instead of two points.
        /// </summary>
        private static Vector3D PerpOfDifference(Vector3D wh, Vector3D wl, Vector3D eh, Vector3D el)
        {
            double ee = eh.LengthSquared;
            if (!(ee > 0)) return wh + wl;
            double tau = Vector3D.Dot(wh, eh) / ee;
            var r = new Vector3D(PerpPart(wh.X, wl.X, eh.X, el.X, tau), PerpPart(wh.Y, wl.Y, eh.Y, el.Y, tau), PerpPart(wh.Z, wl.Z, eh.Z, el.Z, tau));
            return r - eh * (Vector3D.Dot(r, eh) / ee);
        }

        /// <summary>(wh + wl) − (eh + el)·τ: the rounded parts' difference is exact where they cancel (Sterbenz).</summary>
        private static double PerpPart(double wh, double wl, double eh, double el, double tau)
        {
            double p = eh * tau;
            return (wh - p) + ((wl - ProductError(eh, tau, p)) - el * tau);
        }

        /// <summary>
        /// The crossing depth case of 2D capsules: the axes' Minkowski difference holds the origin at depth −g below the
        /// face of <paramref name="axis"/> (unit, A on its + side), so A moves by (−g + ra + rb)·axis. The endpoint that
        /// bounds the extent along the axis (A's, unless the axis is A's own normal) is paired with its image across the
        /// depth on the other axis. Exactly, that image lies on the other axis (the origin's foot on the nearest face of a
        /// convex set lies on the face); when rounding picked between nearly parallel faces of a sliver (axes nearly
        /// collinear and overlapping, every depth at rounding size) it can fall far outside it, and then the pair is
        /// <see cref="OverlapEnds"/>'s.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 Crossing2(in Linear a, double ra, in Linear b, double rb, double g, Vector3D axis, bool aFlat, double reach)
        {
            double s, t, moved;
            Vector3D pa, pb;
            if (!aFlat)
            {
                s = Vector3D.Dot(a.Dir, axis) > 0 ? a.Lo : a.Hi;
                pa = a.PointAt(s);
                pb = pa - axis * g;
                t = Project(b, pb - b.Start, out moved);
            }
            else
            {
                t = Vector3D.Dot(b.Dir, axis) > 0 ? b.Hi : b.Lo;
                pb = b.PointAt(t);
                pa = pb + axis * g;
                s = Project(a, pa - a.Start, out moved);
            }
            // 2^-40 of the reach: far above the rounding of the image, far below any gap a sliver's faces can hide. Not
            // within it also when NaN: a sliver along a ray can pick the ray's infinite end.
            if (!(moved <= reach * 9.094947017729282E-13)) OverlapEnds(a, b, out s, out t, out pa, out pb);
            double d = g - (ra + rb);
            return new DistanceResult3(d, 0, pa - axis * ra, pb + axis * rb, s, t);
        }

        /// <summary>
        /// For axes that overlap nearly collinearly: of the finite ends of each, projected onto the other, the pair
        /// closest together (an end inside the other's stretch, within rounding of it).
        /// </summary>
        private static void OverlapEnds(in Linear a, in Linear b, out double s, out double t, out Vector3D pa, out Vector3D pb)
        {
            double best = double.PositiveInfinity;
            s = 0; t = 0; pa = a.Start; pb = b.Start;
            for (int i = 0; i < 4; i++)
            {
                double si, ti;
                if (i < 2)
                {
                    si = i == 0 ? a.Lo : a.Hi;
                    if (double.IsInfinity(si)) continue;
                    ti = Project(b, a.PointAt(si) - b.Start);
                }
                else
                {
                    ti = i - 2;
                    si = Project(a, b.PointAt(ti) - a.Start);
                }
                Vector3D qa = a.PointAt(si), qb = b.PointAt(ti);
                double e = (qb - qa).LengthSquared;
                if (e < best) { best = e; s = si; t = ti; pa = qa; pb = qb; }
            }
        }

        /// <summary>
        /// The parameter of the point of a nearest to a.Start + q, within a's range. On q and the direction scaled by the
        /// power of two that brings the direction near 1 (exact, so elsewhere the same bits): a short q times a long
        /// direction would underflow at the small end of the fast range.
        /// </summary>
        private static double Project(in Linear a, Vector3D q) => Project(a, q, out _);

        /// <summary>
        /// <see cref="Project(in Linear, Vector3D)"/>, also giving how far the clamp moved the point along a (in the largest
        /// component of its direction; NaN for a NaN q).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Project(in Linear a, Vector3D q, out double moved)
        {
            double m = Range.MaxAbs(a.Dir);
            moved = Range.MaxAbs(q);
            if (m == 0) return 0;
            double k = Num.InversePowerOfTwo(m);
            var dk = a.Dir * k;
            double raw = Vector3D.Dot(q * k, dk) / dk.LengthSquared, s = Num.Clamp(raw, a.Lo, a.Hi);
            moved = Math.Abs(raw - s) * m;
            return s;
        }

        /// <summary>
        /// 2D separation of two linear components: the largest gap between their extents over the axes normal to and
        /// along each direction (Gottschalk's separating-axis test on the Minkowski difference A − B, whose faces are
        /// normal to the directions; the along-axes only tighten it where the difference is a thin sliver). Negative
        /// exactly when the origin is inside A − B, and then −(its depth), the distance to the nearest face: the 2D
        /// crossing depth. <paramref name="axis"/> is the unit axis of the largest gap, oriented with A on its + side
        /// (zero when no direction is non-zero; the result is then +∞); <paramref name="aFlat"/> when A's extent along it
        /// is one value (its own normal, or B's direction when that is perpendicular to A). Extents are measured from A's start, so a common translation costs
        /// nothing. Ties go to the earlier axis.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double Separation2(in Linear a, in Linear b, out Vector3D axis, out bool aFlat)
        {
            double g = double.PositiveInfinity;
            axis = default;
            aFlat = false;
            var w = b.Start - a.Start;
            var da = a.Dir;
            var db = b.Dir;
            double la = Math.Sqrt(da.X * da.X + da.Y * da.Y), lb = Math.Sqrt(db.X * db.X + db.Y * db.Y);
            bool first = true;
            // Unnormalised axes, so a component's own normal meets its direction in an exact 0 (its extent along it is
            // one value, even for a line); the gaps are divided by the length afterwards.
            if (la > 0)
            {
                Gap(new Vector3D(-da.Y, da.X, 0), la, a, b, w, ref g, ref axis, ref first, ref aFlat);
                Gap(new Vector3D(da.X, da.Y, 0), la, a, b, w, ref g, ref axis, ref first, ref aFlat);
            }
            if (lb > 0)
            {
                Gap(new Vector3D(-db.Y, db.X, 0), lb, a, b, w, ref g, ref axis, ref first, ref aFlat);
                Gap(new Vector3D(db.X, db.Y, 0), lb, a, b, w, ref g, ref axis, ref first, ref aFlat);
            }
            return g;
        }

        /// <summary>
        /// Takes the axis e/len when either orientation's gap beats g (ties to the earlier), noting whether A's extent
        /// along it is one value (its direction's component exactly 0). Why per axis and not per family: B's direction
        /// can be A's normal itself (a line perpendicular to B), and rounding then decides which of the two equal gaps
        /// wins; A is flat along either.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static void Gap(Vector3D e, double len, in Linear a, in Linear b, Vector3D w, ref double g, ref Vector3D axis, ref bool first, ref bool aFlat)
        {
            double kA = Vector3D.Dot(a.Dir, e);
            Extent(0, kA, a.Lo, a.Hi, out double loA, out double hiA);
            Extent(Vector3D.Dot(w, e), Vector3D.Dot(b.Dir, e), b.Lo, b.Hi, out double loB, out double hiB);
            double up = (loA - hiB) / len, down = (loB - hiA) / len;
            if (first || up > g) { g = up; axis = e / len; first = false; aFlat = kA == 0; }
            if (down > g) { g = down; axis = -e / len; aFlat = kA == 0; }
        }

        /// <summary>
        /// The extent c + [lo, hi]·k of a component along an axis (k its direction's component; ±∞ for unbounded ends).
        /// Inlined, as <see cref="Project(in Linear, Vector3D, out double)"/>: without dynamic PGO the JIT left both as calls
        /// (ab, 2 × 7, no PGO: 2D line, ray, segment and capsule against a capsule 0.80–0.91; with PGO and on Mono within noise).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Extent(double c, double k, double lo, double hi, out double min, out double max)
        {
            if (k > 0) { min = c + lo * k; max = c + hi * k; }
            else if (k < 0) { min = c + hi * k; max = c + lo * k; }
            else { min = c; max = c; }
        }

        /// <summary>
        /// <see cref="UnboundedPair"/> of two lines or two rays, computed on the pair in canonical order
        /// (<see cref="Order.Swap(Vector3D, Vector3D, Vector3D, Vector3D)"/>) and swapped back, so either argument order
        /// gives the same answer. The inputs are selected first and the kernel is called from one site: called once per
        /// order, it was inlined twice, and the doubled body ran 1.5–3× slower.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 OrderedUnboundedPair(Vector3D oA, Vector3D dA, Vector3D oB, Vector3D dB, bool rays, double range, out bool inRange)
        {
            bool swap = Order.Swap(oA, dA, oB, dB);
            var r = UnboundedPair(swap ? oB : oA, swap ? dB : dA, rays, swap ? oA : oB, swap ? dA : dB, rays, range, out inRange);
            return swap ? r.Swapped() : r;
        }

        /// <summary>The Distance of <see cref="OrderedUnboundedPair"/> alone, bit for bit: the same kernel on the same canonical order.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double OrderedUnboundedDistance(Vector3D oA, Vector3D dA, Vector3D oB, Vector3D dB, bool rays, out bool inRange)
        {
            bool swap = Order.Swap(oA, dA, oB, dB);
            return Math.Sqrt(Unbounded(swap ? oB : oA, swap ? dB : dA, rays, swap ? oA : oB, swap ? dA : dB, rays, out _, out _, out inRange));
        }

        /// <summary>
        /// <see cref="Unbounded"/> as a result: the witnesses Origin + t·Direction of each shape. Should either point or
        /// parameter lie beyond <paramref name="range"/> (the float API passes float.MaxValue), or a parameter beyond
        /// 2^1022·M (<see cref="Unbounded"/>), no pair of points the result can hold realises the distance: the distance
        /// stands, and the witnesses are those of the origins (<see cref="FromOrigins"/>, as for parallel shapes).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 UnboundedPair(Vector3D oA, Vector3D dA, bool rayA, Vector3D oB, Vector3D dB, bool rayB, double range, out bool inRange)
        {
            double r2 = Unbounded(oA, dA, rayA, oB, dB, rayB, out double s, out double t, out inRange);
            s += 0; t += 0; // −0 + 0 = 0
            var pa = oA + dA * s;
            // Meeting shapes answer one common point (the contract for two non-solids).
            var pb = r2 == 0 ? pa : oB + dB * t;
            // Non-short-circuit ands: one branch, not eight (a NaN parameter past reach fails its comparison).
            bool fits = (Math.Abs(pa.X) <= range) & (Math.Abs(pa.Y) <= range) & (Math.Abs(pa.Z) <= range)
                      & (Math.Abs(pb.X) <= range) & (Math.Abs(pb.Y) <= range) & (Math.Abs(pb.Z) <= range)
                      & (Math.Abs(s) <= range) & (Math.Abs(t) <= range);
            if (!fits) return FarWitnesses(oA, dA, rayA, oB, dB, rayB, r2);
            return new DistanceResult3(Math.Sqrt(r2), r2, pa, pb, s, t);
        }

        /// <summary>The distance of <see cref="UnboundedPair"/> with the origins' witnesses: the lines' closest points lie beyond the range. Rare, so out of line.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static DistanceResult3 FarWitnesses(Vector3D oA, Vector3D dA, bool rayA, Vector3D oB, Vector3D dB, bool rayB, double r2)
        {
            FromOrigins(oB - oA, dA, rayA, dB, rayB, out double s, out double t, out _);
            s += 0; t += 0;
            return new DistanceResult3(Math.Sqrt(r2), r2, oA + dA * s, oB + dB * t, s, t);
        }

        /// <summary>
        /// Whether the line or ray meets the closed ball: the squared residual of <see cref="PointLinear"/> against r².
        /// <paramref name="inRange"/>: the larger square in the fast range. Unlike <see cref="WithinRadius"/>, the residual
        /// is checked too: an origin so far from the center that their difference overflows (r² ∞ or NaN) does not make
        /// the line far from it.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool LinearInBall(Vector3D center, Vector3D o, Vector3D d, bool ray, double radius, out bool inRange)
        {
            var w = center - o;
            double t = Vector3D.Dot(w, d);
            if (ray && t <= 0) t = 0;
            double r2 = (t == 0 ? w : w - d * t).LengthSquared, rr = radius * radius;
            inRange = Range.LargerIn(rr, r2);
            return r2 <= rr;
        }

        /// <summary>Whether the capsule axis [b0, b1] comes within r (the sum of the radii) of c; <paramref name="inRange"/> as for <see cref="SegmentInSphere"/> (an infinite sum fails its r² check).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool CapsuleTouchesBall(Vector3D b0, Vector3D b1, Vector3D c, double r, out bool inRange) =>
            SegmentInSphere(b0, b1, c, r, out inRange);

        /// <summary>Whether capsule b comes strictly before capsule a: by axis (<see cref="Order.Swap(Vector3D, Vector3D, Vector3D, Vector3D)"/>), equal axes by radius.</summary>
        public static bool SwapCapsules(Vector3D a0, Vector3D a1, double ra, Vector3D b0, Vector3D b1, double rb) =>
            a0 == b0 && a1 == b1 ? ra > rb : Order.Swap(a0, a1, b0, b1);
    }
}
