using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // 2D ray casts that need 2D-only logic: in the plane a segment, line or ray is crossed, and a triangle is a solid.
    internal static partial class Kernels
    {
        /// <summary>The unit normal of direction e (non-zero) on the side the ray d comes from (−(e's left normal) when d runs along it to the left).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector2D Facing(Vector2D e, Vector2D d)
        {
            var n = Vector2D.From3(Unit(new Vector3D(-e.Y, e.X, 0), default));
            return Vector2D.Dot(n, d) > 0 ? -n : n;
        }

        /// <summary>
        /// Ray against a 2D segment [p, q], crossed as a wall. Each endpoint's side of the ray, f = d × (x − o), is a
        /// value of that endpoint alone, so segments sharing an endpoint agree on it: a ray through a polyline's vertex
        /// hits at least one of its segments. The crossing is the convex combination g_p + s·(g_q − g_p), s = f_p/(f_p − f_q),
        /// of the endpoints' distances g along the ray, the point the same combination of the ends. A ray along the segment
        /// hits its nearer end (T = 0 when the origin lies on it) with normal −d.
        /// </summary>
        public static RayHit2 RaySegment2(Vector2D o, Vector2D d, Vector2D p, Vector2D q, out bool inRange)
        {
            var wp = p - o;
            var wq = q - o;
            inRange = Range.Box(Num.Max(Range.MaxAbs(wp), Range.MaxAbs(wq)));
            if (p == q)
            {
                var h = RayPoint(o.To3(), d.To3(), p.To3(), out _);
                return h.To2();
            }
            double fp = Vector2D.Cross(d, wp), fq = Vector2D.Cross(d, wq);
            if ((fp > 0 && fq > 0) || (fp < 0 && fq < 0)) return RayHit2.Miss;
            double gp = Vector2D.Dot(d, wp), gq = Vector2D.Dot(d, wq);
            if (fp == fq)
            {
                // Both on the ray's line: the ray runs along the segment.
                if (gp < 0 && gq < 0) return RayHit2.Miss;
                if (gp <= 0 || gq <= 0) return new RayHit2(0, o, -d, false);
                return gp <= gq ? new RayHit2(gp, p, -d, false) : new RayHit2(gq, q, -d, false);
            }
            var e = q - p;
            // The origin on the segment is a hit at 0 however the crossing's rounding falls.
            if (Vector2D.Cross(wp, wq) == 0 && Vector2D.Dot(wp, wq) <= 0) return new RayHit2(0, o, Facing(e, d), false);
            // The crossing's parameter on the segment, and T as the same convex combination of the ends' distances along
            // the ray as the point is of the ends ((gp·fq − gq·fp)/(fq − fp) rounds grossly when a side value is subnormal).
            double s = fp / (fp - fq);
            double t = s <= 0.5 ? gp + (gq - gp) * s : gq - (gq - gp) * (1 - s);
            if (!(t >= 0)) return RayHit2.Miss;
            var point = s <= 0.5 ? p + e * s : q - e * (1 - s);
            return new RayHit2(t + 0.0, point, Facing(e, d), false);
        }

        /// <summary>
        /// Ray against a 2D line (p, unit e; <paramref name="half"/>: only s ≥ 0, a ray): crossed at T = ((p − o) × e)/(d × e)
        /// (exactly 0 for an origin on it), at the target's parameter s = (o + T·d − p)·e. Parallel: T = 0 when the origin
        /// lies on it (a ray target: at its origin when that lies ahead on the ray's line), else a miss.
        /// </summary>
        public static RayHit2 RayLine2(Vector2D o, Vector2D d, Vector2D p, Vector2D e, bool half, out bool inRange)
        {
            var w = p - o;
            inRange = Range.Box(Range.MaxAbs(w));
            double fp = Vector2D.Cross(d, w), fe = Vector2D.Cross(d, e);
            if (fe == 0)
            {
                if (fp != 0) return RayHit2.Miss;
                double g = Vector2D.Dot(d, w);
                if (!half || (Vector2D.Dot(d, e) > 0 ? g <= 0 : g >= 0)) return new RayHit2(0, o, -d, false);
                return Vector2D.Dot(d, e) > 0 ? new RayHit2(g, p, -d, false) : RayHit2.Miss;
            }
            double t = Vector2D.Cross(w, e) / fe;
            if (!(t >= 0)) return RayHit2.Miss;
            // The target's parameter of the ray's point at T (not −fp/fe: nearly parallel lines make T and that ratio
            // independent noise, and the point must be the ray's): its foot on the target, on it to rounding.
            double s = t * Vector2D.Dot(d, e) - Vector2D.Dot(w, e);
            if (half && !(s >= 0)) return RayHit2.Miss;
            return new RayHit2(t + 0.0, p + e * s, Facing(e, d), false);
        }

        /// <summary>
        /// Ray against a closed solid 2D triangle: the ray clipped by the three edges' inner sides (Cyrus–Beck), each side
        /// function cross(Q − P, x − P) formed from differences, and by the bounding box. The origin on the boundary is a hit at 0 with the first
        /// such edge's outward normal (A→B, B→C, C→A of the counter-clockwise order). A degenerate triangle is the segment
        /// or point it is. Inlined, as the other casts' kernels: without dynamic PGO a call kept returning this struct
        /// costs a stall reading it back.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static RayHit2 RayTriangle2(Vector2D o, Vector2D d, Vector2D a, Vector2D b, Vector2D c, out bool inRange)
        {
            var wa = a - o;
            var wb = b - o;
            var wc = c - o;
            inRange = Range.Box(Range.MaxAbs(wa, wb, wc));
            double area = Vector2D.Cross(b - a, c - a);
            if (area == 0) return RayCollinear2(o, d, a, b, c);
            if (area < 0) { var swap = b; b = c; c = swap; swap = wb; wb = wc; wc = swap; }
            var eab = b - a;
            var ebc = c - b;
            var eca = a - c;
            // Side of the origin for each edge: positive inside. A sliver's edge lines are parallel to rounding, so far from
            // its vertices their side functions and clip times are noise: the triangle also lies in its bounding box (offsets
            // from the origin, lo ≤ 0 ≤ hi when the origin is in it), which the origin must be in and which clips the ray.
            double loX = Math.Min(wa.X, Math.Min(wb.X, wc.X)), hiX = Math.Max(wa.X, Math.Max(wb.X, wc.X));
            double loY = Math.Min(wa.Y, Math.Min(wb.Y, wc.Y)), hiY = Math.Max(wa.Y, Math.Max(wb.Y, wc.Y));
            double fab = Vector2D.Cross(eab, -wa), fbc = Vector2D.Cross(ebc, -wb), fca = Vector2D.Cross(eca, -wc);
            if (loX <= 0 && hiX >= 0 && loY <= 0 && hiY >= 0)
            {
                if (fab > 0 && fbc > 0 && fca > 0) return RayHit2.Inside(o);
                if (fab >= 0 && fbc >= 0 && fca >= 0)
                    return new RayHit2(0, o, Outward(fab == 0 ? eab : fbc == 0 ? ebc : eca), false);
            }
            double enter = double.NegativeInfinity, exit = double.PositiveInfinity;
            var entry = eab;
            if (!Clip(fab, Vector2D.Cross(eab, d), eab, ref enter, ref exit, ref entry)
                || !Clip(fbc, Vector2D.Cross(ebc, d), ebc, ref enter, ref exit, ref entry)
                || !Clip(fca, Vector2D.Cross(eca, d), eca, ref enter, ref exit, ref entry)
                || !Slab(loX, hiX, d.X, ref enter, ref exit) || !Slab(loY, hiY, d.Y, ref enter, ref exit)
                || !(enter <= exit) || !(enter >= 0))
                return RayHit2.Miss;
            return new RayHit2(enter, o + d * enter, Outward(entry), false);
        }

        /// <summary>A collinear triangle (rare, out of line): the segment between the two vertices farthest apart.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static RayHit2 RayCollinear2(Vector2D o, Vector2D d, Vector2D a, Vector2D b, Vector2D c)
        {
            double ab = (b - a).LengthSquared, bc = (c - b).LengthSquared, ca = (a - c).LengthSquared;
            return ab >= bc && ab >= ca ? RaySegment2(o, d, a, b, out _) : bc >= ca ? RaySegment2(o, d, b, c, out _) : RaySegment2(o, d, c, a, out _);
        }

        /// <summary>The ray clipped to lo ≤ t·v ≤ hi (offsets from the origin); the entry's normal stays the edge's. False when it misses the slab.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Slab(double lo, double hi, double v, ref double enter, ref double exit)
        {
            if (v == 0) return lo <= 0 && hi >= 0;
            double t1 = lo / v, t2 = hi / v;
            double near = v > 0 ? t1 : t2, far = v > 0 ? t2 : t1;
            if (near > enter) enter = near;
            if (far < exit) exit = far;
            return true;
        }

        /// <summary>The outward unit normal of a counter-clockwise edge e (its right-hand side).</summary>
        private static Vector2D Outward(Vector2D e) => Vector2D.From3(Unit(new Vector3D(e.Y, -e.X, 0), default));

        /// <summary>One edge's clip of the ray: f0 + t·rate ≥ 0. False when the edge rejects the whole ray.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool Clip(double f0, double rate, Vector2D edge, ref double enter, ref double exit, ref Vector2D entry)
        {
            if (rate == 0) return f0 >= 0;
            double t = -f0 / rate;
            if (rate > 0) { if (t > enter) { enter = t; entry = edge; } }
            else if (t < exit) exit = t;
            return true;
        }
    }
}
