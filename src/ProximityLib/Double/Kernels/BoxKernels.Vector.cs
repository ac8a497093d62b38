#if NET
using System;
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

        /// <summary>
        /// <see cref="Penetration"/> on AVX2 lanes: A's and B's face normals in one group (A's and B's z in a second), and
        /// a_i × b_j for the three j of each i in one group each (lane 3 is u × ±u = 0 exactly, so not an axis). Every
        /// lane makes the operations of <see cref="TryAxis"/> on its axis, and the winner is the first least overlap in
        /// the scalar form's order (each axis's "down" before its "up"), so both forms return the same bits.
        /// </summary>
        internal static double PenetrationVector(in Box a, in Box b, Vector3D t, out Vector3D push)
        {
            Vector3D ax = a.X, ay = a.Y, az = a.Z, bx = b.X, by = b.Y, bz = b.Z, ha = a.Half, hb = b.Half;
            var h = new AxisLanes(ax, ay, az, bx, by, bz, ha, hb, t);
            h.Overlaps(Vector256.Create(ax.X, ay.X, bx.X, by.X), Vector256.Create(ax.Y, ay.Y, bx.Y, by.Y), Vector256.Create(ax.Z, ay.Z, bx.Z, by.Z),
                out var down0, out var up0);
            var inf = Vector256.Create(double.PositiveInfinity);
            Vector256<double> down1 = inf, up1 = inf, down2 = inf, up2 = inf, down3 = inf, up3 = inf, down4 = inf, up4 = inf;
            bool planar = a.Planar || b.Planar;
            if (!planar)
            {
                h.Overlaps(Vector256.Create(az.X, bz.X, 0, 0), Vector256.Create(az.Y, bz.Y, 0, 0), Vector256.Create(az.Z, bz.Z, 0, 0), out down1, out up1);
                // B's axes as columns: lane j holds b_j.
                Vector256<double> cx = Vector256.Create(bx.X, by.X, bz.X, 0), cy = Vector256.Create(bx.Y, by.Y, bz.Y, 0), cz = Vector256.Create(bx.Z, by.Z, bz.Z, 0);
                h.CrossOverlaps(ax, cx, cy, cz, out down2, out up2);
                h.CrossOverlaps(ay, cx, cy, cz, out down3, out up3);
                h.CrossOverlaps(az, cx, cy, cz, out down4, out up4);
            }
            var m = Vector256.Min(Vector256.Min(Vector256.Min(down0, up0), Vector256.Min(down1, up1)),
                Vector256.Min(Vector256.Min(Vector256.Min(down2, up2), Vector256.Min(down3, up3)), Vector256.Min(down4, up4)));
            m = Vector256.Min(m, Avx.Permute(m, 0b0101));
            m = Vector256.Min(m, Avx.Permute2x128(m, m, 1));
            double best = m.ToScalar();
            push = default;
            // The first axis (in the scalar order) holding the least value, down before up.
            int group = 0;
            uint dm = 0, um = 0;
            for (; group < 5; group++)
            {
                var (dv, uv) = group switch { 0 => (down0, up0), 1 => (down1, up1), 2 => (down2, up2), 3 => (down3, up3), _ => (down4, up4) };
                dm = Vector256.Equals(dv, m).ExtractMostSignificantBits();
                um = Vector256.Equals(uv, m).ExtractMostSignificantBits();
                if ((dm | um) != 0) break;
            }
            if (group == 5) return best; // no axis (every candidate degenerate)
            int lane = System.Numerics.BitOperations.TrailingZeroCount(dm | um);
            Vector3D v = group switch
            {
                0 => lane == 0 ? ax : lane == 1 ? ay : lane == 2 ? bx : by,
                1 => lane == 0 ? az : bz,
                _ => EdgeCross(group == 2 ? ax : group == 3 ? ay : az, lane == 0 ? bx : lane == 1 ? by : bz),
            };
            // The winner's own value (the minimum may carry the other sign of a zero).
            bool down = ((dm >> lane) & 1) != 0;
            var (dw, uw) = group switch { 0 => (down0, up0), 1 => (down1, up1), 2 => (down2, up2), 3 => (down3, up3), _ => (down4, up4) };
            best = (down ? dw : uw).GetElement(lane);
            double len = Math.Sqrt(v.LengthSquared);
            push = v * (down ? -best / len : best / len);
            return best;
        }

        /// <summary>The constants of <see cref="TryAxis"/>, broadcast, and its operations on four axes at once.</summary>
        private readonly struct AxisLanes
        {
            private readonly Vector256<double> _axx, _axy, _axz, _ayx, _ayy, _ayz, _azx, _azy, _azz;
            private readonly Vector256<double> _bxx, _bxy, _bxz, _byx, _byy, _byz, _bzx, _bzy, _bzz;
            private readonly Vector256<double> _hax, _hay, _haz, _hbx, _hby, _hbz, _tx, _ty, _tz;

            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public AxisLanes(Vector3D ax, Vector3D ay, Vector3D az, Vector3D bx, Vector3D by, Vector3D bz, Vector3D ha, Vector3D hb, Vector3D t)
            {
                _axx = Vector256.Create(ax.X); _axy = Vector256.Create(ax.Y); _axz = Vector256.Create(ax.Z);
                _ayx = Vector256.Create(ay.X); _ayy = Vector256.Create(ay.Y); _ayz = Vector256.Create(ay.Z);
                _azx = Vector256.Create(az.X); _azy = Vector256.Create(az.Y); _azz = Vector256.Create(az.Z);
                _bxx = Vector256.Create(bx.X); _bxy = Vector256.Create(bx.Y); _bxz = Vector256.Create(bx.Z);
                _byx = Vector256.Create(by.X); _byy = Vector256.Create(by.Y); _byz = Vector256.Create(by.Z);
                _bzx = Vector256.Create(bz.X); _bzy = Vector256.Create(bz.Y); _bzz = Vector256.Create(bz.Z);
                _hax = Vector256.Create(ha.X); _hay = Vector256.Create(ha.Y); _haz = Vector256.Create(ha.Z);
                _hbx = Vector256.Create(hb.X); _hby = Vector256.Create(hb.Y); _hbz = Vector256.Create(hb.Z);
                _tx = Vector256.Create(t.X); _ty = Vector256.Create(t.Y); _tz = Vector256.Create(t.Z);
            }

            /// <summary>Per lane, <see cref="TryAxis"/>'s down and up for the axis (x, y, z); +∞ where it is no axis.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public void Overlaps(Vector256<double> x, Vector256<double> y, Vector256<double> z, out Vector256<double> down, out Vector256<double> up)
            {
                var len2 = x * x + y * y + z * z;
                var len = Vector256.Sqrt(len2);
                var ra = _hax * Vector256.Abs(_axx * x + _axy * y + _axz * z) + _hay * Vector256.Abs(_ayx * x + _ayy * y + _ayz * z)
                    + _haz * Vector256.Abs(_azx * x + _azy * y + _azz * z);
                var rb = _hbx * Vector256.Abs(_bxx * x + _bxy * y + _bxz * z) + _hby * Vector256.Abs(_byx * x + _byy * y + _byz * z)
                    + _hbz * Vector256.Abs(_bzx * x + _bzy * y + _bzz * z);
                var sep = _tx * x + _ty * y + _tz * z;
                var axis = Vector256.GreaterThan(len2, Vector256<double>.Zero);
                var inf = Vector256.Create(double.PositiveInfinity);
                down = Vector256.ConditionalSelect(axis, (ra + rb - sep) / len, inf);
                up = Vector256.ConditionalSelect(axis, (ra + rb + sep) / len, inf);
            }

            /// <summary><see cref="Overlaps"/> on <see cref="EdgeCross"/>(u, c_j) for the columns c_j in the lanes.</summary>
            [MethodImpl(MethodImplOptions.AggressiveInlining)]
            public void CrossOverlaps(Vector3D u, Vector256<double> cx, Vector256<double> cy, Vector256<double> cz, out Vector256<double> down, out Vector256<double> up)
            {
                Vector256<double> ux = Vector256.Create(u.X), uy = Vector256.Create(u.Y), uz = Vector256.Create(u.Z);
                var same = Vector256.GreaterThanOrEqual(ux * cx + uy * cy + uz * cz, Vector256<double>.Zero);
                var wx = Vector256.ConditionalSelect(same, cx - ux, cx + ux);
                var wy = Vector256.ConditionalSelect(same, cy - uy, cy + uy);
                var wz = Vector256.ConditionalSelect(same, cz - uz, cz + uz);
                Overlaps(uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx, out down, out up);
            }
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
