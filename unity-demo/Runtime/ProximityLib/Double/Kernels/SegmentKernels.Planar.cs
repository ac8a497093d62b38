// Copied from src/ProximityLib/Double/Kernels/SegmentKernels.Planar.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // 2D segment–segment on 2D vectors. The 3D kernel's steps on lifted inputs (z = 0) with the terms that are zero left
    // out: the cross product's only component is the scalar n, and every other step keeps the 3D one's operations in
    // order, so the answers are the lifted kernel's bit for bit (a z term adds ±0 to a non-zero sum or to a zero whose
    // sign the results lose: parameters are normalised by + 0, residuals squared). Lifting cost 2–3x the hand-written
    // form: three 3D cross products and the z lanes of every vector. Nearly parallel and degenerate pairs still take the
    // 3D kernel's rare path, lifted, with the values it would have formed.
    internal static partial class Kernels
    {
        /// <summary>
        /// <see cref="SegmentSegmentInline"/> in the plane: the squared distance between segments [a0, a1] and [b0, b1]
        /// and the parameters (s, t) of a closest pair; crossing segments give exactly 0.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double SegmentSegment2Inline(Vector2D a0, Vector2D a1, Vector2D b0, Vector2D b1, out double s, out double t, out bool inRange)
        {
            var d0 = a1 - a0;
            var d1 = b1 - b0;
            var w = b0 - a0;
            double a = d0.LengthSquared, e = d1.LengthSquared, size2 = a + e + w.LengthSquared;
            double k = InverseSizeScale(size2);
            var d0k = d0 * k;
            var d1k = d1 * k;
            var wk = w * k;
            // The 3D kernel's n = d0 × d1 is (0, 0, n) here, |n|² = n², and its numerators (w × d1)·n and (w × d0)·n are
            // the scalar crosses times n.
            double n = Vector2D.Cross(d0k, d1k), nn = n * n;
            double sNum = Vector2D.Cross(wk, d1k) * n, tNum = Vector2D.Cross(wk, d0k) * n;
            double ak = d0k.LengthSquared, ek = d1k.LengthSquared;
            if (ak == 0 || ek == 0 || !(nn > 0 && nn >= 1e-4 * (ak * ek)))
            {
                var rare = SegmentSegmentRare(a0.To3(), a1.To3(), b0.To3(), b1.To3(), nn, sNum, tNum);
                s = rare.S; t = rare.T; inRange = rare.InRange;
                return rare.R2;
            }
            bool sized = Range.In(size2);
            // Lines that cross inside both segments meet: the gap is exactly 0 (the 3D kernel's w·n is 0 here).
            if (sNum >= 0 && sNum <= nn && tNum >= 0 && tNum <= nn)
            {
                s = sNum / nn; t = tNum / nn;
                if (!(nn >= Shallow2 * (ak * ek)))
                {
                    // ShallowCrossing's parameters, inline (its gap is 0 here): a call with the lifted vectors cost
                    // 2D segment–segment 13–20% on mixed inputs, where one crossing in six is that shallow.
                    var zero = default(Vector2D);
                    double tA = Vector2D.Dot(SegmentPoint2(zero, d0k, s) - wk, d1k) / ek;
                    double sB = Vector2D.Dot(SegmentPoint2(zero, d1k, t) + wk, d0k) / ak;
                    s = Num.Clamp((s + sB) * 0.5, 0, 1);
                    t = Num.Clamp((t + tA) * 0.5, 0, 1);
                }
                inRange = sized;
                return 0;
            }
            double si = sNum / nn, ti = tNum / nn;
            double b = Vector2D.Dot(d0k, d1k), c = -Vector2D.Dot(d0k, wk), f = -Vector2D.Dot(d1k, wk);
            double outS = Num.Max(-si, si - 1), outT = Num.Max(-ti, ti - 1);
            if (outS > outT || (outS == outT && !Order.Swap(a0.To3(), a1.To3(), b0.To3(), b1.To3()))) ClampFirst(ak, ek, b, c, f, si, out s, out t);
            else ClampFirst(ek, ak, b, -f, -c, ti, out t, out s); // the mirror image: t first
            var v = d0k * s - d1k * t - wk;
            double ik = 1 / k, r2 = v.LengthSquared * ik * ik;
            inRange = sized && (Range.In(r2) || v == default);
            return r2;
        }

        /// <summary>
        /// <see cref="SegmentSegmentCore"/> for segments in the z = 0 plane given as 3D points (the planar triangle
        /// kernels' edges): the planar kernel, the same values up to the sign of a zero parameter.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double SegmentSegmentFlat(Vector3D a0, Vector3D a1, Vector3D b0, Vector3D b1, out double s, out double t, out bool inRange) =>
            SegmentSegment2Inline(Vector2D.From3(a0), Vector2D.From3(a1), Vector2D.From3(b0), Vector2D.From3(b1), out s, out t, out inRange);

        /// <summary><see cref="SegmentSegment"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult2 SegmentSegment2(Vector2D a0, Vector2D a1, Vector2D b0, Vector2D b1, out bool inRange)
        {
            double r2 = SegmentSegment2Inline(a0, a1, b0, b1, out double s, out double t, out inRange);
            s += 0; t += 0; // −0 + 0 = 0: the two argument orders may reach a zero parameter with either sign
            return new DistanceResult2(Math.Sqrt(r2), r2, SegmentPoint2(a0, a1, s), SegmentPoint2(b0, b1, t), s, t);
        }

        /// <summary><see cref="SegmentSegmentDistance"/> in the plane: the distance, or NaN where inRange is false.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double SegmentSegment2Distance(Vector2D a0, Vector2D a1, Vector2D b0, Vector2D b1)
        {
            double r2 = SegmentSegment2Inline(a0, a1, b0, b1, out _, out _, out bool inRange);
            return inRange ? Math.Sqrt(r2) : double.NaN;
        }

        /// <summary><see cref="SegmentPoint(Vector3D, Vector3D, double)"/> in the plane (the same operations per component).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D SegmentPoint2(Vector2D a, Vector2D b, double t) =>
            t <= 0.5 ? a + (b - a) * t : b - (b - a) * (1 - t);
    }
}
