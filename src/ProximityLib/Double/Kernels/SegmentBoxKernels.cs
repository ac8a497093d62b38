using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// Minimum over t ∈ [0, 1] of the squared distance from a + t·d to the box [lo, hi] (all box-local). The function is
        /// convex and piecewise quadratic, with breakpoints where the segment crosses a slab plane, so its half-derivative
        /// <see cref="SlabSlope"/> is nondecreasing: its sign at the ends and at the breakpoints brackets the minimum in
        /// one piece, where the set of clamped axes is fixed and the minimum is that piece's clamped stationary point
        /// (the closed form; no sorting, one piece solved). The squared gap is measured at the returned parameter.
        /// The slopes and the stationary point's sums take d scaled by kd, the power of two that brings it near 1 (the
        /// stationary point is unscaled by kd: all exact, so elsewhere the same bits): a segment far shorter than its
        /// distance to the box (a line clipped to a short stretch) at the small end of the fast range would otherwise
        /// square or multiply its direction into underflow, and a zero slope there decides the bracket wrongly.
        /// Inlined on the callers' main paths (rare ones call <see cref="SegmentBoxLocalCall"/>): as a call it took its
        /// four vectors through the stack, and the JIT inlined it only in some callers, and only with dynamic PGO (ab,
        /// 2 × 7: 3D segment–AABB and segment–OBB 0.93–1.02 on .NET 10, 0.94–0.96 without PGO, where also 2D triangle–box
        /// took 0.71–0.76 and 3D line–box and ray–box 0.84–0.93; Mono capsule–box overlap 0.47–0.59, segment–AABB Between 0.91–0.93).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double SegmentBoxLocal(Vector3D a, Vector3D d, Vector3D lo, Vector3D hi, out double t)
        {
            double kd = Num.InversePowerOfTwo(Range.MaxAbs(d));
            var dk = d * kd;
            double left = 0, right = 1;
            if (SlabSlope(a, d, dk, lo, hi, 0) >= 0) right = 0;
            else if (SlabSlope(a, d, dk, lo, hi, 1) <= 0) left = 1;
            else
            {
                Narrow(a, d, dk, lo, hi, (lo.X - a.X) / d.X, ref left, ref right);
                Narrow(a, d, dk, lo, hi, (hi.X - a.X) / d.X, ref left, ref right);
                Narrow(a, d, dk, lo, hi, (lo.Y - a.Y) / d.Y, ref left, ref right);
                Narrow(a, d, dk, lo, hi, (hi.Y - a.Y) / d.Y, ref left, ref right);
                Narrow(a, d, dk, lo, hi, (lo.Z - a.Z) / d.Z, ref left, ref right);
                Narrow(a, d, dk, lo, hi, (hi.Z - a.Z) / d.Z, ref left, ref right);
            }
            if (left < right)
            {
                // One piece: the axes clamped at its middle stay clamped on it; their quadratic's stationary point, clamped.
                double tm = 0.5 * (left + right), num = 0, den = 0;
                Accumulate(a.X, d.X, dk.X, lo.X, hi.X, tm, ref num, ref den);
                Accumulate(a.Y, d.Y, dk.Y, lo.Y, hi.Y, tm, ref num, ref den);
                Accumulate(a.Z, d.Z, dk.Z, lo.Z, hi.Z, tm, ref num, ref den);
                t = den > 0 ? Num.Clamp(num / den * kd, left, right) : left;
            }
            else t = left; // the minimum is at an end or exactly at a breakpoint
            return Gap(a.X, d.X, lo.X, hi.X, t) + Gap(a.Y, d.Y, lo.Y, hi.Y, t) + Gap(a.Z, d.Z, lo.Z, hi.Z, t);
        }

        /// <summary>
        /// <see cref="SegmentBoxLocal"/> as a call, for paths that are rare (a minimum the touching feature did not name) or
        /// were faster so: inlined into capsule–box's apart branch, it took Between 1.10–1.17 times as long on .NET 10 (ab).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double SegmentBoxLocalCall(Vector3D a, Vector3D d, Vector3D lo, Vector3D hi, out double t) => SegmentBoxLocal(a, d, lo, hi, out t);

        /// <summary>
        /// Half the derivative of the squared distance from a + t·d to the box at t, times 1/kd (dk = d·kd, kd &gt; 0: the
        /// same sign): Σ dk_i·(e_i − clamp(e_i)), e = a + t·d. Nondecreasing in t (each term is).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double SlabSlope(Vector3D a, Vector3D d, Vector3D dk, Vector3D lo, Vector3D hi, double t) =>
            dk.X * Outside(a.X + t * d.X, lo.X, hi.X) + dk.Y * Outside(a.Y + t * d.Y, lo.Y, hi.Y) + dk.Z * Outside(a.Z + t * d.Z, lo.Z, hi.Z);

        /// <summary>
        /// e − clamp(e, lo, hi): how far e lies outside [lo, hi], signed (branch-free: at most one term is not 0). With
        /// Num's minsd/maxsd, one instruction each where Math.Min/Max compile to three under AVX-512. Num's precondition
        /// can fail here in one harmless way: e − lo = −0 against 0 gives −0 or +0 by build, but the Max term is then +0
        /// under either rule (max of ±0 and +0), so the sum is +0 on both. A NaN (from an overflowed difference) can
        /// only arise where the range check has already sent the query to the slow path.
        /// </summary>
        /// <remarks>
        /// Without the NET intrinsics (Mono, Unity) min(m, 0) + max(n, 0) is formed as ((m − |m|) + (n + |n|))·0.5: Mono
        /// compiles Math.Min/Max and conditionals to branches, which mispredict on mixed inputs (the segment–box
        /// minimum took 1.3 times as long there), and Math.Abs to one mask. The same value: m − |m| is 2m or +0,
        /// n + |n| is 2n or +0, at most one is not 0 (lo ≤ hi), doubling and halving are exact in range, and inside the
        /// interval the sum is +0 as above (−0 − 0 + (+0) = +0).
        /// </remarks>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
#if NET
        private static double Outside(double e, double lo, double hi) => Num.Min(e - lo, 0) + Num.Max(e - hi, 0);
#else
        private static double Outside(double e, double lo, double hi)
        {
            double m = e - lo, n = e - hi;
            return ((m - Math.Abs(m)) + (n + Math.Abs(n))) * 0.5;
        }
#endif

        /// <summary>
        /// Shrinks the bracket [left, right] of the minimum with breakpoint b (skipped outside the bracket, and when not a
        /// number: an axis the segment does not move along has none): the slope's sign there says on which side the minimum is.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Narrow(Vector3D a, Vector3D d, Vector3D dk, Vector3D lo, Vector3D hi, double b, ref double left, ref double right)
        {
            if (!(b > left && b < right)) return;
            double s = SlabSlope(a, d, dk, lo, hi, b);
            if (s <= 0) left = b;
            if (s >= 0) right = b;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Accumulate(double a, double d, double dk, double lo, double hi, double t, ref double num, ref double den)
        {
            double e = a + t * d;
            double bound;
            if (e < lo) bound = lo;
            else if (e > hi) bound = hi;
            else return;
            num += dk * (bound - a);
            den += dk * dk;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Gap(double a, double d, double lo, double hi, double t)
        {
            double g = Outside(a + t * d, lo, hi);
            return g * g;
        }

        /// <summary>The box point nearest to the box-local point e, in world coordinates.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D ClampToBox(in Box box, Vector3D e) => box.Origin + box.ToWorldOffset(ClampLocal(e, box.Lo, box.Hi));

        /// <summary>The point of [lo, hi] nearest to e (all box-local).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D ClampLocal(Vector3D e, Vector3D lo, Vector3D hi) =>
            new Vector3D(Num.Clamp(e.X, lo.X, hi.X), Num.Clamp(e.Y, lo.Y, hi.Y), Num.Clamp(e.Z, lo.Z, hi.Z));

        /// <summary>
        /// Segment against a solid OBB, read in place: <see cref="SegmentInFrame"/> on its frame, lo = −h and hi = h. Copying
        /// the 152-byte <see cref="Box"/> into the call instead took the distance-only query 1.1–1.2 times as long on .NET 10
        /// and 1.5 times on Mono, and Between 1.2–1.3 times on Mono (ab).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 SegmentObb(Vector3D a, Vector3D b, in Obb3 box, out bool inRange)
        {
            var h = box.HalfExtents;
            return SegmentInFrame(a, b, box.Center, box.AxisX, box.AxisY, box.AxisZ, -h, h, false, out inRange);
        }

        /// <summary>
        /// Segment against the solid box origin + x·u + y·v + z·w, (u, v, w) in [lo, hi] (the fields of <see cref="Box"/>),
        /// in the box frame (<see cref="InFrame"/>); the box witness mapped back to world.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 SegmentInFrame(Vector3D a, Vector3D b, Vector3D origin, Vector3D x, Vector3D y, Vector3D z,
            Vector3D lo, Vector3D hi, bool planar, out bool inRange)
        {
            var ra = a - origin;
            inRange = Range.Box(Range.MaxAbs(ra, b - origin, hi - lo));
            var ld = b - a;
            double dist = InFrame(new Vector3D(Vector3D.Dot(ra, x), Vector3D.Dot(ra, y), Vector3D.Dot(ra, z)),
                new Vector3D(Vector3D.Dot(ld, x), Vector3D.Dot(ld, y), Vector3D.Dot(ld, z)), lo, hi, planar, ref inRange,
                out double d2, out double t, out var onBox, out bool touching);
            var onSegment = SegmentPoint(a, b, t);
            return new DistanceResult3(dist, d2, onSegment, touching ? onSegment : origin + (x * onBox.X + y * onBox.Y + z * onBox.Z), t, 0);
        }

        /// <summary>
        /// The Distance of <see cref="SegmentObb"/>, bit for bit, without the witnesses (<see cref="InFrameDistance"/>). The
        /// frame transform is written out here as in <see cref="SegmentInFrame"/>: shared through a helper with out
        /// vectors, Mono took 1.04–1.08 times as long here and 1.25–1.27 in Between (ab, 2 × 7).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double SegmentObbDistance(Vector3D a, Vector3D b, in Obb3 box, out bool inRange)
        {
            Vector3D o = box.Center, x = box.AxisX, y = box.AxisY, z = box.AxisZ, h = box.HalfExtents;
            var ra = a - o;
            inRange = Range.Box(Range.MaxAbs(ra, b - o, h - (-h)));
            var ld = b - a;
            return InFrameDistance(new Vector3D(Vector3D.Dot(ra, x), Vector3D.Dot(ra, y), Vector3D.Dot(ra, z)),
                new Vector3D(Vector3D.Dot(ld, x), Vector3D.Dot(ld, y), Vector3D.Dot(ld, z)), -h, h, false, ref inRange);
        }

        /// <summary>
        /// <see cref="SegmentInFrame"/> for an AABB given by its corners, without the rotations: its frame is the world's
        /// shifted to min, where a dot product with a unit axis, and the map back, are exact, so the answer is the one
        /// on the frame of <see cref="Aabb3.ToBox"/> and Aabb2.ToBox (up to the sign of a zero coordinate). The identity rotations cost the 2D
        /// query a fifth of its time (ab, .NET 10: 47 → 38 ns; 3D 62 → 59).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 SegmentAabb(Vector3D a, Vector3D b, Vector3D min, Vector3D max, bool planar, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            double dist = InFrame(ra, b - a, default, extent, planar, ref inRange, out double d2, out double t, out var onBox, out bool touching);
            var onSegment = SegmentPoint(a, b, t);
            return new DistanceResult3(dist, d2, onSegment, touching ? onSegment : min + onBox, t, 0);
        }

        /// <summary>The Distance of <see cref="SegmentAabb"/>, bit for bit, without the witnesses.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double SegmentAabbDistance(Vector3D a, Vector3D b, Vector3D min, Vector3D max, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            return InFrameDistance(ra, b - a, default, extent, false, ref inRange);
        }

        /// <summary>
        /// <see cref="InFrame"/>'s distance alone: the same verdict, apart minimum and push depth, without locating the
        /// witnesses (the box point, and for meeting shapes the touching point on the pushed segment).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double InFrameDistance(Vector3D la, Vector3D ld, Vector3D lo, Vector3D hi, bool planar, ref bool inRange)
        {
            var c = (lo + hi) * 0.5;
            var h = (hi - lo) * 0.5;
            if (!SegmentBoxOverlapsLocal(la - c, ld, h, planar))
            {
                double d2 = SegmentBoxLocal(la, ld, lo, hi, out _);
                inRange &= Range.In(d2);
                return Math.Sqrt(d2);
            }
            return -Num.Max(SegmentBoxPenetration(la - c, ld, h, planar, out _), 0);
        }

        /// <summary>
        /// Segment la + [0, 1]·ld against the box [lo, hi], all box-local: the signed distance, its square (0 when they
        /// meet), the segment parameter and the box witness (box-local; <paramref name="touching"/>: it is the segment's
        /// point). Apart (by the separating-axis verdict that Overlaps gives): the piecewise-quadratic minimum above.
        /// Meeting: the minimum translation over the separating-axis candidates of the Minkowski sum (box normals and
        /// segment × box edges), each evaluated on its own normalised direction so a noisy near-degenerate axis can only
        /// overestimate; the witness points are the closest points of the just-touching configuration, moved back.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double InFrame(Vector3D la, Vector3D ld, Vector3D lo, Vector3D hi, bool planar, ref bool inRange,
            out double d2, out double t, out Vector3D onBox, out bool touching)
        {
            var c = (lo + hi) * 0.5;
            var h = (hi - lo) * 0.5;
            // The separating-axis verdict decides which side we are on: the squared gap alone would call a segment
            // crossing a zero-thickness box "apart" by rounding.
            if (!SegmentBoxOverlapsLocal(la - c, ld, h, planar))
            {
                d2 = SegmentBoxLocal(la, ld, lo, hi, out t);
                // A subnormal squared gap has lost bits, and a zero one is rare here (found apart) and may have underflowed:
                // the slow path answers both at a scale where they have not (2^k-scaled inputs agree).
                inRange &= Range.In(d2);
                onBox = ClampLocal(la + ld * t, lo, hi);
                touching = false;
                return Math.Sqrt(d2);
            }

            double depth = Num.Max(SegmentBoxPenetration(la - c, ld, h, planar, out var dir), 0);
            // The segment moved by the push just touches the box: its closest pair there, the segment's point moved back.
            var moved = la + dir * depth;
            t = depth > 0 ? TouchingParameter(la - c, ld, h, dir) : double.NaN;
            if (double.IsNaN(t)) SegmentBoxLocalCall(moved, ld, lo, hi, out t);
            d2 = 0;
            onBox = ClampLocal(moved + ld * t, lo, hi);
            touching = !(depth > 0);
            return -depth;
        }

        /// <summary>
        /// The least push (box-local) that clears the segment m + [0, 1]·d (relative to the box centre) from the box of
        /// half-extents h, over the box normals and the segment × box-edge directions (planar: the in-plane ones): its
        /// length (≤ 0 when the segment only touches the box, or misses it by rounding) and its unit direction
        /// <paramref name="dir"/>, kept apart so a touching segment still has a separating direction. A box normal needs
        /// no normalising; on a segment × edge direction the whole segment projects to one value, and the projections
        /// are divided by the direction's length once.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double SegmentBoxPenetration(Vector3D m, Vector3D d, Vector3D h, bool planar, out Vector3D dir)
        {
            double best = double.PositiveInfinity;
            dir = default;
            TryFaceAxis(m.X, d.X, h.X, Vector3D.UnitX, ref best, ref dir);
            TryFaceAxis(m.Y, d.Y, h.Y, Vector3D.UnitY, ref best, ref dir);
            TryCrossAxis(new Vector3D(d.Y, -d.X, 0), m.X * d.Y - m.Y * d.X, h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X), ref best, ref dir);
            if (!planar)
            {
                TryFaceAxis(m.Z, d.Z, h.Z, Vector3D.UnitZ, ref best, ref dir);
                TryCrossAxis(new Vector3D(0, d.Z, -d.Y), m.Y * d.Z - m.Z * d.Y, h.Y * Math.Abs(d.Z) + h.Z * Math.Abs(d.Y), ref best, ref dir);
                TryCrossAxis(new Vector3D(-d.Z, 0, d.X), m.Z * d.X - m.X * d.Z, h.X * Math.Abs(d.Z) + h.Z * Math.Abs(d.X), ref best, ref dir);
            }
            return best;
        }

        /// <summary>
        /// Where the segment m + [0, 1]·d (relative to the box centre), pushed along <paramref name="dir"/> (the
        /// candidate <see cref="SegmentBoxPenetration"/> chose) until it just touches the box of half-extents h, touches
        /// it, read off the pushed feature instead of minimised on the pushed segment: a box normal's face is touched by the segment's end deepest along it, a segment × edge
        /// direction's edge (the box's support along dir) by the segment's point that crosses it, found in the plane
        /// across the edge; the push is perpendicular to that plane's part of the segment, so the unpushed segment
        /// gives the same point. NaN when the feature does not name one point of itself: a segment parallel to the face
        /// or edge, or the point beyond the face or edge (which candidate wins a near-tie is decided by rounding, and
        /// the pushed segment may then only nearly touch the one chosen); the caller minimises then. Inlined: as a call,
        /// the meeting path spilled the caller's live values around it (ab, 2 × 7, inlined against a call: 3D segment–OBB
        /// Between 0.91–0.98, segment–AABB 0.92–1.03, capsule–box 0.94–0.97 on .NET 10 with and without PGO; 0.99–1.04 on Mono).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double TouchingParameter(Vector3D m, Vector3D d, Vector3D h, Vector3D dir)
        {
            // A face's direction is a unit axis; a segment × edge direction has a zero component along the edge only
            // (two zeros make it a face's: the segment is then parallel to that face, which FaceTouch declines).
            if (dir.Y == 0 && dir.Z == 0) return FaceTouch(m.X, d.X, dir.X, m.Y, d.Y, h.Y, m.Z, d.Z, h.Z);
            if (dir.X == 0 && dir.Z == 0) return FaceTouch(m.Y, d.Y, dir.Y, m.X, d.X, h.X, m.Z, d.Z, h.Z);
            if (dir.X == 0 && dir.Y == 0) return FaceTouch(m.Z, d.Z, dir.Z, m.X, d.X, h.X, m.Y, d.Y, h.Y);
            if (dir.Z == 0) return EdgeTouch(m.X, d.X, dir.X, h.X, m.Y, d.Y, dir.Y, h.Y, m.Z, d.Z, h.Z);
            if (dir.X == 0) return EdgeTouch(m.Y, d.Y, dir.Y, h.Y, m.Z, d.Z, dir.Z, h.Z, m.X, d.X, h.X);
            if (dir.Y == 0) return EdgeTouch(m.Z, d.Z, dir.Z, h.Z, m.X, d.X, dir.X, h.X, m.Y, d.Y, h.Y);
            return double.NaN;
        }

        /// <summary>
        /// The face of axis i the push along n (its sign) leaves the segment on: touched at the end deepest along n (t 0 or
        /// 1), if that end lies within the face's extents on the other axes j, k (the push does not move it along them).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double FaceTouch(double mi, double di, double n, double mj, double dj, double hj, double mk, double dk, double hk)
        {
            if (di == 0) return double.NaN;
            double t = (di > 0) == (n > 0) ? 0 : 1;
            return Math.Abs(mj + t * dj) <= hj && Math.Abs(mk + t * dk) <= hk ? t : double.NaN;
        }

        /// <summary>
        /// The box edge along axis k at the corner (±hi, ±hj) the push (ni, nj) points to: the segment's parameter nearest
        /// that corner in the (i, j) plane (its projection's direction scaled by a power of two near 1, so its square
        /// neither underflows nor overflows; unscaled exactly), if within the segment and the edge's extent along k.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double EdgeTouch(double mi, double di, double ni, double hi, double mj, double dj, double nj, double hj, double mk, double dk, double hk)
        {
            double kd = Num.InversePowerOfTwo(Num.Max(Math.Abs(di), Math.Abs(dj)));
            double si = di * kd, sj = dj * kd;
            double t = ((ni > 0 ? hi : -hi) - mi) * si + ((nj > 0 ? hj : -hj) - mj) * sj;
            t = t / (si * si + sj * sj) * kd;
            return t >= 0 && t <= 1 && Math.Abs(mk + t * dk) <= hk ? t : double.NaN;
        }

        /// <summary>
        /// A box normal n: the segment covers [m, m + d] along it, the box [−h, h]. Of its two pushes the shorter
        /// competes (on a tie −n, as though −n were tried first): one comparison with the best so far instead of two.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryFaceAxis(double m, double d, double h, Vector3D n, ref double best, ref Vector3D dir)
        {
            double e = m + d;
            double down = Num.Max(m, e) + h; // moving the segment by −n·down clears the box
            double up = h - Num.Min(m, e);   // moving it by +n·up clears the box
            bool upward = up < down;
            double push = upward ? up : down;
            if (push < best) { best = push; dir = upward ? n : -n; }
        }

        /// <summary>
        /// A segment × box-edge direction (unnormalised): the segment projects to p along it, the box to [−r, r]. The
        /// shorter of the two pushes, (r − |p|)/len, toward the side p lies on (−axis for p ≤ 0), competes: one division
        /// and one comparison instead of two each (r − |p| is the sum p + r or difference r − p it replaces, bit for bit).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryCrossAxis(Vector3D axis, double p, double r, ref double best, ref Vector3D dir)
        {
            double len2 = axis.LengthSquared;
            if (!(len2 > 0) || double.IsInfinity(len2)) return;
            double len = Math.Sqrt(len2);
            double push = (r - Math.Abs(p)) / len;
            if (push < best) { best = push; dir = axis * ((p > 0 ? 1 : -1) / len); }
        }

        /// <summary><see cref="SegmentBoxOverlaps(Vector3D, Vector3D, in Box)"/>, with whether the magnitudes allow the fast path.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentBoxOverlaps(Vector3D a, Vector3D b, in Box box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Range.MaxAbs(ra, b - box.Origin, box.Hi - box.Lo));
            return SegmentBoxOverlapsLocal(box.ToLocal(ra) - box.LocalCenter, box.ToLocal(b - a), box.Half, box.Planar);
        }

        /// <summary>
        /// <see cref="SegmentBoxOverlaps(Vector3D, Vector3D, in Box, out bool)"/> for an AABB given by its corners: its
        /// frame is the world's shifted to min, so the test sees the same values as through <see cref="Aabb3.ToBox"/>
        /// (a dot product with a unit axis is exact) without forming the 150-byte box.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentAabbOverlaps(Vector3D a, Vector3D b, Vector3D min, Vector3D max, bool planar, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            var half = extent * 0.5;
            return SegmentBoxOverlapsLocal(ra - half, b - a, half, planar);
        }

        /// <summary>Segment–box overlap by the separating-axis test in the box frame, no square roots, early outs.</summary>
        public static bool SegmentBoxOverlaps(Vector3D a, Vector3D b, in Box box) =>
            SegmentBoxOverlapsLocal(box.ToLocal(a - box.Origin) - box.LocalCenter, box.ToLocal(b - a), box.Half, box.Planar);

        /// <summary>
        /// The separating-axis test of the segment m + [0, 1]·d (box-local, relative to the centre) against the box of
        /// half-extents h (Ericson, RTCD §5.3.3): the box normals, then the segment × box-edge directions, on which the
        /// whole segment projects to one value.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool SegmentBoxOverlapsLocal(Vector3D m, Vector3D d, Vector3D h, bool planar)
        {
            if (SlabSeparates(m.X, d.X, h.X) || SlabSeparates(m.Y, d.Y, h.Y)) return false;
            if (!planar && SlabSeparates(m.Z, d.Z, h.Z)) return false;
            if (Math.Abs(m.X * d.Y - m.Y * d.X) > h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X)) return false;
            if (planar) return true;
            return !(Math.Abs(m.Y * d.Z - m.Z * d.Y) > h.Y * Math.Abs(d.Z) + h.Z * Math.Abs(d.Y))
                && !(Math.Abs(m.Z * d.X - m.X * d.Z) > h.X * Math.Abs(d.Z) + h.Z * Math.Abs(d.X));
        }

        /// <summary>Whether the interval [m, m + d] misses [−h, h].</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool SlabSeparates(double m, double d, double h)
        {
            double e = m + d;
            return Num.Min(m, e) > h || Num.Max(m, e) < -h;
        }
    }
}
