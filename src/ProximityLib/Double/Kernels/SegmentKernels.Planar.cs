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
            // In plain doubles, each step as Vector2D's operations would form it (the same bits): Mono keeps every
            // Vector2D temporary in memory, and these steps on Vector2D took 1.4 times as long there. d0, d1, w are
            // scaled by k in place below. Range.In(size2) and 1 / k are written where they are used, and two steps are
            // helpers: past 32 IL locals the JIT no longer inlines this method (that cost 1.2–1.3× on .NET).
            double d0x = a1.X - a0.X, d0y = a1.Y - a0.Y, d1x = b1.X - b0.X, d1y = b1.Y - b0.Y, wx = b0.X - a0.X, wy = b0.Y - a0.Y;
            double size2 = (d0x * d0x + d0y * d0y) + (d1x * d1x + d1y * d1y) + (wx * wx + wy * wy);
            double k = InverseSizeScale(size2);
            d0x *= k; d0y *= k; d1x *= k; d1y *= k; wx *= k; wy *= k;
            // The 3D kernel's n = d0 × d1 is (0, 0, n) here, |n|² = n², and its numerators (w × d1)·n and (w × d0)·n are
            // the scalar crosses times n.
            double n = d0x * d1y - d0y * d1x, nn = n * n;
            double sNum = (wx * d1y - wy * d1x) * n, tNum = (wx * d0y - wy * d0x) * n;
            double ak = d0x * d0x + d0y * d0y, ek = d1x * d1x + d1y * d1y;
            if (ak == 0 || ek == 0 || !(nn > 0 && nn >= 1e-4 * (ak * ek)))
            {
                var rare = SegmentSegmentRare(a0.To3(), a1.To3(), b0.To3(), b1.To3(), nn, sNum, tNum);
                s = rare.S; t = rare.T; inRange = rare.InRange;
                return rare.R2;
            }
            // Lines that cross inside both segments meet: the gap is exactly 0 (the 3D kernel's w·n is 0 here).
            if (sNum >= 0 && sNum <= nn && tNum >= 0 && tNum <= nn)
            {
                s = sNum / nn; t = tNum / nn;
                if (!(nn >= Shallow2 * (ak * ek)))
                {
                    // ShallowCrossing's parameters, inline (its gap is 0 here): a call with the lifted vectors cost
                    // 2D segment–segment 13–20% on mixed inputs, where one crossing in six is that shallow. The points
                    // are SegmentPoint2 from the origin, its 0 + kept (it turns a −0 to +0).
                    double pAx, pAy, pBx, pBy;
                    if (s <= 0.5) { pAx = 0 + d0x * s; pAy = 0 + d0y * s; } else { pAx = d0x - d0x * (1 - s); pAy = d0y - d0y * (1 - s); }
                    if (t <= 0.5) { pBx = 0 + d1x * t; pBy = 0 + d1y * t; } else { pBx = d1x - d1x * (1 - t); pBy = d1y - d1y * (1 - t); }
                    double tA = ((pAx - wx) * d1x + (pAy - wy) * d1y) / ek;
                    double sB = ((pBx + wx) * d0x + (pBy + wy) * d0y) / ak;
                    s = Num.Clamp((s + sB) * 0.5, 0, 1);
                    t = Num.Clamp((t + tA) * 0.5, 0, 1);
                }
                inRange = Range.In(size2);
                return 0;
            }
            double si = sNum / nn, ti = tNum / nn;
            double b = d0x * d1x + d0y * d1y, c = -(d0x * wx + d0y * wy), f = -(d1x * wx + d1y * wy);
            if (FirstFurtherOut(si, ti, a0.To3(), a1.To3(), b0.To3(), b1.To3())) ClampFirst(ak, ek, b, c, f, si, out s, out t);
            else ClampFirst(ek, ak, b, -f, -c, ti, out t, out s); // the mirror image: t first
            return UnscaledLength2(d0x * s - d1x * t - wx, d0y * s - d1y * t - wy, 1 / k, Range.In(size2), out inRange);
        }

        /// <summary>The 3D <see cref="UnscaledLength2(double, double, double, double, bool, out bool)"/> without z.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double UnscaledLength2(double x, double y, double ik, bool sized, out bool inRange)
        {
            double r2 = (x * x + y * y) * ik * ik;
            inRange = sized && (Range.In(r2) || (x == 0 && y == 0));
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

        /// <summary><see cref="SegmentPoint(Vector3D, Vector3D, double)"/> in the plane (the same operations per component, in plain doubles).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector2D SegmentPoint2(Vector2D a, Vector2D b, double t)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y;
            if (t <= 0.5) return new Vector2D(a.X + dx * t, a.Y + dy * t);
            double u = 1 - t;
            return new Vector2D(b.X - dx * u, b.Y - dy * u);
        }
    }
}
