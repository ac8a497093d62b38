using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// A line (origin o, unit direction u), or a ray when <paramref name="ray"/>, against a solid box, as the pair
        /// (line, box), in the box frame relative to the box centre (so a far origin costs only the rounding of its own
        /// offset). Apart (by the separating-axis verdict the overlap query gives): the closest points lie where the line
        /// parameter is within the box's projection onto the line, so the line clipped to that stretch (widened, and for a
        /// ray cut at 0) is a segment whose closest pair with the box (<see cref="SegmentBoxLocal"/>) is the line's.
        /// Meeting: the least push over the directions that can clear it (<see cref="LineBoxPenetration"/>), and the pair of
        /// the just-touching configuration, the line's point moved back.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 LineBox(Vector3D o, Vector3D u, bool ray, in Box box, out bool inRange)
        {
            var ro = o - box.Origin;
            inRange = Range.Box(Num.Max(Range.MaxAbs(ro), Range.MaxAbs(box.Hi - box.Lo)));
            var c = box.LocalCenter;
            var h = box.Half;
            var m = box.ToLocal(ro) - c;
            var d = box.ToLocal(u);
            double t;
            Vector3D e;
            if (!LineBoxOverlapsLocal(m, d, h, box.Planar, ray))
            {
                double g = LineBoxNearest(m, d, h, ray, out t, out e);
                // A subnormal squared gap has lost bits, and a zero one is rare here (found apart) and may have underflowed:
                // the slow path answers both at a scale where they have not (2^k-scaled inputs agree).
                inRange &= Range.In(g);
                return new DistanceResult3(Math.Sqrt(g), g, o + u * t, box.Origin + box.ToWorldOffset(c + Clamp(e, -h, h)), t, 0);
            }
            double depth = Num.Max(LineBoxPenetration(m, d, h, box.Planar, ray, out var dir), 0);
            // The line moved by the push just touches the box: its closest pair there, the line's point moved back.
            LineBoxNearest(m + dir * depth, d, h, ray, out t, out e);
            var onLine = o + u * t;
            return new DistanceResult3(-depth, 0, onLine, depth > 0 ? box.Origin + box.ToWorldOffset(c + Clamp(e, -h, h)) : onLine, t, 0);
        }

        /// <summary>
        /// The squared distance from the line m + t·d (box-local, relative to the centre, d unit to rounding; t ≥ 0 for a
        /// ray) to the box [−h, h], its parameter t and its point e. Every closest point of the line has t within the
        /// box's projection onto it, [tc − reach, tc + reach] with tc the parameter nearest the centre; the stretch is
        /// doubled (and widened by 2^-40·|tc| for the rounding of tc) so the clipped segment holds the minimum strictly.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double LineBoxNearest(Vector3D m, Vector3D d, Vector3D h, bool ray, out double t, out Vector3D e)
        {
            double tc = -Vector3D.Dot(m, d);
            double reach = h.X * Math.Abs(d.X) + h.Y * Math.Abs(d.Y) + h.Z * Math.Abs(d.Z);
            double w = 2 * reach + Math.Abs(tc) * (1.0 / (1L << 40));
            double t0 = tc - w, t1 = tc + w;
            if (ray) { t0 = Math.Max(t0, 0); t1 = Math.Max(t1, 0); }
            double len = t1 - t0;
            var a = m + d * t0;
            var span = d * len;
            double g = SegmentBoxLocal(a, span, -h, h, out double s);
            t = s <= 0.5 ? t0 + len * s : t1 - len * (1 - s);
            e = a + span * s;
            return g;
        }

        /// <summary>
        /// The least push (box-local; its length, and its unit direction in <paramref name="dir"/>) that clears the line m + t·d (relative to the box centre) from the box of
        /// half-extents h. A line can only be cleared sideways: over the directions d × box axis (planar: the in-plane
        /// one), on which the whole line projects to one value; they include every box normal perpendicular to the line.
        /// A ray can also be pushed back past a face it leaves through: along a box normal n with n·d ≥ 0, by the
        /// distance from its origin to that face.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double LineBoxPenetration(Vector3D m, Vector3D d, Vector3D h, bool planar, bool ray, out Vector3D dir)
        {
            double best = double.PositiveInfinity;
            dir = default;
            if (ray)
            {
                TryRayFace(m.X, d.X, h.X, Vector3D.UnitX, ref best, ref dir);
                TryRayFace(m.Y, d.Y, h.Y, Vector3D.UnitY, ref best, ref dir);
                if (!planar) TryRayFace(m.Z, d.Z, h.Z, Vector3D.UnitZ, ref best, ref dir);
            }
            TryCrossAxis(new Vector3D(d.Y, -d.X, 0), m.X * d.Y - m.Y * d.X, h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X), ref best, ref dir);
            if (!planar)
            {
                TryCrossAxis(new Vector3D(0, d.Z, -d.Y), m.Y * d.Z - m.Z * d.Y, h.Y * Math.Abs(d.Z) + h.Z * Math.Abs(d.Y), ref best, ref dir);
                TryCrossAxis(new Vector3D(-d.Z, 0, d.X), m.Z * d.X - m.X * d.Z, h.X * Math.Abs(d.Z) + h.Z * Math.Abs(d.X), ref best, ref dir);
            }
            return best;
        }

        /// <summary>A box normal n along which the ray covers [m, ∞) (d &gt; 0), (−∞, m] (d &lt; 0) or {m} (d = 0); the box [−h, h].</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryRayFace(double m, double d, double h, Vector3D n, ref double best, ref Vector3D dir)
        {
            if (d >= 0 && h - m < best) { best = h - m; dir = n; }
            if (d <= 0 && m + h < best) { best = m + h; dir = -n; }
        }

        /// <summary>Whether a line or ray meets a solid box (separating-axis test, no square roots).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool LineBoxOverlaps(Vector3D o, Vector3D u, bool ray, in Box box, out bool inRange)
        {
            var ro = o - box.Origin;
            inRange = Range.Box(Num.Max(Range.MaxAbs(ro), Range.MaxAbs(box.Hi - box.Lo)));
            return LineBoxOverlapsLocal(box.ToLocal(ro) - box.LocalCenter, box.ToLocal(u), box.Half, box.Planar, ray);
        }

        /// <summary>
        /// The separating-axis test of the line (or ray) m + t·d, relative to the box centre, against the box of
        /// half-extents h: for a ray the box normals (it covers a half-line along each), then for both the d × box-axis
        /// directions, on which the line projects to one value (the segment test's cross axes; Ericson RTCD §5.3.3).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool LineBoxOverlapsLocal(Vector3D m, Vector3D d, Vector3D h, bool planar, bool ray)
        {
            if (ray && (RaySlabSeparates(m.X, d.X, h.X) || RaySlabSeparates(m.Y, d.Y, h.Y) || (!planar && RaySlabSeparates(m.Z, d.Z, h.Z)))) return false;
            if (Math.Abs(m.X * d.Y - m.Y * d.X) > h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X)) return false;
            if (planar) return true;
            return !(Math.Abs(m.Y * d.Z - m.Z * d.Y) > h.Y * Math.Abs(d.Z) + h.Z * Math.Abs(d.Y))
                && !(Math.Abs(m.Z * d.X - m.X * d.Z) > h.X * Math.Abs(d.Z) + h.Z * Math.Abs(d.X));
        }

        /// <summary>Whether the ray's cover of one axis (from m, heading the sign of d) misses [−h, h].</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool RaySlabSeparates(double m, double d, double h) => (m > h && d >= 0) || (m < -h && d <= 0);

        /// <summary>
        /// The Distance of <see cref="CapsuleBox"/>, bit for bit, without the witnesses and the near-touch normal: in every
        /// branch there the distance is the axis's signed distance to the box less the radius (apart: the gap's root;
        /// apart by the verdict with a zero squared gap: the push, which is then 0 as that verdict's axis gives a
        /// negative push; meeting: minus the push), which is <see cref="InFrameDistance"/>'s, under the same range guard.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static double CapsuleBoxDistance(Vector3D a, Vector3D b, double r, in Box box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Num.Max(Num.Max(Range.MaxAbs(ra), r), Num.Max(Range.MaxAbs(b - box.Origin), Range.MaxAbs(box.Hi - box.Lo))));
            return InFrameDistance(box.ToLocal(ra), box.ToLocal(b - a), box.Lo, box.Hi, box.Planar, ref inRange) - r;
        }

        /// <summary>
        /// A capsule (axis [a, b], radius r) against a solid box: the axis's solid signed distance (as
        /// <see cref="SegmentInFrame"/>: the same verdict, minimum and push) less r, and the axis's witness moved by r along the
        /// contact direction: toward the box when apart (the box-local gap vector, normalised), against the push when the
        /// axis meets the box, also where the push is zero (the axis touching: the direction of the separating axis).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 CapsuleBox(Vector3D a, Vector3D b, double r, in Box box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Num.Max(Num.Max(Range.MaxAbs(ra), r), Num.Max(Range.MaxAbs(b - box.Origin), Range.MaxAbs(box.Hi - box.Lo))));
            var la = box.ToLocal(ra);
            var ld = box.ToLocal(b - a);
            Vector3D lo = box.Lo, hi = box.Hi, c = box.LocalCenter, h = box.Half;
            double t, dist;
            bool apart = !SegmentBoxOverlapsLocal(la - c, ld, h, box.Planar);
            if (apart)
            {
                double g = SegmentBoxLocalCall(la, ld, lo, hi, out t);
                inRange &= Range.In(g);
                if (g > 0)
                {
                    var e = la + ld * t;
                    var q = Clamp(e, lo, hi);
                    double gap = Math.Sqrt(g);
                    dist = gap - r;
                    // q − e has the components whose squares summed to g: its length is gap.
                    var toward = box.ToWorldOffset(q - e) * (1 / gap);
                    // Near: within 2^-26 of the box-frame magnitudes, whose rounding the residual carries (an AABB's
                    // frame starts at its min corner, so the box point alone can be 0 there).
                    if (g < NearTouch2 * Math.Max(q.LengthSquared, Math.Max(la.LengthSquared, ld.LengthSquared)))
                        toward = NearCapsuleBoxNormal(a, b, box, toward);
                    return new DistanceResult3(dist, dist > 0 ? dist * dist : 0, SegmentPoint(a, b, t) + toward * r, box.Origin + box.ToWorldOffset(q), t, 0);
                }
                // Apart by the verdict but touching to rounding: the touching branch below.
            }
            double depth = Num.Max(SegmentBoxPenetration(la - c, ld, h, box.Planar, out var dir), 0);
            // The push direction separates the axis from the box even when the axis only touches it (depth 0): a face
            // normal there could lead the rest of the axis back into the box.
            var outward = box.ToWorldOffset(dir);
            Vector3D onAxis, onBox;
            if (depth > 0)
            {
                var moved = la + dir * depth;
                t = TouchingParameter(la - c, ld, h, dir);
                if (double.IsNaN(t)) SegmentBoxLocalCall(moved, ld, lo, hi, out t);
                onAxis = SegmentPoint(a, b, t);
                onBox = ClampToBox(box, moved + ld * t);
            }
            else
            {
                SegmentBoxLocalCall(la, ld, lo, hi, out t);
                onAxis = onBox = SegmentPoint(a, b, t);
                // Touching to rounding: the separating axis found may be any whose push rounds to 0, and a radius
                // pushed along the wrong one leaves up to the radius of overlap; the near-touch normal is exact.
                outward = -NearCapsuleBoxNormal(a, b, box, -outward);
            }
            // Apart by the verdict, the depth is 0 and the distance the zero gap's, +0 (as CapsuleBoxDistance has it), not −0.
            dist = (apart ? 0 : -depth) - r;
            return new DistanceResult3(dist, dist > 0 ? dist * dist : 0, onAxis - outward * r, onBox, t, 0);
        }

        /// <summary>
        /// The unit normal from a capsule's axis [a, b] to a box it nearly touches (within 2^-26 of the box-frame
        /// magnitudes) or touches to rounding. The rounded residual turns by about u·size/gap there, and which features
        /// hold the pair is as uncertain, so every feature pair's normal is formed from the exact inputs: an end's
        /// (<see cref="NearBoxNormal"/>), the axis against each box edge direction (their common normal), against each
        /// vertex (its perpendicular to the axis, <see cref="VertexPerp"/>), and the face normals; and the one whose
        /// plane leaves the box farthest from the axis (<see cref="BoxSupport"/>) is taken: the exact normal's support
        /// is the gap itself, and pushing along one whose support is within δ of it leaves the shapes within δ of
        /// touching. <paramref name="toward"/> (the rounded residual's direction) competes too.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static Vector3D NearCapsuleBoxNormal(Vector3D a, Vector3D b, in Box box, Vector3D toward)
        {
            var oa = box.Origin - a;
            var ab = b - a;
            double best = double.NegativeInfinity;
            var n = toward;
            Consider(toward, oa, ab, box, ref best, ref n);
            for (int i = 0; i < 2; i++)
            {
                var p = i == 0 ? a : b;
                var q = box.ToLocal(p - box.Origin);
                var c = Clamp(q, box.Lo, box.Hi);
                if (q != c) Consider(-NearBoxNormal(p, box, c, default), oa, ab, box, ref best, ref n);
            }
            // The face normals, and the axis against an edge along each box axis (their common normal); in the plane the
            // axis against a vertex, whose normal is the axis's own.
            var abk = ab * Num.InversePowerOfTwo(Num.Max(Range.MaxAbs(ab), double.Epsilon));
            for (int i = 0; i < (box.Planar ? 2 : 3); i++)
            {
                var e = box.Axis(i);
                Consider(e, oa, ab, box, ref best, ref n);
                Consider(-e, oa, ab, box, ref best, ref n);
                if (box.Planar) continue;
                var cn = Vector3D.Cross(abk, e);
                Consider(cn, oa, ab, box, ref best, ref n);
                Consider(-cn, oa, ab, box, ref best, ref n);
            }
            if (box.Planar)
            {
                var cn = Vector3D.Cross(abk, Vector3D.UnitZ);
                Consider(cn, oa, ab, box, ref best, ref n);
                Consider(-cn, oa, ab, box, ref best, ref n);
            }
            if (!box.Planar)
                for (int v = 0; v < 8; v++)
                {
                    var corner = new Vector3D((v & 1) == 0 ? box.Lo.X : box.Hi.X, (v & 2) == 0 ? box.Lo.Y : box.Hi.Y, (v & 4) == 0 ? box.Lo.Z : box.Hi.Z);
                    Consider(VertexPerp(a, b, box, corner), oa, ab, box, ref best, ref n);
                }
            return n;
        }

        /// <summary>Takes direction v (from the axis toward the box) if its <see cref="BoxSupport"/> beats <paramref name="best"/>.</summary>
        private static void Consider(Vector3D v, Vector3D oa, Vector3D ab, in Box box, ref double best, ref Vector3D n)
        {
            if (v == default) return;
            var u = Unit(v, default);
            double h = BoxSupport(u, oa, ab, box);
            if (h > best) { best = h; n = u; }
        }

        /// <summary>
        /// The least of (box point − axis point)·u over the box and the axis [a, b] (oa = origin − a, ab = b − a): the
        /// box's least extent along u from its axes' projections, less the axis's greatest. Rounded (to a few u of the
        /// size): that is all a choice between push directions needs, as each pushes out to within its support's error.
        /// </summary>
        private static double BoxSupport(Vector3D u, Vector3D oa, Vector3D ab, in Box box)
        {
            double cx = Vector3D.Dot(box.X, u), cy = Vector3D.Dot(box.Y, u), cz = Vector3D.Dot(box.Z, u);
            return Vector3D.Dot(oa, u) + Math.Min(box.Lo.X * cx, box.Hi.X * cx) + Math.Min(box.Lo.Y * cy, box.Hi.Y * cy)
                + Math.Min(box.Lo.Z * cz, box.Hi.Z * cz) - Math.Max(0, Vector3D.Dot(ab, u));
        }

        /// <summary>
        /// The perpendicular from the axis's line through [a, b] to the box vertex at box-local corner c (from the axis
        /// toward the vertex), to about a rounding of itself (<see cref="PerpOfDifference"/>): the vertex's offset from
        /// a summed to about u² of itself per component, origin − a split exactly and the three axis products with their
        /// exact errors, by two-sums (the rounded vertex alone is off by u·size, which turns the normal by u·size/gap).
        /// Scaled by k, a power of two near 1/size, so 2^j-scaled inputs give the same direction, bit for bit.
        /// </summary>
        private static Vector3D VertexPerp(Vector3D a, Vector3D b, in Box box, Vector3D c)
        {
            // The offset's own size counts: at an AABB's min corner c is 0, and a k from c and a zero-length axis alone
            // (2^1022) overflowed the offset, so that vertex's normal depended on the scale (fuzz seed 122).
            double k = Num.InversePowerOfTwo(Range.MaxAbs(b - a, c, a - box.Origin));
            var ck = c * k;
            VertexOffset(box.Origin.X, a.X, box.X.X, box.Y.X, box.Z.X, ck, k, out double hx, out double lx);
            VertexOffset(box.Origin.Y, a.Y, box.X.Y, box.Y.Y, box.Z.Y, ck, k, out double hy, out double ly);
            VertexOffset(box.Origin.Z, a.Z, box.X.Z, box.Y.Z, box.Z.Z, ck, k, out double hz, out double lz);
            ExactDiff(b, a, k, out var dh, out var dl);
            return PerpOfDifference(new Vector3D(hx, hy, hz), new Vector3D(lx, ly, lz), dh, dl);
        }

        /// <summary>One component of (origin + x·c.X + y·c.Y + z·c.Z − a)·k as h + l (c already scaled by k).</summary>
        private static void VertexOffset(double origin, double a, double x, double y, double z, Vector3D ck, double k, out double h, out double l)
        {
            TwoDiff(origin, a, k, out h, out l);
            double px = x * ck.X, py = y * ck.Y, pz = z * ck.Z;
            l += ProductError(x, ck.X, px) + ProductError(y, ck.Y, py) + ProductError(z, ck.Z, pz);
            h = TwoSum(h, px, ref l);
            h = TwoSum(h, py, ref l);
            h = TwoSum(h, pz, ref l);
        }

        /// <summary>Whether a capsule meets a solid box: the axis does (the segment test), or its gap is at most r (as <see cref="CapsuleBox"/> decides).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool CapsuleBoxOverlaps(Vector3D a, Vector3D b, double r, in Box box, out bool inRange)
        {
            var ra = a - box.Origin;
            inRange = Range.Box(Num.Max(Num.Max(Range.MaxAbs(ra), r), Num.Max(Range.MaxAbs(b - box.Origin), Range.MaxAbs(box.Hi - box.Lo))));
            var la = box.ToLocal(ra);
            var ld = box.ToLocal(b - a);
            if (SegmentBoxOverlapsLocal(la - box.LocalCenter, ld, box.Half, box.Planar)) return true;
            double g = SegmentBoxLocal(la, ld, box.Lo, box.Hi, out _);
            inRange &= Range.In(g);
            return Math.Sqrt(g) - r <= 0;
        }
    }
}
