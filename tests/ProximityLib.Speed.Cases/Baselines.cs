using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using static ProximitySpeed.Source;

namespace ProximitySpeed
{
    // The hand-written baselines: the simplest correct C# a user would write from the formula for the same answer
    // (signed: minus the depth when overlapping, as the library answers), on plain structs of their own: System.Numerics
    // in float, scalar arithmetic in double. Each has a distance-only form, a form with witness points (folded as the
    // library's results are) and, where the pair has a cheap test, an overlap test. They read the same input numbers
    // as the library's cases.

    public readonly struct SphereF { public readonly Vector3 Center; public readonly float Radius; public SphereF(Vector3 c, float r) { Center = c; Radius = r; } }
    public readonly struct BoxF { public readonly Vector3 Min, Max; public BoxF(Vector3 min, Vector3 max) { Min = min; Max = max; } }
    public readonly struct SegmentF { public readonly Vector3 P, Q; public SegmentF(Vector3 p, Vector3 q) { P = p; Q = q; } }
    public readonly struct Segment2F { public readonly Vector2 P, Q; public Segment2F(Vector2 p, Vector2 q) { P = p; Q = q; } }
    public readonly struct PointD { public readonly double X, Y, Z; public PointD(double x, double y, double z) { X = x; Y = y; Z = z; } }
    public readonly struct SphereD { public readonly double X, Y, Z, R; public SphereD(double x, double y, double z, double r) { X = x; Y = y; Z = z; R = r; } }
    public readonly struct BoxD
    {
        public readonly double MinX, MinY, MinZ, MaxX, MaxY, MaxZ;
        public BoxD(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) { MinX = minX; MinY = minY; MinZ = minZ; MaxX = maxX; MaxY = maxY; MaxZ = maxZ; }
    }
    public readonly struct SegmentD
    {
        public readonly double PX, PY, PZ, QX, QY, QZ;
        public SegmentD(double px, double py, double pz, double qx, double qy, double qz) { PX = px; PY = py; PZ = pz; QX = qx; QY = qy; QZ = qz; }
    }
    public readonly struct Segment2D { public readonly double PX, PY, QX, QY; public Segment2D(double px, double py, double qx, double qy) { PX = px; PY = py; QX = qx; QY = qy; } }
    public readonly struct CircleF { public readonly Vector2 Center; public readonly float Radius; public CircleF(Vector2 c, float r) { Center = c; Radius = r; } }
    public readonly struct CircleD { public readonly double X, Y, R; public CircleD(double x, double y, double r) { X = x; Y = y; R = r; } }

    // ---- float (System.Numerics) ----

    /// <summary>|ca − cb| − ra − rb; witnesses along the line of centers; overlap when |ca − cb|² ≤ (ra + rb)².</summary>
    [Case(Baseline, Precision.Float, "3D sphere–sphere")]
    public readonly struct SphereSphereF : IBetween<SphereF, SphereF>, IDistance<SphereF, SphereF>, IOverlap<SphereF, SphereF>
    {
        public double Distance(in SphereF a, in SphereF b) => Vector3.Distance(a.Center, b.Center) - a.Radius - b.Radius;

        public double Between(in SphereF a, in SphereF b)
        {
            var d = b.Center - a.Center;
            float length = d.Length();
            var n = length > 0 ? d / length : Vector3.UnitX;
            return Fold.Of(length - a.Radius - b.Radius, a.Center + n * a.Radius, b.Center - n * b.Radius);
        }

        public bool Overlaps(in SphereF a, in SphereF b)
        {
            float r = a.Radius + b.Radius;
            return Vector3.DistanceSquared(a.Center, b.Center) <= r * r;
        }
    }

    /// <summary>|a − b|; the points themselves are the witnesses; overlap when they are equal.</summary>
    [Case(Baseline, Precision.Float, "3D point–point")]
    public readonly struct PointPointF : IBetween<Vector3, Vector3>, IDistance<Vector3, Vector3>, IOverlap<Vector3, Vector3>
    {
        public double Distance(in Vector3 a, in Vector3 b) => Vector3.Distance(a, b);
        public double Between(in Vector3 a, in Vector3 b) => Fold.Of(Vector3.Distance(a, b), a, b);
        public bool Overlaps(in Vector3 a, in Vector3 b) => a == b;
    }

    /// <summary>|p − c| − r; the sphere's witness along the line from its center to the point; overlap when |p − c|² ≤ r².</summary>
    [Case(Baseline, Precision.Float, "3D point–sphere")]
    public readonly struct PointSphereF : IBetween<Vector3, SphereF>, IDistance<Vector3, SphereF>, IOverlap<Vector3, SphereF>
    {
        public double Distance(in Vector3 p, in SphereF s) => Vector3.Distance(p, s.Center) - s.Radius;

        public double Between(in Vector3 p, in SphereF s)
        {
            var d = p - s.Center;
            float length = d.Length();
            var n = length > 0 ? d / length : Vector3.UnitX;
            return Fold.Of(length - s.Radius, p, s.Center + n * s.Radius);
        }

        public bool Overlaps(in Vector3 p, in SphereF s) => Vector3.DistanceSquared(p, s.Center) <= s.Radius * s.Radius;
    }

    /// <summary>The sphere–sphere formulas in the plane.</summary>
    [Case(Baseline, Precision.Float, "2D circle–circle")]
    public readonly struct CircleCircleF : IBetween<CircleF, CircleF>, IDistance<CircleF, CircleF>, IOverlap<CircleF, CircleF>
    {
        public double Distance(in CircleF a, in CircleF b) => Vector2.Distance(a.Center, b.Center) - a.Radius - b.Radius;

        public double Between(in CircleF a, in CircleF b)
        {
            var d = b.Center - a.Center;
            float length = d.Length();
            var n = length > 0 ? d / length : Vector2.UnitX;
            return Fold.Of(length - a.Radius - b.Radius, a.Center + n * a.Radius, b.Center - n * b.Radius);
        }

        public bool Overlaps(in CircleF a, in CircleF b)
        {
            float r = a.Radius + b.Radius;
            return Vector2.DistanceSquared(a.Center, b.Center) <= r * r;
        }
    }

    /// <summary>Clamp to the box; inside, minus the depth to the nearest face; overlap by interval tests.</summary>
    [Case(Baseline, Precision.Float, "3D point–AABB")]
    public readonly struct PointAabbF : IBetween<Vector3, BoxF>, IDistance<Vector3, BoxF>, IOverlap<Vector3, BoxF>
    {
        public double Distance(in Vector3 p, in BoxF b)
        {
            var q = Vector3.Clamp(p, b.Min, b.Max);
            float d2 = Vector3.DistanceSquared(p, q);
            if (d2 > 0) return MathF.Sqrt(d2);
            var lo = p - b.Min;
            var hi = b.Max - p;
            return -MathF.Min(MathF.Min(MathF.Min(lo.X, hi.X), MathF.Min(lo.Y, hi.Y)), MathF.Min(lo.Z, hi.Z));
        }

        public double Between(in Vector3 p, in BoxF b)
        {
            var q = Vector3.Clamp(p, b.Min, b.Max);
            float d2 = Vector3.DistanceSquared(p, q);
            if (d2 > 0) return Fold.Of(MathF.Sqrt(d2), p, q);
            var lo = p - b.Min;
            var hi = b.Max - p;
            float depth = lo.X;
            q.X = b.Min.X;
            if (hi.X < depth) { depth = hi.X; q = new Vector3(b.Max.X, p.Y, p.Z); }
            if (lo.Y < depth) { depth = lo.Y; q = new Vector3(p.X, b.Min.Y, p.Z); }
            if (hi.Y < depth) { depth = hi.Y; q = new Vector3(p.X, b.Max.Y, p.Z); }
            if (lo.Z < depth) { depth = lo.Z; q = new Vector3(p.X, p.Y, b.Min.Z); }
            if (hi.Z < depth) { depth = hi.Z; q = new Vector3(p.X, p.Y, b.Max.Z); }
            return Fold.Of(-depth, p, q);
        }

        public bool Overlaps(in Vector3 p, in BoxF b) =>
            p.X >= b.Min.X && p.X <= b.Max.X && p.Y >= b.Min.Y && p.Y <= b.Max.Y && p.Z >= b.Min.Z && p.Z <= b.Max.Z;
    }

    /// <summary>Project onto the segment's line, clamp the parameter to [0, 1].</summary>
    [Case(Baseline, Precision.Float, "3D point–segment")]
    public readonly struct PointSegmentF : IBetween<Vector3, SegmentF>, IDistance<Vector3, SegmentF>
    {
        public double Distance(in Vector3 p, in SegmentF s) => Vector3.Distance(p, Closest(p, s));

        public double Between(in Vector3 p, in SegmentF s)
        {
            var q = Closest(p, s);
            return Fold.Of(Vector3.Distance(p, q), p, q);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector3 Closest(Vector3 p, SegmentF s)
        {
            var d = s.Q - s.P;
            float dd = Vector3.Dot(d, d);
            float t = dd > 0 ? Clamp01.Of(Vector3.Dot(p - s.P, d) / dd) : 0;
            return s.P + d * t;
        }
    }

    /// <summary>Per-axis gaps: the length of the positive ones, else (overlapping) the largest, minus the least penetration.</summary>
    [Case(Baseline, Precision.Float, "3D AABB–AABB")]
    public readonly struct AabbAabbF : IBetween<BoxF, BoxF>, IDistance<BoxF, BoxF>, IOverlap<BoxF, BoxF>
    {
        public double Distance(in BoxF a, in BoxF b)
        {
            var gap = Vector3.Max(b.Min - a.Max, a.Min - b.Max);
            float outside = Vector3.Max(gap, Vector3.Zero).LengthSquared();
            return outside > 0 ? MathF.Sqrt(outside) : MathF.Max(gap.X, MathF.Max(gap.Y, gap.Z));
        }

        public double Between(in BoxF a, in BoxF b)
        {
            var gap = Vector3.Max(b.Min - a.Max, a.Min - b.Max);
            // Apart: the middle of the boxes' common range on each axis, clamped into each box.
            var mid = (Vector3.Max(a.Min, b.Min) + Vector3.Min(a.Max, b.Max)) * 0.5f;
            var pa = Vector3.Clamp(mid, a.Min, a.Max);
            var pb = Vector3.Clamp(mid, b.Min, b.Max);
            float outside = Vector3.Max(gap, Vector3.Zero).LengthSquared();
            if (outside > 0) return Fold.Of(MathF.Sqrt(outside), pa, pb);
            // Overlapping: the two faces along the axis of least penetration.
            if (gap.X >= gap.Y && gap.X >= gap.Z)
            {
                bool up = b.Min.X - a.Max.X >= a.Min.X - b.Max.X;
                pa.X = up ? a.Max.X : a.Min.X;
                pb.X = up ? b.Min.X : b.Max.X;
                return Fold.Of(gap.X, pa, pb);
            }
            if (gap.Y >= gap.Z)
            {
                bool up = b.Min.Y - a.Max.Y >= a.Min.Y - b.Max.Y;
                pa.Y = up ? a.Max.Y : a.Min.Y;
                pb.Y = up ? b.Min.Y : b.Max.Y;
                return Fold.Of(gap.Y, pa, pb);
            }
            bool upZ = b.Min.Z - a.Max.Z >= a.Min.Z - b.Max.Z;
            pa.Z = upZ ? a.Max.Z : a.Min.Z;
            pb.Z = upZ ? b.Min.Z : b.Max.Z;
            return Fold.Of(gap.Z, pa, pb);
        }

        public bool Overlaps(in BoxF a, in BoxF b) =>
            a.Min.X <= b.Max.X && a.Max.X >= b.Min.X && a.Min.Y <= b.Max.Y && a.Max.Y >= b.Min.Y && a.Min.Z <= b.Max.Z && a.Max.Z >= b.Min.Z;
    }

    /// <summary>Overlap when the center's squared distance to its clamp into the box is at most r².</summary>
    [Case(Baseline, Precision.Float, "3D sphere–AABB")]
    public readonly struct SphereAabbF : IOverlap<SphereF, BoxF>
    {
        public bool Overlaps(in SphereF s, in BoxF b) => Vector3.DistanceSquared(s.Center, Vector3.Clamp(s.Center, b.Min, b.Max)) <= s.Radius * s.Radius;
    }

    /// <summary>Closest points of two segments by the clamped normal equations (SegmentParameters).</summary>
    [Case(Baseline, Precision.Float, "3D segment–segment")]
    public readonly struct SegmentSegmentF : IBetween<SegmentF, SegmentF>, IDistance<SegmentF, SegmentF>
    {
        public double Distance(in SegmentF a, in SegmentF b)
        {
            Closest(a, b, out var pa, out var pb);
            return Vector3.Distance(pa, pb);
        }

        public double Between(in SegmentF a, in SegmentF b)
        {
            Closest(a, b, out var pa, out var pb);
            return Fold.Of(Vector3.Distance(pa, pb), pa, pb);
        }

        /// <summary>The closest points (shared with the capsule baselines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void Closest(in SegmentF a, in SegmentF b, out Vector3 pa, out Vector3 pb)
        {
            Vector3 d1 = a.Q - a.P, d2 = b.Q - b.P;
            var r = a.P - b.P;
            SegmentParameters.Of(Vector3.Dot(d1, d1), Vector3.Dot(d1, d2), Vector3.Dot(d2, d2), Vector3.Dot(d1, r), Vector3.Dot(d2, r), out float s, out float t);
            pa = a.P + d1 * s;
            pb = b.P + d2 * t;
        }
    }

    /// <summary>The same closest points in the plane.</summary>
    [Case(Baseline, Precision.Float, "2D segment–segment")]
    public readonly struct SegmentSegment2F : IBetween<Segment2F, Segment2F>, IDistance<Segment2F, Segment2F>
    {
        public double Distance(in Segment2F a, in Segment2F b)
        {
            Vector2 d1 = a.Q - a.P, d2 = b.Q - b.P;
            var r = a.P - b.P;
            SegmentParameters.Of(Vector2.Dot(d1, d1), Vector2.Dot(d1, d2), Vector2.Dot(d2, d2), Vector2.Dot(d1, r), Vector2.Dot(d2, r), out float s, out float t);
            return Vector2.Distance(a.P + d1 * s, b.P + d2 * t);
        }

        public double Between(in Segment2F a, in Segment2F b)
        {
            Vector2 d1 = a.Q - a.P, d2 = b.Q - b.P;
            var r = a.P - b.P;
            SegmentParameters.Of(Vector2.Dot(d1, d1), Vector2.Dot(d1, d2), Vector2.Dot(d2, d2), Vector2.Dot(d1, r), Vector2.Dot(d2, r), out float s, out float t);
            Vector2 pa = a.P + d1 * s, pb = b.P + d2 * t;
            return Fold.Of(Vector2.Distance(pa, pb), pa, pb);
        }
    }

    // ---- double (scalar arithmetic) ----

    /// <summary>|ca − cb| − ra − rb; witnesses along the line of centers; overlap when |ca − cb|² ≤ (ra + rb)².</summary>
    [Case(Baseline, Precision.Double, "3D sphere–sphere")]
    public readonly struct SphereSphereD : IBetween<SphereD, SphereD>, IDistance<SphereD, SphereD>, IOverlap<SphereD, SphereD>
    {
        public double Distance(in SphereD a, in SphereD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, dz = b.Z - a.Z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz) - a.R - b.R;
        }

        public double Between(in SphereD a, in SphereD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, dz = b.Z - a.Z;
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double nx = 1, ny = 0, nz = 0;
            if (length > 0) { nx = dx / length; ny = dy / length; nz = dz / length; }
            return Fold.Of(length - a.R - b.R, a.X + nx * a.R, a.Y + ny * a.R, a.Z + nz * a.R, b.X - nx * b.R, b.Y - ny * b.R, b.Z - nz * b.R);
        }

        public bool Overlaps(in SphereD a, in SphereD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, dz = b.Z - a.Z, r = a.R + b.R;
            return dx * dx + dy * dy + dz * dz <= r * r;
        }
    }

    /// <summary>|a − b|; the points themselves are the witnesses; overlap when they are equal.</summary>
    [Case(Baseline, Precision.Double, "3D point–point")]
    public readonly struct PointPointD : IBetween<PointD, PointD>, IDistance<PointD, PointD>, IOverlap<PointD, PointD>
    {
        public double Distance(in PointD a, in PointD b)
        {
            double dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        public double Between(in PointD a, in PointD b)
        {
            double dx = a.X - b.X, dy = a.Y - b.Y, dz = a.Z - b.Z;
            return Fold.Of(Math.Sqrt(dx * dx + dy * dy + dz * dz), a.X, a.Y, a.Z, b.X, b.Y, b.Z);
        }

        public bool Overlaps(in PointD a, in PointD b) => a.X == b.X && a.Y == b.Y && a.Z == b.Z;
    }

    /// <summary>|p − c| − r; the sphere's witness along the line from its center to the point; overlap when |p − c|² ≤ r².</summary>
    [Case(Baseline, Precision.Double, "3D point–sphere")]
    public readonly struct PointSphereD : IBetween<PointD, SphereD>, IDistance<PointD, SphereD>, IOverlap<PointD, SphereD>
    {
        public double Distance(in PointD p, in SphereD s)
        {
            double dx = p.X - s.X, dy = p.Y - s.Y, dz = p.Z - s.Z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz) - s.R;
        }

        public double Between(in PointD p, in SphereD s)
        {
            double dx = p.X - s.X, dy = p.Y - s.Y, dz = p.Z - s.Z;
            double length = Math.Sqrt(dx * dx + dy * dy + dz * dz);
            double nx = 1, ny = 0, nz = 0;
            if (length > 0) { nx = dx / length; ny = dy / length; nz = dz / length; }
            return Fold.Of(length - s.R, p.X, p.Y, p.Z, s.X + nx * s.R, s.Y + ny * s.R, s.Z + nz * s.R);
        }

        public bool Overlaps(in PointD p, in SphereD s)
        {
            double dx = p.X - s.X, dy = p.Y - s.Y, dz = p.Z - s.Z;
            return dx * dx + dy * dy + dz * dz <= s.R * s.R;
        }
    }

    /// <summary>The sphere–sphere formulas in the plane.</summary>
    [Case(Baseline, Precision.Double, "2D circle–circle")]
    public readonly struct CircleCircleD : IBetween<CircleD, CircleD>, IDistance<CircleD, CircleD>, IOverlap<CircleD, CircleD>
    {
        public double Distance(in CircleD a, in CircleD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y;
            return Math.Sqrt(dx * dx + dy * dy) - a.R - b.R;
        }

        public double Between(in CircleD a, in CircleD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y;
            double length = Math.Sqrt(dx * dx + dy * dy);
            double nx = 1, ny = 0;
            if (length > 0) { nx = dx / length; ny = dy / length; }
            return Fold.Of(length - a.R - b.R, a.X + nx * a.R, a.Y + ny * a.R, b.X - nx * b.R, b.Y - ny * b.R);
        }

        public bool Overlaps(in CircleD a, in CircleD b)
        {
            double dx = b.X - a.X, dy = b.Y - a.Y, r = a.R + b.R;
            return dx * dx + dy * dy <= r * r;
        }
    }

    /// <summary>Clamp to the box; inside, minus the depth to the nearest face; overlap by interval tests.</summary>
    [Case(Baseline, Precision.Double, "3D point–AABB")]
    public readonly struct PointAabbD : IBetween<PointD, BoxD>, IDistance<PointD, BoxD>, IOverlap<PointD, BoxD>
    {
        public double Distance(in PointD p, in BoxD b)
        {
            double dx = p.X - Math.Min(Math.Max(p.X, b.MinX), b.MaxX);
            double dy = p.Y - Math.Min(Math.Max(p.Y, b.MinY), b.MaxY);
            double dz = p.Z - Math.Min(Math.Max(p.Z, b.MinZ), b.MaxZ);
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > 0) return Math.Sqrt(d2);
            return -Math.Min(Math.Min(Math.Min(p.X - b.MinX, b.MaxX - p.X), Math.Min(p.Y - b.MinY, b.MaxY - p.Y)), Math.Min(p.Z - b.MinZ, b.MaxZ - p.Z));
        }

        public double Between(in PointD p, in BoxD b)
        {
            double qx = Math.Min(Math.Max(p.X, b.MinX), b.MaxX);
            double qy = Math.Min(Math.Max(p.Y, b.MinY), b.MaxY);
            double qz = Math.Min(Math.Max(p.Z, b.MinZ), b.MaxZ);
            double dx = p.X - qx, dy = p.Y - qy, dz = p.Z - qz;
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > 0) return Fold.Of(Math.Sqrt(d2), p.X, p.Y, p.Z, qx, qy, qz);
            double depth = p.X - b.MinX;
            qx = b.MinX;
            if (b.MaxX - p.X < depth) { depth = b.MaxX - p.X; qx = b.MaxX; }
            if (p.Y - b.MinY < depth) { depth = p.Y - b.MinY; qx = p.X; qy = b.MinY; }
            if (b.MaxY - p.Y < depth) { depth = b.MaxY - p.Y; qx = p.X; qy = b.MaxY; }
            if (p.Z - b.MinZ < depth) { depth = p.Z - b.MinZ; qx = p.X; qy = p.Y; qz = b.MinZ; }
            if (b.MaxZ - p.Z < depth) { depth = b.MaxZ - p.Z; qx = p.X; qy = p.Y; qz = b.MaxZ; }
            return Fold.Of(-depth, p.X, p.Y, p.Z, qx, qy, qz);
        }

        public bool Overlaps(in PointD p, in BoxD b) =>
            p.X >= b.MinX && p.X <= b.MaxX && p.Y >= b.MinY && p.Y <= b.MaxY && p.Z >= b.MinZ && p.Z <= b.MaxZ;
    }

    /// <summary>Project onto the segment's line, clamp the parameter to [0, 1].</summary>
    [Case(Baseline, Precision.Double, "3D point–segment")]
    public readonly struct PointSegmentD : IBetween<PointD, SegmentD>, IDistance<PointD, SegmentD>
    {
        public double Distance(in PointD p, in SegmentD s)
        {
            double t = Parameter(p, s);
            double dx = s.PX + (s.QX - s.PX) * t - p.X, dy = s.PY + (s.QY - s.PY) * t - p.Y, dz = s.PZ + (s.QZ - s.PZ) * t - p.Z;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        public double Between(in PointD p, in SegmentD s)
        {
            double t = Parameter(p, s);
            double qx = s.PX + (s.QX - s.PX) * t, qy = s.PY + (s.QY - s.PY) * t, qz = s.PZ + (s.QZ - s.PZ) * t;
            double dx = qx - p.X, dy = qy - p.Y, dz = qz - p.Z;
            return Fold.Of(Math.Sqrt(dx * dx + dy * dy + dz * dz), p.X, p.Y, p.Z, qx, qy, qz);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Parameter(PointD p, SegmentD s)
        {
            double dx = s.QX - s.PX, dy = s.QY - s.PY, dz = s.QZ - s.PZ;
            double dd = dx * dx + dy * dy + dz * dz;
            return dd > 0 ? Clamp01.Of(((p.X - s.PX) * dx + (p.Y - s.PY) * dy + (p.Z - s.PZ) * dz) / dd) : 0;
        }
    }

    /// <summary>Per-axis gaps: the length of the positive ones, else (overlapping) the largest, minus the least penetration.</summary>
    [Case(Baseline, Precision.Double, "3D AABB–AABB")]
    public readonly struct AabbAabbD : IBetween<BoxD, BoxD>, IDistance<BoxD, BoxD>, IOverlap<BoxD, BoxD>
    {
        public double Distance(in BoxD a, in BoxD b)
        {
            double gx = Math.Max(b.MinX - a.MaxX, a.MinX - b.MaxX), gy = Math.Max(b.MinY - a.MaxY, a.MinY - b.MaxY), gz = Math.Max(b.MinZ - a.MaxZ, a.MinZ - b.MaxZ);
            double ox = Math.Max(gx, 0), oy = Math.Max(gy, 0), oz = Math.Max(gz, 0);
            double outside = ox * ox + oy * oy + oz * oz;
            return outside > 0 ? Math.Sqrt(outside) : Math.Max(gx, Math.Max(gy, gz));
        }

        public double Between(in BoxD a, in BoxD b)
        {
            double gx = Math.Max(b.MinX - a.MaxX, a.MinX - b.MaxX), gy = Math.Max(b.MinY - a.MaxY, a.MinY - b.MaxY), gz = Math.Max(b.MinZ - a.MaxZ, a.MinZ - b.MaxZ);
            // Apart: the middle of the boxes' common range on each axis, clamped into each box.
            double mx = (Math.Max(a.MinX, b.MinX) + Math.Min(a.MaxX, b.MaxX)) * 0.5;
            double my = (Math.Max(a.MinY, b.MinY) + Math.Min(a.MaxY, b.MaxY)) * 0.5;
            double mz = (Math.Max(a.MinZ, b.MinZ) + Math.Min(a.MaxZ, b.MaxZ)) * 0.5;
            double ax = Math.Min(Math.Max(mx, a.MinX), a.MaxX), ay = Math.Min(Math.Max(my, a.MinY), a.MaxY), az = Math.Min(Math.Max(mz, a.MinZ), a.MaxZ);
            double bx = Math.Min(Math.Max(mx, b.MinX), b.MaxX), by = Math.Min(Math.Max(my, b.MinY), b.MaxY), bz = Math.Min(Math.Max(mz, b.MinZ), b.MaxZ);
            double ox = Math.Max(gx, 0), oy = Math.Max(gy, 0), oz = Math.Max(gz, 0);
            double outside = ox * ox + oy * oy + oz * oz;
            if (outside > 0) return Fold.Of(Math.Sqrt(outside), ax, ay, az, bx, by, bz);
            // Overlapping: the two faces along the axis of least penetration.
            if (gx >= gy && gx >= gz)
            {
                bool up = b.MinX - a.MaxX >= a.MinX - b.MaxX;
                return Fold.Of(gx, up ? a.MaxX : a.MinX, ay, az, up ? b.MinX : b.MaxX, by, bz);
            }
            if (gy >= gz)
            {
                bool up = b.MinY - a.MaxY >= a.MinY - b.MaxY;
                return Fold.Of(gy, ax, up ? a.MaxY : a.MinY, az, bx, up ? b.MinY : b.MaxY, bz);
            }
            bool upZ = b.MinZ - a.MaxZ >= a.MinZ - b.MaxZ;
            return Fold.Of(gz, ax, ay, upZ ? a.MaxZ : a.MinZ, bx, by, upZ ? b.MinZ : b.MaxZ);
        }

        public bool Overlaps(in BoxD a, in BoxD b) =>
            a.MinX <= b.MaxX && a.MaxX >= b.MinX && a.MinY <= b.MaxY && a.MaxY >= b.MinY && a.MinZ <= b.MaxZ && a.MaxZ >= b.MinZ;
    }

    /// <summary>Overlap when the center's squared distance to its clamp into the box is at most r².</summary>
    [Case(Baseline, Precision.Double, "3D sphere–AABB")]
    public readonly struct SphereAabbD : IOverlap<SphereD, BoxD>
    {
        public bool Overlaps(in SphereD s, in BoxD b)
        {
            double dx = s.X - Math.Min(Math.Max(s.X, b.MinX), b.MaxX);
            double dy = s.Y - Math.Min(Math.Max(s.Y, b.MinY), b.MaxY);
            double dz = s.Z - Math.Min(Math.Max(s.Z, b.MinZ), b.MaxZ);
            return dx * dx + dy * dy + dz * dz <= s.R * s.R;
        }
    }

    /// <summary>Closest points of two segments by the clamped normal equations (SegmentParameters).</summary>
    [Case(Baseline, Precision.Double, "3D segment–segment")]
    public readonly struct SegmentSegmentD : IBetween<SegmentD, SegmentD>, IDistance<SegmentD, SegmentD>
    {
        public double Distance(in SegmentD a, in SegmentD b)
        {
            Closest(a, b, out double ax, out double ay, out double az, out double bx, out double by, out double bz);
            double dx = ax - bx, dy = ay - by, dz = az - bz;
            return Math.Sqrt(dx * dx + dy * dy + dz * dz);
        }

        public double Between(in SegmentD a, in SegmentD b)
        {
            Closest(a, b, out double ax, out double ay, out double az, out double bx, out double by, out double bz);
            double dx = ax - bx, dy = ay - by, dz = az - bz;
            return Fold.Of(Math.Sqrt(dx * dx + dy * dy + dz * dz), ax, ay, az, bx, by, bz);
        }

        /// <summary>The closest points (shared with the capsule baselines).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static void Closest(in SegmentD a, in SegmentD b, out double ax, out double ay, out double az, out double bx, out double by, out double bz)
        {
            double d1x = a.QX - a.PX, d1y = a.QY - a.PY, d1z = a.QZ - a.PZ;
            double d2x = b.QX - b.PX, d2y = b.QY - b.PY, d2z = b.QZ - b.PZ;
            double rx = a.PX - b.PX, ry = a.PY - b.PY, rz = a.PZ - b.PZ;
            SegmentParameters.Of(d1x * d1x + d1y * d1y + d1z * d1z, d1x * d2x + d1y * d2y + d1z * d2z, d2x * d2x + d2y * d2y + d2z * d2z,
                d1x * rx + d1y * ry + d1z * rz, d2x * rx + d2y * ry + d2z * rz, out double s, out double t);
            ax = a.PX + d1x * s; ay = a.PY + d1y * s; az = a.PZ + d1z * s;
            bx = b.PX + d2x * t; by = b.PY + d2y * t; bz = b.PZ + d2z * t;
        }
    }

    /// <summary>The same closest points in the plane.</summary>
    [Case(Baseline, Precision.Double, "2D segment–segment")]
    public readonly struct SegmentSegment2D : IBetween<Segment2D, Segment2D>, IDistance<Segment2D, Segment2D>
    {
        public double Distance(in Segment2D a, in Segment2D b)
        {
            Closest(a, b, out double ax, out double ay, out double bx, out double by);
            double dx = ax - bx, dy = ay - by;
            return Math.Sqrt(dx * dx + dy * dy);
        }

        public double Between(in Segment2D a, in Segment2D b)
        {
            Closest(a, b, out double ax, out double ay, out double bx, out double by);
            double dx = ax - bx, dy = ay - by;
            return Fold.Of(Math.Sqrt(dx * dx + dy * dy), ax, ay, bx, by);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void Closest(in Segment2D a, in Segment2D b, out double ax, out double ay, out double bx, out double by)
        {
            double d1x = a.QX - a.PX, d1y = a.QY - a.PY, d2x = b.QX - b.PX, d2y = b.QY - b.PY, rx = a.PX - b.PX, ry = a.PY - b.PY;
            SegmentParameters.Of(d1x * d1x + d1y * d1y, d1x * d2x + d1y * d2y, d2x * d2x + d2y * d2y, d1x * rx + d1y * ry, d2x * rx + d2y * ry, out double s, out double t);
            ax = a.PX + d1x * s; ay = a.PY + d1y * s;
            bx = b.PX + d2x * t; by = b.PY + d2y * t;
        }
    }

    /// <summary>
    /// The parameters s, t ∈ [0, 1] of the closest points of P(s) = P0 + s·d1 and Q(t) = Q0 + t·d2, from the normal
    /// equations of |r + s·d1 − t·d2|² (r = P0 − Q0), with a = d1·d1, b = d1·d2, e = d2·d2, c = d1·r, f = d2·r:
    /// s = (bf − ce)/(ae − b²) clamped (0 when parallel), t = (bs + f)/e, and when t leaves [0, 1] it is clamped and s
    /// solved again for it. A zero-length segment fixes its own parameter at 0.
    /// </summary>
    internal static class SegmentParameters
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Of(float a, float b, float e, float c, float f, out float s, out float t)
        {
            if (a == 0) { s = 0; t = e > 0 ? Clamp01.Of(f / e) : 0; return; }
            if (e == 0) { t = 0; s = Clamp01.Of(-c / a); return; }
            float denominator = a * e - b * b;
            s = denominator != 0 ? Clamp01.Of((b * f - c * e) / denominator) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = Clamp01.Of(-c / a); }
            else if (t > 1) { t = 1; s = Clamp01.Of((b - c) / a); }
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static void Of(double a, double b, double e, double c, double f, out double s, out double t)
        {
            if (a == 0) { s = 0; t = e > 0 ? Clamp01.Of(f / e) : 0; return; }
            if (e == 0) { t = 0; s = Clamp01.Of(-c / a); return; }
            double denominator = a * e - b * b;
            s = denominator != 0 ? Clamp01.Of((b * f - c * e) / denominator) : 0;
            t = (b * s + f) / e;
            if (t < 0) { t = 0; s = Clamp01.Of(-c / a); }
            else if (t > 1) { t = 1; s = Clamp01.Of((b - c) / a); }
        }
    }

    internal static class Clamp01
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Of(float x) => x < 0 ? 0 : x > 1 ? 1 : x;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(double x) => x < 0 ? 0 : x > 1 ? 1 : x;
    }
}
