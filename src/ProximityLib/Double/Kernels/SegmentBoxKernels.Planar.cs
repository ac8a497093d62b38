using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // 2D segment–box on 2D vectors and the planar Box2. The 3D kernel's steps on a lifted planar box (z = 0, Lo.Z = Hi.Z
    // = 0) with the z terms left out: they only add exact zeros (an unmoving axis has no breakpoint, no gap, no
    // stationary term, no separating or push-out direction), so the answers are the lifted kernel's bit for bit, up to the
    // sign of a zero coordinate. Lifting cost the 150-byte Box with its third axis and the z lanes of every step.
    internal static partial class Kernels
    {
        /// <summary><see cref="SegmentInFrame"/> in the plane: segment [a, b] against a solid planar box, in the box frame.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 SegmentBox2(Vector2D a, Vector2D b, in Box2 box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Range.MaxAbs(ra, b - box.Origin, box.Hi - box.Lo));
            double dist = InFrame2(box.ToLocal(ra), box.ToLocal(b - a), box.Lo, box.Hi, ref inRange, out double d2, out double t, out var onBox, out bool touching);
            var onSegment = SegmentPoint2(a, b, t);
            return new DistanceResult2(dist, d2, onSegment, touching ? onSegment : box.Origin + box.ToWorldOffset(onBox), t, 0);
        }

        /// <summary><see cref="SegmentAabb"/> in the plane: the box's frame is the world's shifted to min.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 SegmentAabb2(Vector2D a, Vector2D b, Vector2D min, Vector2D max, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            double dist = InFrame2(ra, b - a, default, extent, ref inRange, out double d2, out double t, out var onBox, out bool touching);
            var onSegment = SegmentPoint2(a, b, t);
            return new DistanceResult2(dist, d2, onSegment, touching ? onSegment : min + onBox, t, 0);
        }

        /// <summary>The Distance of <see cref="SegmentBox2"/>, bit for bit, without the witnesses.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double SegmentBoxDistance2(Vector2D a, Vector2D b, in Box2 box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Range.MaxAbs(ra, b - box.Origin, box.Hi - box.Lo));
            return InFrameDistance2(box.ToLocal(ra), box.ToLocal(b - a), box.Lo, box.Hi, ref inRange);
        }

        /// <summary>The Distance of <see cref="SegmentAabb2"/>, bit for bit, without the witnesses.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double SegmentAabbDistance2(Vector2D a, Vector2D b, Vector2D min, Vector2D max, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            return InFrameDistance2(ra, b - a, default, extent, ref inRange);
        }

        /// <summary><see cref="SegmentBoxOverlaps(Vector3D, Vector3D, in Box, out bool)"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentBoxOverlaps2(Vector2D a, Vector2D b, in Box2 box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Range.MaxAbs(ra, b - box.Origin, box.Hi - box.Lo));
            return SegmentBoxOverlapsLocal2(box.ToLocal(ra) - box.LocalCenter, box.ToLocal(b - a), box.Half);
        }

        /// <summary><see cref="SegmentAabbOverlaps"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentAabbOverlaps2(Vector2D a, Vector2D b, Vector2D min, Vector2D max, out bool inRange)
        {
            var ra = a - min;
            var extent = max - min;
            inRange = Range.Box(Range.MaxAbs(ra, b - min, extent));
            var half = extent * 0.5;
            return SegmentBoxOverlapsLocal2(ra - half, b - a, half);
        }

        /// <summary><see cref="InFrame"/> in the plane (the separating-axis verdict, then the apart minimum or the push).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double InFrame2(Vector2D la, Vector2D ld, Vector2D lo, Vector2D hi, ref bool inRange,
            out double d2, out double t, out Vector2D onBox, out bool touching)
        {
            var c = (lo + hi) * 0.5;
            var h = (hi - lo) * 0.5;
            if (!SegmentBoxOverlapsLocal2(la - c, ld, h))
            {
                d2 = SegmentBoxLocal2(la, ld, lo, hi, out t);
                inRange &= Range.In(d2);
                onBox = ClampLocal2(la + ld * t, lo, hi);
                touching = false;
                return Math.Sqrt(d2);
            }

            double depth = Num.Max(SegmentBoxPenetration2(la - c, ld, h, out var dir), 0);
            var moved = la + dir * depth;
            t = depth > 0 ? TouchingParameter2(la - c, ld, h, dir) : double.NaN;
            if (double.IsNaN(t)) SegmentBoxLocal2(moved, ld, lo, hi, out t);
            d2 = 0;
            onBox = ClampLocal2(moved + ld * t, lo, hi);
            touching = !(depth > 0);
            return -depth;
        }

        /// <summary><see cref="InFrameDistance"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double InFrameDistance2(Vector2D la, Vector2D ld, Vector2D lo, Vector2D hi, ref bool inRange)
        {
            var c = (lo + hi) * 0.5;
            var h = (hi - lo) * 0.5;
            if (!SegmentBoxOverlapsLocal2(la - c, ld, h))
            {
                double d2 = SegmentBoxLocal2(la, ld, lo, hi, out _);
                inRange &= Range.In(d2);
                return Math.Sqrt(d2);
            }
            return -Num.Max(SegmentBoxPenetration2(la - c, ld, h, out _), 0);
        }

        /// <summary><see cref="SegmentBoxLocal"/> in the plane: the bracketing of the convex piecewise quadratic by its slopes.</summary>
        private static double SegmentBoxLocal2(Vector2D a, Vector2D d, Vector2D lo, Vector2D hi, out double t)
        {
            double kd = Num.InversePowerOfTwo(Range.MaxAbs(d));
            var dk = d * kd;
            double left = 0, right = 1;
            if (SlabSlope2(a, d, dk, lo, hi, 0) >= 0) right = 0;
            else if (SlabSlope2(a, d, dk, lo, hi, 1) <= 0) left = 1;
            else
            {
                Narrow2(a, d, dk, lo, hi, (lo.X - a.X) / d.X, ref left, ref right);
                Narrow2(a, d, dk, lo, hi, (hi.X - a.X) / d.X, ref left, ref right);
                Narrow2(a, d, dk, lo, hi, (lo.Y - a.Y) / d.Y, ref left, ref right);
                Narrow2(a, d, dk, lo, hi, (hi.Y - a.Y) / d.Y, ref left, ref right);
            }
            if (left < right)
            {
                double tm = 0.5 * (left + right), num = 0, den = 0;
                Accumulate(a.X, d.X, dk.X, lo.X, hi.X, tm, ref num, ref den);
                Accumulate(a.Y, d.Y, dk.Y, lo.Y, hi.Y, tm, ref num, ref den);
                t = den > 0 ? Num.Clamp(num / den * kd, left, right) : left;
            }
            else t = left;
            return Gap(a.X, d.X, lo.X, hi.X, t) + Gap(a.Y, d.Y, lo.Y, hi.Y, t);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double SlabSlope2(Vector2D a, Vector2D d, Vector2D dk, Vector2D lo, Vector2D hi, double t) =>
            dk.X * Outside(a.X + t * d.X, lo.X, hi.X) + dk.Y * Outside(a.Y + t * d.Y, lo.Y, hi.Y);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Narrow2(Vector2D a, Vector2D d, Vector2D dk, Vector2D lo, Vector2D hi, double b, ref double left, ref double right)
        {
            if (!(b > left && b < right)) return;
            double s = SlabSlope2(a, d, dk, lo, hi, b);
            if (s <= 0) left = b;
            if (s >= 0) right = b;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector2D ClampLocal2(Vector2D e, Vector2D lo, Vector2D hi) =>
            new Vector2D(Num.Clamp(e.X, lo.X, hi.X), Num.Clamp(e.Y, lo.Y, hi.Y));

        /// <summary><see cref="SegmentBoxPenetration"/> in the plane: the two box normals and the segment's normal.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double SegmentBoxPenetration2(Vector2D m, Vector2D d, Vector2D h, out Vector2D dir)
        {
            double best = double.PositiveInfinity;
            dir = default;
            TryFaceAxis2(m.X, d.X, h.X, new Vector2D(1, 0), ref best, ref dir);
            TryFaceAxis2(m.Y, d.Y, h.Y, new Vector2D(0, 1), ref best, ref dir);
            TryNormalAxis2(m, d, h, ref best, ref dir);
            return best;
        }

        /// <summary>
        /// <see cref="TryCrossAxis"/> in the plane: the normal (d.Y, −d.X) of the segment or line m + t·d, along which it
        /// projects to one value p and the box of half-extents h to [−r, r]; the shorter push competes.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryNormalAxis2(Vector2D m, Vector2D d, Vector2D h, ref double best, ref Vector2D dir)
        {
            var axis = new Vector2D(d.Y, -d.X);
            double len2 = axis.LengthSquared;
            if (!(len2 > 0) || double.IsInfinity(len2)) return;
            double p = m.X * d.Y - m.Y * d.X, r = h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X);
            double len = Math.Sqrt(len2);
            double push = (r - Math.Abs(p)) / len;
            if (push < best) { best = push; dir = axis * ((p > 0 ? 1 : -1) / len); }
        }

        /// <summary><see cref="TouchingParameter"/> in the plane: a face, or the corner the push along the segment's normal points to.</summary>
        private static double TouchingParameter2(Vector2D m, Vector2D d, Vector2D h, Vector2D dir)
        {
            if (dir.Y == 0) return FaceTouch(m.X, d.X, dir.X, m.Y, d.Y, h.Y, 0, 0, 0);
            if (dir.X == 0) return FaceTouch(m.Y, d.Y, dir.Y, m.X, d.X, h.X, 0, 0, 0);
            return EdgeTouch(m.X, d.X, dir.X, h.X, m.Y, d.Y, dir.Y, h.Y, 0, 0, 0);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryFaceAxis2(double m, double d, double h, Vector2D n, ref double best, ref Vector2D dir)
        {
            double e = m + d;
            double down = Num.Max(m, e) + h;
            double up = h - Num.Min(m, e);
            bool upward = up < down;
            double push = upward ? up : down;
            if (push < best) { best = push; dir = upward ? n : -n; }
        }

        /// <summary><see cref="SegmentBoxOverlapsLocal"/> in the plane: the two slabs and the segment's normal.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool SegmentBoxOverlapsLocal2(Vector2D m, Vector2D d, Vector2D h) =>
            !(SlabSeparates(m.X, d.X, h.X) || SlabSeparates(m.Y, d.Y, h.Y))
            && !(Math.Abs(m.X * d.Y - m.Y * d.X) > h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X));
    }
}
