using System;
using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>
    /// The source paper's formulas, implemented as printed (in double), as the baseline the robust forms are measured
    /// against. Not for use: each one has a known numerical weakness, named on the method.
    /// </summary>
    public static class PaperFormulas
    {
        /// <summary>Point–segment by Eqs. 9–11: interior distance as sqrt(|w|² − (v·w)²/|v|²) (Eq. 10), which cancels.</summary>
        public static double PointSegment(Vector3D y, Vector3D p, Vector3D q)
        {
            var v = q - p;
            var w = y - p;
            double vv = v.LengthSquared;
            double t = vv > 0 ? Vector3D.Dot(v, w) / vv : 0;
            if (t <= 0) return w.Length;
            if (t >= 1) return (y - q).Length;
            double vw = Vector3D.Dot(v, w);
            return Math.Sqrt(Math.Max(0, w.LengthSquared - vw * vw / vv));
        }

        /// <summary>
        /// Segment–segment from Eq. 13 by its normal equations, with det = |d0|²|d1|² − (d0·d1)² and "parallel" meaning
        /// det == 0 exactly; clamp s, solve t, re-clamp s (the common textbook form). det cancels for nearly parallel
        /// segments, so the interior solve runs on noise.
        /// </summary>
        public static double SegmentSegment(Vector3D p0, Vector3D p1, Vector3D q0, Vector3D q1)
        {
            var d0 = p1 - p0;
            var d1 = q1 - q0;
            var r = p0 - q0;
            double a = d0.LengthSquared, e = d1.LengthSquared, f = Vector3D.Dot(d1, r);
            double s, t;
            if (a == 0 && e == 0) return r.Length;
            if (a == 0) { s = 0; t = Clamp01(f / e); }
            else
            {
                double c = Vector3D.Dot(d0, r);
                if (e == 0) { t = 0; s = Clamp01(-c / a); }
                else
                {
                    double b = Vector3D.Dot(d0, d1);
                    double det = a * e - b * b;
                    s = det != 0 ? Clamp01((b * f - c * e) / det) : 0;
                    t = (b * s + f) / e;
                    if (t < 0) { t = 0; s = Clamp01(-c / a); }
                    else if (t > 1) { t = 1; s = Clamp01((b - c) / a); }
                }
            }
            return (p0 + d0 * s - (q0 + d1 * t)).Length;
        }

        /// <summary>
        /// 2D segment–segment by Eqs. 14–15: parallel iff the cross product is exactly 0; crossing when the lines'
        /// intersection parameters are inside both; otherwise the best endpoint–segment distance, using |d⊥·w|/|d| for
        /// an interior projection.
        /// </summary>
        public static double SegmentSegment2(Vector2D p0, Vector2D p1, Vector2D q0, Vector2D q1)
        {
            var d0 = p1 - p0;
            var d1 = q1 - q0;
            double cross = Vector2D.Cross(d0, d1);
            if (cross != 0)
            {
                var w = q0 - p0;
                double s = Vector2D.Cross(w, d1) / cross, t = Vector2D.Cross(w, d0) / cross;
                if (s > 0 && s < 1 && t > 0 && t < 1) return 0;
            }
            return Math.Min(Math.Min(EndpointToSegment(p0, q0, d1), EndpointToSegment(p1, q0, d1)),
                Math.Min(EndpointToSegment(q0, p0, d0), EndpointToSegment(q1, p0, d0)));
        }

        private static double EndpointToSegment(Vector2D y, Vector2D p, Vector2D d)
        {
            var w = y - p;
            double dd = d.LengthSquared;
            double t = dd > 0 ? Vector2D.Dot(w, d) / dd : 0;
            if (t <= 0) return w.Length;
            if (t >= 1) return (w - d).Length;
            return Math.Abs(Vector2D.Cross(d, w)) / Math.Sqrt(dd);
        }

        /// <summary>
        /// OBB–OBB overlap by the 15-axis SAT as usually printed (Eqs. 19–20; Gottschalk et al.): |R| without an ε and
        /// the orthonormality identities for B's projected radius on cross axes, so nearly parallel edges can turn
        /// an overlapping pair "separated".
        /// </summary>
        public static bool ObbObbOverlaps(Obb3 a, Obb3 b)
        {
            Vector3D a0 = a.AxisX, a1 = a.AxisY, a2 = a.AxisZ, b0 = b.AxisX, b1 = b.AxisY, b2 = b.AxisZ;
            double ha0 = a.HalfExtents.X, ha1 = a.HalfExtents.Y, ha2 = a.HalfExtents.Z;
            double hb0 = b.HalfExtents.X, hb1 = b.HalfExtents.Y, hb2 = b.HalfExtents.Z;
            double r00 = Vector3D.Dot(a0, b0), r01 = Vector3D.Dot(a0, b1), r02 = Vector3D.Dot(a0, b2);
            double r10 = Vector3D.Dot(a1, b0), r11 = Vector3D.Dot(a1, b1), r12 = Vector3D.Dot(a1, b2);
            double r20 = Vector3D.Dot(a2, b0), r21 = Vector3D.Dot(a2, b1), r22 = Vector3D.Dot(a2, b2);
            double q00 = Math.Abs(r00), q01 = Math.Abs(r01), q02 = Math.Abs(r02);
            double q10 = Math.Abs(r10), q11 = Math.Abs(r11), q12 = Math.Abs(r12);
            double q20 = Math.Abs(r20), q21 = Math.Abs(r21), q22 = Math.Abs(r22);
            var tw = b.Center - a.Center;
            double t0 = Vector3D.Dot(tw, a0), t1 = Vector3D.Dot(tw, a1), t2 = Vector3D.Dot(tw, a2);
            if (Math.Abs(t0) > ha0 + hb0 * q00 + hb1 * q01 + hb2 * q02) return false;
            if (Math.Abs(t1) > ha1 + hb0 * q10 + hb1 * q11 + hb2 * q12) return false;
            if (Math.Abs(t2) > ha2 + hb0 * q20 + hb1 * q21 + hb2 * q22) return false;
            if (Math.Abs(t0 * r00 + t1 * r10 + t2 * r20) > ha0 * q00 + ha1 * q10 + ha2 * q20 + hb0) return false;
            if (Math.Abs(t0 * r01 + t1 * r11 + t2 * r21) > ha0 * q01 + ha1 * q11 + ha2 * q21 + hb1) return false;
            if (Math.Abs(t0 * r02 + t1 * r12 + t2 * r22) > ha0 * q02 + ha1 * q12 + ha2 * q22 + hb2) return false;
            // L = A_i × B_j with B's radius from the orthonormality identities and no ε (Ericson's form without its ε).
            if (Math.Abs(t2 * r10 - t1 * r20) > ha1 * q20 + ha2 * q10 + hb1 * q02 + hb2 * q01) return false;
            if (Math.Abs(t2 * r11 - t1 * r21) > ha1 * q21 + ha2 * q11 + hb0 * q02 + hb2 * q00) return false;
            if (Math.Abs(t2 * r12 - t1 * r22) > ha1 * q22 + ha2 * q12 + hb0 * q01 + hb1 * q00) return false;
            if (Math.Abs(t0 * r20 - t2 * r00) > ha0 * q20 + ha2 * q00 + hb1 * q12 + hb2 * q11) return false;
            if (Math.Abs(t0 * r21 - t2 * r01) > ha0 * q21 + ha2 * q01 + hb0 * q12 + hb2 * q10) return false;
            if (Math.Abs(t0 * r22 - t2 * r02) > ha0 * q22 + ha2 * q02 + hb0 * q11 + hb1 * q10) return false;
            if (Math.Abs(t1 * r00 - t0 * r10) > ha0 * q10 + ha1 * q00 + hb1 * q22 + hb2 * q21) return false;
            if (Math.Abs(t1 * r01 - t0 * r11) > ha0 * q11 + ha1 * q01 + hb0 * q22 + hb2 * q20) return false;
            if (Math.Abs(t1 * r02 - t0 * r12) > ha0 * q12 + ha1 * q02 + hb0 * q21 + hb1 * q20) return false;
            return true;
        }

        private static double Clamp01(double x) => x < 0 ? 0 : (x > 1 ? 1 : x);
    }
}
