// Copied from src/ProximityLib/Double/Kernels/BoxKernels.Planar.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// Box against box in the plane: <see cref="BoxBox"/> on planar boxes with its z parts dropped (they only added
        /// exact zeros), so the same steps and the same bits up to the sign of a zero. Overlap by the four face axes;
        /// apart, the least of the eight vertex–box clamps (in 2D the closest pair always has a vertex of one box, so no
        /// edge closed form is needed); overlapping, the least push-out over the four face axes, then the same vertex
        /// search on A moved by it.
        /// </summary>
        public static DistanceResult2 BoxBox2(in Box2 a, in Box2 b, out bool inRange)
        {
            bool overlap = Front2(a, b, out double size, out var d, out var t);
            double k = Num.InversePowerOfTwo(size);
            inRange = Range.Box(size);
            var shift = a.Origin;
            Vector2D onA, onB;
            if (!overlap)
            {
                double gap = BoxesApart2(a, default, b, d, k, out onA, out onB);
                inRange &= Range.In(gap); // a zero gap of boxes found apart may have underflowed: the slow path
                return new DistanceResult2(Math.Sqrt(gap), gap, onA + shift, onB + shift, 0, 0);
            }
            double depth = Penetration2(a, b, t, out var push);
            if (depth < 0) push = default;
            double g = BoxesApart2(a, push, b, d, k, out onA, out onB);
            onA = onA - push + shift;
            onB += shift;
            if (depth < 0)
            {
                inRange &= Range.In(g); // a zero gap of boxes found apart may have underflowed: the slow path
                return new DistanceResult2(Math.Sqrt(g), g, onA, onB, 0, 0);
            }
            return new DistanceResult2(-depth, 0, onA, onB, 0, 0);
        }

        /// <summary><see cref="BoxBox2"/> on two OBBs in canonical order, one call (as <see cref="ObbObb"/>).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 ObbObb2(in Obb2 a, in Obb2 b, out bool inRange)
        {
            if (!Order.Swap(a, b)) return BoxBox2(a.ToBox2(), b.ToBox2(), out inRange);
            return BoxBox2(b.ToBox2(), a.ToBox2(), out inRange).Swapped();
        }

        /// <summary>
        /// The distance of <see cref="BoxBox2"/> alone: the same steps, without the witness search of overlapping boxes
        /// unless the depth search found a separation (then its gap is the answer, as there).
        /// </summary>
        public static double BoxBoxDistance2(in Box2 a, in Box2 b, out bool inRange)
        {
            bool overlap = Front2(a, b, out double size, out var d, out var t);
            inRange = Range.Box(size);
            if (overlap)
            {
                double depth = Penetration2(a, b, t, out _);
                if (depth >= 0) return -depth;
            }
            double gap = BoxesApart2(a, default, b, d, Num.InversePowerOfTwo(size), out _, out _);
            inRange &= Range.In(gap); // a zero gap of boxes found apart may have underflowed: the slow path
            return Math.Sqrt(gap);
        }

        /// <summary>
        /// The front of <see cref="BoxBox2"/> and <see cref="BoxBoxDistance2"/>: the overlap verdict (<see cref="BoxBoxOverlaps2"/>),
        /// the configuration's size (the largest magnitude of B's origin from A's and the boxes' extents), B's origin
        /// from A's (<paramref name="d"/>) and B's centre from A's (<paramref name="t"/>, world axes). In plain doubles,
        /// each step as Vector2D's operations would form it, in their order (the same bits): Mono keeps every Vector2D
        /// temporary in memory.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Front2(in Box2 a, in Box2 b, out double size, out Vector2D d, out Vector2D t)
        {
            double dX = b.Origin.X - a.Origin.X, dY = b.Origin.Y - a.Origin.Y;
            double loAx = a.Lo.X, loAy = a.Lo.Y, hiAx = a.Hi.X, hiAy = a.Hi.Y, loBx = b.Lo.X, loBy = b.Lo.Y, hiBx = b.Hi.X, hiBy = b.Hi.Y;
            double eaX = hiAx - loAx, eaY = hiAy - loAy, ebX = hiBx - loBx, ebY = hiBy - loBy;
            size = Num.Max(Num.Max(Math.Abs(dX), Math.Abs(dY)), Num.Max(Num.Max(Math.Abs(eaX), Math.Abs(eaY)), Num.Max(Math.Abs(ebX), Math.Abs(ebY))));
            double aXx = a.X.X, aXy = a.X.Y, aYx = a.Y.X, aYy = a.Y.Y, bXx = b.X.X, bXy = b.X.Y, bYx = b.Y.X, bYy = b.Y.Y;
            // The centres in world axes: ToWorldOffset(LocalCenter) = X·c.X + Y·c.Y, LocalCenter = (Lo + Hi)·0.5.
            double cAx = (loAx + hiAx) * 0.5, cAy = (loAy + hiAy) * 0.5, cBx = (loBx + hiBx) * 0.5, cBy = (loBy + hiBy) * 0.5;
            double tX = (dX + (bXx * cBx + bYx * cBy)) - (aXx * cAx + aYx * cAy);
            double tY = (dY + (bXy * cBx + bYy * cBy)) - (aXy * cAx + aYy * cAy);
            d = new Vector2D(dX, dY);
            t = new Vector2D(tX, tY);
            return OverlapsCentered2(tX, tY, aXx, aXy, aYx, aYy, eaX * 0.5, eaY * 0.5, bXx, bXy, bYx, bYy, ebX * 0.5, ebY * 0.5);
        }

        /// <summary>The planar case of <see cref="BoxBoxOverlapsScalar"/>: the four face axes, in A's frame.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool BoxBoxOverlaps2(in Box2 a, in Box2 b) => Front2(a, b, out _, out _, out _);

        /// <summary>
        /// Whether two OBBs overlap (<see cref="BoxBoxOverlaps2(in Box2, in Box2)"/> on their Box2 forms) and whether their
        /// magnitudes allow the fast path (the size <see cref="Front2"/> forms for them in range), from their fields: the Box2 forms
        /// have centre 0, where the general form's offsets add only zeros, (h − (−h))·0.5 is h and h − (−h) is h + h. On
        /// Mono building and passing the Box2 forms cost more than the test.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool ObbObbOverlaps2(in Obb2 a, in Obb2 b, out bool inRange)
        {
            var tw = b.Center - a.Center;
            Vector2D ha = a.HalfExtents, hb = b.HalfExtents;
            inRange = Range.Box(Range.MaxAbs(tw, ha + ha, hb + hb));
            return OverlapsCentered2(tw, a.AxisX, a.AxisY, ha, b.AxisX, b.AxisY, hb);
        }

        /// <summary><see cref="ObbObbOverlaps2"/> for an AABB (its Box2 form: origin Min, [0, Max − Min], unit axes) and an OBB.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AabbObbOverlaps2(in Aabb2 a, in Obb2 b, out bool inRange)
        {
            var ea = a.Max - a.Min;
            var ha = ea * 0.5;
            var hb = b.HalfExtents;
            var ob = b.Center - a.Min;
            inRange = Range.Box(Range.MaxAbs(ob, ea, hb + hb));
            return OverlapsCentered2(ob - ha, Vector2D.UnitX, Vector2D.UnitY, ha, b.AxisX, b.AxisY, hb);
        }

        /// <summary><see cref="BoxBoxOverlaps2(in Box2, in Box2)"/> on boxes centred on their origins, tw = B's centre − A's centre.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapsCentered2(Vector2D tw, Vector2D ax, Vector2D ay, Vector2D ha, Vector2D bx, Vector2D by, Vector2D hb) =>
            OverlapsCentered2(tw.X, tw.Y, ax.X, ax.Y, ay.X, ay.Y, ha.X, ha.Y, bx.X, bx.Y, by.X, by.Y, hb.X, hb.Y);

        /// <summary><see cref="OverlapsCentered2(Vector2D, Vector2D, Vector2D, Vector2D, Vector2D, Vector2D, Vector2D)"/> on the vectors' components (Vector2D.Dot is x·x' + y·y').</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapsCentered2(double twX, double twY, double axX, double axY, double ayX, double ayY, double haX, double haY,
            double bxX, double bxY, double byX, double byY, double hbX, double hbY)
        {
            double tx = twX * axX + twY * axY, ty = twX * ayX + twY * ayY;
            double r00 = axX * bxX + axY * bxY, r01 = axX * byX + axY * byY;
            double r10 = ayX * bxX + ayY * bxY, r11 = ayX * byX + ayY * byY;
            double q00 = Math.Abs(r00), q01 = Math.Abs(r01), q10 = Math.Abs(r10), q11 = Math.Abs(r11);
            return !(Math.Abs(tx) > haX + hbX * q00 + hbY * q01)
                & !(Math.Abs(ty) > haY + hbX * q10 + hbY * q11)
                & !(Math.Abs(tx * r00 + ty * r10) > haX * q00 + haY * q10 + hbX)
                & !(Math.Abs(tx * r01 + ty * r11) > haX * q01 + haY * q11 + hbY);
        }

        /// <summary>The planar case of <see cref="PenetrationScalar"/>: A's and B's face normals, in that order.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double Penetration2(in Box2 a, in Box2 b, Vector2D t, out Vector2D push)
        {
            Vector2D ax = a.X, ay = a.Y, bx = b.X, by = b.Y, ha = a.Half, hb = b.Half;
            double best = double.PositiveInfinity, scale = 0;
            Vector2D axis = default;
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported)
            {
                // The first axis holding the least push-out, then that axis alone in the scalar steps: the same bits.
                int first = LeastAxis2(ax, ay, bx, by, ha, hb, t);
                if (first >= 0)
                    TryAxis2(first == 0 ? ax : first == 1 ? ay : first == 2 ? bx : by, ax, ay, bx, by, ha, hb, t, ref best, ref axis, ref scale);
                push = axis * scale;
                return best;
            }
#endif
            TryAxis2(ax, ax, ay, bx, by, ha, hb, t, ref best, ref axis, ref scale);
            TryAxis2(ay, ax, ay, bx, by, ha, hb, t, ref best, ref axis, ref scale);
            TryAxis2(bx, ax, ay, bx, by, ha, hb, t, ref best, ref axis, ref scale);
            TryAxis2(by, ax, ay, bx, by, ha, hb, t, ref best, ref axis, ref scale);
            push = axis * scale;
            return best;
        }

        /// <summary>The planar <see cref="TryAxis"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryAxis2(Vector2D v, Vector2D ax, Vector2D ay, Vector2D bx, Vector2D by, Vector2D ha, Vector2D hb, Vector2D t,
            ref double best, ref Vector2D axis, ref double scale)
        {
            double len2 = v.LengthSquared;
            if (!(len2 > 0)) return;
            double len = Math.Sqrt(len2);
            double ra = ha.X * Math.Abs(Vector2D.Dot(ax, v)) + ha.Y * Math.Abs(Vector2D.Dot(ay, v));
            double rb = hb.X * Math.Abs(Vector2D.Dot(bx, v)) + hb.Y * Math.Abs(Vector2D.Dot(by, v));
            double sep = Vector2D.Dot(t, v);
            double down = (ra + rb - sep) / len, up = (ra + rb + sep) / len;
            if (down < best) { best = down; axis = v; scale = -down / len; }
            if (up < best) { best = up; axis = v; scale = up / len; }
        }

        /// <summary>
        /// The planar <see cref="BoxesApart"/>: the least squared gap of A's four corners to box B (in B's frame) and of
        /// B's four corners to box A (the first of equal ones, A's before B's), and the pair realising it in world
        /// coordinates (relative to the common origin the caller subtracted). The gaps are compared scaled by k, the power
        /// of two that brings the configuration's size near 1: at the small end of the fast range the squares of gaps
        /// between touching boxes underflow to equal zeros, and the first of them is not the corner the same boxes
        /// scaled up would pick.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double BoxesApart2(in Box2 a, Vector2D originA, in Box2 b, Vector2D originB, double k, out Vector2D onA, out Vector2D onB)
        {
            // In plain doubles, each step as Vector2D's operations would form it, in their order (the same bits): Mono
            // keeps every Vector2D temporary in memory, a round of stores and loads per operation.
            double aXx = a.X.X, aXy = a.X.Y, aYx = a.Y.X, aYy = a.Y.Y, bXx = b.X.X, bXy = b.X.Y, bYx = b.Y.X, bYy = b.Y.Y;
            // Rows: A's axes in B's frame, ax = b.ToLocal(a.X), ay = b.ToLocal(a.Y); the columns are B's axes in A's frame,
            // bx = (ax.X, ay.X), by = (ax.Y, ay.Y).
            double axX = aXx * bXx + aXy * bXy, axY = aXx * bYx + aXy * bYy;
            double ayX = aYx * bXx + aYy * bXy, ayY = aYx * bYx + aYy * bYy;
            double dX = originB.X - originA.X, dY = originB.Y - originA.Y;
            double loAx = a.Lo.X, loAy = a.Lo.Y, hiAx = a.Hi.X, hiAy = a.Hi.Y, loBx = b.Lo.X, loBy = b.Lo.Y, hiBx = b.Hi.X, hiBy = b.Hi.Y;
            double eaX = hiAx - loAx, eaY = hiAy - loAy, ebX = hiBx - loBx, ebY = hiBy - loBy;
            // A's edge vectors dx = ax·ea.X, dy = ay·ea.Y and corner 0, pa = b.ToLocal(−d) + ax·loA.X + ay·loA.Y, in B's
            // frame; B's ex = bx·eb.X, ey = by·eb.Y and pb = a.ToLocal(d) + bx·loB.X + by·loB.Y in A's.
            double dxX = axX * eaX, dxY = axY * eaX, dyX = ayX * eaY, dyY = ayY * eaY;
            double ndX = -dX, ndY = -dY;
            double paX = ((ndX * bXx + ndY * bXy) + axX * loAx) + ayX * loAy;
            double paY = ((ndX * bYx + ndY * bYy) + axY * loAx) + ayY * loAy;
            double exX = axX * ebX, exY = ayX * ebX, eyX = axY * ebY, eyY = ayY * ebY;
            double pbX = ((dX * aXx + dY * aXy) + axX * loBx) + axY * loBy;
            double pbY = ((dX * aYx + dY * aYy) + ayX * loBx) + ayY * loBy;

            double best;
            int win;
#if NET
            if (System.Runtime.Intrinsics.X86.Avx2.IsSupported)
                best = Corners2Vector(new Vector2D(paX, paY), new Vector2D(dxX, dxY), new Vector2D(dyX, dyY), new Vector2D(loBx, loBy), new Vector2D(hiBx, hiBy),
                    new Vector2D(pbX, pbY), new Vector2D(exX, exY), new Vector2D(eyX, eyY), new Vector2D(loAx, loAy), new Vector2D(hiAx, hiAy), k, out win);
            else
#endif
                best = Corners2Core(paX, paY, dxX, dxY, dyX, dyY, loBx, loBy, hiBx, hiBy, pbX, pbY, exX, exY, eyX, eyY, loAx, loAy, hiAx, hiAy, k, out win);
            double ik = 1 / k;
            best = best * ik * ik;

            int c = win & 3;
            bool hx = (c & 1) != 0, hy = (c & 2) != 0;
            if (win < 4)
            {
                // A's corner (p + dx) + dy against B, clamped into B.
                double px = hx ? paX + dxX : paX, py = hx ? paY + dxY : paY;
                if (hy) { px += dyX; py += dyY; }
                onA = originA + a.ToWorldOffset(new Vector2D(hx ? hiAx : loAx, hy ? hiAy : loAy));
                onB = originB + b.ToWorldOffset(new Vector2D(Num.Clamp(px, loBx, hiBx), Num.Clamp(py, loBy, hiBy)));
            }
            else
            {
                double px = hx ? pbX + exX : pbX, py = hx ? pbY + exY : pbY;
                if (hy) { px += eyX; py += eyY; }
                onB = originB + b.ToWorldOffset(new Vector2D(hx ? hiBx : loBx, hy ? hiBy : loBy));
                onA = originA + a.ToWorldOffset(new Vector2D(Num.Clamp(px, loAx, hiAx), Num.Clamp(py, loAy, hiAy)));
            }
            return best;
        }

        /// <summary>
        /// The least squared gap of A's corners (pa + sums of dx, dy; B's frame) to B's box and of B's corners (pb + sums
        /// of ex, ey; A's frame) to A's box, and which corner holds it (0–3 A's, 4–7 B's; bit 0 adds the x edge, bit 1
        /// the y edge, as (p + dx) + dy; the first of equal ones), still scaled by k²: each gap's components are
        /// multiplied by k (a power of two) before squaring, so where nothing underflows these are the unscaled values'
        /// bits times k², and where the unscaled squares would underflow the comparisons still tell them apart. The
        /// scalar form, on the vectors' components (<see cref="Corners2Core"/>); Corners2Vector on AVX2.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static double Corners2Scalar(Vector2D pa, Vector2D dx, Vector2D dy, Vector2D loB, Vector2D hiB,
            Vector2D pb, Vector2D ex, Vector2D ey, Vector2D loA, Vector2D hiA, double k, out int win) =>
            Corners2Core(pa.X, pa.Y, dx.X, dx.Y, dy.X, dy.Y, loB.X, loB.Y, hiB.X, hiB.Y, pb.X, pb.Y, ex.X, ex.Y, ey.X, ey.Y, loA.X, loA.Y, hiA.X, hiA.Y, k, out win);

        /// <summary>
        /// <see cref="Corners2Scalar"/> in plain doubles (the only form on netstandard2.1, Unity): the corners as
        /// Vector2D's additions form them ((p + dx) + dy), in the same order.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Corners2Core(double paX, double paY, double dxX, double dxY, double dyX, double dyY, double loBx, double loBy, double hiBx, double hiBy,
            double pbX, double pbY, double exX, double exY, double eyX, double eyY, double loAx, double loAy, double hiAx, double hiAy, double k, out int win)
        {
            double pa1X = paX + dxX, pa1Y = paY + dxY, pb1X = pbX + exX, pb1Y = pbY + exY;
            double best = Gap2(paX, paY, loBx, loBy, hiBx, hiBy, k);
            win = 0;
            Least(Gap2(pa1X, pa1Y, loBx, loBy, hiBx, hiBy, k), 1, ref best, ref win);
            Least(Gap2(paX + dyX, paY + dyY, loBx, loBy, hiBx, hiBy, k), 2, ref best, ref win);
            Least(Gap2(pa1X + dyX, pa1Y + dyY, loBx, loBy, hiBx, hiBy, k), 3, ref best, ref win);
            Least(Gap2(pbX, pbY, loAx, loAy, hiAx, hiAy, k), 4, ref best, ref win);
            Least(Gap2(pb1X, pb1Y, loAx, loAy, hiAx, hiAy, k), 5, ref best, ref win);
            Least(Gap2(pbX + eyX, pbY + eyY, loAx, loAy, hiAx, hiAy, k), 6, ref best, ref win);
            Least(Gap2(pb1X + eyX, pb1Y + eyY, loAx, loAy, hiAx, hiAy, k), 7, ref best, ref win);
            return best;
        }

        /// <summary>The squared length of (p − clamp(p))·k against the box [lo, hi] (box-local).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Gap2(double px, double py, double loX, double loY, double hiX, double hiY, double k)
        {
            double x = Outside(px, loX, hiX) * k, y = Outside(py, loY, hiY) * k;
            return x * x + y * y;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Least(double g, int which, ref double best, ref int win)
        {
            if (g < best) { best = g; win = which; }
        }
    }
}
