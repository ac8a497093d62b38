using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>A point against a shape: signed distance, the shape's witness point, and the unit normal from that point toward the query point (outward when inside).</summary>
    internal readonly struct PointContact
    {
        public readonly double Distance, DistanceSquared, Parameter;
        public readonly Vector3D Closest, Normal;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public PointContact(double distance, double distanceSquared, Vector3D closest, Vector3D normal, double parameter)
        {
            Distance = distance; DistanceSquared = distanceSquared; Closest = closest; Normal = normal; Parameter = parameter;
        }

        /// <summary>The point's result against the shape, as the pair (point, shape).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public DistanceResult3 AsPointFirst(Vector3D p) => new DistanceResult3(Distance, DistanceSquared, p, Closest, 0, Parameter);

        /// <summary>A sphere of the given radius centred at the query point: the same witness on the shape, distance less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public DistanceResult3 AsSphereFirst(Vector3D center, double radius)
        {
            double d = Distance - radius;
            return new DistanceResult3(d, d > 0 ? d * d : 0, center - Normal * radius, Closest, 0, Parameter);
        }
    }

    /// <summary>
    /// The algorithms, in double, shared by the double and float APIs. Inlining is chosen by measurement. Many small
    /// kernels are AggressiveInlining. Of the others, those above the JIT's default inline size (128 IL bytes) are
    /// mostly NoInlining: without PGO (and on Mono) the JIT does not inline them anyway, but dynamic PGO inlines callees
    /// of up to about 1,000 IL bytes at a hot call site, and merged into the caller's loop they ran up to 3× slower than
    /// called (ab against the previous commit, .NET 10: 2D segment–AABB 116 → 49 ns, line–capsule 266 → 100 ns). Those
    /// left without it measured slower with it: the ray casts, half-space pairs, several overlap tests and the 3D
    /// segment–triangle helpers.
    /// </summary>
    internal static partial class Kernels
    {
        /// <summary>
        /// Residual p − q from the closest point q = a + t·(b − a) of segment [a, b] to p. The residual is formed from the
        /// nearer endpoint so a point far along the line loses nothing to a large t·(b − a) (Eberly, "Distance from a point
        /// to a segment"; not the paper's Eq. 10, whose |w|² − (w·v)²/|v|² cancels catastrophically).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D PointSegmentResidual(Vector3D p, Vector3D a, Vector3D b, out double t) => PointSegmentResidual(p, a, b, out t, out _);

        /// <summary><see cref="PointSegmentResidual(Vector3D, Vector3D, Vector3D, out double)"/>, also giving dd = |b − a|².</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D PointSegmentResidual(Vector3D p, Vector3D a, Vector3D b, out double t, out double dd)
        {
            var d = b - a;
            var w = p - a;
            dd = d.LengthSquared;
            double wd = Vector3D.Dot(w, d);
            if (wd <= 0 || dd == 0) { t = 0; return w; }
            if (wd >= dd) { t = 1; return p - b; }
            t = wd / dd;
            return t <= 0.5 ? w - d * t : (p - b) + d * (1 - t);
        }

        /// <summary>
        /// The point at t of the segment [a, b], from the nearer end: a + (b − a)·t, or b − (b − a)·(1 − t). In plain
        /// doubles, each component as Vector3D's operations form it (the same bits): Mono keeps every Vector3D temporary
        /// in memory. With the vector form, a 3D segment–segment Between on Mono spent about 80 of its 210 ns forming its
        /// two points (ab, 2 × 7, two runs: that query 0.66–0.74 in plain doubles; .NET 10 within noise).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D SegmentPoint(Vector3D a, Vector3D b, double t)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, dz = b.Z - a.Z;
            if (t <= 0.5) return new Vector3D(a.X + dx * t, a.Y + dy * t, a.Z + dz * t);
            double u = 1 - t;
            return new Vector3D(b.X - dx * u, b.Y - dy * u, b.Z - dz * u);
        }

        /// <summary>
        /// Point against segment as the pair (point, segment): the distance, the segment's point and its parameter.
        /// <paramref name="inRange"/>: the squared gap and the segment's squared length lie in the fast range (see
        /// <see cref="Range"/>), or are exactly 0 because the residual vector is (the point on the segment, as touching
        /// inputs often are) or the segment is one point: a zero that no underflow made, answered here as the slow path
        /// would answer it.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // an out parameter on a call that is not inlined costs 4x here without PGO
        public static DistanceResult3 PointSegment(Vector3D p, Vector3D a, Vector3D b, out bool inRange)
        {
            double r2 = PointSegmentGap2(p, a, b, out double t, out double dd, out double rx, out double ry, out double rz);
            inRange = Range.Length2(rx, ry, rz, r2) && (Range.In(dd) || a == b);
            double ex = b.X - a.X, ey = b.Y - a.Y, ez = b.Z - a.Z; // SegmentPoint(a, b, t)
            var q = t <= 0.5 ? new Vector3D(a.X + ex * t, a.Y + ey * t, a.Z + ez * t) : new Vector3D(b.X - ex * (1 - t), b.Y - ey * (1 - t), b.Z - ez * (1 - t));
            return new DistanceResult3(Math.Sqrt(r2), r2, p, q, 0, t);
        }

        /// <summary>
        /// |<see cref="PointSegmentResidual(Vector3D, Vector3D, Vector3D, out double, out double)"/>|² and the residual
        /// (rx, ry, rz), in plain doubles from the same operations (the same bits): Mono keeps every Vector3D temporary in
        /// memory, and point–segment on Vector3D took 1.4 times as long there.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double PointSegmentGap2(in Vector3D p, in Vector3D a, in Vector3D b, out double t, out double dd, out double rx, out double ry, out double rz)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, dz = b.Z - a.Z, wx = p.X - a.X, wy = p.Y - a.Y, wz = p.Z - a.Z;
            dd = dx * dx + dy * dy + dz * dz;
            double wd = wx * dx + wy * dy + wz * dz;
            if (wd <= 0 || dd == 0) { t = 0; rx = wx; ry = wy; rz = wz; }
            else if (wd >= dd) { t = 1; rx = p.X - b.X; ry = p.Y - b.Y; rz = p.Z - b.Z; }
            else
            {
                t = wd / dd;
                if (t <= 0.5) { rx = wx - dx * t; ry = wy - dy * t; rz = wz - dz * t; }
                else { double u = 1 - t; rx = (p.X - b.X) + dx * u; ry = (p.Y - b.Y) + dy * u; rz = (p.Z - b.Z) + dz * u; }
            }
            return rx * rx + ry * ry + rz * rz;
        }

        /// <summary>
        /// 2^-28: below this fraction of a segment's length a point whose foot lies near an end takes its push-out normal
        /// from the exact inputs (which feature holds the pair is in doubt there, and the two candidates differ by a tilt
        /// along the axis, which leaves r·θ²/2 of overlap). Lower than <see cref="NearTouch"/>, as the residual is bounded
        /// tighter: formed from the nearer end, off by less than 1.3·u·length, so at this gap a radius r pushed along it
        /// leaves at most 7·u·r.
        /// </summary>
        private const double NearPoint = 3.7252902984619141E-09;

        /// <summary>NearPoint², for comparing squared gaps.</summary>
        private const double NearPoint2 = NearPoint * NearPoint;

        /// <summary>
        /// The unit direction of residual r (length <paramref name="len"/>) from segment [a, b]'s point at t toward a point:
        /// r's own, or <see cref="AnyPerpendicular"/> of the segment for a point on it or within 2^-49 of its length of an
        /// interior point, where r is all rounding. For callers that refine near-touch normals themselves.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Vector3D SegmentNormal(Vector3D r, double r2, double len, Vector3D a, Vector3D b, double t, double dd) =>
            len > 0 && !(r2 <= dd * 3.1554436208840472e-30 && t > 0 && t < 1) ? r * (1 / len) : AnyPerpendicular(b - a);

        /// <summary>The unit direction of r less its part along d (dd = |d|²): exact in direction in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static Vector3D Across(Vector3D r, Vector3D d, double dd)
        {
            r -= d * (Vector3D.Dot(r, d) / dd);
            return r * (1 / r.Length);
        }

        /// <summary>
        /// The unit direction from segment [a, b] to a point p near it, from the exact inputs (<see cref="EdgeVector"/>:
        /// the perpendicular or the difference to the nearer end, the foot placed by compensated dot products);
        /// <see cref="AnyPerpendicular"/> of the segment when p lies on it exactly. A foot t far inside (by 2^-16; its
        /// rounding is far less) goes straight to the perpendicular.
        /// </summary>
        private static Vector3D NearSegmentNormal(Vector3D p, Vector3D a, Vector3D b, double t)
        {
            double k = Num.InversePowerOfTwo(Range.MaxAbs(b - a));
            Vector3D v;
            if (Clear(t, 0, 1, 1))
            {
                ExactDiff(b, a, k, out var eh, out var el);
                v = AccuratePerp(p, a, k, eh, el);
            }
            else v = EdgeVector(p, a, b, k);
            return v != default ? Unit(v, default) : AnyPerpendicular(b - a);
        }

        /// <summary>
        /// Whether p lies on the closed segment [a, b]: the residual is exactly zero. <paramref name="inRange"/>: the
        /// segment's squared length lies in the fast range, or it is a point (then the test is p == a, exact).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointOnSegment(in Vector3D p, in Vector3D a, in Vector3D b, out bool inRange)
        {
            var r = PointSegmentResidual(p, a, b, out _, out double dd);
            inRange = Range.In(dd) || a == b;
            return r == default;
        }

        /// <summary>
        /// Whether segment [a, b] meets the closed sphere (center, radius). <paramref name="inRange"/>: the segment's
        /// squared length and r² lie in the fast range (<see cref="WithinRadius"/>: then a residual that overflowed means
        /// a far center), or the slow path answers.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentInSphere(Vector3D a, Vector3D b, Vector3D center, double radius, out bool inRange)
        {
            var r = PointSegmentResidual(center, a, b, out _, out double dd);
            bool within = WithinRadius(r.LengthSquared, radius, out inRange);
            inRange &= Range.In(dd);
            return within;
        }

        /// <summary>A unit vector perpendicular to d, in the z = 0 plane whenever d is (so the 2D API stays planar); +X for d = 0.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)] // on rare branches only, where a call would spill the caller's inputs
        public static Vector3D AnyPerpendicular(Vector3D d)
        {
            double m = Range.MaxAbs(d);
            if (m > 0) d *= Num.InversePowerOfTwo(m); // exact, so tiny and huge directions get the same unit vector
            var n = new Vector3D(d.Y, -d.X, 0);
            if (n.LengthSquared == 0) n = new Vector3D(0, d.Z, -d.Y);
            double len = n.Length;
            return len > 0 ? n / len : Vector3D.UnitX;
        }

        /// <summary>
        /// v normalised, or the fallback for a zero v. Scaled by a power of two first (exact), so |v|² neither overflows
        /// nor underflows for any finite v: the witnesses' difference of a tiny gap, or a cross product of tiny or huge
        /// directions, still gives a unit vector.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Unit(Vector3D v, Vector3D fallback)
        {
            double m = Range.MaxAbs(v);
            if (m == 0) return fallback;
            v *= Num.InversePowerOfTwo(m);
            return v / v.Length;
        }

        /// <summary>Point against sphere; <paramref name="inRange"/> tells whether the squared gap could be trusted (see <see cref="Range"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static PointContact PointSphere(Vector3D p, Vector3D center, double radius, out bool inRange)
        {
            var r = p - center;
            double r2 = r.LengthSquared, len = Math.Sqrt(r2);
            inRange = Range.Length2(r, r2); // an exact 0 (the point at the centre) is no underflow
            // Coincident centres have no preferred direction: +X is documented and keeps the 2D API planar.
            var n = len > 0 ? r * (1 / len) : Vector3D.UnitX;
            double d = len - radius;
            return new PointContact(d, d > 0 ? d * d : 0, center + n * radius, n, 0);
        }

        /// <summary>
        /// Point against a solid box. Outside: clamp in the box frame (Ericson, RTCD §5.1.3). Inside or on the boundary:
        /// the nearest face gives the penetration depth and its outward normal; ties go to the lower axis, Lo before Hi.
        /// <paramref name="inRange"/>: the squared gap could be trusted, or, inside, the depth is far above the
        /// subnormal range (a point-sized box at the origin could otherwise swallow a subnormal offset).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static PointContact PointBox(Vector3D p, in Box box, out bool inRange)
        {
            var q = box.ToLocal(p - box.Origin);
            var c = new Vector3D(Num.Clamp(q.X, box.Lo.X, box.Hi.X), Num.Clamp(q.Y, box.Lo.Y, box.Hi.Y), Num.Clamp(q.Z, box.Lo.Z, box.Hi.Z));
            if (q != c) return PointBoxOutside(p, box, q, c, false, out inRange);

            double depth = NearestFace(q, box.Lo, box.Hi, box.Planar, out int face);
            inRange = depth >= Range.Lo;
            var onFace = FacePoint(q, box.Lo, box.Hi, face);
            return new PointContact(-depth, 0, box.Origin + box.ToWorldOffset(onFace), box.ToWorldOffset(FaceNormal(face)), 0);
        }

        /// <summary>
        /// <see cref="PointBox"/> outside the box, from its box-frame point q and the clamp c: the decision is made in the
        /// box frame; the gap is measured in world space from p − origin, which carries one rounding per component
        /// instead of a rotated copy's three. <paramref name="near"/>: the normal from <see cref="NearBoxNormal"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static PointContact PointBoxOutside(Vector3D p, in Box box, Vector3D q, Vector3D c, bool near, out bool inRange)
        {
            var offset = box.ToWorldOffset(c);
            var diff = (p - box.Origin) - offset;
            double d2 = diff.LengthSquared;
            // Within 2^-26 of the box point's own magnitude (q's rounding is u of it): out of line, returned directly so
            // nothing here is kept across the call.
            if (!near && d2 < NearTouch2 * c.LengthSquared) return PointBoxNear(p, box, q, c, out inRange);
            double d = Math.Sqrt(d2);
            var normal = d > 0 ? diff * (1 / d) : box.ToWorldOffset(Unit(q - c));
            if (near) normal = NearBoxNormal(p, box, c, normal);
            inRange = Range.In(d2);
            return new PointContact(d, d2, box.Origin + offset, normal, 0);
        }

        /// <summary><see cref="PointBoxOutside"/> with the near-touch normal, out of line (rare).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static PointContact PointBoxNear(Vector3D p, in Box box, Vector3D q, Vector3D c, out bool inRange) =>
            PointBoxOutside(p, box, q, c, true, out inRange);

        /// <summary>
        /// The unit normal from a box to a point just outside it (within 2^-26 of the size). The rounded residual turns by
        /// about u·size/gap there (the point's box-frame coordinates carry u·size), and a sphere pushed out along it
        /// leaves radius·angle²/2 of overlap (a sphere 1e-13 from an OBB edge: 3e-9). So each box-frame coordinate's
        /// excess over its slab is formed to about a rounding of itself (<see cref="SlabExcess"/>) and rotated back;
        /// <paramref name="fallback"/> (the rounded residual's direction) if that underflows.
        /// </summary>
        private static Vector3D NearBoxNormal(Vector3D p, in Box box, Vector3D c, Vector3D fallback)
        {
            // Scaled by k, a power of two near 1/|c| (exact), so the error terms stay clear of underflow and 2^j-scaled
            // inputs give the same direction, bit for bit; |p − origin| too, as c is 0 at an AABB's min corner.
            double k = Num.InversePowerOfTwo(Num.Max(Range.MaxAbs(c), Range.MaxAbs(p - box.Origin)));
            ExactDiff(p, box.Origin, k, out var wh, out var wl);
            Vector3D lo = box.Lo * k, hi = box.Hi * k;
            var r = new Vector3D(SlabExcess(box.X, wh, wl, lo.X, hi.X), SlabExcess(box.Y, wh, wl, lo.Y, hi.Y),
                SlabExcess(box.Z, wh, wl, lo.Z, hi.Z));
            if (r != default) return Unit(box.ToWorldOffset(r), fallback);
            // Inside or on the box after all (q's rounding put it out): the normal of a face c lies on, as for a point
            // inside; the rounded residual's direction is then only rounding (at a corner, anywhere between the faces).
            NearestFace(c, box.Lo, box.Hi, box.Planar, out int face);
            return box.ToWorldOffset(FaceNormal(face));
        }

        /// <summary>
        /// x − clamp(x, lo, hi) for x = axis·(wh + wl), to about a rounding of itself: the products with their exact
        /// errors, summed with exact two-sums before the bound is taken off (a compensated dot product, Ogita–Rump–Oishi).
        /// </summary>
        private static double SlabExcess(Vector3D axis, Vector3D wh, Vector3D wl, double lo, double hi)
        {
            double above = OffsetFrom(axis, wh, wl, hi);
            if (above > 0) return above;
            double below = OffsetFrom(axis, wh, wl, lo);
            return below < 0 ? below : 0;
        }

        /// <summary>axis·(wh + wl) − bound to about a rounding of itself.</summary>
        private static double OffsetFrom(Vector3D axis, Vector3D wh, Vector3D wl, double bound)
        {
            double px = axis.X * wh.X, py = axis.Y * wh.Y, pz = axis.Z * wh.Z;
            double err = ProductError(axis.X, wh.X, px) + ProductError(axis.Y, wh.Y, py) + ProductError(axis.Z, wh.Z, pz);
            double s = TwoSum(px, py, ref err);
            s = TwoSum(s, pz, ref err);
            s = TwoSum(s, -bound, ref err);
            return s + (err + Vector3D.Dot(axis, wl));
        }

        /// <summary>a + b rounded, its exact rounding error added to <paramref name="err"/> (Knuth).</summary>
        private static double TwoSum(double a, double b, ref double err)
        {
            double s = a + b, bv = s - a, av = s - bv;
            err += (a - av) + (b - bv);
            return s;
        }

        /// <summary>The distance of <see cref="PointSegment"/> alone, from the same operations (so the same bits) and the same <paramref name="inRange"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointSegmentDistance(in Vector3D p, in Vector3D a, in Vector3D b, out bool inRange)
        {
            double r2 = PointSegmentGap2(p, a, b, out _, out double dd, out double rx, out double ry, out double rz);
            inRange = Range.Length2(rx, ry, rz, r2) && (Range.In(dd) || a == b);
            return Math.Sqrt(r2);
        }

        /// <summary>The distance of <see cref="PointSphere"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointSphereDistance(Vector3D p, Vector3D center, double radius, out bool inRange)
        {
            var r = p - center;
            double r2 = r.LengthSquared;
            inRange = Range.Length2(r, r2);
            return Math.Sqrt(r2) - radius;
        }

        /// <summary>The distance of <see cref="PointBox"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointBoxDistance(Vector3D p, in Box box, out bool inRange)
        {
            var q = box.ToLocal(p - box.Origin);
            var c = new Vector3D(Num.Clamp(q.X, box.Lo.X, box.Hi.X), Num.Clamp(q.Y, box.Lo.Y, box.Hi.Y), Num.Clamp(q.Z, box.Lo.Z, box.Hi.Z));
            if (q != c)
            {
                double d2 = ((p - box.Origin) - box.ToWorldOffset(c)).LengthSquared;
                inRange = Range.In(d2);
                return Math.Sqrt(d2);
            }
            double depth = NearestFace(q, box.Lo, box.Hi, box.Planar, out _);
            inRange = depth >= Range.Lo;
            return -depth;
        }

        /// <summary>The distance of <see cref="PointAabb"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointAabbDistance(in Vector3D p, in Vector3D min, in Vector3D max, bool planar, out bool inRange)
        {
            // In plain doubles, as PointAabbPair. A difference of doubles is 0 exactly when they are equal (subnormals
            // included), so the tests of x, y, z are p ≠ clamp(p).
            double x = p.X - Num.Clamp(p.X, min.X, max.X), y = p.Y - Num.Clamp(p.Y, min.Y, max.Y), z = p.Z - Num.Clamp(p.Z, min.Z, max.Z);
            if (x != 0 || y != 0 || z != 0)
            {
                double d2 = x * x + y * y + z * z;
                inRange = Range.In(d2);
                return Math.Sqrt(d2);
            }
            inRange = true;
            return -NearestFace(p, min, max, planar, out _);
        }

        /// <summary>
        /// <see cref="PointAabb"/> as the pair (point, box), without the normal: in plain doubles from the same
        /// operations (the same bits), as Mono keeps every Vector3D temporary in memory.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 PointAabbPair(Vector3D p, Vector3D min, Vector3D max, bool planar, out bool inRange)
        {
            double cx = Num.Clamp(p.X, min.X, max.X), cy = Num.Clamp(p.Y, min.Y, max.Y), cz = Num.Clamp(p.Z, min.Z, max.Z);
            double x = p.X - cx, y = p.Y - cy, z = p.Z - cz;
            if (x != 0 || y != 0 || z != 0)
            {
                double d2 = x * x + y * y + z * z;
                inRange = Range.In(d2);
                return new DistanceResult3(Math.Sqrt(d2), d2, p, new Vector3D(cx, cy, cz), 0, 0);
            }
            inRange = true;
            double depth = NearestFace(p, min, max, planar, out int face);
            return new DistanceResult3(-depth, 0, p, FacePoint(p, min, max, face), 0, 0);
        }

        /// <summary>
        /// Point against an axis-aligned box given by its corners. The clamp is exact in world coordinates and the gap is
        /// one subtraction per axis, so this is both the fastest and the most accurate form for AABBs.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static PointContact PointAabb(Vector3D p, Vector3D min, Vector3D max, bool planar, out bool inRange)
        {
            var c = new Vector3D(Num.Clamp(p.X, min.X, max.X), Num.Clamp(p.Y, min.Y, max.Y), Num.Clamp(p.Z, min.Z, max.Z));
            if (p != c)
            {
                var diff = p - c;
                double d2 = diff.LengthSquared;
                double d = Math.Sqrt(d2);
                inRange = Range.In(d2);
                return new PointContact(d, d2, c, d > 0 ? diff * (1 / d) : Unit(diff / Range.MaxAbs(diff)), 0);
            }
            // Inside, the depth is a difference of coordinates: exact up to one rounding at any magnitude.
            inRange = true;
            double depth = NearestFace(p, min, max, planar, out int face);
            return new PointContact(-depth, 0, FacePoint(p, min, max, face), FaceNormal(face), 0);
        }

        /// <summary>
        /// Depth of a point inside [lo, hi] below its nearest face; face = 2·axis + (1 for the hi face). Ties go to the
        /// lower axis and the lo face. Planar boxes skip z.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double NearestFace(Vector3D q, Vector3D lo, Vector3D hi, bool planar, out int face)
        {
            double best = q.X - lo.X, t;
            face = 0;
            if ((t = hi.X - q.X) < best) { best = t; face = 1; }
            if ((t = q.Y - lo.Y) < best) { best = t; face = 2; }
            if ((t = hi.Y - q.Y) < best) { best = t; face = 3; }
            if (!planar)
            {
                if ((t = q.Z - lo.Z) < best) { best = t; face = 4; }
                if ((t = hi.Z - q.Z) < best) { best = t; face = 5; }
            }
            return best;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D FacePoint(Vector3D q, Vector3D lo, Vector3D hi, int face) => face switch
        {
            0 => new Vector3D(lo.X, q.Y, q.Z),
            1 => new Vector3D(hi.X, q.Y, q.Z),
            2 => new Vector3D(q.X, lo.Y, q.Z),
            3 => new Vector3D(q.X, hi.Y, q.Z),
            4 => new Vector3D(q.X, q.Y, lo.Z),
            _ => new Vector3D(q.X, q.Y, hi.Z),
        };

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D FaceNormal(int face) => face switch
        {
            0 => new Vector3D(-1, 0, 0),
            1 => new Vector3D(1, 0, 0),
            2 => new Vector3D(0, -1, 0),
            3 => new Vector3D(0, 1, 0),
            4 => new Vector3D(0, 0, -1),
            _ => new Vector3D(0, 0, 1),
        };

        private static Vector3D Unit(Vector3D v) => v / v.Length;

        /// <summary>
        /// Whether p lies in the closed box (no square root). A point-sized box is compared exactly: a subnormal offset
        /// could otherwise vanish in the rotation.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointInBox(Vector3D p, in Box box)
        {
            var q = box.ToLocal(p - box.Origin);
            return q.X >= box.Lo.X && q.X <= box.Hi.X && q.Y >= box.Lo.Y && q.Y <= box.Hi.Y && q.Z >= box.Lo.Z && q.Z <= box.Hi.Z
                && (box.Lo != box.Hi || p == box.Origin + box.ToWorldOffset(box.Lo));
        }

        /// <summary>Whether p lies in the closed sphere; <paramref name="inRange"/> as for <see cref="WithinRadius"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointInSphere(in Vector3D p, in Vector3D center, double radius, out bool inRange) =>
            WithinRadius(Vec.Distance2(p, center), radius, out inRange);

        /// <summary>
        /// Point against point, symmetric by construction: the witnesses are the points themselves and |b − a| = |a − b|
        /// bit for bit. <paramref name="inRange"/> as for <see cref="PointSphere"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 PointPoint(Vector3D a, Vector3D b, out bool inRange)
        {
            var d = b - a;
            double d2 = d.LengthSquared;
            inRange = Range.Length2(d, d2); // equal points: an exact 0, no underflow
            return new DistanceResult3(Math.Sqrt(d2), d2, a, b, 0, 0);
        }

        /// <summary>
        /// Sphere against sphere, symmetric by construction: swapping the spheres negates d and n exactly and the radii
        /// are summed (which commutes), so the swapped answer is this one with its witnesses swapped, bit for bit.
        /// Coincident centres: the sphere first in the canonical order (the smaller radius) is pushed along +X, the other
        /// along −X, whichever argument it is. In plain doubles, as Vector3D's operations would form them (the same
        /// bits): Mono keeps every Vector3D temporary in memory, and this query on Vector3D took 1.3 times as long there.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 SphereSphere(Vector3D ca, double ra, Vector3D cb, double rb, out bool inRange)
        {
            double dx = cb.X - ca.X, dy = cb.Y - ca.Y, dz = cb.Z - ca.Z;
            double d2 = dx * dx + dy * dy + dz * dz, len = Math.Sqrt(d2);
            double nx, ny, nz;
            if (len > 0) { double inverse = 1 / len; nx = dx * inverse; ny = dy * inverse; nz = dz * inverse; }
            else if (Order.Before(ca, ra, cb, rb)) { nx = -1; ny = -0.0; nz = -0.0; } // −UnitX
            else { nx = 1; ny = 0; nz = 0; }
            double r = ra + rb, dist = len - r;
            // As for a point and a sphere of radius ra + rb; that sum is the only other quantity that could overflow while
            // the answer is finite.
            inRange = Range.Length2(dx, dy, dz, d2) & r <= double.MaxValue;
            // Shapes store no −0 (see Num.NoNegativeZero), so where the centres agree in a coordinate d is +0 in either
            // order and the witnesses' zero signs agree too.
            return new DistanceResult3(dist, dist > 0 ? dist * dist : 0, new Vector3D(ca.X + nx * ra, ca.Y + ny * ra, ca.Z + nz * ra),
                new Vector3D(cb.X - nx * rb, cb.Y - ny * rb, cb.Z - nz * rb), 0, 0);
        }

        /// <summary>The distance of <see cref="PointPoint"/> alone.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointPointDistance(Vector3D a, Vector3D b, out bool inRange)
        {
            var d = b - a;
            double d2 = d.LengthSquared;
            inRange = Range.Length2(d, d2);
            return Math.Sqrt(d2);
        }

        /// <summary>The distance of <see cref="SphereSphere"/> alone (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double SphereSphereDistance(in Vector3D ca, double ra, in Vector3D cb, double rb, out bool inRange)
        {
            double dx = cb.X - ca.X, dy = cb.Y - ca.Y, dz = cb.Z - ca.Z;
            double d2 = dx * dx + dy * dy + dz * dz;
            double r = ra + rb;
            inRange = Range.Length2(dx, dy, dz, d2) & r <= double.MaxValue;
            return Math.Sqrt(d2) - r;
        }

        /// <summary>Whether p lies in the closed axis-aligned box [min, max].</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointInAabb(in Vector3D p, in Vector3D min, in Vector3D max) =>
            p.X >= min.X && p.X <= max.X && p.Y >= min.Y && p.Y <= max.Y && p.Z >= min.Z && p.Z <= max.Z;

        /// <summary>Squared distance from p to the closed axis-aligned box (Arvo's test without the square root); 0 inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointAabbDistanceSquared(Vector3D p, Vector3D min, Vector3D max)
        {
            double dx = p.X - Num.Clamp(p.X, min.X, max.X);
            double dy = p.Y - Num.Clamp(p.Y, min.Y, max.Y);
            double dz = p.Z - Num.Clamp(p.Z, min.Z, max.Z);
            return dx * dx + dy * dy + dz * dz;
        }

        /// <summary>Squared distance from p to the closed box (Arvo's test in the box's frame); 0 inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointBoxDistanceSquared(Vector3D p, in Box box)
        {
            var q = box.ToLocal(p - box.Origin);
            double dx = q.X - Num.Clamp(q.X, box.Lo.X, box.Hi.X);
            double dy = q.Y - Num.Clamp(q.Y, box.Lo.Y, box.Hi.Y);
            double dz = q.Z - Num.Clamp(q.Z, box.Lo.Z, box.Hi.Z);
            return dx * dx + dy * dy + dz * dz;
        }

        /// <summary>
        /// The verdict d2 ≤ r² of a ball test. <paramref name="inRange"/>: r² lies in the fast range. That is enough when
        /// d2 is a squared distance that overflows (or turns NaN from an overflowed difference) only if the true one is
        /// far above 2^960 (a difference of two points, a clamp against a box of moderate size, a residual from a segment
        /// whose length is in range): then false is right. A d2 that underflowed lies below 2^-960 whatever its rounding,
        /// far under r², and true is right. So d2 needs no check, and r² depends on the radius alone, off the path to the
        /// verdict: the check is most of this test's cost over the bare comparison. A radius of 0 (or below 2^-480) takes
        /// the slow path. A line's residual does not qualify (a far origin, a near line): see <see cref="LinearInBall"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool WithinRadius(double d2, double radius, out bool inRange)
        {
            double rr = radius * radius;
            inRange = Range.In(rr);
            return d2 <= rr;
        }
    }

    internal static class Vec
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Get(Vector3D v, int i) => i == 0 ? v.X : (i == 1 ? v.Y : v.Z);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D With(Vector3D v, int i, double value) =>
            i == 0 ? new Vector3D(value, v.Y, v.Z) : (i == 1 ? new Vector3D(v.X, value, v.Z) : new Vector3D(v.X, v.Y, value));

        /// <summary>(a − b).LengthSquared in plain doubles, the same bits: on Mono without a Vector3D temporary in memory.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Distance2(in Vector3D a, in Vector3D b)
        {
            double x = a.X - b.X, y = a.Y - b.Y, z = a.Z - b.Z;
            return x * x + y * y + z * z;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector3D Abs(Vector3D v) => new Vector3D(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));
    }
}
