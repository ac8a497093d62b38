// Copied from src/ProximityLib/Double/Kernels/BoxKernels.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// Box against box. Everything is first made relative to A's origin, so a common translation adds no error.
        /// Separating-axis candidates (face normals of both, and in 3D the nine edge×edge directions; Gottschalk,
        /// Lin &amp; Manocha 1996) contain the exact minimum-translation direction of two polytopes. Both boxes are
        /// projected on each candidate honestly (in A's frame, B through R and its 2×2 minors, no orthonormality
        /// shortcuts), so a noisy, near-degenerate cross axis can only overestimate the overlap and never wins wrongly;
        /// the winner is projected once more in world axes (<see cref="OverlapDepth"/>). Apart: the best of the
        /// vertex–box and edge–box closed forms that can hold the closest pair (<see cref="BoxesApart"/>). Overlapping:
        /// A moved by the minimum translation just touches B, and a pair of the touching configuration found the same
        /// way, moved back, realises the penetration.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 BoxBox(in Box a, in Box b, out bool inRange)
        {
            // Relative to A's origin: B's origin there is the same difference the overlap test forms, so the verdict is
            // the overlap query's own (the two agree).
            Front(a, b, out double size, out var d, out var t);
            double k = Num.InversePowerOfTwo(size);
            inRange = Range.Box(size);
            var shift = a.Origin;
            Vector3D onA, onB;
            // Apart: the depth search has nothing to add.
            if (!OverlapDepth(a, b, t, out double depth, out var push))
            {
                double gap = BoxesApart(a, default, b, d, 0, k, out onA, out onB);
                // A subnormal squared gap has lost bits, and a zero one is rare here (the boxes are apart) and may have
                // underflowed: the slow path answers both at a scale where they have not (2^k-scaled inputs agree).
                inRange &= Range.In(gap);
                return new DistanceResult3(Math.Sqrt(gap), gap, onA + shift, onB + shift, 0, 0);
            }
            // A moved by the push just touches B: its squared gap there is rounding, and any pair within 2^-50·S of
            // touching realises the depth as well as the nearest one (apart by rounding, the gap must be the least).
            // BoxesApart compares at the scale k, where S is about 1.
            if (depth < 0) push = default;
            double touch = size * k * (1.0 / (1L << 50)), enough = depth < 0 ? 0 : touch * touch;
            double g = BoxesApart(a, push, b, d, enough, k, out onA, out onB);
            onA = onA - push + shift;
            onB += shift;
            if (depth < 0)
            {
                inRange &= Range.In(g); // a zero gap of boxes found apart may have underflowed: the slow path
                return new DistanceResult3(Math.Sqrt(g), g, onA, onB, 0, 0);
            }
            return new DistanceResult3(-depth, 0, onA, onB, 0, 0);
        }

        /// <summary>
        /// <see cref="BoxBox"/> on two OBBs in canonical order (the result swapped back): one call on two Box forms built
        /// here, where the pair's one call per order had the caller's frame hold four, zeroed on every query without
        /// dynamic PGO (ab, 3 × 7: 0.93–0.99 of the time, Mono 0.96–1.0). The distance alone measured 1.03–1.09 so
        /// wrapped, and keeps the call per order.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 ObbObb(in Obb3 a, in Obb3 b, out bool inRange)
        {
            if (!Order.Swap(a, b)) return BoxBox(a.ToBox(), b.ToBox(), out inRange);
            return BoxBox(b.ToBox(), a.ToBox(), out inRange).Swapped();
        }

        /// <summary>
        /// The distance of <see cref="BoxBox"/> alone: the same steps, without the witness search of overlapping boxes
        /// unless the depth search found a separation (then its gap is the answer, as there, from the same search).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double BoxBoxDistance(in Box a, in Box b, out bool inRange)
        {
            Front(a, b, out double size, out var d, out var t);
            inRange = Range.Box(size);
            if (OverlapDepth(a, b, t, out double depth, out _) && depth >= 0)
                return -depth;
            double gap = BoxesApart(a, default, b, d, 0, Num.InversePowerOfTwo(size), out _, out _);
            inRange &= Range.In(gap); // a zero gap of boxes found apart may have underflowed: the slow path
            return Math.Sqrt(gap);
        }

        /// <summary>
        /// The separating-axis test (the verdict of <see cref="BoxBoxOverlaps(in Box, in Box)"/>) and, for boxes it finds
        /// overlapping, the least translation of A that clears B (returned as <paramref name="push"/>, its length as
        /// <paramref name="depth"/>) over the face normals and, in 3D, the edge × edge directions; a negative depth when
        /// the winning axis separates after all (the push is then unused). t: B's centre from A's, in world axes. The axis
        /// is chosen in A's frame, where each one's overlap is a few of the test's own values (R = a_i · b_j, T, the
        /// minors), where the world-axis form projected both boxes afresh on each of the 15 axes (sharing them took 3D
        /// OBB–OBB Distance 0.80–0.83 of its time, ab). The chosen axis is
        /// then tried alone in world axes (<see cref="TryAxis"/>, on <see cref="WorldAxis"/>), so the depth and push are
        /// those of honest world projections on it; two axes whose overlaps differ by rounding are equally good minima.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapDepth(in Box a, in Box b, Vector3D t, out double depth, out Vector3D push)
        {
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported && !(a.Planar || b.Planar)) return OverlapDepthVector(a, b, t, out depth, out push);
#endif
            if (!OverlapsCenteredScalar(t, a, b))
            {
                depth = 0;
                push = default;
                return false;
            }
            depth = PenetrationScalar(a, b, t, out push);
            return true;
        }

        /// <summary>
        /// The depth search of <see cref="OverlapDepth"/> in plain doubles, for boxes the test found overlapping: the only
        /// form on netstandard2.1 (Unity) and without AVX2. Each axis's overlap is formed with the operations of a lane of
        /// the AVX2 form (OverlapDepthVector, BoxKernels.Vector.cs), in its order, so both forms choose the same axis and return the same bits.
        /// Planar boxes (the 2D kernels' lifted reference) take the four face axes in world axes, as BoxBox2 does.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static double PenetrationScalar(in Box a, in Box b, in Vector3D t, out Vector3D push)
        {
            Vector3D ax = a.X, ay = a.Y, az = a.Z, bx = b.X, by = b.Y, bz = b.Z, ha = a.Half, hb = b.Half;
            double best = double.PositiveInfinity, scale = 0;
            Vector3D axis = default;
            if (a.Planar || b.Planar)
            {
                // The first axis holding the least push-out, tried alone (TryAxis's steps, the smaller of down and up).
                int planarWin = -1;
                double least = double.PositiveInfinity;
                PlanarCandidate(ax, 0, ax, ay, bx, by, ha, hb, t, ref least, ref planarWin);
                PlanarCandidate(ay, 1, ax, ay, bx, by, ha, hb, t, ref least, ref planarWin);
                PlanarCandidate(bx, 2, ax, ay, bx, by, ha, hb, t, ref least, ref planarWin);
                PlanarCandidate(by, 3, ax, ay, bx, by, ha, hb, t, ref least, ref planarWin);
                if (planarWin >= 0)
                    TryAxis(WorldAxis(planarWin, ax, ay, az, bx, by, bz, 0, 0, 0), ax, ay, az, bx, by, bz, ha, hb, t, ref best, ref axis, ref scale);
                push = axis * scale;
                return best;
            }
            // A's frame: r_ij = a_i · b_j and T's components, as FrameOfA's lanes.
            double tx = Vector3D.Dot(ax, t), ty = Vector3D.Dot(ay, t), tz = Vector3D.Dot(az, t);
            double r00 = Vector3D.Dot(ax, bx), r01 = Vector3D.Dot(ax, by), r02 = Vector3D.Dot(ax, bz);
            double r10 = Vector3D.Dot(ay, bx), r11 = Vector3D.Dot(ay, by), r12 = Vector3D.Dot(ay, bz);
            double r20 = Vector3D.Dot(az, bx), r21 = Vector3D.Dot(az, by), r22 = Vector3D.Dot(az, bz);
            int win = -1;
            double m = double.PositiveInfinity;
            // In the order of the bits: a_x, a_y, b_x, b_y, a_z, b_z, then a_i × b_j with i major.
            Candidate(ha.X + Math.Abs(r00) * hb.X + Math.Abs(r01) * hb.Y + Math.Abs(r02) * hb.Z - Math.Abs(tx), 0, ref m, ref win);
            Candidate(ha.Y + Math.Abs(r10) * hb.X + Math.Abs(r11) * hb.Y + Math.Abs(r12) * hb.Z - Math.Abs(ty), 1, ref m, ref win);
            Candidate(Math.Abs(r00) * ha.X + Math.Abs(r10) * ha.Y + Math.Abs(r20) * ha.Z + hb.X - Math.Abs(r00 * tx + r10 * ty + r20 * tz), 2, ref m, ref win);
            Candidate(Math.Abs(r01) * ha.X + Math.Abs(r11) * ha.Y + Math.Abs(r21) * ha.Z + hb.Y - Math.Abs(r01 * tx + r11 * ty + r21 * tz), 3, ref m, ref win);
            Candidate(ha.Z + Math.Abs(r20) * hb.X + Math.Abs(r21) * hb.Y + Math.Abs(r22) * hb.Z - Math.Abs(tz), 4, ref m, ref win);
            Candidate(Math.Abs(r02) * ha.X + Math.Abs(r12) * ha.Y + Math.Abs(r22) * ha.Z + hb.Z - Math.Abs(r02 * tx + r12 * ty + r22 * tz), 5, ref m, ref win);
            // e_x × b_j: rows p = y, q = z.
            Candidate(EdgeOverlap(ty, tz, ha.Y, ha.Z, r10, r20, r11, r21, r12, r22, hb.Y, hb.Z), 6, ref m, ref win);
            Candidate(EdgeOverlap(ty, tz, ha.Y, ha.Z, r11, r21, r12, r22, r10, r20, hb.Z, hb.X), 7, ref m, ref win);
            Candidate(EdgeOverlap(ty, tz, ha.Y, ha.Z, r12, r22, r10, r20, r11, r21, hb.X, hb.Y), 8, ref m, ref win);
            // e_y × b_j: p = z, q = x.
            Candidate(EdgeOverlap(tz, tx, ha.Z, ha.X, r20, r00, r21, r01, r22, r02, hb.Y, hb.Z), 9, ref m, ref win);
            Candidate(EdgeOverlap(tz, tx, ha.Z, ha.X, r21, r01, r22, r02, r20, r00, hb.Z, hb.X), 10, ref m, ref win);
            Candidate(EdgeOverlap(tz, tx, ha.Z, ha.X, r22, r02, r20, r00, r21, r01, hb.X, hb.Y), 11, ref m, ref win);
            // e_z × b_j: p = x, q = y.
            Candidate(EdgeOverlap(tx, ty, ha.X, ha.Y, r00, r10, r01, r11, r02, r12, hb.Y, hb.Z), 12, ref m, ref win);
            Candidate(EdgeOverlap(tx, ty, ha.X, ha.Y, r01, r11, r02, r12, r00, r10, hb.Z, hb.X), 13, ref m, ref win);
            Candidate(EdgeOverlap(tx, ty, ha.X, ha.Y, r02, r12, r00, r10, r01, r11, hb.X, hb.Y), 14, ref m, ref win);
            if (win >= 0)
            {
                int j = win < 6 ? 0 : (win - 6) % 3; // b_j's column of R, used for an edge axis
                var column = j == 0 ? new Vector3D(r00, r10, r20) : j == 1 ? new Vector3D(r01, r11, r21) : new Vector3D(r02, r12, r22);
                TryAxis(WorldAxis(win, ax, ay, az, bx, by, bz, column.X, column.Y, column.Z), ax, ay, az, bx, by, bz, ha, hb, t, ref best, ref axis, ref scale);
            }
            push = axis * scale;
            return best;
        }

        /// <summary>Keeps the first candidate holding the least overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Candidate(double overlap, int bit, ref double least, ref int win)
        {
            if (overlap < least) { least = overlap; win = bit; }
        }

        /// <summary>
        /// The overlap over |L| on the axis L = e_i × b_j, for the A axis i whose two other axes are p and q (cyclic): in
        /// A's frame L has r_qj, r_pj in them (pj, qj); (pn, qn) and (pv, qv) are r_p, r_q in columns j + 1 and j − 1, hn
        /// and hv B's half-extents there. A lane of the AVX2 form's EdgeRadii − EdgeSeparation, over |L| in EdgeOverlap,
        /// step for step; +∞ when L is zero (parallel edges).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double EdgeOverlap(double tp, double tq, double hp, double hq, double pj, double qj, double pn, double qn,
            double pv, double qv, double hn, double hv)
        {
            double next = Math.Abs(pn * qj - qn * pj), prev = Math.Abs(pj * qv - qj * pv);
            double overlap = Math.Abs(qj) * hp + Math.Abs(pj) * hq + hn * next + hv * prev - Math.Abs(pj * tq - qj * tp);
            double len2 = pj * pj + qj * qj;
            return len2 > 0 ? overlap / Math.Sqrt(len2) : double.PositiveInfinity;
        }

        /// <summary>A planar box pair's face axis v (bit 0–3) in world axes: TryAxis's smaller push-out, ra + rb − |sep| over |v|.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void PlanarCandidate(Vector3D v, int bit, Vector3D ax, Vector3D ay, Vector3D bx, Vector3D by, Vector3D ha, Vector3D hb, Vector3D t,
            ref double least, ref int win)
        {
            double len2 = v.LengthSquared;
            if (!(len2 > 0)) return;
            double ra = ha.X * Math.Abs(Vector3D.Dot(ax, v)) + ha.Y * Math.Abs(Vector3D.Dot(ay, v));
            double rb = hb.X * Math.Abs(Vector3D.Dot(bx, v)) + hb.Y * Math.Abs(Vector3D.Dot(by, v));
            Candidate((ra + rb - Math.Abs(Vector3D.Dot(t, v))) / Math.Sqrt(len2), bit, ref least, ref win);
        }

        /// <summary>
        /// Axis <paramref name="bit"/> of the depth search in world axes: a_x, a_y, b_x, b_y, a_z, b_z, then a_i × b_j as its
        /// A-frame form L mapped back (L's two components along A's other axes p, q are −r_qj and r_pj, (rx, ry, rz) being
        /// b_j in A's frame), so the world form projects the boxes on the direction whose overlap won. The world cross
        /// product would be another direction where the edges are nearly parallel (there L is known only to within u/sin θ
        /// either way), and its overlap, though honest, could be far larger than the one that won.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D WorldAxis(int bit, Vector3D ax, Vector3D ay, Vector3D az, Vector3D bx, Vector3D by, Vector3D bz, double rx, double ry, double rz)
        {
            if (bit < 6) return bit < 4 ? (bit == 0 ? ax : bit == 1 ? ay : bit == 2 ? bx : by) : bit == 4 ? az : bz;
            int i = (bit - 6) / 3;
            return i == 0 ? ay * -rz + az * ry : i == 1 ? az * -rx + ax * rz : ax * -ry + ay * rx;
        }

        /// <summary>
        /// Both boxes projected on axis v with their actual axes (half-widths ra, rb; B's centre at sep from A's), over
        /// |v|: moving A by −v·down/|v|² or +v·up/|v|² clears B. A negative overlap proves separation and is kept too.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryAxis(Vector3D v, Vector3D ax, Vector3D ay, Vector3D az, Vector3D bx, Vector3D by, Vector3D bz,
            Vector3D ha, Vector3D hb, Vector3D t, ref double best, ref Vector3D axis, ref double scale)
        {
            double len2 = v.LengthSquared;
            if (!(len2 > 0)) return;
            double len = Math.Sqrt(len2);
            double ra = ha.X * Math.Abs(Vector3D.Dot(ax, v)) + ha.Y * Math.Abs(Vector3D.Dot(ay, v)) + ha.Z * Math.Abs(Vector3D.Dot(az, v));
            double rb = hb.X * Math.Abs(Vector3D.Dot(bx, v)) + hb.Y * Math.Abs(Vector3D.Dot(by, v)) + hb.Z * Math.Abs(Vector3D.Dot(bz, v));
            double sep = Vector3D.Dot(t, v);
            double down = (ra + rb - sep) / len, up = (ra + rb + sep) / len;
            if (down < best) { best = down; axis = v; scale = -down / len; }
            if (up < best) { best = up; axis = v; scale = up / len; }
        }

        /// <summary>
        /// Squared distance between two boxes known to be apart or touching (placed at <paramref name="originA"/> and
        /// <paramref name="originB"/>), and a pair of points realising it. The closest pair of two disjoint convex polytopes
        /// can always be taken with a point on an edge of A or a vertex of B: where A's point lies inside a face, the
        /// contact face of B beyond it lies inside that face too (else it would cross the face's boundary), and it has a
        /// vertex. So the minimum over A's edges against box B and B's vertices against box A is exact; in 2D a vertex of
        /// either suffices. Each vertex is one clamp in the other box's frame. The distance along an edge is convex, so an
        /// edge beats its own ends only if it descends from both, which the ends' clamp residuals tell: only such edges
        /// are minimised (the closed form of <see cref="SegmentBoxLocal"/>), and only while a lower bound on their
        /// distance (their squared gaps along B's axes, summed: no point of the edge is nearer on any axis) does not
        /// exceed the best pair (with a margin, so rounding never hides a win). The search also stops once the best
        /// squared gap is at most <paramref name="enough"/>. The gaps are compared scaled by k, the power of two that brings
        /// the configuration's size near 1 (<paramref name="enough"/> is at that scale; the gap returned is not): at the
        /// small end of the fast range the squares of sub-rounding gaps between touching boxes underflow to equal zeros,
        /// and the first of them is not the pair the same boxes scaled up pick (fuzz seed 2041), as in BoxesApart2.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double BoxesApart(in Box a, Vector3D originA, in Box b, Vector3D originB, double enough, double k, out Vector3D onA, out Vector3D onB)
        {
            bool planar = a.Planar || b.Planar;
            // In plain doubles, each step as Vector3D's operations would form it, in their order (the same bits): Mono
            // keeps every Vector3D temporary in memory, a round of stores and loads per operation.
            Vector3D aX = a.X, aY = a.Y, aZ = a.Z, bX = b.X, bY = b.Y, bZ = b.Z;
            // Rows: A's axes in B's frame, ax = b.ToLocal(a.X) = (a.X·b.X, a.X·b.Y, a.X·b.Z) (Dot: x·x' + y·y' + z·z'), ay,
            // az; the columns are B's axes in A's frame, bx = (ax.X, ay.X, az.X), by, bz (the same products).
            double axX = aX.X * bX.X + aX.Y * bX.Y + aX.Z * bX.Z, axY = aX.X * bY.X + aX.Y * bY.Y + aX.Z * bY.Z, axZ = aX.X * bZ.X + aX.Y * bZ.Y + aX.Z * bZ.Z;
            double ayX = aY.X * bX.X + aY.Y * bX.Y + aY.Z * bX.Z, ayY = aY.X * bY.X + aY.Y * bY.Y + aY.Z * bY.Z, ayZ = aY.X * bZ.X + aY.Y * bZ.Y + aY.Z * bZ.Z;
            double azX = aZ.X * bX.X + aZ.Y * bX.Y + aZ.Z * bX.Z, azY = aZ.X * bY.X + aZ.Y * bY.Y + aZ.Z * bY.Z, azZ = aZ.X * bZ.X + aZ.Y * bZ.Y + aZ.Z * bZ.Z;
            double dX = originB.X - originA.X, dY = originB.Y - originA.Y, dZ = originB.Z - originA.Z, nX = -dX, nY = -dY, nZ = -dZ;
            Vector3D loA = a.Lo, hiA = a.Hi, loB = b.Lo, hiB = b.Hi;
            double eaX = hiA.X - loA.X, eaY = hiA.Y - loA.Y, eaZ = hiA.Z - loA.Z, ebX = hiB.X - loB.X, ebY = hiB.Y - loB.Y, ebZ = hiB.Z - loB.Z;
            // A's corners in B's frame and B's in A's (bit i of the index picks Hi on axis i), and the edge vectors:
            // dx = ax·ea.X, dy, dz; pa = b.ToLocal(−d) + ax·loA.X + ay·loA.Y + az·loA.Z; ex = bx·eb.X, ey, ez;
            // pb = a.ToLocal(d) + bx·loB.X + by·loB.Y + bz·loB.Z.
            var dx = new Vector3D(axX * eaX, axY * eaX, axZ * eaX);
            var dy = new Vector3D(ayX * eaY, ayY * eaY, ayZ * eaY);
            var dz = new Vector3D(azX * eaZ, azY * eaZ, azZ * eaZ);
            var pa = new Vector3D(
                (((nX * bX.X + nY * bX.Y + nZ * bX.Z) + axX * loA.X) + ayX * loA.Y) + azX * loA.Z,
                (((nX * bY.X + nY * bY.Y + nZ * bY.Z) + axY * loA.X) + ayY * loA.Y) + azY * loA.Z,
                (((nX * bZ.X + nY * bZ.Y + nZ * bZ.Z) + axZ * loA.X) + ayZ * loA.Y) + azZ * loA.Z);
            var ex = new Vector3D(axX * ebX, ayX * ebX, azX * ebX);
            var ey = new Vector3D(axY * ebY, ayY * ebY, azY * ebY);
            var ez = new Vector3D(axZ * ebZ, ayZ * ebZ, azZ * ebZ);
            var pb = new Vector3D(
                (((dX * aX.X + dY * aX.Y + dZ * aX.Z) + axX * loB.X) + axY * loB.Y) + axZ * loB.Z,
                (((dX * aY.X + dY * aY.Y + dZ * aY.Z) + ayX * loB.X) + ayY * loB.Y) + ayZ * loB.Z,
                (((dX * aZ.X + dY * aZ.Y + dZ * aZ.Z) + azX * loB.X) + azY * loB.Y) + azZ * loB.Z);
            // The search's copies, scaled by k (exact where nothing underflows: the same comparisons as unscaled there).
            var s = new Corners(pa * k, dx * k, dy * k, dz * k, loB * k, hiB * k, pb * k, ex * k, ey * k, ez * k, loA * k, hiA * k);

            // win: 0–7 A's corner, 8–15 B's corner, 16 + 8i + c the edge from corner c along axis i.
            int win;
            double best, winT = 0;
            uint edges;
            if (enough > 0 && !planar && Touching(originA, a, b, s, enough, out best, out win, out winT))
                edges = 0;
            else
                // Every vertex against the other box, and the edges of A to minimise (bit 8i + c: the edge from corner c
                // along axis i).
                best = Vertices(s, planar, out win, out edges);
            // Those whose lower bound does not exceed the best pair, until the best is good enough.
            for (int bit = 0; edges >> bit != 0 && best > enough; bit++)
            {
                if (((edges >> bit) & 1) == 0) continue;
                int i = bit >> 3, from = bit & 7;
                var dir = i == 0 ? s.Dx : (i == 1 ? s.Dy : s.Dz);
                var p = Corner(s.Pa, s.Dx, s.Dy, s.Dz, from);
                if (SpanGap2(p, Corner(s.Pa, s.Dx, s.Dy, s.Dz, from | (1 << i)), s.LoB, s.HiB) > best * (1 + 1e-9)) continue;
                double g = SegmentBoxLocal(p, dir, s.LoB, s.HiB, out double t);
                if (g < best) { best = g; win = 16 + bit; winT = t; }
            }

            // The winning pair in world coordinates, from its box-local coordinates.
            if (win < 8)
            {
                onA = originA + a.ToWorldOffset(Corner(loA, hiA, win));
                onB = originB + b.ToWorldOffset(Clamp(Corner(pa, dx, dy, dz, win), loB, hiB));
            }
            else if (win < 16)
            {
                onB = originB + b.ToWorldOffset(Corner(loB, hiB, win - 8));
                onA = originA + a.ToWorldOffset(Clamp(Corner(pb, ex, ey, ez, win - 8), loA, hiA));
            }
            else
            {
                int i = (win - 16) >> 3, from = (win - 16) & 7;
                var dir = i == 0 ? dx : (i == 1 ? dy : dz);
                var local = Corner(loA, hiA, from);
                double lo = Vec.Get(loA, i), hi = Vec.Get(hiA, i), x = winT <= 0.5 ? lo + (hi - lo) * winT : hi - (hi - lo) * (1 - winT);
                local = new Vector3D(i == 0 ? x : local.X, i == 1 ? x : local.Y, i == 2 ? x : local.Z);
                onA = originA + a.ToWorldOffset(local);
                onB = originB + b.ToWorldOffset(Clamp(Corner(pa, dx, dy, dz, from) + dir * winT, loB, hiB));
            }
            double ik = 1 / k;
            return best * ik * ik;
        }

        /// <summary>
        /// A moved by <paramref name="push"/> (the depth search's) just touches B: the contact is at A's support feature
        /// in direction −push and B's in direction +push. Tries A's support corner against box B and B's against box A
        /// (the first of equal ones, A's first, as <see cref="Vertices"/> orders them), then A's edge through its corner
        /// along the axis most nearly across the push (an edge–edge contact) at its crossing with B's edge likewise, or
        /// minimised against B where that crossing does not touch; true with that pair when its squared gap is at most
        /// <paramref name="enough"/> (the touching configuration's rounding), false to search every feature.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Touching(Vector3D push, in Box a, in Box b, in Corners s, double enough, out double best, out int win, out double winT)
        {
            double px = Vector3D.Dot(push, a.X), py = Vector3D.Dot(push, a.Y), pz = Vector3D.Dot(push, a.Z);
            double qx = Vector3D.Dot(push, b.X), qy = Vector3D.Dot(push, b.Y), qz = Vector3D.Dot(push, b.Z);
            int ca = (px < 0 ? 1 : 0) | (py < 0 ? 2 : 0) | (pz < 0 ? 4 : 0);
            int cb = (qx > 0 ? 1 : 0) | (qy > 0 ? 2 : 0) | (qz > 0 ? 4 : 0);
            best = Residual(Corner(s.Pa, s.Dx, s.Dy, s.Dz, ca), s.LoB, s.HiB).LengthSquared;
            win = ca;
            winT = 0;
            double g = Residual(Corner(s.Pb, s.Ex, s.Ey, s.Ez, cb), s.LoA, s.HiA).LengthSquared;
            if (g < best) { best = g; win = 8 + cb; }
            if (best <= enough) return true;
            double ax = Math.Abs(px), ay = Math.Abs(py), az = Math.Abs(pz);
            int i = ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2);
            int from = ca & ~(1 << i);
            var p = Corner(s.Pa, s.Dx, s.Dy, s.Dz, from);
            var dir = i == 0 ? s.Dx : (i == 1 ? s.Dy : s.Dz);
            // B's edge through its corner along the axis most nearly across the push, j: A's edge crosses it where the
            // two meet in the plane across b_j (B's frame: the two coordinates other than j). Taken when that point is on
            // A's edge and touches B; else the edge is minimised against B.
            double bxa = Math.Abs(qx), bya = Math.Abs(qy), bza = Math.Abs(qz);
            int j = bxa <= bya && bxa <= bza ? 0 : (bya <= bza ? 1 : 2), k1 = j == 0 ? 1 : 0, k2 = j == 2 ? 1 : 2;
            var corner = Corner(s.LoB, s.HiB, cb);
            double d1 = Vec.Get(dir, k1), d2 = Vec.Get(dir, k2);
            double t = ((Vec.Get(corner, k1) - Vec.Get(p, k1)) * d1 + (Vec.Get(corner, k2) - Vec.Get(p, k2)) * d2) / (d1 * d1 + d2 * d2);
            if (!(t >= 0 && t <= 1 && (g = Residual(p + dir * t, s.LoB, s.HiB).LengthSquared) <= enough))
            {
                g = SegmentBoxLocal(p, dir, s.LoB, s.HiB, out t);
                if (!(g <= enough)) return false;
            }
            best = g;
            win = 16 + 8 * i + from;
            winT = t;
            return true;
        }

        /// <summary>
        /// The witness search's view of two boxes, each in the other's frame: A's corner 0 (Pa) and edge vectors (Dx, Dy,
        /// Dz) in B's frame with B's box [LoB, HiB], and B's (Pb; Ex, Ey, Ez) in A's frame with A's box [LoA, HiA]. One
        /// struct passed by reference instead of twelve vectors by value (36 doubles copied per call; measured within noise).
        /// </summary>
        internal readonly struct Corners
        {
            public readonly Vector3D Pa, Dx, Dy, Dz, LoB, HiB, Pb, Ex, Ey, Ez, LoA, HiA;

            public Corners(Vector3D pa, Vector3D dx, Vector3D dy, Vector3D dz, Vector3D loB, Vector3D hiB,
                Vector3D pb, Vector3D ex, Vector3D ey, Vector3D ez, Vector3D loA, Vector3D hiA)
            {
                Pa = pa; Dx = dx; Dy = dy; Dz = dz; LoB = loB; HiB = hiB; Pb = pb; Ex = ex; Ey = ey; Ez = ez; LoA = loA; HiA = hiA;
            }
        }

        /// <summary>
        /// The least squared gap of A's corners (Pa + sums of Dx, Dy, Dz; B's frame) to B's box [LoB, HiB] and of B's
        /// corners to A's box, and which corner (0–7 A's, 8–15 B's, the first of equal ones); 4 of each when planar (the
        /// z bit picks the same corner). In 3D also A's edges that descend from both ends (bit 8i + c: the edge from
        /// corner c along axis i, whose slope dir·r is &lt; 0 at c and &gt; 0 at its other end, r the clamp residual): the
        /// distance along an edge is convex, so only these can beat their ends.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Vertices(in Corners s, bool planar, out int win, out uint edges)
        {
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported) return VerticesVector(s, planar, out win, out edges);
#endif
            return VerticesScalar(s, planar, out win, out edges);
        }

        /// <summary>
        /// The scalar form of <see cref="Vertices"/>: the only one on netstandard2.1 (Unity) and without AVX2. Per
        /// coordinate in plain doubles: Mono keeps every Vector3D temporary in memory, and the same steps written on
        /// Vector3D (Corner, Residual) took more than twice as long there.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static unsafe double VerticesScalar(in Corners q, bool planar, out int win, out uint edges)
        {
            Vector3D pa = q.Pa, dx = q.Dx, dy = q.Dy, dz = q.Dz, loB = q.LoB, hiB = q.HiB, pb = q.Pb, ex = q.Ex, ey = q.Ey, ez = q.Ez, loA = q.LoA, hiA = q.HiA;
            // Clamp residuals, coordinate-major: r[8k + c] is coordinate k of A's corner c (B's frame), s[8k + c] of B's.
            double* r = stackalloc double[24], s = stackalloc double[24];
            CornerResiduals(pa.X, dx.X, dy.X, dz.X, loB.X, hiB.X, r);
            CornerResiduals(pa.Y, dx.Y, dy.Y, dz.Y, loB.Y, hiB.Y, r + 8);
            CornerResiduals(pa.Z, dx.Z, dy.Z, dz.Z, loB.Z, hiB.Z, r + 16);
            CornerResiduals(pb.X, ex.X, ey.X, ez.X, loA.X, hiA.X, s);
            CornerResiduals(pb.Y, ex.Y, ey.Y, ez.Y, loA.Y, hiA.Y, s + 8);
            CornerResiduals(pb.Z, ex.Z, ey.Z, ez.Z, loA.Z, hiA.Z, s + 16);
            int n = planar ? 4 : 8;
            double best = double.PositiveInfinity;
            win = 0;
            for (int c = 0; c < n; c++)
            {
                double g = r[c] * r[c] + r[8 + c] * r[8 + c] + r[16 + c] * r[16 + c];
                if (g < best) { best = g; win = c; }
            }
            for (int c = 0; c < n; c++)
            {
                double g = s[c] * s[c] + s[8 + c] * s[8 + c] + s[16 + c] * s[16 + c];
                if (g < best) { best = g; win = 8 + c; }
            }
            edges = 0;
            if (planar) return best;
            for (int i = 0; i < 3; i++)
            {
                var dir = i == 0 ? dx : (i == 1 ? dy : dz);
                double x = dir.X, y = dir.Y, z = dir.Z;
                for (int c = 0; c < 8; c++)
                {
                    int e = c | (1 << i);
                    if (c == e) continue;
                    if (x * r[c] + y * r[8 + c] + z * r[16 + c] < 0 && x * r[e] + y * r[8 + e] + z * r[16 + e] > 0)
                        edges |= 1u << (8 * i + c);
                }
            }
            return best;
        }

        /// <summary>
        /// One coordinate of the clamp residuals of the eight corners p + [0, 1]·d1 + [0, 1]·d2 + [0, 1]·d3 against
        /// [lo, hi], into r[0..7]: the sums in <see cref="Corner(Vector3D, Vector3D, Vector3D, Vector3D, int)"/>'s order.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static unsafe void CornerResiduals(double p, double d1, double d2, double d3, double lo, double hi, double* r)
        {
            double p1 = p + d1, p2 = p + d2, p3 = p1 + d2;
            r[0] = Outside(p, lo, hi);
            r[1] = Outside(p1, lo, hi);
            r[2] = Outside(p2, lo, hi);
            r[3] = Outside(p3, lo, hi);
            r[4] = Outside(p + d3, lo, hi);
            r[5] = Outside(p1 + d3, lo, hi);
            r[6] = Outside(p2 + d3, lo, hi);
            r[7] = Outside(p3 + d3, lo, hi);
        }

        /// <summary>
        /// Corner c of the box p + [0, 1]·dx + [0, 1]·dy + [0, 1]·dz (bit i of c picks the far end on axis i): the sums in
        /// one order, so an edge's two ends and a vertex seen twice are the same values.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D Corner(Vector3D p, Vector3D dx, Vector3D dy, Vector3D dz, int c)
        {
            if ((c & 1) != 0) p += dx;
            if ((c & 2) != 0) p += dy;
            if ((c & 4) != 0) p += dz;
            return p;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D Corner(Vector3D lo, Vector3D hi, int c) =>
            new Vector3D((c & 1) != 0 ? hi.X : lo.X, (c & 2) != 0 ? hi.Y : lo.Y, (c & 4) != 0 ? hi.Z : lo.Z);

        /// <summary>p − clamp(p) against the box [lo, hi] (box-local).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D Residual(Vector3D p, Vector3D lo, Vector3D hi) =>
            new Vector3D(Outside(p.X, lo.X, hi.X), Outside(p.Y, lo.Y, hi.Y), Outside(p.Z, lo.Z, hi.Z));

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D Clamp(Vector3D p, Vector3D lo, Vector3D hi) =>
            new Vector3D(Num.Clamp(p.X, lo.X, hi.X), Num.Clamp(p.Y, lo.Y, hi.Y), Num.Clamp(p.Z, lo.Z, hi.Z));

        /// <summary>
        /// A lower bound on the squared distance from segment [p, q] to the box [lo, hi] (box-local): every point of the
        /// segment is at least the segment's gap along each axis outside that axis's slab, so at least their root-sum-square.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double SpanGap2(Vector3D p, Vector3D q, Vector3D lo, Vector3D hi)
        {
            double x = AxisSpanGap(p.X, q.X, lo.X, hi.X), y = AxisSpanGap(p.Y, q.Y, lo.Y, hi.Y), z = AxisSpanGap(p.Z, q.Z, lo.Z, hi.Z);
            return x * x + y * y + z * z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double AxisSpanGap(double p, double q, double lo, double hi) =>
            Num.Max(Num.Max(Num.Min(p, q) - hi, lo - Num.Max(p, q)), 0); // squared by the caller: a zero's sign is lost

        /// <summary>
        /// The front of <see cref="BoxBox"/> and <see cref="BoxBoxDistance"/>: the size, the largest magnitude among the
        /// boxes' relative position and extents (within [2^-450, 2^450], or 0, the box kernels' products stay far from
        /// underflow and overflow: see <see cref="Range"/>), B's origin from A's (<paramref name="d"/>) and B's centre from
        /// A's in world axes (<paramref name="t"/>, which <see cref="BoxBoxOverlapsScalar"/> tests). In plain doubles,
        /// each step as Vector3D's operations would form it, in their order (the same bits): Mono keeps every Vector3D
        /// temporary in memory.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Front(in Box a, in Box b, out double size, out Vector3D d, out Vector3D t)
        {
            double dX = b.Origin.X - a.Origin.X, dY = b.Origin.Y - a.Origin.Y, dZ = b.Origin.Z - a.Origin.Z;
            double loAx = a.Lo.X, loAy = a.Lo.Y, loAz = a.Lo.Z, hiAx = a.Hi.X, hiAy = a.Hi.Y, hiAz = a.Hi.Z;
            double loBx = b.Lo.X, loBy = b.Lo.Y, loBz = b.Lo.Z, hiBx = b.Hi.X, hiBy = b.Hi.Y, hiBz = b.Hi.Z;
            // Range.MaxAbs of the three vectors: Num.Max(MaxAbs(d), Num.Max(MaxAbs(ea), MaxAbs(eb))).
            double ea = Num.Max(Math.Abs(hiAx - loAx), Num.Max(Math.Abs(hiAy - loAy), Math.Abs(hiAz - loAz)));
            double eb = Num.Max(Math.Abs(hiBx - loBx), Num.Max(Math.Abs(hiBy - loBy), Math.Abs(hiBz - loBz)));
            size = Num.Max(Num.Max(Math.Abs(dX), Num.Max(Math.Abs(dY), Math.Abs(dZ))), Num.Max(ea, eb));
            // The centres: ToWorldOffset(LocalCenter) = (X·c.X + Y·c.Y) + Z·c.Z with LocalCenter = (Lo + Hi)·0.5.
            double cAx = (loAx + hiAx) * 0.5, cAy = (loAy + hiAy) * 0.5, cAz = (loAz + hiAz) * 0.5;
            double cBx = (loBx + hiBx) * 0.5, cBy = (loBy + hiBy) * 0.5, cBz = (loBz + hiBz) * 0.5;
            Vector3D aX = a.X, aY = a.Y, aZ = a.Z, bX = b.X, bY = b.Y, bZ = b.Z;
            double tX = (dX + (bX.X * cBx + bY.X * cBy + bZ.X * cBz)) - (aX.X * cAx + aY.X * cAy + aZ.X * cAz);
            double tY = (dY + (bX.Y * cBx + bY.Y * cBy + bZ.Y * cBz)) - (aX.Y * cAx + aY.Y * cAy + aZ.Y * cAz);
            double tZ = (dZ + (bX.Z * cBx + bY.Z * cBy + bZ.Z * cBz)) - (aX.Z * cAx + aY.Z * cAy + aZ.Z * cAz);
            d = new Vector3D(dX, dY, dZ);
            t = new Vector3D(tX, tY, tZ);
        }

        /// <summary>
        /// Whether two OBBs overlap (<see cref="BoxBoxOverlaps(in Box, in Box)"/> on their <see cref="Box"/> forms, without
        /// building them) and whether their magnitudes allow the fast path (the size <see cref="Front"/> forms for them in range).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool ObbObbOverlaps(in Obb3 a, in Obb3 b, out bool inRange)
        {
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported)
            {
                int r = ObbObbOverlapsVector(a, b);
                inRange = (r & 2) != 0;
                return (r & 1) != 0;
            }
#endif
            return ObbObbOverlapsScalar(a, b, out inRange);
        }

        /// <summary>
        /// <see cref="ObbObbOverlaps"/> without AVX2 (Mono, Unity): the scalar test on the OBBs' fields, without their
        /// <see cref="Box"/> forms, whose building and passing (two 152-byte structs) cost Mono more than the test.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool ObbObbOverlapsScalar(in Obb3 a, in Obb3 b, out bool inRange)
        {
            var tw = b.Center - a.Center;
            Vector3D ha = a.HalfExtents, hb = b.HalfExtents;
            inRange = Range.Box(Range.MaxAbs(tw, ha + ha, hb + hb)); // Size of the Box forms: h − (−h) is h + h
            return OverlapsCenteredScalar(tw, a.AxisX, a.AxisY, a.AxisZ, ha, b.AxisX, b.AxisY, b.AxisZ, hb, false);
        }

        /// <summary><see cref="ObbObbOverlaps"/> for an AABB and an OBB.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AabbObbOverlaps(in Aabb3 a, in Obb3 b, out bool inRange)
        {
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported)
            {
                int r = AabbObbOverlapsVector(a, b);
                inRange = (r & 2) != 0;
                return (r & 1) != 0;
            }
#endif
            return AabbObbOverlapsScalar(a, b, out inRange);
        }

        /// <summary>
        /// <see cref="AabbObbOverlaps"/> without AVX2: <see cref="ObbObbOverlapsScalar"/>'s way, on the values of the AABB's
        /// Box form (origin Min, [0, Max − Min]; its unit axes map offsets exactly).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool AabbObbOverlapsScalar(in Aabb3 a, in Obb3 b, out bool inRange)
        {
            var ea = a.Max - a.Min;
            var ha = ea * 0.5;
            var hb = b.HalfExtents;
            var ob = b.Center - a.Min;
            inRange = Range.Box(Range.MaxAbs(ob, ea, hb + hb));
            return OverlapsCenteredScalar(ob - ha, Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ, ha, b.AxisX, b.AxisY, b.AxisZ, hb, false);
        }

        /// <summary>
        /// Box–box overlap by the separating-axis test with early outs and no square roots (Gottschalk et al. 1996;
        /// Ericson, RTCD §4.4.1), in A's frame. Cross axes are projected honestly instead of with the usual ε added to |R|,
        /// so nearly parallel edges neither invent a separation nor need a scale-dependent fudge. 2D uses the four face axes.
        /// </summary>
        public static bool BoxBoxOverlaps(in Box a, in Box b)
        {
#if NET
            // The same test on AVX2 lanes where the hardware has them (BoxKernels.Vector.cs); planar boxes need 4 axes only.
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported && !(a.Planar || b.Planar)) return BoxBoxOverlapsVector(a, b);
#endif
            return BoxBoxOverlapsScalar(a, b);
        }

        /// <summary>The scalar form of <see cref="BoxBoxOverlaps(in Box, in Box)"/>: the only one on netstandard2.1 (Unity) and for planar boxes.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool BoxBoxOverlapsScalar(in Box a, in Box b)
        {
            Front(a, b, out _, out _, out var t);
            return OverlapsCenteredScalar(t, a, b);
        }

        /// <summary><see cref="OverlapsCenteredScalar(in Vector3D, in Vector3D, in Vector3D, in Vector3D, in Vector3D, in Vector3D, in Vector3D, in Vector3D, in Vector3D, bool)"/> on two boxes' axes and half-extents ((Hi − Lo)·0.5), B's centre tw from A's.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapsCenteredScalar(in Vector3D tw, in Box a, in Box b)
        {
            var ha = new Vector3D((a.Hi.X - a.Lo.X) * 0.5, (a.Hi.Y - a.Lo.Y) * 0.5, (a.Hi.Z - a.Lo.Z) * 0.5);
            var hb = new Vector3D((b.Hi.X - b.Lo.X) * 0.5, (b.Hi.Y - b.Lo.Y) * 0.5, (b.Hi.Z - b.Lo.Z) * 0.5);
            return OverlapsCenteredScalar(tw, a.X, a.Y, a.Z, ha, b.X, b.Y, b.Z, hb, a.Planar || b.Planar);
        }

        /// <summary>
        /// <see cref="BoxBoxOverlapsScalar"/> on boxes centred on their origins, tw = B's centre − A's centre in world
        /// axes: two OBBs need nothing more (as OverlapsCentered on AVX2 lanes, BoxKernels.Vector.cs).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool OverlapsCenteredScalar(in Vector3D tw, in Vector3D ax, in Vector3D ay, in Vector3D az, in Vector3D ha,
            in Vector3D bx, in Vector3D by, in Vector3D bz, in Vector3D hb, bool planar)
        {
            // The dot products written out (Vector3D.Dot's x·x' + y·y' + z·z', the same bits) on components read once:
            // on Mono each Vector3D passed to an inlined Dot is copied first.
            double twX = tw.X, twY = tw.Y, twZ = tw.Z, axX = ax.X, axY = ax.Y, axZ = ax.Z, ayX = ay.X, ayY = ay.Y, ayZ = ay.Z;
            double azX = az.X, azY = az.Y, azZ = az.Z, bxX = bx.X, bxY = bx.Y, bxZ = bx.Z, byX = by.X, byY = by.Y, byZ = by.Z;
            double bzX = bz.X, bzY = bz.Y, bzZ = bz.Z;
            double tx = twX * axX + twY * axY + twZ * axZ, ty = twX * ayX + twY * ayY + twZ * ayZ, tz = twX * azX + twY * azY + twZ * azZ;
            // r_ij = a_i · b_j: B's axes as columns in A's frame.
            double r00 = axX * bxX + axY * bxY + axZ * bxZ, r01 = axX * byX + axY * byY + axZ * byZ, r02 = axX * bzX + axY * bzY + axZ * bzZ;
            double r10 = ayX * bxX + ayY * bxY + ayZ * bxZ, r11 = ayX * byX + ayY * byY + ayZ * byZ, r12 = ayX * bzX + ayY * bzY + ayZ * bzZ;
            double r20 = azX * bxX + azY * bxY + azZ * bxZ, r21 = azX * byX + azY * byY + azZ * byZ, r22 = azX * bzX + azY * bzY + azZ * bzZ;
            double q00 = Math.Abs(r00), q01 = Math.Abs(r01), q02 = Math.Abs(r02);
            double q10 = Math.Abs(r10), q11 = Math.Abs(r11), q12 = Math.Abs(r12);
            double q20 = Math.Abs(r20), q21 = Math.Abs(r21), q22 = Math.Abs(r22);

            // A's and B's face axes.
            if (Math.Abs(tx) > ha.X + hb.X * q00 + hb.Y * q01 + hb.Z * q02) return false;
            if (Math.Abs(ty) > ha.Y + hb.X * q10 + hb.Y * q11 + hb.Z * q12) return false;
            if (Math.Abs(tx * r00 + ty * r10 + tz * r20) > ha.X * q00 + ha.Y * q10 + ha.Z * q20 + hb.X) return false;
            if (Math.Abs(tx * r01 + ty * r11 + tz * r21) > ha.X * q01 + ha.Y * q11 + ha.Z * q21 + hb.Y) return false;
            if (planar) return true;
            if (Math.Abs(tz) > ha.Z + hb.X * q20 + hb.Y * q21 + hb.Z * q22) return false;
            if (Math.Abs(tx * r02 + ty * r12 + tz * r22) > ha.X * q02 + ha.Y * q12 + ha.Z * q22 + hb.Z) return false;

            // Edge × edge axes L = e_i × b_j. B's radius uses b_k·L, the 2×2 minors of R, rather than the orthonormality
            // shortcut |r|: a nearly degenerate L then still yields a true projection, so it can only fail to separate.
            // e_x × b_j = (0, −r2j, r1j)
            if (Separates(tz * r10 - ty * r20, ha.Y * q20 + ha.Z * q10, hb.Y, r11 * r20 - r21 * r10, hb.Z, r12 * r20 - r22 * r10)) return false;
            if (Separates(tz * r11 - ty * r21, ha.Y * q21 + ha.Z * q11, hb.X, r10 * r21 - r20 * r11, hb.Z, r12 * r21 - r22 * r11)) return false;
            if (Separates(tz * r12 - ty * r22, ha.Y * q22 + ha.Z * q12, hb.X, r10 * r22 - r20 * r12, hb.Y, r11 * r22 - r21 * r12)) return false;
            // e_y × b_j = (r2j, 0, −r0j)
            if (Separates(tx * r20 - tz * r00, ha.X * q20 + ha.Z * q00, hb.Y, r01 * r20 - r21 * r00, hb.Z, r02 * r20 - r22 * r00)) return false;
            if (Separates(tx * r21 - tz * r01, ha.X * q21 + ha.Z * q01, hb.X, r00 * r21 - r20 * r01, hb.Z, r02 * r21 - r22 * r01)) return false;
            if (Separates(tx * r22 - tz * r02, ha.X * q22 + ha.Z * q02, hb.X, r00 * r22 - r20 * r02, hb.Y, r01 * r22 - r21 * r02)) return false;
            // e_z × b_j = (−r1j, r0j, 0)
            if (Separates(ty * r00 - tx * r10, ha.X * q10 + ha.Y * q00, hb.Y, r11 * r00 - r01 * r10, hb.Z, r12 * r00 - r02 * r10)) return false;
            if (Separates(ty * r01 - tx * r11, ha.X * q11 + ha.Y * q01, hb.X, r10 * r01 - r00 * r11, hb.Z, r12 * r01 - r02 * r11)) return false;
            return !Separates(ty * r02 - tx * r12, ha.X * q12 + ha.Y * q02, hb.X, r10 * r02 - r00 * r12, hb.Y, r11 * r02 - r01 * r12);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Separates(double tl, double ra, double h1, double m1, double h2, double m2) =>
            Math.Abs(tl) > ra + h1 * Math.Abs(m1) + h2 * Math.Abs(m2);
    }
}
