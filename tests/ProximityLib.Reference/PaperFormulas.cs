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
            var ax = new[] { a.AxisX, a.AxisY, a.AxisZ };
            var bx = new[] { b.AxisX, b.AxisY, b.AxisZ };
            var ha = new[] { a.HalfExtents.X, a.HalfExtents.Y, a.HalfExtents.Z };
            var hb = new[] { b.HalfExtents.X, b.HalfExtents.Y, b.HalfExtents.Z };
            var R = new double[3, 3];
            var AbsR = new double[3, 3];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) { R[i, j] = Vector3D.Dot(ax[i], bx[j]); AbsR[i, j] = Math.Abs(R[i, j]); }
            var tw = b.Center - a.Center;
            var t = new[] { Vector3D.Dot(tw, ax[0]), Vector3D.Dot(tw, ax[1]), Vector3D.Dot(tw, ax[2]) };
            for (int i = 0; i < 3; i++)
                if (Math.Abs(t[i]) > ha[i] + hb[0] * AbsR[i, 0] + hb[1] * AbsR[i, 1] + hb[2] * AbsR[i, 2]) return false;
            for (int j = 0; j < 3; j++)
                if (Math.Abs(t[0] * R[0, j] + t[1] * R[1, j] + t[2] * R[2, j]) > ha[0] * AbsR[0, j] + ha[1] * AbsR[1, j] + ha[2] * AbsR[2, j] + hb[j]) return false;
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++)
                {
                    int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
                    double ra = ha[i1] * AbsR[i2, j] + ha[i2] * AbsR[i1, j];
                    double rb = hb[j1] * AbsR[i, j2] + hb[j2] * AbsR[i, j1];
                    if (Math.Abs(t[i2] * R[i1, j] - t[i1] * R[i2, j]) > ra + rb) return false;
                }
            return true;
        }

        private static double Clamp01(double x) => x < 0 ? 0 : (x > 1 ? 1 : x);
    }
}
