using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A triangle prepared for the kernels, in a frame scaled by a power of two K (exact) chosen from the whole
    /// configuration's size, so every product below stays far from overflow and underflow. N = E1 × E2 is formed with
    /// exact products (<see cref="Kernels.AccurateCross"/>): its direction is then right to a few ulps of the rounded
    /// edges even for a sliver, where the plain cross product's is off by u/sinθ (a height error of u·S/sinθ). Flat: the
    /// sine of the angle at A is below 2^-52 (the triangle lies within 2u·S of its edges, which answer it exactly as
    /// the segment or point it then is) or |N| is below 2^-300 of the configuration (it would have lost bits; the
    /// triangle is then thinner than that).
    /// </summary>
    internal readonly struct TriFrame
    {
        /// <summary>The vertices, as given.</summary>
        public readonly Vector3D A, B, C;
        /// <summary>The scaled edges (B − A)·K, (C − A)·K, (C − B)·K and normal E1 × E2 (zero when flat).</summary>
        public readonly Vector3D E1, E2, E3, N;
        /// <summary>N / |N| (zero when flat).</summary>
        public readonly Vector3D Unit;
        public readonly double K;
        public readonly bool Flat;

        private const double Sliver2 = 4.930380657631324e-32;   // 2^-104: sin² of the angle at A
        private const double Tiny2 = 2.409919865102884e-181;    // 2^-600: |N|² in the scaled frame

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public TriFrame(Vector3D a, Vector3D b, Vector3D c, double k)
        {
            A = a; B = b; C = c; K = k;
            E1 = (b - a) * k;
            E2 = (c - a) * k;
            E3 = (c - b) * k;
            var n = Kernels.AccurateCross(E1, E2);
            double nn = n.LengthSquared;
            Flat = !(nn >= Tiny2 && nn >= Sliver2 * (E1.LengthSquared * E2.LengthSquared));
            N = Flat ? default : n;
            Unit = Flat ? default : n / Math.Sqrt(nn);
        }

        /// <summary>Whether x projects into the closed triangle along N: on the inner side of every edge (not flat only).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public bool Inside(Vector3D x) =>
            Vector3D.Dot(Vector3D.Cross(E1, (x - A) * K), N) >= 0
            && Vector3D.Dot(Vector3D.Cross(E3, (x - B) * K), N) >= 0
            && Vector3D.Dot(Vector3D.Cross((x - C) * K, E2), N) >= 0;

        /// <summary>Edge i (0: A→B, 1: B→C, 2: C→A). Inlined, as is Kernels.Crossing:
        /// without dynamic PGO the JIT kept them calls, and 3D segment–triangle ran 1.4× slower.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Edge(int i, out Vector3D from, out Vector3D to)
        {
            from = i == 0 ? A : (i == 1 ? B : C);
            to = i == 0 ? B : (i == 1 ? C : A);
        }

        /// <summary>The squared size of a configuration made of this triangle and the points p, q (relative to A).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Size2(Vector3D a, Vector3D b, Vector3D c, Vector3D p, Vector3D q) =>
            (b - a).LengthSquared + (c - a).LengthSquared + (p - a).LengthSquared + (q - a).LengthSquared;
    }

    /// <summary>A segment's ends and a triangle's vertices as given, before any shift of frame.</summary>
    internal readonly struct TriangleInputs
    {
        public readonly Vector3D P0, P1, A, B, C;

        public TriangleInputs(Vector3D p0, Vector3D p1, Vector3D a, Vector3D b, Vector3D c)
        {
            P0 = p0; P1 = p1; A = a; B = b; C = c;
        }

        /// <summary>Edge i of the triangle (0: A→B, 1: B→C, 2: C→A), as <see cref="TriFrame.Edge"/>.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public void Edge(int i, out Vector3D from, out Vector3D to)
        {
            from = i == 0 ? A : (i == 1 ? B : C);
            to = i == 0 ? B : (i == 1 ? C : A);
        }
    }

    internal static partial class Kernels
    {
        // ---- Exact products (Dekker): the same bits on every runtime, no fused multiply-add needed (shared with the linear kernels) ----

        private const double Splitter = 134217729.0; // 2^27 + 1

        /// <summary>The rounding error a·b − fl(a·b) exactly (Dekker's two-product; exact while nothing over- or underflows).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double ProductError(double a, double b, double p)
        {
            double ca = Splitter * a, ah = ca - (ca - a), al = a - ah;
            double cb = Splitter * b, bh = cb - (cb - b), bl = b - bh;
            return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
        }

        /// <summary>
        /// a·b − c·d to about one rounding of the result (Kahan's problem): the rounded products' difference is exact when
        /// they cancel (Sterbenz), and their exact rounding errors are added back.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DiffOfProducts(double a, double b, double c, double d)
        {
            double p = a * b, q = c * d;
            return (p - q) + (ProductError(a, b, p) - ProductError(c, d, q));
        }

        /// <summary>u × v with each component to about one rounding of itself (see <see cref="DiffOfProducts"/>).</summary>
        internal static Vector3D AccurateCross(Vector3D u, Vector3D v) =>
            new Vector3D(DiffOfProducts(u.Y, v.Z, u.Z, v.Y), DiffOfProducts(u.Z, v.X, u.X, v.Z), DiffOfProducts(u.X, v.Y, u.Y, v.X));

        // ---- Point against triangle ----

        /// <summary>
        /// Point against a 3D triangle (not solid). Projecting into the triangle: the height over its plane, measured from
        /// A along the accurate unit normal (so a sliver costs no accuracy). Otherwise, or flat: the nearest of the three
        /// edges (every closest point outside the projection lies on the boundary), the first of equal ones.
        /// <paramref name="fine"/>: the squared gap is in the fast range or exactly 0. The normal is the unit direction from
        /// the triangle's point toward p; the plane normal (+N) for a point on a non-flat triangle. Near touching it is
        /// formed exactly (<see cref="NearPointTriangleNormal"/>) only <paramref name="withNormal"/>: a point's result,
        /// and a segment's ends, never read it.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static PointContact PointTriangle(Vector3D p, in TriFrame f, bool withNormal, out bool fine)
        {
            if (!f.Flat && f.Inside(p))
            {
                double h = Vector3D.Dot((p - f.A) * f.K, f.Unit) / f.K;
                double dist = Math.Abs(h), d2 = dist * dist;
                fine = h == 0 || Range.In(d2);
                var up = h < 0 ? -f.Unit : f.Unit;
                // Near touching: out of line, in tail position, so nothing here is kept in memory across the call.
                if (withNormal && dist > 0 && dist * f.K < NearTouch) return NearPointTriangle(p, f, true, up, dist, d2, p - f.Unit * h);
                return new PointContact(dist, d2, p - f.Unit * h, up, 0);
            }
            double g = NearestEdge(p, f, out int edge, out double t, out var r);
            f.Edge(edge, out var v0, out var v1);
            double len = Math.Sqrt(g);
            fine = Range.Length2(r, g);
            var normal = len > 0 ? SegmentNormal(r, g, len, v0, v1, t, (v1 - v0).LengthSquared) : (f.Flat ? AnyPerpendicular(Longest(f)) : f.Unit);
            if (withNormal && len > 0 && len * f.K < NearTouch) return NearPointTriangle(p, f, !f.Flat, normal, len, g, SegmentPoint(v0, v1, t));
            return new PointContact(len, g, SegmentPoint(v0, v1, t), normal, 0);
        }

        /// <summary>A point-triangle contact with <see cref="NearPointTriangleNormal"/>'s normal, out of line (rare).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static PointContact NearPointTriangle(Vector3D p, in TriFrame f, bool face, Vector3D fallback, double dist, double d2, Vector3D closest) =>
            new PointContact(dist, d2, closest, NearPointTriangleNormal(p, f, face, fallback), 0);

        /// <summary>
        /// The unit normal from a triangle to a point p near it (within 2^-26 of the size). The rounded residual turns by
        /// u·S/gap there, and whether the foot is over the face, on an edge or at a vertex is as uncertain, so each
        /// feature's normal is formed from the exact inputs (the plane's normal either way when <paramref name="face"/>,
        /// each edge's <see cref="EdgeVector"/>), and the one whose plane leaves the triangle farthest on its far side
        /// (the least of (p − vertex)·n, each by a compensated dot product) is taken: the exact normal's is the distance
        /// itself, and one within δ of it pushes out to within δ. The supports carry the rounding of the unit vectors
        /// times the size (a gap of 4e-17 at size 5 can measure slightly negative), so the largest is taken whatever
        /// its sign; <paramref name="fallback"/> only when every candidate is zero.
        /// </summary>
        private static Vector3D NearPointTriangleNormal(Vector3D p, in TriFrame f, bool face, Vector3D fallback)
        {
            double best = double.NegativeInfinity;
            var n = fallback;
            if (face)
            {
                ConsiderFrom(f.Unit, p, f, ref best, ref n);
                ConsiderFrom(-f.Unit, p, f, ref best, ref n);
            }
            for (int i = 0; i < 3; i++)
            {
                f.Edge(i, out var v0, out var v1);
                ConsiderFrom(EdgeVector(p, v0, v1, f.K), p, f, ref best, ref n);
            }
            return n;
        }

        /// <summary>Takes direction v (from the triangle toward p) if the least of (p − vertex)·v̂ beats <paramref name="best"/>.</summary>
        private static void ConsiderFrom(Vector3D v, Vector3D p, in TriFrame f, ref double best, ref Vector3D n)
        {
            if (v == default) return;
            var u = Unit(v, default);
            double h = Math.Min(Support(u, p, f.A, f.K), Math.Min(Support(u, p, f.B, f.K), Support(u, p, f.C, f.K)));
            if (h > best) { best = h; n = u; }
        }

        /// <summary>The squared distance from p to the nearest edge of the triangle (the first of equal ones), its index, parameter and residual.</summary>
        private static double NearestEdge(Vector3D p, in TriFrame f, out int edge, out double t, out Vector3D r)
        {
            r = PointSegmentResidual(p, f.A, f.B, out t);
            double best = r.LengthSquared;
            edge = 0;
            var r1 = PointSegmentResidual(p, f.B, f.C, out double t1);
            double g = r1.LengthSquared;
            if (g < best) { best = g; edge = 1; r = r1; t = t1; }
            r1 = PointSegmentResidual(p, f.C, f.A, out t1);
            g = r1.LengthSquared;
            if (g < best) { best = g; edge = 2; r = r1; t = t1; }
            return best;
        }

        /// <summary>Point against a 3D triangle (<paramref name="withNormal"/>: as above); <paramref name="inRange"/>: the configuration's squared size and the squared gap are in the fast range.</summary>
        public static PointContact PointTriangle(Vector3D p, Vector3D a, Vector3D b, Vector3D c, bool withNormal, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p, p);
            var r = PointTriangle(p, new TriFrame(a, b, c, InverseSizeScale(size2)), withNormal, out bool fine);
            inRange = fine & (Range.In(size2) | (a == b & a == c & a == p));
            return r;
        }

        /// <summary>
        /// Whether p lies on a 3D triangle: the decision of <see cref="PointTriangle(Vector3D, in TriFrame, bool, out bool)"/>
        /// with its height or edge residual exactly zero (no underflowed square decides it).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointOnTriangle(Vector3D p, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p, p);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            inRange = Range.In(size2) | (a == b & a == c & a == p);
            if (!f.Flat && f.Inside(p)) return Vector3D.Dot((p - f.A) * f.K, f.Unit) == 0;
            NearestEdge(p, f, out _, out _, out var r);
            return r == default;
        }

        /// <summary>
        /// Point against a solid 2D triangle (z = 0). Inside or on the boundary (on the inner side of every edge, the
        /// triangle not flat): minus the distance to the nearest edge, the normal that edge's outward normal. Outside, or
        /// flat (no interior: the segment or point it is): the nearest edge, its normal near touching formed exactly
        /// (<see cref="NearPointTriangleNormal"/>) when <paramref name="withNormal"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static PointContact PointTriangle2(Vector3D p, Vector3D a, Vector3D b, Vector3D c, bool withNormal, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p, p);
            double k = InverseSizeScale(size2);
            var f = new TriFrame(a, b, c, k);
            double g = NearestEdge(p, f, out int edge, out double t, out var r);
            f.Edge(edge, out var v0, out var v1);
            double len = Math.Sqrt(g);
            inRange = Range.Length2(r, g) & (Range.In(size2) | (a == b & a == c & a == p));
            double area = Area2(f);
            if (area != 0 && Inside2(p, f, area))
            {
                return new PointContact(len > 0 ? -len : 0, 0, SegmentPoint(v0, v1, t), Outward2(v1 - v0, area), 0);
            }
            var normal = len > 0 ? SegmentNormal(r, g, len, v0, v1, t, (v1 - v0).LengthSquared) : (area != 0 ? Outward2(v1 - v0, area) : AnyPerpendicular(Longest(f)));
            if (withNormal && len > 0 && len * k < NearTouch) return NearPointTriangle(p, f, false, normal, len, g, SegmentPoint(v0, v1, t));
            return new PointContact(len, g, SegmentPoint(v0, v1, t), normal, 0);
        }

        /// <summary>
        /// The orientation of a 2D triangle as −1, 0 or +1: the exact sign of (B − A) × (C − A) for the given vertices. The
        /// rounded edges decide it when their cross product (formed with exact products) is clear of their rounding;
        /// otherwise the exact value is summed without error. Exactness matters here: a triangle with any area is a solid
        /// (a segment crossing a sliver is inside it by up to the sliver's length), a flat one is the segment it is.
        /// </summary>
        private static double Area2(in TriFrame f) => Area2(f, f.A, f.B, f.C);

        /// <summary>
        /// <see cref="Area2(in TriFrame)"/> for a frame built on the vertices moved (rounded) into another frame: the edges
        /// E1, E2 are the rounded differences of the given vertices a, b, c either way, and the exact sign is theirs.
        /// </summary>
        private static double Area2(in TriFrame f, Vector3D a, Vector3D b, Vector3D c)
        {
            double area = DiffOfProducts(f.E1.X, f.E2.Y, f.E1.Y, f.E2.X);
            if (Math.Abs(area) > 4.440892098500626e-16 * (Math.Abs(f.E1.X * f.E2.Y) + Math.Abs(f.E1.Y * f.E2.X))) return Math.Sign(area);
            return OrientationSign(a, b, c, f.K);
        }

        /// <summary>
        /// The exact sign of (b − a) × (c − a) (x, y only): each difference exactly as two doubles (Knuth's two-sum), scaled
        /// by the power of two k (exact, and far from underflow), the eight products exactly as two doubles each (Dekker),
        /// summed into a non-overlapping expansion (Shewchuk's grow-expansion, zeros dropped) whose largest component has
        /// the sign of the sum.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double OrientationSign(Vector3D a, Vector3D b, Vector3D c, double k)
        {
            TwoDiff(b.X, a.X, k, out double h1, out double l1);
            TwoDiff(c.Y, a.Y, k, out double h2, out double l2);
            TwoDiff(b.Y, a.Y, k, out double h3, out double l3);
            TwoDiff(c.X, a.X, k, out double h4, out double l4);
            Span<double> e = stackalloc double[16];
            int n = 0;
            AddProduct(e, ref n, h1, h2); AddProduct(e, ref n, h1, l2); AddProduct(e, ref n, l1, h2); AddProduct(e, ref n, l1, l2);
            AddProduct(e, ref n, -h3, h4); AddProduct(e, ref n, -h3, l4); AddProduct(e, ref n, -l3, h4); AddProduct(e, ref n, -l3, l4);
            for (int i = n - 1; i >= 0; i--)
                if (e[i] != 0) return Math.Sign(e[i]);
            return 0;
        }

        /// <summary>x − y = (h + l)/k exactly, with h = fl(x − y)·k.</summary>
        private static void TwoDiff(double x, double y, double k, out double h, out double l)
        {
            double d = x - y, yv = x - d, xv = d + yv;
            l = ((x - xv) + (yv - y)) * k;
            h = d * k;
        }

        private static void AddProduct(Span<double> e, ref int n, double x, double y)
        {
            double p = x * y;
            Grow(e, ref n, ProductError(x, y, p));
            Grow(e, ref n, p);
        }

        /// <summary>Adds b to the expansion e[0..n) exactly (Shewchuk's grow-expansion with zero elimination).</summary>
        private static void Grow(Span<double> e, ref int n, double b)
        {
            double q = b;
            int m = 0;
            for (int i = 0; i < n; i++)
            {
                double sum = q + e[i], bv = sum - q, av = sum - bv, err = (q - av) + (e[i] - bv);
                if (err != 0) e[m++] = err;
                q = sum;
            }
            if (q != 0) e[m++] = q;
            n = m;
        }

        /// <summary>Whether the 2D point x lies on the inner side of (or on) every edge of the triangle of orientation <paramref name="area"/>.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool Inside2(Vector3D x, in TriFrame f, double area)
        {
            var w0 = (x - f.A) * f.K;
            var w1 = (x - f.B) * f.K;
            var w2 = (x - f.C) * f.K;
            double s0 = f.E1.X * w0.Y - f.E1.Y * w0.X;
            double s1 = f.E3.X * w1.Y - f.E3.Y * w1.X;
            double s2 = w2.X * f.E2.Y - w2.Y * f.E2.X;
            return area > 0 ? (s0 >= 0 && s1 >= 0 && s2 >= 0) : (s0 <= 0 && s1 <= 0 && s2 <= 0);
        }

        /// <summary>The outward unit normal of a 2D edge with direction e of a triangle of orientation <paramref name="area"/>.</summary>
        private static Vector3D Outward2(Vector3D e, double area)
        {
            var n = area > 0 ? new Vector3D(e.Y, -e.X, 0) : new Vector3D(-e.Y, e.X, 0);
            double m = Range.MaxAbs(n);
            if (m == 0) return Vector3D.UnitX;
            n *= Num.InversePowerOfTwo(m);
            return n / n.Length;
        }

        // ---- Segment against triangle ----

        /// <summary>
        /// Squared distance between segment [p0, p1] and a 3D triangle (neither solid), the segment's parameter and a
        /// closest pair. Crossing the plane (heights of opposite signs along N) at a point that projects into the
        /// triangle: 0 there. Otherwise the least of the endpoints against the triangle and the segment against the three
        /// edges (every other closest pair has one of these forms), the first of equal ones in that order; a segment in
        /// the plane, parallel to it or nearly so, is one of these cases too, so no ill-conditioned crossing is trusted.
        /// <paramref name="fine"/>: the winning candidate's own check, its squared distance in the fast range or exactly 0
        /// (a crossing, a zero residual). A zero is not trusted by its value: a gap below 2^-537 squares to 0, and at a
        /// configuration scaled by 2^-443 that is a gap of 2^-100 of its size (fuzz: touching triangles scaled down).
        /// </summary>
        public static double SegmentTriangle(Vector3D p0, Vector3D p1, in TriFrame f, out double s, out Vector3D onSeg, out Vector3D onTri, out bool fine)
        {
            if (Crossing(p0, p1, f, out s, out onSeg)) { onTri = onSeg; fine = true; return 0; }
            var c = PointTriangle(p0, f, false, out fine);
            double best = c.DistanceSquared;
            s = 0; onSeg = p0; onTri = c.Closest;
            if (best == 0) return 0;
            c = PointTriangle(p1, f, false, out bool fineEnd);
            if (c.DistanceSquared < best) { best = c.DistanceSquared; s = 1; onSeg = p1; onTri = c.Closest; fine = fineEnd; }
            for (int i = 0; i < 3 && best > 0; i++)
            {
                f.Edge(i, out var v0, out var v1);
                double g = SegmentSegmentCore(p0, p1, v0, v1, out double se, out double te, out bool fineEdge);
                if (g < best) { best = g; s = se + 0; onSeg = SegmentPoint(p0, p1, se); onTri = SegmentPoint(v0, v1, te); fine = fineEdge; }
            }
            return best;
        }

        /// <summary>
        /// Whether segment [p0, p1] crosses the plane of a non-flat triangle inside it (its ends on either side or on it,
        /// the crossing on the inner side of every edge): the parameter <paramref name="s"/> and the point.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Crossing(Vector3D p0, Vector3D p1, in TriFrame f, out double s, out Vector3D x)
        {
            if (!f.Flat)
            {
                double h0 = Vector3D.Dot((p0 - f.A) * f.K, f.N), h1 = Vector3D.Dot((p1 - f.A) * f.K, f.N);
                if (h0 != h1 && (h0 <= 0 ? h1 >= 0 : h1 <= 0))
                {
                    s = h0 / (h0 - h1);
                    x = SegmentPoint(p0, p1, s);
                    if (f.Inside(x)) return true;
                }
            }
            s = 0;
            x = default;
            return false;
        }

        /// <summary>Segment against a 3D triangle as a result; <paramref name="inRange"/>: the configuration's squared size and the squared distance are in the fast range (or an exact 0).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 SegmentTriangle(Vector3D p0, Vector3D p1, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            // In the frame of a, so a translation adds no error (see TriangleTriangle).
            var o = a;
            a = default; b -= o; c -= o; p0 -= o; p1 -= o;
            double size2 = TriFrame.Size2(a, b, c, p0, p1);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            double g = SegmentTriangle(p0, p1, f, out double s, out var onSeg, out var onTri, out bool fine);
            inRange = (Range.In(size2) | (a == b & a == c & a == p0 & a == p1)) & fine;
            return new DistanceResult3(Math.Sqrt(g), g, onSeg + o, onTri + o, s, 0);
        }

        /// <summary>
        /// The least translation of segment [p0, p1] that clears a 3D triangle it meets, over the facet normals of their
        /// Minkowski difference (a prism: N and the segment × edge directions), each projected honestly, so a noisy axis
        /// can only overestimate. Returns the depth and the unit direction to move the segment (zero when none). A flat
        /// triangle (within 2u·S of its edges) has a prism no thicker than that: its depth is 0, as the segment's it is.
        /// </summary>
        private static double SegmentTrianglePenetration(Vector3D p0, Vector3D p1, in TriFrame f, out Vector3D dir)
        {
            dir = default;
            if (f.Flat) return 0;
            double best = PrismPush(p0, p1, f, out dir);
            return best < double.PositiveInfinity ? Math.Max(0, best) / f.K : 0;
        }

        /// <summary>
        /// The least push (scaled by f.K, negative when the facet separates: minus its gap) over the facet normals of the
        /// Minkowski prism of segment [p0, p1] and a non-flat triangle, and the unit direction that moves the segment
        /// away along it; +∞ and zero when every axis is zero.
        /// </summary>
        private static double PrismPush(Vector3D p0, Vector3D p1, in TriFrame f, out Vector3D dir)
        {
            dir = default;
            var q0 = (p0 - f.A) * f.K;
            var q1 = (p1 - f.A) * f.K;
            // The segment × edge axes from the exact differences (rounded part and rest): the plain cross product of the
            // rounded differences turns by u/sinθ for an axis at angle θ to an edge, the depth along it then by u·S/sinθ.
            ExactDiff(p1, p0, f.K, out var d, out var dl);
            double best = double.PositiveInfinity;
            SegmentAxis(f.N, q0, q1, f, ref best, ref dir);
            ExactDiff(f.B, f.A, f.K, out var e, out var el);
            SegmentAxis(FacetAxis(d, dl, e, el), q0, q1, f, ref best, ref dir);
            ExactDiff(f.C, f.A, f.K, out e, out el);
            SegmentAxis(FacetAxis(d, dl, e, el), q0, q1, f, ref best, ref dir);
            ExactDiff(f.C, f.B, f.K, out e, out el);
            SegmentAxis(FacetAxis(d, dl, e, el), q0, q1, f, ref best, ref dir);
            return best;
        }

        /// <summary>(x − y)·k exactly as a rounded part and the rest (Knuth's two-sum per component; k a power of two).</summary>
        private static void ExactDiff(Vector3D x, Vector3D y, double k, out Vector3D h, out Vector3D l)
        {
            TwoDiff(x.X, y.X, k, out double hx, out double lx);
            TwoDiff(x.Y, y.Y, k, out double hy, out double ly);
            TwoDiff(x.Z, y.Z, k, out double hz, out double lz);
            h = new Vector3D(hx, hy, hz);
            l = new Vector3D(lx, ly, lz);
        }

        /// <summary>
        /// (dh + dl) × (eh + el) with each component to about a rounding of itself while the angle between d and e is well
        /// above u: the rounded parts' product formed with exact products, plus the first-order terms of the rests (the
        /// second-order one is below u² of |d||e|).
        /// </summary>
        private static Vector3D FacetAxis(Vector3D dh, Vector3D dl, Vector3D eh, Vector3D el) =>
            AccurateCross(dh, eh) + (Vector3D.Cross(dl, eh) + Vector3D.Cross(dh, el));

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void SegmentAxis(Vector3D axis, Vector3D q0, Vector3D q1, in TriFrame f, ref double best, ref Vector3D dir)
        {
            double e1 = Vector3D.Dot(f.E1, axis), e2 = Vector3D.Dot(f.E2, axis), s0 = Vector3D.Dot(q0, axis), s1 = Vector3D.Dot(q1, axis);
            PushAxis(axis, Math.Min(s0, s1), Math.Max(s0, s1), Math.Min(0, Math.Min(e1, e2)), Math.Max(0, Math.Max(e1, e2)), ref best, ref dir);
        }

        /// <summary>
        /// Shape A projects to [minA, maxA] on the (unnormalised) axis, B to [minB, maxB]: moving A by −axis·(maxA − minB)/|axis|²
        /// or +axis·(maxB − minA)/|axis|² clears B; the shorter is kept if it beats <paramref name="best"/> (as a length), the
        /// first of equal ones. A zero (or overflowing) axis is skipped.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void PushAxis(Vector3D axis, double minA, double maxA, double minB, double maxB, ref double best, ref Vector3D dir)
        {
            double len2 = axis.LengthSquared;
            if (!(len2 > 0) || double.IsInfinity(len2)) return;
            double len = Math.Sqrt(len2);
            double down = (maxA - minB) / len, up = (maxB - minA) / len;
            if (down < best) { best = down; dir = axis * (-1 / len); }
            if (up < best) { best = up; dir = axis * (1 / len); }
        }

        /// <summary>
        /// A capsule's result from its axis's signed distance <paramref name="sd"/> to the other shape (solid sense), the
        /// axis point and the other's point of the closest (or, overlapping, just-touching moved back) pair, and the unit
        /// direction <paramref name="dir"/> that moves the axis away from the other shape: the distance less the radius,
        /// PointA the axis point moved back by the radius.
        /// </summary>
        private static DistanceResult3 Inflated(double sd, Vector3D onAxis, Vector3D onOther, Vector3D dir, double t, double radius)
        {
            double d = sd - radius;
            return new DistanceResult3(d == 0 ? 0 : d, d > 0 ? d * d : 0, onAxis - dir * radius, onOther, t, 0);
        }

        /// <summary>
        /// Capsule against a 3D triangle: the solid signed distance of the axis to the triangle less the radius. Apart: the
        /// segment–triangle closest pair. The axis meeting the triangle: the prism depth of <see cref="SegmentTrianglePenetration"/>
        /// (0 when the axis lies in the plane or the triangle is flat), the witnesses from the axis moved by it, just touching;
        /// with no depth direction, the plane normal (a flat triangle: a direction perpendicular to the axis and the triangle).
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 CapsuleTriangle(Vector3D p0, Vector3D p1, double radius, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            // In the frame of a, so a translation adds no error (see TriangleTriangle); the witnesses move back at the end.
            // The given inputs are kept: a near-touch normal is formed from them (the shift rounds each by u·S).
            var given = new TriangleInputs(p0, p1, a, b, c);
            var o = a;
            a = default; b -= o; c -= o; p0 -= o; p1 -= o;
            double size2 = TriFrame.Size2(a, b, c, p0, p1);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            double g = SegmentTriangle(p0, p1, f, out double s, out var onSeg, out var onTri, out bool fine);
            inRange = (Range.In(size2) | (a == b & a == c & a == p0 & a == p1)) & fine;
            if (g > 0)
            {
                double dist = Math.Sqrt(g);
                var away = dist * f.K < NearTouch ? NearTouchDirection(p0, p1, f, dist, onSeg, onTri, given)
                    : Unit(onSeg - onTri, f.Flat ? FlatPushDirection(p1 - p0, f) : f.Unit);
                return Inflated(dist, onSeg + o, onTri + o, away, s, radius);
            }
            double depth = SegmentTrianglePenetration(p0, p1, f, out var dir);
            if (dir == default) dir = f.Flat ? FlatPushDirection(p1 - p0, f) : f.Unit;
            var push = dir * depth;
            SegmentTriangle(p0 + push, p1 + push, f, out s, out onSeg, out onTri, out bool fineTouch);
            inRange &= fineTouch; // the just-touching pair's gap is rounding, whose square can underflow at the smallest fast scales
            return Inflated(-depth, onSeg - push + o, onTri + o, dir, s, radius);
        }

        /// <summary>
        /// The unit direction that moves segment [p0, p1] away from a triangle it nearly touches (scaled gap dist·K below
        /// 2^-26). There the residual onSeg − onTri is mostly rounding: its direction turns by about u·S/dist, and pushing
        /// a capsule out along a turned direction leaves radius·angle²/2 of overlap (an axis along an edge 2e-15 away:
        /// 5e-8); which features hold the pair is as uncertain. So: when a facet of the Minkowski difference separates by
        /// nearly dist (the plane's normal, or the common normal of the segment and an edge), that facet's normal, formed
        /// from exact differences. Else every other feature pair's normal is formed from the <paramref name="given"/>
        /// inputs (the frame's are rounded by the shift to A, which alone turns it by u·S/dist): each end's exact vector
        /// from each edge (<see cref="EdgeVector"/>), each vertex's perpendicular to the segment's line, the plane's
        /// normal either way; with the best facet and the residual, the one whose plane leaves the triangle farthest from
        /// the segment (<see cref="TriangleSupport"/>) is taken: the exact normal's support is the gap itself, and pushing
        /// along one within δ of it leaves the shapes within δ of touching.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static Vector3D NearTouchDirection(Vector3D p0, Vector3D p1, in TriFrame f, double dist, Vector3D onSeg, Vector3D onTri, in TriangleInputs given)
        {
            double facetGap = f.Flat ? FlatPush(p0, p1, f, out var facet) : PrismPush(p0, p1, f, out facet);
            if (facet != default && -facetGap >= dist * f.K - FacetSlack) return facet;
            double k = f.K, best = double.NegativeInfinity;
            var fallback = f.Flat ? FlatPushDirection(p1 - p0, f) : f.Unit;
            var n = Unit(onSeg - onTri, fallback);
            ConsiderAway(n, given, ref best, ref n);
            ConsiderAway(facet, given, ref best, ref n);
            if (!f.Flat)
            {
                ConsiderAway(f.Unit, given, ref best, ref n);
                ConsiderAway(-f.Unit, given, ref best, ref n);
            }
            ExactDiff(given.P1, given.P0, k, out var dh, out var dl);
            for (int i = 0; i < 3; i++)
            {
                given.Edge(i, out var w0, out var w1);
                ConsiderAway(EdgeVector(given.P0, w0, w1, k), given, ref best, ref n);
                ConsiderAway(EdgeVector(given.P1, w0, w1, k), given, ref best, ref n);
                ConsiderAway(-AccuratePerp(w0, given.P0, k, dh, dl), given, ref best, ref n);
            }
            return n;
        }

        /// <summary>Takes direction v (from the triangle toward the segment) if its <see cref="TriangleSupport"/> beats <paramref name="best"/>.</summary>
        private static void ConsiderAway(Vector3D v, in TriangleInputs given, ref double best, ref Vector3D n)
        {
            if (v == default) return;
            var u = Unit(v, default);
            double h = TriangleSupport(u, given);
            if (h > best) { best = h; n = u; }
        }

        /// <summary>
        /// The least of (segment point − triangle point)·u: over their ends and vertices, from differences to A (so a
        /// translation adds nothing). Rounded (a few u of the size): that is all a choice between push directions needs,
        /// as each pushes out to within its support's error.
        /// </summary>
        private static double TriangleSupport(Vector3D u, in TriangleInputs g)
        {
            double e0 = Vector3D.Dot(g.P0 - g.A, u), e1 = Vector3D.Dot(g.P1 - g.A, u);
            double vb = Vector3D.Dot(g.B - g.A, u), vc = Vector3D.Dot(g.C - g.A, u);
            return Math.Min(e0, e1) - Math.Max(0, Math.Max(vb, vc));
        }

        /// <summary>
        /// (p − its nearest point on segment [w0, w1])·k, for a power of two k, to about a rounding of itself: p's
        /// perpendicular to the line (<see cref="AccuratePerp"/>) when its foot falls inside, else the exact difference to
        /// the nearer end, the foot placed by compensated dot products (wrong only within u² of an end, where the two
        /// agree to u²).
        /// </summary>
        private static Vector3D EdgeVector(Vector3D p, Vector3D w0, Vector3D w1, double k)
        {
            ExactDiff(w1, w0, k, out var eh, out var el);
            ExactDiff(p, w0, k, out var ah, out var al);
            if (!(OffsetFrom(eh, ah, al, 0) + Vector3D.Dot(el, ah) > 0)) return ah + al;
            ExactDiff(p, w1, k, out var bh, out var bl);
            if (!(OffsetFrom(eh, bh, bl, 0) + Vector3D.Dot(el, bh) < 0)) return bh + bl;
            return AccuratePerp(p, w0, k, eh, el);
        }

        /// <summary>
        /// <see cref="PrismPush"/> for a flat triangle (its longest edge, a segment): the axes normal to the Minkowski
        /// difference of two segments, a parallelogram: the common normal d × e from exact differences, and its two
        /// in-plane edge normals.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double FlatPush(Vector3D p0, Vector3D p1, in TriFrame f, out Vector3D dir)
        {
            dir = default;
            int i = LongestIndex(f);
            ExactDiff(p1, p0, f.K, out var d, out var dl);
            ExactDiff(i == 0 ? f.B : f.C, i == 2 ? f.B : f.A, f.K, out var e, out var el);
            var c = FacetAxis(d, dl, e, el);
            var q0 = (p0 - f.A) * f.K;
            var q1 = (p1 - f.A) * f.K;
            double best = double.PositiveInfinity;
            SegmentAxis(c, q0, q1, f, ref best, ref dir);
            SegmentAxis(Vector3D.Cross(c, d), q0, q1, f, ref best, ref dir);
            SegmentAxis(Vector3D.Cross(c, e), q0, q1, f, ref best, ref dir);
            return best;
        }

        /// <summary>
        /// 2^-26: gaps below this fraction of the size are near touching, where a rounded residual's direction is no longer
        /// good to 2^-26 (a radius r pushed along it then leaves up to r·2^-53 of overlap, a rounding of r) and the
        /// near-touch normals are formed from exact inputs. No higher: the float API's inputs, rounded to float, put
        /// nearly every shape built around another's point within 2^-24 of it, where the rounded residual is still fine
        /// and the slow path would be taken for nothing.
        /// </summary>
        private const double NearTouch = 1.4901161193847656E-08;

        /// <summary>NearTouch², for comparing squared gaps.</summary>
        private const double NearTouch2 = NearTouch * NearTouch;

        /// <summary>2^-48 of the scaled size: a facet whose gap is this close to the distance is the pair's normal.</summary>
        private const double FacetSlack = 3.552713678800501E-15;

        /// <summary>A unit direction perpendicular to the axis d and to the longest edge of a flat triangle (any perpendicular when they are parallel).</summary>
        private static Vector3D FlatPushDirection(Vector3D d, in TriFrame f)
        {
            var e = Longest(f);
            var n = Vector3D.Cross(d * Num.InversePowerOfTwo(Num.Max(Range.MaxAbs(d), double.Epsilon)), e);
            double m = Range.MaxAbs(n);
            if (m == 0) return AnyPerpendicular(Range.MaxAbs(d) > 0 ? d : e);
            n *= Num.InversePowerOfTwo(m);
            return n / n.Length;
        }

        /// <summary>The longest scaled edge (the first of equal ones): a flat triangle's hull.</summary>
        private static Vector3D Longest(in TriFrame f)
        {
            int i = LongestIndex(f);
            return i == 0 ? f.E1 : i == 1 ? f.E2 : f.E3;
        }

        /// <summary>Which edge <see cref="Longest"/> is: 0 for E1 (A→B), 1 for E2 (A→C), 2 for E3 (B→C).</summary>
        private static int LongestIndex(in TriFrame f)
        {
            double l1 = f.E1.LengthSquared, l2 = f.E2.LengthSquared, l3 = f.E3.LengthSquared;
            return l1 >= l2 ? (l1 >= l3 ? 0 : 2) : (l2 >= l3 ? 1 : 2);
        }

        // ---- 2D: segment against a solid triangle ----

        /// <summary>
        /// Segment [p0, p1] against a solid 2D triangle (z = 0), as a signed distance with the closest (or, overlapping,
        /// just-touching moved back) pair and the unit direction that moves the segment away. Overlap: the separating-axis
        /// test over the triangle's edge normals and the segment's normal (the facet normals of their Minkowski difference;
        /// strict inequalities, and a zero axis separates nothing); the depth is the least push over the same axes and the
        /// witnesses come from the segment moved by it, just touching. Apart: the segment against the three edges.
        /// A flat triangle is the segment or point it is: never negative unless <paramref name="flatDepth"/> (a capsule's axis,
        /// whose crossing of a segment has a 2D depth), then the same axes measure that crossing.
        /// <paramref name="fine"/>: the squared distance of the closest edge pair (apart) or of the just-touching pair that gives
        /// the witnesses (overlapping) is in the fast range or an exact 0 (see
        /// <see cref="SegmentTriangle(Vector3D, Vector3D, in TriFrame, out double, out Vector3D, out Vector3D, out bool)"/>):
        /// a square that underflowed may have picked the wrong pair.
        /// </summary>
        private static double SegmentTriangle2(Vector3D p0, Vector3D p1, in TriFrame f, bool flatDepth, out double s, out Vector3D onSeg, out Vector3D onTri, out Vector3D dir, out bool fine) =>
            SegmentTriangle2(p0, p1, f, Area2(f), flatDepth, out s, out onSeg, out onTri, out dir, out fine);

        /// <summary>As above, with the triangle's orientation <paramref name="area"/> given (only whether it is 0 matters).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double SegmentTriangle2(Vector3D p0, Vector3D p1, in TriFrame f, double area, bool flatDepth, out double s, out Vector3D onSeg, out Vector3D onTri, out Vector3D dir, out bool fine)
        {
            double g = 0;
            s = 0; onSeg = p0; onTri = f.A;
            fine = true;
            bool apart;
            if (area != 0)
            {
                apart = !SegmentTriangleOverlaps2(p0, p1, f);
                if (apart) g = EdgesDistance(p0, p1, f, out s, out onSeg, out onTri, out fine);
            }
            else
            {
                // Flat: the segment it is. Meeting it has a depth (and a push direction from the axes below) only for a
                // capsule's axis: touching (an exact 0) or properly crossing (exact signs: the rounded distance of two
                // crossing segments is rounding noise, not 0).
                g = EdgesDistance(p0, p1, f, out s, out onSeg, out onTri, out fine);
                apart = !flatDepth || (g > 0 && !CrossesFlat2(p0, p1, f));
            }
            if (apart)
            {
                double d = Math.Sqrt(g);
                var diff = onSeg - onTri;
                dir = default;
                // Below 2^-30 of the configuration's size (K is its inverse) the witnesses' difference carries the rounding
                // of their coordinates, enough to turn a capsule pushed out along it into overlap. When the closest
                // features are an edge and a point or the segment and a vertex, the separating axis is that direction
                // exactly: taken when the difference agrees with it up to rounding (its part across the axis below
                // 2^-46 of the size). Otherwise (a vertex and an endpoint) the difference is the direction.
                if (area != 0 && g * f.K * f.K < 8.673617379884035e-19)
                {
                    SeparatingAxis(p0, p1, f, out var axis);
                    if (Math.Abs(diff.X * axis.Y - diff.Y * axis.X) * f.K <= 1.4210854715202004e-14) dir = axis;
                }
                if (dir == default) dir = Unit(diff, AnyPerpendicular(Range.MaxAbs(p1 - p0) > 0 ? p1 - p0 : Longest(f)));
                return d;
            }
            double best = SeparatingAxis(p0, p1, f, out dir);
            double depth = best < double.PositiveInfinity ? Math.Max(0, best) / f.K : 0;
            if (dir == default) dir = AnyPerpendicular(Range.MaxAbs(p1 - p0) > 0 ? p1 - p0 : Longest(f));
            var push = dir * depth;
            // The just-touching pair's gap is rounding, whose square can be subnormal at the smallest fast scales.
            EdgesDistance(p0 + push, p1 + push, f, out s, out onSeg, out onTri, out fine);
            onSeg -= push;
            return depth > 0 ? -depth : 0;
        }

        /// <summary>
        /// The separating-axis search of a segment against a 2D triangle over the edges' normals and the segment's: the
        /// unit direction of the shortest push of the segment clear of the triangle (<see cref="PushAxis"/>; negative
        /// when apart: then the axis of largest separation) and that push in the triangle's scaled frame. No axis (both
        /// degenerate) leaves <paramref name="dir"/> zero.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double SeparatingAxis(Vector3D p0, Vector3D p1, in TriFrame f, out Vector3D dir)
        {
            var q0 = (p0 - f.A) * f.K;
            var q1 = (p1 - f.A) * f.K;
            double best = double.PositiveInfinity;
            dir = default;
            SegmentAxis(Perp(f.E1), q0, q1, f, ref best, ref dir);
            SegmentAxis(Perp(f.E2), q0, q1, f, ref best, ref dir);
            SegmentAxis(Perp(f.E3), q0, q1, f, ref best, ref dir);
            SegmentAxis(Perp(q1 - q0), q0, q1, f, ref best, ref dir);
            return best;
        }

        /// <summary>
        /// Whether segment [p0, p1] properly crosses a flat 2D triangle (exactly collinear vertices): the segment and the
        /// triangle's hull (its extreme vertices along the coordinate of larger spread) each have their ends strictly on
        /// either side of the other's line, by exact orientation signs.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static bool CrossesFlat2(Vector3D p0, Vector3D p1, in TriFrame f)
        {
            bool alongX = Math.Max(Math.Abs(f.E1.X), Math.Abs(f.E2.X)) >= Math.Max(Math.Abs(f.E1.Y), Math.Abs(f.E2.Y));
            Vector3D lo = f.A, hi = f.A;
            Extend(f.B, alongX, ref lo, ref hi);
            Extend(f.C, alongX, ref lo, ref hi);
            return OrientationSign(lo, hi, p0, f.K) * OrientationSign(lo, hi, p1, f.K) < 0
                && OrientationSign(p0, p1, lo, f.K) * OrientationSign(p0, p1, hi, f.K) < 0;
        }

        private static void Extend(Vector3D v, bool alongX, ref Vector3D lo, ref Vector3D hi)
        {
            double x = alongX ? v.X : v.Y;
            if (x < (alongX ? lo.X : lo.Y)) lo = v;
            if (x > (alongX ? hi.X : hi.Y)) hi = v;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3D Perp(Vector3D e) => new Vector3D(e.Y, -e.X, 0);

        /// <summary>The separating-axis test of a segment against a solid, non-flat 2D triangle (see <see cref="SegmentTriangle2(Vector3D, Vector3D, in TriFrame, bool, out double, out Vector3D, out Vector3D, out Vector3D, out bool)"/>).</summary>
        private static bool SegmentTriangleOverlaps2(Vector3D p0, Vector3D p1, in TriFrame f)
        {
            var q0 = (p0 - f.A) * f.K;
            var q1 = (p1 - f.A) * f.K;
            return !SegmentSeparated(Perp(f.E1), q0, q1, f) && !SegmentSeparated(Perp(f.E2), q0, q1, f)
                && !SegmentSeparated(Perp(f.E3), q0, q1, f) && !SegmentSeparated(Perp(q1 - q0), q0, q1, f);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool SegmentSeparated(Vector3D axis, Vector3D q0, Vector3D q1, in TriFrame f)
        {
            double e1 = Vector3D.Dot(f.E1, axis), e2 = Vector3D.Dot(f.E2, axis), s0 = Vector3D.Dot(q0, axis), s1 = Vector3D.Dot(q1, axis);
            return Math.Min(s0, s1) > Math.Max(0, Math.Max(e1, e2)) || Math.Max(s0, s1) < Math.Min(0, Math.Min(e1, e2));
        }

        /// <summary>The least squared distance of segment [p0, p1] to the triangle's three edges (the first of equal ones); <paramref name="fine"/>: that pair's own range check (in range or an exact 0).</summary>
        private static double EdgesDistance(Vector3D p0, Vector3D p1, in TriFrame f, out double s, out Vector3D onSeg, out Vector3D onTri, out bool fine)
        {
            double best = double.PositiveInfinity;
            s = 0; onSeg = p0; onTri = f.A;
            fine = true;
            for (int i = 0; i < 3; i++)
            {
                f.Edge(i, out var v0, out var v1);
                double g = SegmentSegmentFlat(p0, p1, v0, v1, out double se, out double te, out bool fineEdge);
                if (g < best) { best = g; s = se + 0; onSeg = SegmentPoint(p0, p1, se); onTri = SegmentPoint(v0, v1, te); fine = fineEdge; }
            }
            return best;
        }

        /// <summary>Segment against a solid 2D triangle (z = 0) as a result: negative when they overlap; a flat triangle is the segment it is (never negative).</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult3 SegmentTriangle2(Vector3D p0, Vector3D p1, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p0, p1);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            double sd = SegmentTriangle2(p0, p1, f, false, out double s, out var onSeg, out var onTri, out _, out bool fine);
            inRange = (Range.In(size2) | (a == b & a == c & a == p0 & a == p1)) & fine;
            return new DistanceResult3(sd, sd > 0 ? sd * sd : 0, onSeg, onTri, s, 0);
        }

        /// <summary>Whether a segment meets a solid 2D triangle: the separating-axis test, or for a flat triangle an exactly zero segment distance.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool SegmentTriangleOverlaps2(Vector3D p0, Vector3D p1, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p0, p1);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            inRange = Range.In(size2) | (a == b & a == c & a == p0 & a == p1);
            if (Area2(f) != 0) return SegmentTriangleOverlaps2(p0, p1, f);
            bool met = EdgesDistance(p0, p1, f, out _, out _, out _, out bool fine) == 0;
            inRange &= fine;
            return met;
        }

        /// <summary>
        /// Capsule against a solid 2D triangle: the solid signed distance of the axis (the separating-axis depth when it
        /// meets the triangle, including a flat triangle it crosses) less the radius.
        /// </summary>
        public static DistanceResult3 CapsuleTriangle2(Vector3D p0, Vector3D p1, double radius, Vector3D a, Vector3D b, Vector3D c, out bool inRange)
        {
            double size2 = TriFrame.Size2(a, b, c, p0, p1);
            var f = new TriFrame(a, b, c, InverseSizeScale(size2));
            double sd = SegmentTriangle2(p0, p1, f, true, out double s, out var onSeg, out var onTri, out var dir, out bool fine);
            inRange = (Range.In(size2) | (a == b & a == c & a == p0 & a == p1)) & fine;
            return Inflated(sd, onSeg, onTri, dir, s, radius);
        }
    }
}
