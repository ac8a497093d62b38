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
        /// the edge–box distances is exact. Overlapping: A moved by the minimum translation just touches B, and the
        /// touching pair found the same way, moved back, realises the penetration.
        /// </summary>
        public static DistanceResult3 BoxBox(in Box boxA, in Box boxB)
        {
            var shift = boxA.Origin;
            var a = boxA.Translated(-shift);
            var b = boxB.Translated(-shift);
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
                        TryBoxAxis(Vector3D.Cross(a.Axis(i), b.Axis(j)), a, b, ca, cb, ha, hb, ref depth, ref push);
            }

            if (depth < 0) push = default;
            var moved = a.Translated(push);
            double g = EdgesApart(moved, b, out var onA, out var onB);
            onA = onA - push + shift;
            onB += shift;
            if (depth < 0) return new DistanceResult3(Math.Sqrt(g), g, onA, onB, 0, 0);
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
            for (int i = 0; i < 3; i++)
            {
                // A zero-length edge is a vertex, already an endpoint of another edge (unless the box is a point).
                if (Vec.Get(lo, i) == Vec.Get(hi, i) && !(point && i == 0)) continue;
                int j = (i + 1) % 3, k = (i + 2) % 3;
                for (int sj = 0; sj < 2; sj++)
                {
                    if (sj == 1 && Vec.Get(lo, j) == Vec.Get(hi, j)) break;
                    for (int sk = 0; sk < 2; sk++)
                    {
                        if (sk == 1 && Vec.Get(lo, k) == Vec.Get(hi, k)) break;
                        var start = Vec.With(Vec.With(lo, j, Vec.Get(sj == 0 ? lo : hi, j)), k, Vec.Get(sk == 0 ? lo : hi, k));
                        var end = Vec.With(start, i, Vec.Get(hi, i));
                        var p = edges.Origin + edges.ToWorldOffset(start);
                        var q = edges.Origin + edges.ToWorldOffset(end);
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

        /// <summary>
        /// Box–box overlap by the separating-axis test with early outs and no square roots (Gottschalk et al. 1996;
        /// Ericson, RTCD §4.4.1), in A's frame. Cross axes are projected honestly instead of with the usual ε added to |R|,
        /// so nearly parallel edges neither invent a separation nor need a scale-dependent fudge. 2D uses the four face axes.
        /// </summary>
        public static bool BoxBoxOverlaps(in Box a, in Box b)
        {
            var tw = (b.Origin - a.Origin) + b.ToWorldOffset(b.LocalCenter) - a.ToWorldOffset(a.LocalCenter);
            var t = a.ToLocal(tw);
            var r0 = a.ToLocal(b.X);
            var r1 = a.ToLocal(b.Y);
            var r2 = a.ToLocal(b.Z);
            var ha = a.Half;
            var hb = b.Half;
            bool planar = a.Planar || b.Planar;

            // A's face axes: e_i, where B's radius is Σ_k hb_k |R_k,i|.
            if (Math.Abs(t.X) > ha.X + hb.X * Math.Abs(r0.X) + hb.Y * Math.Abs(r1.X) + hb.Z * Math.Abs(r2.X)) return false;
            if (Math.Abs(t.Y) > ha.Y + hb.X * Math.Abs(r0.Y) + hb.Y * Math.Abs(r1.Y) + hb.Z * Math.Abs(r2.Y)) return false;
            if (!planar && Math.Abs(t.Z) > ha.Z + hb.X * Math.Abs(r0.Z) + hb.Y * Math.Abs(r1.Z) + hb.Z * Math.Abs(r2.Z)) return false;
            // B's face axes.
            if (Math.Abs(Vector3D.Dot(t, r0)) > Vector3D.Dot(ha, Vec.Abs(r0)) + hb.X) return false;
            if (Math.Abs(Vector3D.Dot(t, r1)) > Vector3D.Dot(ha, Vec.Abs(r1)) + hb.Y) return false;
            if (planar) return true;
            if (Math.Abs(Vector3D.Dot(t, r2)) > Vector3D.Dot(ha, Vec.Abs(r2)) + hb.Z) return false;
            // Edge × edge axes e_i × R_j.
            return !CrossSeparates(t, ha, hb, r0, r1, r2, r0) && !CrossSeparates(t, ha, hb, r0, r1, r2, r1)
                && !CrossSeparates(t, ha, hb, r0, r1, r2, r2);
        }

        private static bool CrossSeparates(Vector3D t, Vector3D ha, Vector3D hb, Vector3D r0, Vector3D r1, Vector3D r2, Vector3D rj)
        {
            return AxisSeparates(new Vector3D(0, -rj.Z, rj.Y), t, ha, hb, r0, r1, r2)
                || AxisSeparates(new Vector3D(rj.Z, 0, -rj.X), t, ha, hb, r0, r1, r2)
                || AxisSeparates(new Vector3D(-rj.Y, rj.X, 0), t, ha, hb, r0, r1, r2);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool AxisSeparates(Vector3D l, Vector3D t, Vector3D ha, Vector3D hb, Vector3D r0, Vector3D r1, Vector3D r2)
        {
            double rb = hb.X * Math.Abs(Vector3D.Dot(r0, l)) + hb.Y * Math.Abs(Vector3D.Dot(r1, l)) + hb.Z * Math.Abs(Vector3D.Dot(r2, l));
            return Math.Abs(Vector3D.Dot(t, l)) > Vector3D.Dot(ha, Vec.Abs(l)) + rb;
        }

        /// <summary>
        /// AABB against AABB, per axis and exact up to one subtraction per gap. Apart: the per-axis gaps; overlapping axes
        /// put both witnesses at the middle of the shared interval. Overlapping: the axis of least overlap.
        /// </summary>
        public static DistanceResult3 AabbAabb(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB, bool planar)
        {
            var x = new AxisGap(minA.X, maxA.X, minB.X, maxB.X);
            var y = new AxisGap(minA.Y, maxA.Y, minB.Y, maxB.Y);
            var z = new AxisGap(minA.Z, maxA.Z, minB.Z, maxB.Z);
            double g2 = x.Gap2 + y.Gap2 + z.Gap2;
            var pa = new Vector3D(x.A, y.A, z.A);
            var pb = new Vector3D(x.B, y.B, z.B);
            if (g2 > 0) return new DistanceResult3(Math.Sqrt(g2), g2, pa, pb, 0, 0);

            // Overlapping on every axis: push A out along the axis of least overlap, down before up, x before y before z.
            double depth = x.Down;
            int face = 0;
            if (x.Up < depth) { depth = x.Up; face = 1; }
            if (y.Down < depth) { depth = y.Down; face = 2; }
            if (y.Up < depth) { depth = y.Up; face = 3; }
            if (!planar)
            {
                if (z.Down < depth) { depth = z.Down; face = 4; }
                if (z.Up < depth) { depth = z.Up; face = 5; }
            }
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
                    // Shared interval: both witnesses at its middle.
                    double lo = Math.Max(aLo, bLo), hi = Math.Min(aHi, bHi);
                    Gap2 = 0;
                    A = B = lo + 0.5 * (hi - lo);
                }
            }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AabbAabbOverlaps(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB) =>
            minA.X <= maxB.X && maxA.X >= minB.X && minA.Y <= maxB.Y && maxA.Y >= minB.Y && minA.Z <= maxB.Z && maxA.Z >= minB.Z;
    }
}
