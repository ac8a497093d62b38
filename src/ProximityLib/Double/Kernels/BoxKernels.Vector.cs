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
        internal static bool BoxBoxOverlapsVector(in Box a, in Box b) =>
            OverlapsVector(V(a.Origin), V(a.X), V(a.Y), V(a.Z), V(a.Lo), V(a.Hi), V(b.Origin), V(b.X), V(b.Y), V(b.Z), V(b.Lo), V(b.Hi));

        /// <summary>
        /// <see cref="BoxBoxOverlapsVector(in Box, in Box)"/> on OBBs, and whether their magnitudes allow the fast path,
        /// with each vector made from the shapes' fields: a caller building two <see cref="Box"/> forms to pass spent
        /// more than the test (zeroing and copying 150-byte structs). Bit 0: they overlap; bit 1: in range (no out
        /// parameter, which would pin the caller's local in memory).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static unsafe int ObbObbOverlapsVector(in Obb3 a, in Obb3 b)
        {
            // Pinned once each (C# 9 cannot pass the readonly references to the Unsafe and span helpers, whose
            // parameters are now ref readonly), then loaded in place.
            fixed (Obb3* pa = &a)
            fixed (Obb3* pb = &b)
            {
                Vector256<double> ha = LoadLast(&pa->HalfExtents.X), hb = LoadLast(&pb->HalfExtents.X), tw = Load(&pb->Center.X) - Load(&pa->Center.X);
                int inRange = Range.Box(BoxSize(tw, ha + ha, hb + hb)) ? 2 : 0;
                Axes(pa, out var ax, out var ay, out var az);
                Axes(pb, out var bx, out var by, out var bz);
                return inRange | (OverlapsCentered(tw, ax, ay, az, ha, bx, by, bz, hb) ? 1 : 0);
            }
        }

        /// <summary><see cref="ObbObbOverlapsVector"/> for an AABB (origin Min, [0, Max − Min]) against an OBB.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static unsafe int AabbObbOverlapsVector(in Aabb3 a, in Obb3 b)
        {
            fixed (Aabb3* pa = &a)
            fixed (Obb3* pb = &b)
            {
                Vector256<double> oa = Load(&pa->Min.X), hiA = LoadLast(&pa->Max.X) - oa, hb = LoadLast(&pb->HalfExtents.X), ob = Load(&pb->Center.X);
                int inRange = Range.Box(BoxSize(ob - oa, hiA, hb + hb)) ? 2 : 0;
                Axes(pb, out var bx, out var by, out var bz);
                return inRange | (OverlapsVector(oa, Vector256.Create(1.0, 0, 0, 0), Vector256.Create(0, 1.0, 0, 0), Vector256.Create(0, 0, 1.0, 0), Vector256<double>.Zero, hiA,
                    ob, bx, by, bz, -hb, hb) ? 1 : 0);
            }
        }

        /// <summary>
        /// The three doubles at p in lanes 0–2 and 0 in lane 3: one load of four doubles and a blend, where
        /// <see cref="Vector256.Create(double, double, double, double)"/> of a Vector3D takes seven instructions. The
        /// fourth double must belong to the same struct (a following field or padding): loaded, then dropped.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static unsafe Vector256<double> Load(double* p) => Avx.Blend(Avx.LoadVector256(p), Vector256<double>.Zero, 0b1000);

        /// <summary><see cref="Load"/> for a struct's last field: the load starts one double before p (the field before it) and the lanes move down.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static unsafe Vector256<double> LoadLast(double* p) =>
            Avx.Blend(Avx2.Permute4x64(Avx.LoadVector256(p - 1), 0b11_11_10_01), Vector256<double>.Zero, 0b1000);

        /// <summary>The OBB's axes as vectors: loaded in place, or the world's for default(Obb3), which stores none.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static unsafe void Axes(Obb3* box, out Vector256<double> x, out Vector256<double> y, out Vector256<double> z)
        {
            if (box->HasStoredAxes)
            {
                double* p = Obb3.StoredAxes(box);
                x = Load(p); y = Load(p + 3); z = Load(p + 6);
            }
            else { x = Vector256.Create(1.0, 0, 0, 0); y = Vector256.Create(0, 1.0, 0, 0); z = Vector256.Create(0, 0, 1.0, 0); }
        }

        /// <summary>The size of <see cref="Front"/> on lanes 0–2: the largest magnitude of the three.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double BoxSize(Vector256<double> d, Vector256<double> ea, Vector256<double> eb)
        {
            // The hardware's max (Vector256.Max spends eight more instructions on NaN and zero-sign rules): the lanes are
            // magnitudes, never NaN (finite shapes; an overflowed difference is +∞, which maxpd orders).
            var m = Vector256.MaxNative(Vector256.Abs(d), Vector256.MaxNative(Vector256.Abs(ea), Vector256.Abs(eb)));
            m = Vector256.MaxNative(m, Avx.Permute(m, 0b0101));
            return Num.Max(m.ToScalar(), m.GetElement(2));
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapsVector(Vector256<double> oa, Vector256<double> ax0, Vector256<double> ay0, Vector256<double> az0,
            Vector256<double> loA, Vector256<double> hiA, Vector256<double> ob, Vector256<double> bx0, Vector256<double> by0,
            Vector256<double> bz0, Vector256<double> loB, Vector256<double> hiB)
        {
            var ca = (loA + hiA) * 0.5;
            var cb = (loB + hiB) * 0.5;
            // tw = (Ob − Oa) + B.ToWorldOffset(cb) − A.ToWorldOffset(ca), the scalar form's sums in its order.
            var tw = (ob - oa) + (bx0 * Lane(cb, 0) + by0 * Lane(cb, 1) + bz0 * Lane(cb, 2)) - (ax0 * Lane(ca, 0) + ay0 * Lane(ca, 1) + az0 * Lane(ca, 2));
            return OverlapsCentered(tw, ax0, ay0, az0, (hiA - loA) * 0.5, bx0, by0, bz0, (hiB - loB) * 0.5);
        }

        /// <summary>
        /// The test on boxes centred on their origins, tw = B's centre − A's centre in world axes. Two OBBs need nothing
        /// more: their <see cref="Box"/> forms have centre 0, where the general form's offsets add only zeros (up to the
        /// sign of a zero, which no verdict sees) and (h − (−h)) · 0.5 is h exactly.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool OverlapsCentered(Vector256<double> tw, Vector256<double> ax0, Vector256<double> ay0, Vector256<double> az0,
            Vector256<double> ha, Vector256<double> bx0, Vector256<double> by0, Vector256<double> bz0, Vector256<double> hb)
        {
            FrameOfA(tw, ax0, ay0, az0, bx0, by0, bz0, out var r0, out var r1, out var r2, out var c0, out var c1, out var c2, out var t);
            Vector256<double> tx = Lane(t, 0), ty = Lane(t, 1), tz = Lane(t, 2);
            Vector256<double> hax = Lane(ha, 0), hay = Lane(ha, 1), haz = Lane(ha, 2);

            var faceA = Vector256.GreaterThan(Vector256.Abs(t), FaceARadii(ha, hb, c0, c1, c2));
            var faceB = Vector256.GreaterThan(FaceBSeparation(t, r0, r1, r2), FaceBRadii(ha, hb, r0, r1, r2));
            if ((faceA | faceB).ExtractMostSignificantBits() != 0) return false;

            var hbNext = Avx2.Permute4x64(hb, Next);
            var hbPrev = Avx2.Permute4x64(hb, Prev);
            var edges = Vector256.GreaterThan(EdgeSeparation(ty, tz, r1, r2), EdgeRadii(hay, haz, r1, r2, hbNext, hbPrev))   // e_x × b_j
                | Vector256.GreaterThan(EdgeSeparation(tz, tx, r2, r0), EdgeRadii(haz, hax, r2, r0, hbNext, hbPrev))         // e_y × b_j
                | Vector256.GreaterThan(EdgeSeparation(tx, ty, r0, r1), EdgeRadii(hax, hay, r0, r1, hbNext, hbPrev));        // e_z × b_j
            return edges.ExtractMostSignificantBits() == 0;
        }

        /// <summary>
        /// The separating-axis values in A's frame, from the boxes' axes as rows (lane 3 of each 0): the rows r_i of R (lane j
        /// is a_i · b_j), its columns c_j (lane i is a_i · b_j: the transpose, the same bits as forming each dot product
        /// again) and T = tw in A's frame (lane i is a_i · tw), each lane the scalar form's Vector3D.Dot.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void FrameOfA(Vector256<double> tw, Vector256<double> ax0, Vector256<double> ay0, Vector256<double> az0,
            Vector256<double> bx0, Vector256<double> by0, Vector256<double> bz0, out Vector256<double> r0, out Vector256<double> r1,
            out Vector256<double> r2, out Vector256<double> c0, out Vector256<double> c1, out Vector256<double> c2, out Vector256<double> t)
        {
            // Columns: lane i of ax is a_i.X (A's axes are the rows ax0, ay0, az0); likewise for B.
            Transpose(ax0, ay0, az0, out var ax, out var ay, out var az);
            Transpose(bx0, by0, bz0, out var bx, out var by, out var bz);
            r0 = bx * Lane(ax0, 0) + by * Lane(ax0, 1) + bz * Lane(ax0, 2);
            r1 = bx * Lane(ay0, 0) + by * Lane(ay0, 1) + bz * Lane(ay0, 2);
            r2 = bx * Lane(az0, 0) + by * Lane(az0, 1) + bz * Lane(az0, 2);
            Transpose(r0, r1, r2, out c0, out c1, out c2);
            t = ax * Lane(tw, 0) + ay * Lane(tw, 1) + az * Lane(tw, 2);
        }

        /// <summary>A's face axes (lane i): the radii h_a,i + Σ_j h_b,j |a_i · b_j| of both boxes along a_i.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> FaceARadii(Vector256<double> ha, Vector256<double> hb, Vector256<double> c0, Vector256<double> c1, Vector256<double> c2) =>
            ha + Vector256.Abs(c0) * Lane(hb, 0) + Vector256.Abs(c1) * Lane(hb, 1) + Vector256.Abs(c2) * Lane(hb, 2);

        /// <summary>B's face axes (lane j): the radii Σ_i h_a,i |a_i · b_j| + h_b,j along b_j.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> FaceBRadii(Vector256<double> ha, Vector256<double> hb, Vector256<double> r0, Vector256<double> r1, Vector256<double> r2) =>
            Vector256.Abs(r0) * Lane(ha, 0) + Vector256.Abs(r1) * Lane(ha, 1) + Vector256.Abs(r2) * Lane(ha, 2) + hb;

        /// <summary>B's face axes (lane j): |T · b_j|.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> FaceBSeparation(Vector256<double> t, Vector256<double> r0, Vector256<double> r1, Vector256<double> r2) =>
            Vector256.Abs(r0 * Lane(t, 0) + r1 * Lane(t, 1) + r2 * Lane(t, 2));

        /// <summary>
        /// The axes e_i × b_j (j in the lanes) for the A axis i whose two other axes are p and q (cyclic): in A's frame
        /// L = (…, −r_qj, r_pj), so |T·L| = |t_q r_pj − t_p r_qj|.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> EdgeSeparation(Vector256<double> tp, Vector256<double> tq, Vector256<double> rp, Vector256<double> rq) =>
            Vector256.Abs(rp * tq - rq * tp);

        /// <summary>
        /// The radii of both boxes along e_i × b_j (<see cref="EdgeSeparation"/>'s axes): A's h_p|r_qj| + h_q|r_pj|, and B's
        /// from the 2×2 minors b_k · L of rows p, q (not the orthonormality shortcut), as in the scalar form.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> EdgeRadii(Vector256<double> hp, Vector256<double> hq, Vector256<double> rp, Vector256<double> rq,
            Vector256<double> hbNext, Vector256<double> hbPrev)
        {
            // Lane j: the minor of columns j and j + 1; the minor of j and j − 1 is lane j − 1 of it, negated.
            var next = Vector256.Abs(Avx2.Permute4x64(rp, Next) * rq - Avx2.Permute4x64(rq, Next) * rp);
            var prev = Avx2.Permute4x64(next, Prev);
            return Vector256.Abs(rq) * hp + Vector256.Abs(rp) * hq + hbNext * next + hbPrev * prev;
        }

        /// <summary>
        /// <see cref="OverlapDepth"/> on AVX2 lanes for boxes that are not planar: <see cref="OverlapsCentered"/>'s test on the
        /// Box forms (the same values, so the same verdict) and, where no axis separates, each axis's overlap from those
        /// values, (radii − |T·L|)/|L|: A's and B's face axes are unit, an edge axis e_i × b_j has |L|² = r_pj² + r_qj²
        /// (lane 3 of every group is no axis). The first axis holding the least, in <see cref="PenetrationScalar"/>'s
        /// order, is then tried alone by <see cref="TryAxis"/> in world axes (on <see cref="WorldAxis"/>), as that form does:
        /// the same bits.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static bool OverlapDepthVector(in Box a, in Box b, Vector3D t, out double depth, out Vector3D push)
        {
            Vector3D ax = a.X, ay = a.Y, az = a.Z, bx = b.X, by = b.Y, bz = b.Z, ha = a.Half, hb = b.Half;
            Vector256<double> vha = V(ha), vhb = V(hb);
            FrameOfA(V(t), V(ax), V(ay), V(az), V(bx), V(by), V(bz), out var r0, out var r1, out var r2, out var c0, out var c1, out var c2, out var tl);
            Vector256<double> tx = Lane(tl, 0), ty = Lane(tl, 1), tz = Lane(tl, 2);
            Vector256<double> hax = Lane(vha, 0), hay = Lane(vha, 1), haz = Lane(vha, 2);
            // radii − |separation|: negative exactly where the test's |separation| > radii holds (a rounded difference keeps
            // its sign). The face axes first, as the test does: most boxes that are apart are told apart by one of them.
            var faceA = FaceARadii(vha, vhb, c0, c1, c2) - Vector256.Abs(tl);
            var faceB = FaceBRadii(vha, vhb, r0, r1, r2) - FaceBSeparation(tl, r0, r1, r2);
            var zero = Vector256<double>.Zero;
            depth = 0;
            push = default;
            if ((Vector256.LessThan(faceA, zero) | Vector256.LessThan(faceB, zero)).ExtractMostSignificantBits() != 0) return false;
            var hbNext = Avx2.Permute4x64(vhb, Next);
            var hbPrev = Avx2.Permute4x64(vhb, Prev);
            var ex = EdgeRadii(hay, haz, r1, r2, hbNext, hbPrev) - EdgeSeparation(ty, tz, r1, r2);
            var ey = EdgeRadii(haz, hax, r2, r0, hbNext, hbPrev) - EdgeSeparation(tz, tx, r2, r0);
            var ez = EdgeRadii(hax, hay, r0, r1, hbNext, hbPrev) - EdgeSeparation(tx, ty, r0, r1);
            if ((Vector256.LessThan(ex, zero) | Vector256.LessThan(ey, zero) | Vector256.LessThan(ez, zero)).ExtractMostSignificantBits() != 0) return false;
            var inf = Vector256.Create(double.PositiveInfinity);
            var none = Vector256.Create(0, 0, 0, -1L).AsDouble();
            faceA = Vector256.ConditionalSelect(none, inf, faceA);
            faceB = Vector256.ConditionalSelect(none, inf, faceB);
            ex = EdgeOverlap(ex, r1, r2, inf);
            ey = EdgeOverlap(ey, r2, r0, inf);
            ez = EdgeOverlap(ez, r0, r1, inf);
            // The hardware's min (Vector256.Min spends eight more instructions per call on NaN and zero-sign rules): the
            // lanes are never NaN in range, and only which lanes equal the least matters, where −0 == +0.
            var m = Vector256.MinNative(Vector256.MinNative(faceA, faceB), Vector256.MinNative(Vector256.MinNative(ex, ey), ez));
            m = Vector256.MinNative(m, Avx.Permute(m, 0b0101));
            m = Vector256.MinNative(m, Avx.Permute2x128(m, m, 1));
            // Bits in the scalar order: a_x, a_y, b_x, b_y, a_z, b_z, then a_i × b_j with i major.
            uint fa = Vector256.Equals(faceA, m).ExtractMostSignificantBits(), fb = Vector256.Equals(faceB, m).ExtractMostSignificantBits();
            uint hits = (fa & 3) | (fb & 3) << 2 | (fa & 4) << 2 | (fb & 4) << 3 | (Vector256.Equals(ex, m).ExtractMostSignificantBits() & 7) << 6
                | (Vector256.Equals(ey, m).ExtractMostSignificantBits() & 7) << 9 | (Vector256.Equals(ez, m).ExtractMostSignificantBits() & 7) << 12;
            depth = double.PositiveInfinity;
            double scale = 0;
            Vector3D axis = default;
            if (hits != 0)
            {
                int bit = System.Numerics.BitOperations.TrailingZeroCount(hits), j = bit < 6 ? 0 : (bit - 6) % 3;
                var column = j == 0 ? c0 : j == 1 ? c1 : c2; // b_j in A's frame, used for an edge axis
                TryAxis(WorldAxis(bit, ax, ay, az, bx, by, bz, column.GetElement(0), column.GetElement(1), column.GetElement(2)), ax, ay, az, bx, by, bz,
                    ha, hb, t, ref depth, ref axis, ref scale);
            }
            push = axis * scale;
            return true;
        }

        /// <summary>An edge group's overlaps over |L| (lane 3 and zero axes: +∞), L's components in A's frame being (rp, rq) in its two other axes.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> EdgeOverlap(Vector256<double> overlap, Vector256<double> rp, Vector256<double> rq, Vector256<double> inf)
        {
            var len2 = rp * rp + rq * rq;
            return Vector256.ConditionalSelect(Vector256.GreaterThan(len2, Vector256<double>.Zero), overlap / Vector256.Sqrt(len2), inf);
        }

        /// <summary>
        /// <see cref="VerticesScalar"/> on AVX2 lanes, four corners per vector. A lane's corner is the scalar form's sums
        /// with zeros added where it adds nothing (which can only change the sign of a zero coordinate, and the squared
        /// gap not at all), so both forms return the same bits and the same corner.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        internal static double VerticesVector(in Corners q, bool planar, out int win, out uint edges)
        {
            Vector3D pa = q.Pa, dx = q.Dx, dy = q.Dy, dz = q.Dz, loB = q.LoB, hiB = q.HiB, pb = q.Pb, ex = q.Ex, ey = q.Ey, ez = q.Ez, loA = q.LoA, hiA = q.HiA;
            // Corners 0–3 per coordinate; corners 4–7 add dz to them. r: A's clamp residuals.
            Vector256<double> ax = Corners4(pa.X, dx.X, dy.X), ay = Corners4(pa.Y, dx.Y, dy.Y), az = Corners4(pa.Z, dx.Z, dy.Z);
            Vector256<double> bx = Corners4(pb.X, ex.X, ey.X), by = Corners4(pb.Y, ex.Y, ey.Y), bz = Corners4(pb.Z, ex.Z, ey.Z);
            Vector256<double> rx0 = Outside(ax, loB.X, hiB.X), ry0 = Outside(ay, loB.Y, hiB.Y), rz0 = Outside(az, loB.Z, hiB.Z);
            var a0 = rx0 * rx0 + ry0 * ry0 + rz0 * rz0;
            var b0 = Gaps(bx, by, bz, loA, hiA);
            var inf = Vector256.Create(double.PositiveInfinity);
            Vector256<double> a1 = inf, b1 = inf;
            edges = 0;
            if (!planar)
            {
                Vector256<double> rx1 = Outside(ax + Vector256.Create(dz.X), loB.X, hiB.X), ry1 = Outside(ay + Vector256.Create(dz.Y), loB.Y, hiB.Y),
                    rz1 = Outside(az + Vector256.Create(dz.Z), loB.Z, hiB.Z);
                a1 = rx1 * rx1 + ry1 * ry1 + rz1 * rz1;
                b1 = Gaps(bx + Vector256.Create(ez.X), by + Vector256.Create(ez.Y), bz + Vector256.Create(ez.Z), loA, hiA);
                // Slopes dir·r at all eight corners per axis: the edge from c descends if < 0 there and > 0 at c + 2^i.
                edges = Descending(dx, rx0, ry0, rz0, rx1, ry1, rz1, 1) & 0x55
                    | (Descending(dy, rx0, ry0, rz0, rx1, ry1, rz1, 2) & 0x33) << 8
                    | (Descending(dz, rx0, ry0, rz0, rx1, ry1, rz1, 4) & 0x0F) << 16;
            }
            var m = Vector256.MinNative(Vector256.MinNative(a0, a1), Vector256.MinNative(b0, b1));
            m = Vector256.MinNative(m, Avx.Permute(m, 0b0101));
            m = Vector256.MinNative(m, Avx.Permute2x128(m, m, 1));
            // The first corner holding the least gap, in the scalar order (A's 0–7, then B's 0–7).
            uint hits = Vector256.Equals(a0, m).ExtractMostSignificantBits() | (Vector256.Equals(a1, m).ExtractMostSignificantBits() << 4)
                | (Vector256.Equals(b0, m).ExtractMostSignificantBits() << 8) | (Vector256.Equals(b1, m).ExtractMostSignificantBits() << 12);
            win = hits == 0 ? 0 : System.Numerics.BitOperations.TrailingZeroCount(hits);
            return hits == 0 ? double.PositiveInfinity : m.ToScalar();
        }

        /// <summary>
        /// <see cref="Corners2Scalar"/> on AVX2 lanes, A's four corners in one vector and B's in another: each lane makes
        /// the scalar form's operations (a zero added where it adds nothing), so the same bits and the same corner.
        /// Inlined into its one caller: as a call, its ten vectors went through registers and the stack (with <see cref="LeastAxis2"/>
        /// inlined too, 2D OBB–OBB and AABB–OBB took 0.86–0.94 times as long on .NET 10 in both modes; ab, 2 × 7).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double Corners2Vector(Vector2D pa, Vector2D dx, Vector2D dy, Vector2D loB, Vector2D hiB,
            Vector2D pb, Vector2D ex, Vector2D ey, Vector2D loA, Vector2D hiA, double k, out int win)
        {
            var kk = Vector256.Create(k);
            Vector256<double> rx = Outside(Corners4(pa.X, dx.X, dy.X), loB.X, hiB.X) * kk, ry = Outside(Corners4(pa.Y, dx.Y, dy.Y), loB.Y, hiB.Y) * kk;
            Vector256<double> sx = Outside(Corners4(pb.X, ex.X, ey.X), loA.X, hiA.X) * kk, sy = Outside(Corners4(pb.Y, ex.Y, ey.Y), loA.Y, hiA.Y) * kk;
            var a = rx * rx + ry * ry;
            var b = sx * sx + sy * sy;
            var m = Vector256.MinNative(a, b);
            m = Vector256.MinNative(m, Avx.Permute(m, 0b0101));
            m = Vector256.MinNative(m, Avx.Permute2x128(m, m, 1));
            uint hits = Vector256.Equals(a, m).ExtractMostSignificantBits() | (Vector256.Equals(b, m).ExtractMostSignificantBits() << 4);
            win = hits == 0 ? 0 : System.Numerics.BitOperations.TrailingZeroCount(hits);
            return hits == 0 ? double.PositiveInfinity : m.ToScalar();
        }

        /// <summary>
        /// The first of the axes (ax, ay, bx, by) holding the least of <see cref="TryAxis2"/>'s push-outs, or −1 when none
        /// is an axis: per lane (ra + rb − |sep|)/len, exactly the smaller of its down and up. Inlined into its one caller
        /// (see <see cref="Corners2Vector"/>).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static int LeastAxis2(Vector2D ax, Vector2D ay, Vector2D bx, Vector2D by, Vector2D ha, Vector2D hb, Vector2D t)
        {
            Vector256<double> x = Vector256.Create(ax.X, ay.X, bx.X, by.X), y = Vector256.Create(ax.Y, ay.Y, bx.Y, by.Y);
            var len2 = x * x + y * y;
            var ra = Vector256.Create(ha.X) * Vector256.Abs(Vector256.Create(ax.X) * x + Vector256.Create(ax.Y) * y)
                + Vector256.Create(ha.Y) * Vector256.Abs(Vector256.Create(ay.X) * x + Vector256.Create(ay.Y) * y);
            var rb = Vector256.Create(hb.X) * Vector256.Abs(Vector256.Create(bx.X) * x + Vector256.Create(bx.Y) * y)
                + Vector256.Create(hb.Y) * Vector256.Abs(Vector256.Create(by.X) * x + Vector256.Create(by.Y) * y);
            var least = (ra + rb - Vector256.Abs(Vector256.Create(t.X) * x + Vector256.Create(t.Y) * y)) / Vector256.Sqrt(len2);
            least = Vector256.ConditionalSelect(Vector256.GreaterThan(len2, Vector256<double>.Zero), least, Vector256.Create(double.PositiveInfinity));
            var m = Vector256.MinNative(least, Avx.Permute(least, 0b0101));
            m = Vector256.MinNative(m, Avx.Permute2x128(m, m, 1));
            uint hits = Vector256.Equals(least, m).ExtractMostSignificantBits();
            return hits == 0 ? -1 : System.Numerics.BitOperations.TrailingZeroCount(hits);
        }

        /// <summary>Bit c: the slope dir·r is negative at corner c and positive at corner c + step (residuals of corners 0–3, 4–7).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static uint Descending(Vector3D dir, Vector256<double> rx0, Vector256<double> ry0, Vector256<double> rz0,
            Vector256<double> rx1, Vector256<double> ry1, Vector256<double> rz1, int step)
        {
            Vector256<double> x = Vector256.Create(dir.X), y = Vector256.Create(dir.Y), z = Vector256.Create(dir.Z);
            var s0 = x * rx0 + y * ry0 + z * rz0;
            var s1 = x * rx1 + y * ry1 + z * rz1;
            uint neg = Vector256.LessThan(s0, Vector256<double>.Zero).ExtractMostSignificantBits() | (Vector256.LessThan(s1, Vector256<double>.Zero).ExtractMostSignificantBits() << 4);
            uint pos = Vector256.GreaterThan(s0, Vector256<double>.Zero).ExtractMostSignificantBits() | (Vector256.GreaterThan(s1, Vector256<double>.Zero).ExtractMostSignificantBits() << 4);
            return neg & (pos >> step);
        }

        /// <summary>(p, p + dx, p + dy, (p + dx) + dy): one coordinate of corners 0–3.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> Corners4(double p, double dx, double dy) =>
            Vector256.Create(p) + Vector256.Create(0, dx, 0, dx) + Vector256.Create(0, 0, dy, dy);

        /// <summary>Per lane, the squared gap of the point (x, y, z) to the box [lo, hi], as the squared length of <see cref="Residual(Vector3D, Vector3D, Vector3D)"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> Gaps(Vector256<double> x, Vector256<double> y, Vector256<double> z, Vector3D lo, Vector3D hi)
        {
            var rx = Outside(x, lo.X, hi.X);
            var ry = Outside(y, lo.Y, hi.Y);
            var rz = Outside(z, lo.Z, hi.Z);
            return rx * rx + ry * ry + rz * rz;
        }

        /// <summary>The scalar Outside's Num.Min and Num.Max lane by lane: the same operands in the same order, so the same bits.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> Outside(Vector256<double> e, double lo, double hi) =>
            Vector256.MinNative(e - Vector256.Create(lo), Vector256<double>.Zero) + Vector256.MaxNative(e - Vector256.Create(hi), Vector256<double>.Zero);

        /// <summary>(v.X, v.Y, v.Z, 0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector256<double> V(Vector3D v) => Vector256.Create(v.X, v.Y, v.Z, 0);

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
    }
}
#endif
