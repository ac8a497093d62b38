// Copied from src/ProximityLib/Double/Kernels/BoxKernels.Vector.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
#if NET
using System.Runtime.CompilerServices;
using System.Runtime.Intrinsics;
using System.Runtime.Intrinsics.X86;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        // Permute4x64 controls: lane j of Permute4x64(v, Next) is v[j + 1 mod 3], with Prev v[j − 1 mod 3]; lane 3 stays.
        private const byte Next = 0b11_00_10_01, Prev = 0b11_01_00_10;

        /// <summary>
        /// The 3D test of <see cref="BoxBoxOverlapsScalar"/> with each group of three axes (A's faces, B's faces, and
        /// a_i × b_j for the three j of each i) in one Vector256 whose lane 3 is 0 and never separates. The scalar form
        /// keeps 27 values live and spills most of them with 16 registers; here the whole test fits. Every axis uses the
        /// same products and the same sums as the scalar form (only the two minor terms of an edge axis may be added
        /// in the other order), so the verdicts agree up to one rounding in the last additions.
        /// </summary>
        internal static bool BoxBoxOverlapsVector(in Box a, in Box b)
        {
            // Each Vector3D field of a Box is three consecutive doubles; lane 3 (the next field) is masked off. The
            // copies give refs to load from (C# 9 cannot take a ref of an in parameter); they are a few vector moves.
            Box boxA = a, boxB = b;
            ref double pa = ref Unsafe.As<Box, double>(ref boxA);
            ref double pb = ref Unsafe.As<Box, double>(ref boxB);
            var xyz = Vector256.Create(-1L, -1L, -1L, 0).AsDouble();
            Vector256<double> oa = Vector256.LoadUnsafe(ref pa, 0) & xyz, ax0 = Vector256.LoadUnsafe(ref pa, 3) & xyz,
                ay0 = Vector256.LoadUnsafe(ref pa, 6) & xyz, az0 = Vector256.LoadUnsafe(ref pa, 9) & xyz,
                loA = Vector256.LoadUnsafe(ref pa, 12) & xyz, hiA = Vector256.LoadUnsafe(ref pa, 15) & xyz;
            Vector256<double> ob = Vector256.LoadUnsafe(ref pb, 0) & xyz, bx0 = Vector256.LoadUnsafe(ref pb, 3) & xyz,
                by0 = Vector256.LoadUnsafe(ref pb, 6) & xyz, bz0 = Vector256.LoadUnsafe(ref pb, 9) & xyz,
                loB = Vector256.LoadUnsafe(ref pb, 12) & xyz, hiB = Vector256.LoadUnsafe(ref pb, 15) & xyz;
            var ha = (hiA - loA) * 0.5;
            var hb = (hiB - loB) * 0.5;
            var ca = (loA + hiA) * 0.5;
            var cb = (loB + hiB) * 0.5;
            // tw = (Ob − Oa) + B.ToWorldOffset(cb) − A.ToWorldOffset(ca), the scalar form's sums in its order.
            var tw = (ob - oa) + (bx0 * Lane(cb, 0) + by0 * Lane(cb, 1) + bz0 * Lane(cb, 2)) - (ax0 * Lane(ca, 0) + ay0 * Lane(ca, 1) + az0 * Lane(ca, 2));

            // Columns: lane i of ax is a_i.X (A's axes are the rows ax0, ay0, az0); likewise for B.
            Transpose(ax0, ay0, az0, out var ax, out var ay, out var az);
            Transpose(bx0, by0, bz0, out var bx, out var by, out var bz);
            // Rows of R (lane j of r_i is a_i · b_j), its columns (lane i of c_j is a_i · b_j), and T in A's frame.
            var r0 = bx * Lane(ax0, 0) + by * Lane(ax0, 1) + bz * Lane(ax0, 2);
            var r1 = bx * Lane(ay0, 0) + by * Lane(ay0, 1) + bz * Lane(ay0, 2);
            var r2 = bx * Lane(az0, 0) + by * Lane(az0, 1) + bz * Lane(az0, 2);
            var c0 = ax * Lane(bx0, 0) + ay * Lane(bx0, 1) + az * Lane(bx0, 2);
            var c1 = ax * Lane(by0, 0) + ay * Lane(by0, 1) + az * Lane(by0, 2);
            var c2 = ax * Lane(bz0, 0) + ay * Lane(bz0, 1) + az * Lane(bz0, 2);
            var t = ax * Lane(tw, 0) + ay * Lane(tw, 1) + az * Lane(tw, 2);
            Vector256<double> tx = Lane(t, 0), ty = Lane(t, 1), tz = Lane(t, 2);
            Vector256<double> hax = Lane(ha, 0), hay = Lane(ha, 1), haz = Lane(ha, 2);

            var faceA = Vector256.GreaterThan(Vector256.Abs(t),
                ha + Vector256.Abs(c0) * Lane(hb, 0) + Vector256.Abs(c1) * Lane(hb, 1) + Vector256.Abs(c2) * Lane(hb, 2));
            var faceB = Vector256.GreaterThan(Vector256.Abs(r0 * tx + r1 * ty + r2 * tz),
                Vector256.Abs(r0) * hax + Vector256.Abs(r1) * hay + Vector256.Abs(r2) * haz + hb);
            if ((faceA | faceB).ExtractMostSignificantBits() != 0) return false;

            var hbNext = Avx2.Permute4x64(hb, Next);
            var hbPrev = Avx2.Permute4x64(hb, Prev);
            var edges = EdgeAxesSeparate(ty, tz, hay, haz, r1, r2, hbNext, hbPrev)   // e_x × b_j
                | EdgeAxesSeparate(tz, tx, haz, hax, r2, r0, hbNext, hbPrev)         // e_y × b_j
                | EdgeAxesSeparate(tx, ty, hax, hay, r0, r1, hbNext, hbPrev);        // e_z × b_j
            return edges.ExtractMostSignificantBits() == 0;
        }

        /// <summary>Lane i of v in every lane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
#pragma warning disable CA1857 // always inlined with a literal i, so the control byte is a constant
        private static Vector256<double> Lane(Vector256<double> v, byte i) => Avx2.Permute4x64(v, (byte)(i * 0b01010101));
#pragma warning restore CA1857

        /// <summary>The 3×3 transpose of rows u, v, w (lane 3 of each is 0 and stays 0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Transpose(Vector256<double> u, Vector256<double> v, Vector256<double> w,
            out Vector256<double> c0, out Vector256<double> c1, out Vector256<double> c2)
        {
            var lo = Avx.UnpackLow(u, v);                      // u0 v0 u2 v2
            var hi = Avx.UnpackHigh(u, v);                     // u1 v1 u3 v3
            var wlo = Avx.UnpackLow(w, Vector256<double>.Zero);  // w0 0 w2 0
            var whi = Avx.UnpackHigh(w, Vector256<double>.Zero); // w1 0 w3 0
            c0 = Avx.Permute2x128(lo, wlo, 0x20);
            c1 = Avx.Permute2x128(hi, whi, 0x20);
            c2 = Avx.Permute2x128(lo, wlo, 0x31);
        }

        /// <summary>
        /// The axes e_i × b_j (j in the lanes) for the A axis i whose two other axes are p and q (cyclic): in A's frame
        /// L = (…, −r_qj, r_pj), so T·L = t_q r_pj − t_p r_qj, A's radius h_p|r_qj| + h_q|r_pj|, and B's radius uses
        /// the 2×2 minors b_k · L of rows p, q (not the orthonormality shortcut), as in the scalar form.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> EdgeAxesSeparate(Vector256<double> tp, Vector256<double> tq, Vector256<double> hp, Vector256<double> hq,
            Vector256<double> rp, Vector256<double> rq, Vector256<double> hbNext, Vector256<double> hbPrev)
        {
            var tl = rp * tq - rq * tp;
            var ra = Vector256.Abs(rq) * hp + Vector256.Abs(rp) * hq;
            // Lane j: the minor of columns j and j + 1; the minor of j and j − 1 is lane j − 1 of it, negated.
            var next = Vector256.Abs(Avx2.Permute4x64(rp, Next) * rq - Avx2.Permute4x64(rq, Next) * rp);
            var prev = Avx2.Permute4x64(next, Prev);
            return Vector256.GreaterThan(Vector256.Abs(tl), ra + hbNext * next + hbPrev * prev);
        }
    }
}
#endif
