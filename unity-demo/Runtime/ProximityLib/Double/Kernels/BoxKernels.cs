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
        /// Lin &amp; Manocha 1996) contain the exact minimum-translation direction of two polytopes. Each candidate is
        /// normalised and both boxes are projected on it honestly (no orthonormality shortcuts), so a noisy,
        /// near-degenerate cross axis can only overestimate the overlap and never wins wrongly. Apart: the closest pair
        /// always involves an edge of A or of B (a face–face contact region is bounded by edges), so the minimum of
        /// the edge–box distances is exact; an edge whose gap along the other box's axes already exceeds the best pair
        /// cannot win and is skipped. Overlapping: A moved by the minimum translation just touches B, and the
        /// touching pair found the same way, moved back, realises the penetration.
        /// </summary>
        public static DistanceResult3 BoxBox(in Box boxA, in Box boxB, out bool inRange)
        {
            inRange = Range.Box(Size(boxA, boxB));
            var shift = boxA.Origin;
            var a = boxA.Translated(-shift);
            var b = boxB.Translated(-shift);
            Vector3D onA, onB;
            // Apart (by the overlap query's own verdict, so the two agree): the depth search below has nothing to add.
            if (!BoxBoxOverlaps(a, b))
            {
                double gap = EdgesApart(a, b, out onA, out onB);
                // A subnormal squared gap has lost bits: the slow path answers it at a scale where it has not.
                inRange &= gap == 0 || Range.In(gap);
                return new DistanceResult3(Math.Sqrt(gap), gap, onA + shift, onB + shift, 0, 0);
            }
            var ca = a.Origin + a.ToWorldOffset(a.LocalCenter);
            var cb = b.Origin + b.ToWorldOffset(b.LocalCenter);
            var ha = a.Half;
            var hb = b.Half;
            bool planar = a.Planar || b.Planar;
            int faces = planar ? 2 : 3;

            double depth = double.PositiveInfinity;
            Vector3D push = default;
            for (int i = 0; i < faces; i++)
            {
                TryBoxAxis(a.Axis(i), a, b, ca, cb, ha, hb, ref depth, ref push);
                TryBoxAxis(b.Axis(i), a, b, ca, cb, ha, hb, ref depth, ref push);
            }
            if (!planar)
            {
                for (int i = 0; i < 3; i++)
                    for (int j = 0; j < 3; j++)
                        TryBoxAxis(EdgeCross(a.Axis(i), b.Axis(j)), a, b, ca, cb, ha, hb, ref depth, ref push);
            }

            if (depth < 0) push = default;
            var moved = a.Translated(push);
            double g = EdgesApart(moved, b, out onA, out onB);
            onA = onA - push + shift;
            onB += shift;
            if (depth < 0)
            {
                inRange &= g == 0 || Range.In(g);
                return new DistanceResult3(Math.Sqrt(g), g, onA, onB, 0, 0);
            }
            return new DistanceResult3(-depth, 0, onA, onB, 0, 0);
        }

        private static void TryBoxAxis(Vector3D axis, in Box a, in Box b, Vector3D ca, Vector3D cb, Vector3D ha, Vector3D hb, ref double best, ref Vector3D push)
        {
            double len2 = axis.LengthSquared;
            if (!(len2 > 0)) return;
            var n = axis / Math.Sqrt(len2);
            double ra = Radius(a, ha, n), rb = Radius(b, hb, n);
            double sep = Vector3D.Dot(cb - ca, n);
            double down = ra + rb - sep;  // moving A by −n·down clears B
            double up = ra + rb + sep;    // moving A by +n·up clears B
            // A negative overlap proves separation; record it so the caller knows (the push is then unused).
            if (down < best) { best = down; push = -n * down; }
            if (up < best) { best = up; push = n * up; }
        }

        /// <summary>
        /// u × v for two unit box axes, accurate in direction even when they are nearly parallel: u × v = u × (v ∓ u),
        /// v ∓ u carries one relative rounding per component, and u × (v ∓ u) has no cancellation (v ∓ u is nearly
        /// perpendicular to u). The plain product's direction is off by u/sinθ, which moves a projection by that much
        /// of the boxes' size: nearly identical rotations would overstate the depth or miss a separation.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Vector3D EdgeCross(Vector3D u, Vector3D v) => Vector3D.Cross(u, Vector3D.Dot(u, v) >= 0 ? v - u : v + u);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Radius(in Box box, Vector3D h, Vector3D n) =>
            h.X * Math.Abs(Vector3D.Dot(box.X, n)) + h.Y * Math.Abs(Vector3D.Dot(box.Y, n)) + h.Z * Math.Abs(Vector3D.Dot(box.Z, n));

        /// <summary>Squared distance between two boxes known to be apart or touching, as the best edge–box pair.</summary>
        private static double EdgesApart(in Box a, in Box b, out Vector3D onA, out Vector3D onB)
        {
            double best = double.PositiveInfinity;
            onA = default; onB = default;
            EdgesAgainst(a, b, false, ref best, ref onA, ref onB);
            EdgesAgainst(b, a, true, ref best, ref onA, ref onB);
            return best;
        }

        private static void EdgesAgainst(in Box edges, in Box other, bool swapped, ref double best, ref Vector3D onA, ref Vector3D onB)
        {
            var lo = edges.Lo;
            var hi = edges.Hi;
            bool point = lo == hi;
            var center = other.Origin + other.ToWorldOffset(other.LocalCenter);
            var half = other.Half;
            // The eight corners once (bit i of the index picks Hi on axis i); each edge joins two of them.
            Span<Vector3D> corner = stackalloc Vector3D[8];
            for (int c = 0; c < 8; c++)
                corner[c] = edges.Origin + edges.ToWorldOffset(new Vector3D((c & 1) != 0 ? hi.X : lo.X, (c & 2) != 0 ? hi.Y : lo.Y, (c & 4) != 0 ? hi.Z : lo.Z));
            for (int i = 0; i < 3; i++)
            {
                // A zero-length edge is a vertex, already an endpoint of another edge (unless the box is a point).
                if (Vec.Get(lo, i) == Vec.Get(hi, i) && !(point && i == 0)) continue;
                int j = (i + 1) % 3, k = (i + 2) % 3;
                int nj = Vec.Get(lo, j) == Vec.Get(hi, j) ? 1 : 2, nk = Vec.Get(lo, k) == Vec.Get(hi, k) ? 1 : 2;
                for (int sj = 0; sj < nj; sj++)
                {
                    for (int sk = 0; sk < nk; sk++)
                    {
                        int from = (sj << j) | (sk << k);
                        var p = corner[from];
                        var q = corner[from | (1 << i)];
                        // The gap along any of the other box's axes bounds the edge's distance from below: an edge
                        // that cannot beat the best pair so far is skipped (with a margin, so rounding never hides a win).
                        double lb = Math.Max(SlabGap(p, q, center, other.X, half.X),
                            Math.Max(SlabGap(p, q, center, other.Y, half.Y), SlabGap(p, q, center, other.Z, half.Z)));
                        if (lb * lb > best * (1 + 1e-9)) continue;
                        double g = SegmentBoxSeparated(p, q, other, out _, out var onEdge, out var onOther);
                        if (g < best)
                        {
                            best = g;
                            if (swapped) { onA = onOther; onB = onEdge; }
                            else { onA = onEdge; onB = onOther; }
                        }
                    }
                }
            }
        }

        /// <summary>How far segment [p, q] lies outside the slab |(x − center)·axis| ≤ half (axis a unit box axis).</summary>
        private static double SlabGap(Vector3D p, Vector3D q, Vector3D center, Vector3D axis, double half)
        {
            double sp = Vector3D.Dot(p - center, axis), sq = Vector3D.Dot(q - center, axis);
            return Math.Max(0, Math.Max(Math.Min(sp, sq) - half, -half - Math.Max(sp, sq)));
        }

        /// <summary>
        /// The largest magnitude among the boxes' relative position and extents: within [2^-450, 2^450] (or 0) the box
        /// kernels' products stay far from underflow and overflow (see <see cref="Range"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Size(in Box a, in Box b) =>
            Math.Max(Range.MaxAbs(b.Origin - a.Origin), Math.Max(Range.MaxAbs(a.Hi - a.Lo), Range.MaxAbs(b.Hi - b.Lo)));

        /// <summary><see cref="BoxBoxOverlaps(in Box, in Box)"/>, with whether the boxes' magnitudes allow the fast path.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool BoxBoxOverlaps(in Box a, in Box b, out bool inRange)
        {
            inRange = Range.Box(Size(a, b));
            return BoxBoxOverlaps(a, b);
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
        internal static bool BoxBoxOverlapsScalar(in Box a, in Box b)
        {
            var tw = (b.Origin - a.Origin) + b.ToWorldOffset(b.LocalCenter) - a.ToWorldOffset(a.LocalCenter);
            double tx = Vector3D.Dot(tw, a.X), ty = Vector3D.Dot(tw, a.Y), tz = Vector3D.Dot(tw, a.Z);
            // r_ij = a_i · b_j: B's axes as columns in A's frame.
            double r00 = Vector3D.Dot(a.X, b.X), r01 = Vector3D.Dot(a.X, b.Y), r02 = Vector3D.Dot(a.X, b.Z);
            double r10 = Vector3D.Dot(a.Y, b.X), r11 = Vector3D.Dot(a.Y, b.Y), r12 = Vector3D.Dot(a.Y, b.Z);
            double r20 = Vector3D.Dot(a.Z, b.X), r21 = Vector3D.Dot(a.Z, b.Y), r22 = Vector3D.Dot(a.Z, b.Z);
            var ha = a.Half;
            var hb = b.Half;
            double q00 = Math.Abs(r00), q01 = Math.Abs(r01), q02 = Math.Abs(r02);
            double q10 = Math.Abs(r10), q11 = Math.Abs(r11), q12 = Math.Abs(r12);
            double q20 = Math.Abs(r20), q21 = Math.Abs(r21), q22 = Math.Abs(r22);
            bool planar = a.Planar || b.Planar;

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

        /// <summary>
        /// AABB against AABB, per axis and exact up to one subtraction per gap. Apart: the per-axis gaps; overlapping axes
        /// put both witnesses at the middle of the shared interval. Overlapping: the axis of least overlap.
        /// </summary>
        /// <remarks>
        /// <paramref name="inRange"/>: apart, the squared gap lies in the fast range; overlapping, no axis had a positive gap
        /// whose square underflowed (the depths are differences, exact at any magnitude).
        /// </remarks>
        public static DistanceResult3 AabbAabb(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB, bool planar, out bool inRange)
        {
            var x = new AxisGap(minA.X, maxA.X, minB.X, maxB.X);
            var y = new AxisGap(minA.Y, maxA.Y, minB.Y, maxB.Y);
            var z = new AxisGap(minA.Z, maxA.Z, minB.Z, maxB.Z);
            double g2 = x.Gap2 + y.Gap2 + z.Gap2;
            var pa = new Vector3D(x.A, y.A, z.A);
            var pb = new Vector3D(x.B, y.B, z.B);
            if (g2 > 0)
            {
                inRange = Range.In(g2);
                return new DistanceResult3(Math.Sqrt(g2), g2, pa, pb, 0, 0);
            }

            // Overlapping on every axis: push A out along the axis of least overlap (x before y before z on ties), down or
            // up, whichever is shorter. Swapping the boxes swaps each axis's two push-outs, so a tie between them is
            // broken by the canonical order of the boxes, which flips too: either argument order gives one answer.
            double mx = Math.Min(x.Down, x.Up), my = Math.Min(y.Down, y.Up), depth = mx;
            int axis = 0;
            if (my < depth) { depth = my; axis = 1; }
            if (!planar && Math.Min(z.Down, z.Up) < depth) { depth = Math.Min(z.Down, z.Up); axis = 2; }
            var g = axis == 0 ? x : (axis == 1 ? y : z);
            bool down = g.Down < g.Up || (g.Down == g.Up && Order.Before(minA, maxA, minB, maxB));
            int face = 2 * axis + (down ? 0 : 1);
            inRange = depth >= 0;
            // Moving A down along the axis by `depth` puts its max face on B's min face, and vice versa.
            switch (face)
            {
                case 0: pa = new Vector3D(maxA.X, pa.Y, pa.Z); pb = new Vector3D(minB.X, pb.Y, pb.Z); break;
                case 1: pa = new Vector3D(minA.X, pa.Y, pa.Z); pb = new Vector3D(maxB.X, pb.Y, pb.Z); break;
                case 2: pa = new Vector3D(pa.X, maxA.Y, pa.Z); pb = new Vector3D(pb.X, minB.Y, pb.Z); break;
                case 3: pa = new Vector3D(pa.X, minA.Y, pa.Z); pb = new Vector3D(pb.X, maxB.Y, pb.Z); break;
                case 4: pa = new Vector3D(pa.X, pa.Y, maxA.Z); pb = new Vector3D(pb.X, pb.Y, minB.Z); break;
                default: pa = new Vector3D(pa.X, pa.Y, minA.Z); pb = new Vector3D(pb.X, pb.Y, maxB.Z); break;
            }
            return new DistanceResult3(-depth, 0, pa, pb, 0, 0);
        }

        /// <summary>
        /// The distance of <see cref="AabbAabb"/> alone, branch-free per axis: an axis's gap is the larger of its two
        /// one-sided gaps (at most one is positive), and its push-out the smaller of the two negated. The same operations
        /// on the same values as <see cref="AxisGap"/> (zero signs included), so the same bits and <paramref name="inRange"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double AabbAabbDistance(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB, bool planar, out bool inRange)
        {
            double ax = minB.X - maxA.X, bx = minA.X - maxB.X;
            double ay = minB.Y - maxA.Y, by = minA.Y - maxB.Y;
            double az = minB.Z - maxA.Z, bz = minA.Z - maxB.Z;
            double gx = Math.Max(Math.Max(ax, bx), 0), gy = Math.Max(Math.Max(ay, by), 0), gz = Math.Max(Math.Max(az, bz), 0);
            double g2 = gx * gx + gy * gy + gz * gz;
            if (g2 > 0)
            {
                inRange = Range.In(g2);
                return Math.Sqrt(g2);
            }
            double depth = Math.Min(-ax, -bx), my = Math.Min(-ay, -by);
            if (my < depth) depth = my;
            if (!planar && Math.Min(-az, -bz) < depth) depth = Math.Min(-az, -bz);
            inRange = depth >= 0;
            return -depth;
        }

        /// <summary>One axis of an AABB pair: the gap (if apart), the witness coordinates, and both push-out distances.</summary>
        private readonly struct AxisGap
        {
            public readonly double Gap2, A, B, Down, Up;

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public AxisGap(double aLo, double aHi, double bLo, double bHi)
            {
                double above = bLo - aHi, below = aLo - bHi;
                Down = -above;
                Up = -below;
                if (above > 0) { Gap2 = above * above; A = aHi; B = bLo; }
                else if (below > 0) { Gap2 = below * below; A = aLo; B = bHi; }
                else
                {
                    // Shared interval: both witnesses at its middle (halves first: hi − lo can overflow).
                    double lo = Math.Max(aLo, bLo), hi = Math.Min(aHi, bHi);
                    Gap2 = 0;
                    A = B = 0.5 * lo + 0.5 * hi;
                }
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AabbAabbOverlaps(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB) =>
            minA.X <= maxB.X && maxA.X >= minB.X && minA.Y <= maxB.Y && maxA.Y >= minB.Y && minA.Z <= maxB.Z && maxA.Z >= minB.Z;
    }
}
