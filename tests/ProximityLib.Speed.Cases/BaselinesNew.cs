using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using static ProximitySpeed.Source;

namespace ProximitySpeed
{
    // Hand-written baselines for issue 12's pairs where a short textbook form exists (Baselines.cs's conventions:
    // signed, minus the depth when overlapping; System.Numerics in float, scalar arithmetic in double): a capsule is its
    // segment grown by its radius, so capsule and sphere distances are segment and point distances minus the radii; a
    // half-space is n·x ≤ d with n a unit vector (PlaneF, PlaneD in Raycasts.cs); point–triangle is Ericson's closest point.

    public readonly struct CapsuleF { public readonly SegmentF S; public readonly float R; public CapsuleF(SegmentF s, float r) { S = s; R = r; } }
    public readonly struct CapsuleD { public readonly SegmentD S; public readonly double R; public CapsuleD(SegmentD s, double r) { S = s; R = r; } }

    /// <summary>Segment–segment closest points (SegmentParameters) minus both radii; witnesses moved by the radii along the line between them.</summary>
    [Case(Baseline, Precision.Float, "3D capsule–capsule")]
    public readonly struct CapsuleCapsuleF : IBetween<CapsuleF, CapsuleF>, IDistance<CapsuleF, CapsuleF>, IOverlap<CapsuleF, CapsuleF>
    {
        public double Distance(in CapsuleF a, in CapsuleF b) => new SegmentSegmentF().Distance(a.S, b.S) - a.R - b.R;

        public double Between(in CapsuleF a, in CapsuleF b)
        {
            SegmentSegmentF.Closest(a.S, b.S, out var pa, out var pb);
            var d = pb - pa;
            float length = d.Length();
            var n = length > 0 ? d / length : Vector3.UnitX;
            return Fold.Of(length - a.R - b.R, pa + n * a.R, pb - n * b.R);
        }

        public bool Overlaps(in CapsuleF a, in CapsuleF b)
        {
            SegmentSegmentF.Closest(a.S, b.S, out var pa, out var pb);
            float r = a.R + b.R;
            return Vector3.DistanceSquared(pa, pb) <= r * r;
        }
    }

    /// <summary>Point–segment distance from the sphere's center to the capsule's axis, minus both radii.</summary>
    [Case(Baseline, Precision.Float, "3D sphere–capsule")]
    public readonly struct SphereCapsuleF : IBetween<SphereF, CapsuleF>, IDistance<SphereF, CapsuleF>, IOverlap<SphereF, CapsuleF>
    {
        public double Distance(in SphereF s, in CapsuleF c) => Vector3.Distance(s.Center, Axis(s.Center, c.S)) - s.Radius - c.R;

        public double Between(in SphereF s, in CapsuleF c)
        {
            var q = Axis(s.Center, c.S);
            var d = q - s.Center;
            float length = d.Length();
            var n = length > 0 ? d / length : Vector3.UnitX;
            return Fold.Of(length - s.Radius - c.R, s.Center + n * s.Radius, q - n * c.R);
        }

        public bool Overlaps(in SphereF s, in CapsuleF c)
        {
            float r = s.Radius + c.R;
            return Vector3.DistanceSquared(s.Center, Axis(s.Center, c.S)) <= r * r;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3 Axis(Vector3 p, SegmentF s)
        {
            var d = s.Q - s.P;
            float dd = Vector3.Dot(d, d);
            float t = dd > 0 ? Clamp01.Of(Vector3.Dot(p - s.P, d) / dd) : 0;
            return s.P + d * t;
        }
    }

    /// <summary>Ericson's closest point on a triangle (Real-Time Collision Detection §5.1.5): the Voronoi region of a corner, an edge or the face.</summary>
    [Case(Baseline, Precision.Float, "3D point–triangle")]
    public readonly struct PointTriangleF : IBetween<Vector3, TriangleF>, IDistance<Vector3, TriangleF>
    {
        public double Distance(in Vector3 p, in TriangleF t) => Vector3.Distance(p, Closest(p, t));

        public double Between(in Vector3 p, in TriangleF t)
        {
            var q = Closest(p, t);
            return Fold.Of(Vector3.Distance(p, q), p, q);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3 Closest(Vector3 p, TriangleF t)
        {
            Vector3 ab = t.B - t.A, ac = t.C - t.A, ap = p - t.A;
            float d1 = Vector3.Dot(ab, ap), d2 = Vector3.Dot(ac, ap);
            if (d1 <= 0 && d2 <= 0) return t.A;
            var bp = p - t.B;
            float d3 = Vector3.Dot(ab, bp), d4 = Vector3.Dot(ac, bp);
            if (d3 >= 0 && d4 <= d3) return t.B;
            float vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) return t.A + ab * (d1 / (d1 - d3));
            var cp = p - t.C;
            float d5 = Vector3.Dot(ab, cp), d6 = Vector3.Dot(ac, cp);
            if (d6 >= 0 && d5 <= d6) return t.C;
            float vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) return t.A + ac * (d2 / (d2 - d6));
            float va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return t.B + (t.C - t.B) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
            float denom = 1 / (va + vb + vc);
            return t.A + ab * (vb * denom) + ac * (vc * denom);
        }
    }

    /// <summary>The signed plane distance n·p − d; the witness is p moved back along n; overlap when it is ≤ 0.</summary>
    [Case(Baseline, Precision.Float, "3D point–half-space")]
    public readonly struct PointPlaneF : IBetween<Vector3, PlaneF>, IDistance<Vector3, PlaneF>, IOverlap<Vector3, PlaneF>
    {
        public double Distance(in Vector3 p, in PlaneF h) => Vector3.Dot(h.N, p) - h.D;

        public double Between(in Vector3 p, in PlaneF h)
        {
            float d = Vector3.Dot(h.N, p) - h.D;
            return Fold.Of(d, p, p - h.N * d);
        }

        public bool Overlaps(in Vector3 p, in PlaneF h) => Vector3.Dot(h.N, p) <= h.D;
    }

    /// <summary>The center's signed plane distance minus the radius.</summary>
    [Case(Baseline, Precision.Float, "3D sphere–half-space")]
    public readonly struct SpherePlaneF : IBetween<SphereF, PlaneF>, IDistance<SphereF, PlaneF>, IOverlap<SphereF, PlaneF>
    {
        public double Distance(in SphereF s, in PlaneF h) => Vector3.Dot(h.N, s.Center) - h.D - s.Radius;

        public double Between(in SphereF s, in PlaneF h)
        {
            float d = Vector3.Dot(h.N, s.Center) - h.D;
            var a = s.Center - h.N * s.Radius;
            return Fold.Of(d - s.Radius, a, s.Center - h.N * d);
        }

        public bool Overlaps(in SphereF s, in PlaneF h) => Vector3.Dot(h.N, s.Center) - h.D <= s.Radius;
    }

    /// <summary>The lower end of the capsule's axis (the smaller signed plane distance) minus the radius.</summary>
    [Case(Baseline, Precision.Float, "3D capsule–half-space")]
    public readonly struct CapsulePlaneF : IDistance<CapsuleF, PlaneF>, IOverlap<CapsuleF, PlaneF>
    {
        public double Distance(in CapsuleF c, in PlaneF h) => MathF.Min(Vector3.Dot(h.N, c.S.P), Vector3.Dot(h.N, c.S.Q)) - h.D - c.R;
        public bool Overlaps(in CapsuleF c, in PlaneF h) => MathF.Min(Vector3.Dot(h.N, c.S.P), Vector3.Dot(h.N, c.S.Q)) - h.D <= c.R;
    }

    // ---- double (scalar arithmetic) ----

    /// <summary>Segment–segment closest points (SegmentParameters) minus both radii; witnesses moved by the radii along the line between them.</summary>
    [Case(Baseline, Precision.Double, "3D capsule–capsule")]
    public readonly struct CapsuleCapsuleD : IBetween<CapsuleD, CapsuleD>, IDistance<CapsuleD, CapsuleD>, IOverlap<CapsuleD, CapsuleD>
    {
        public double Distance(in CapsuleD a, in CapsuleD b) => new SegmentSegmentD().Distance(a.S, b.S) - a.R - b.R;

        public double Between(in CapsuleD a, in CapsuleD b)
        {
            SegmentSegmentD.Closest(a.S, b.S, out double ax, out double ay, out double az, out double bx, out double by, out double bz);
            double dx = bx - ax, dy = by - ay, dz = bz - az;
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double nx = 1, ny = 0, nz = 0;
            if (length > 0) { nx = dx / length; ny = dy / length; nz = dz / length; }
            return Fold.Of(length - a.R - b.R, ax + nx * a.R, ay + ny * a.R, az + nz * a.R, bx - nx * b.R, by - ny * b.R, bz - nz * b.R);
        }

        public bool Overlaps(in CapsuleD a, in CapsuleD b)
        {
            SegmentSegmentD.Closest(a.S, b.S, out double ax, out double ay, out double az, out double bx, out double by, out double bz);
            double dx = bx - ax, dy = by - ay, dz = bz - az, r = a.R + b.R;
            return dx * dx + dy * dy + dz * dz <= r * r;
        }
    }

    /// <summary>Point–segment distance from the sphere's center to the capsule's axis, minus both radii.</summary>
    [Case(Baseline, Precision.Double, "3D sphere–capsule")]
    public readonly struct SphereCapsuleD : IBetween<SphereD, CapsuleD>, IDistance<SphereD, CapsuleD>, IOverlap<SphereD, CapsuleD>
    {
        public double Distance(in SphereD s, in CapsuleD c) => new PointSegmentD().Distance(new PointD(s.X, s.Y, s.Z), c.S) - s.R - c.R;

        public double Between(in SphereD s, in CapsuleD c)
        {
            double t = Parameter(s, c.S);
            double qx = c.S.PX + (c.S.QX - c.S.PX) * t, qy = c.S.PY + (c.S.QY - c.S.PY) * t, qz = c.S.PZ + (c.S.QZ - c.S.PZ) * t;
            double dx = qx - s.X, dy = qy - s.Y, dz = qz - s.Z;
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double nx = 1, ny = 0, nz = 0;
            if (length > 0) { nx = dx / length; ny = dy / length; nz = dz / length; }
            return Fold.Of(length - s.R - c.R, s.X + nx * s.R, s.Y + ny * s.R, s.Z + nz * s.R, qx - nx * c.R, qy - ny * c.R, qz - nz * c.R);
        }

        public bool Overlaps(in SphereD s, in CapsuleD c)
        {
            double t = Parameter(s, c.S);
            double dx = c.S.PX + (c.S.QX - c.S.PX) * t - s.X, dy = c.S.PY + (c.S.QY - c.S.PY) * t - s.Y, dz = c.S.PZ + (c.S.QZ - c.S.PZ) * t - s.Z;
            double r = s.R + c.R;
            return dx * dx + dy * dy + dz * dz <= r * r;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Parameter(in SphereD p, in SegmentD s)
        {
            double dx = s.QX - s.PX, dy = s.QY - s.PY, dz = s.QZ - s.PZ;
            double dd = dx * dx + dy * dy + dz * dz;
            return dd > 0 ? Clamp01.Of(((p.X - s.PX) * dx + (p.Y - s.PY) * dy + (p.Z - s.PZ) * dz) / dd) : 0;
        }
    }

    /// <summary>Ericson's closest point on a triangle, as the float form, in scalar double.</summary>
    [Case(Baseline, Precision.Double, "3D point–triangle")]
    public readonly struct PointTriangleD : IBetween<PointD, TriangleD>, IDistance<PointD, TriangleD>
    {
        public double Distance(in PointD p, in TriangleD t)
        {
            Closest(p, t, out double x, out double y, out double z);
            double dx = p.X - x, dy = p.Y - y, dz = p.Z - z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        public double Between(in PointD p, in TriangleD t)
        {
            Closest(p, t, out double x, out double y, out double z);
            double dx = p.X - x, dy = p.Y - y, dz = p.Z - z;
            return Fold.Of(Math.Sqrt(dx * dx + dy * dy + dz * dz), p.X, p.Y, p.Z, x, y, z);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Closest(in PointD p, in TriangleD t, out double x, out double y, out double z)
        {
            PointD a = t.A, b = t.B, c = t.C;
            double abx = b.X - a.X, aby = b.Y - a.Y, abz = b.Z - a.Z, acx = c.X - a.X, acy = c.Y - a.Y, acz = c.Z - a.Z;
            double apx = p.X - a.X, apy = p.Y - a.Y, apz = p.Z - a.Z;
            double d1 = abx * apx + aby * apy + abz * apz, d2 = acx * apx + acy * apy + acz * apz;
            if (d1 <= 0 && d2 <= 0) { x = a.X; y = a.Y; z = a.Z; return; }
            double bpx = p.X - b.X, bpy = p.Y - b.Y, bpz = p.Z - b.Z;
            double d3 = abx * bpx + aby * bpy + abz * bpz, d4 = acx * bpx + acy * bpy + acz * bpz;
            if (d3 >= 0 && d4 <= d3) { x = b.X; y = b.Y; z = b.Z; return; }
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) { double v = d1 / (d1 - d3); x = a.X + abx * v; y = a.Y + aby * v; z = a.Z + abz * v; return; }
            double cpx = p.X - c.X, cpy = p.Y - c.Y, cpz = p.Z - c.Z;
            double d5 = abx * cpx + aby * cpy + abz * cpz, d6 = acx * cpx + acy * cpy + acz * cpz;
            if (d6 >= 0 && d5 <= d6) { x = c.X; y = c.Y; z = c.Z; return; }
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) { double w = d2 / (d2 - d6); x = a.X + acx * w; y = a.Y + acy * w; z = a.Z + acz * w; return; }
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
            {
                double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
                x = b.X + (c.X - b.X) * w; y = b.Y + (c.Y - b.Y) * w; z = b.Z + (c.Z - b.Z) * w;
                return;
            }
            double denom = 1 / (va + vb + vc), sv = vb * denom, sw = vc * denom;
            x = a.X + abx * sv + acx * sw; y = a.Y + aby * sv + acy * sw; z = a.Z + abz * sv + acz * sw;
        }
    }

    /// <summary>The signed plane distance n·p − d; the witness is p moved back along n; overlap when it is ≤ 0.</summary>
    [Case(Baseline, Precision.Double, "3D point–half-space")]
    public readonly struct PointPlaneD : IBetween<PointD, PlaneD>, IDistance<PointD, PlaneD>, IOverlap<PointD, PlaneD>
    {
        public double Distance(in PointD p, in PlaneD h) => h.NX * p.X + h.NY * p.Y + h.NZ * p.Z - h.D;

        public double Between(in PointD p, in PlaneD h)
        {
            double d = h.NX * p.X + h.NY * p.Y + h.NZ * p.Z - h.D;
            return Fold.Of(d, p.X, p.Y, p.Z, p.X - h.NX * d, p.Y - h.NY * d, p.Z - h.NZ * d);
        }

        public bool Overlaps(in PointD p, in PlaneD h) => h.NX * p.X + h.NY * p.Y + h.NZ * p.Z <= h.D;
    }

    /// <summary>The center's signed plane distance minus the radius.</summary>
    [Case(Baseline, Precision.Double, "3D sphere–half-space")]
    public readonly struct SpherePlaneD : IBetween<SphereD, PlaneD>, IDistance<SphereD, PlaneD>, IOverlap<SphereD, PlaneD>
    {
        public double Distance(in SphereD s, in PlaneD h) => h.NX * s.X + h.NY * s.Y + h.NZ * s.Z - h.D - s.R;

        public double Between(in SphereD s, in PlaneD h)
        {
            double d = h.NX * s.X + h.NY * s.Y + h.NZ * s.Z - h.D;
            return Fold.Of(d - s.R, s.X - h.NX * s.R, s.Y - h.NY * s.R, s.Z - h.NZ * s.R, s.X - h.NX * d, s.Y - h.NY * d, s.Z - h.NZ * d);
        }

        public bool Overlaps(in SphereD s, in PlaneD h) => h.NX * s.X + h.NY * s.Y + h.NZ * s.Z - h.D <= s.R;
    }

    /// <summary>The lower end of the capsule's axis (the smaller signed plane distance) minus the radius.</summary>
    [Case(Baseline, Precision.Double, "3D capsule–half-space")]
    public readonly struct CapsulePlaneD : IDistance<CapsuleD, PlaneD>, IOverlap<CapsuleD, PlaneD>
    {
        public double Distance(in CapsuleD c, in PlaneD h) =>
            Math.Min(h.NX * c.S.PX + h.NY * c.S.PY + h.NZ * c.S.PZ, h.NX * c.S.QX + h.NY * c.S.QY + h.NZ * c.S.QZ) - h.D - c.R;

        public bool Overlaps(in CapsuleD c, in PlaneD h) =>
            Math.Min(h.NX * c.S.PX + h.NY * c.S.PY + h.NZ * c.S.PZ, h.NX * c.S.QX + h.NY * c.S.QY + h.NZ * c.S.QZ) - h.D <= c.R;
    }
}
