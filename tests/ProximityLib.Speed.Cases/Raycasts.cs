using System;
using System.Numerics;
using ProximityLib.Batch;
using static ProximitySpeed.Source;
using D = ProximityLib.Double;
using F = ProximityLib;
using DR = ProximityLib.Double.Raycast;
using FR = ProximityLib.Raycast;

namespace ProximitySpeed
{
    // Ray casts (issue 12): the library's Raycast.Cast against every solid target it has, float and double, 3D and 2D;
    // the textbook forms a game engine would write for sphere, AABB, triangle and half-space; and the batch casts (one
    // ray against many). The answer timed is T (+∞ for a miss): the library also fills RayHit's point and normal, which
    // these cases leave unused, as a caller needing only the distance would.
    [Case(Library, Precision.Float, "3D ray cast–sphere")] public readonly struct F3CastSphere : IRaycast<F.Ray3, F.Sphere> { public double Cast(in F.Ray3 r, in F.Sphere s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "3D ray cast–AABB")] public readonly struct F3CastAabb : IRaycast<F.Ray3, F.Aabb3> { public double Cast(in F.Ray3 r, in F.Aabb3 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "3D ray cast–triangle")] public readonly struct F3CastTriangle : IRaycast<F.Ray3, F.Triangle3> { public double Cast(in F.Ray3 r, in F.Triangle3 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "3D ray cast–capsule")] public readonly struct F3CastCapsule : IRaycast<F.Ray3, F.Capsule3> { public double Cast(in F.Ray3 r, in F.Capsule3 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "3D ray cast–OBB")] public readonly struct F3CastObb : IRaycast<F.Ray3, F.Obb3> { public double Cast(in F.Ray3 r, in F.Obb3 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "3D ray cast–half-space")] public readonly struct F3CastHalfSpace : IRaycast<F.Ray3, F.HalfSpace> { public double Cast(in F.Ray3 r, in F.HalfSpace s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–circle")] public readonly struct F2CastCircle : IRaycast<F.Ray2, F.Circle> { public double Cast(in F.Ray2 r, in F.Circle s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–AABB")] public readonly struct F2CastAabb : IRaycast<F.Ray2, F.Aabb2> { public double Cast(in F.Ray2 r, in F.Aabb2 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–triangle")] public readonly struct F2CastTriangle : IRaycast<F.Ray2, F.Triangle2> { public double Cast(in F.Ray2 r, in F.Triangle2 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–capsule")] public readonly struct F2CastCapsule : IRaycast<F.Ray2, F.Capsule2> { public double Cast(in F.Ray2 r, in F.Capsule2 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–OBB")] public readonly struct F2CastObb : IRaycast<F.Ray2, F.Obb2> { public double Cast(in F.Ray2 r, in F.Obb2 s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Float, "2D ray cast–half-plane")] public readonly struct F2CastHalfPlane : IRaycast<F.Ray2, F.HalfPlane> { public double Cast(in F.Ray2 r, in F.HalfPlane s) => FR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–sphere")] public readonly struct D3CastSphere : IRaycast<D.Ray3, D.Sphere> { public double Cast(in D.Ray3 r, in D.Sphere s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–AABB")] public readonly struct D3CastAabb : IRaycast<D.Ray3, D.Aabb3> { public double Cast(in D.Ray3 r, in D.Aabb3 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–triangle")] public readonly struct D3CastTriangle : IRaycast<D.Ray3, D.Triangle3> { public double Cast(in D.Ray3 r, in D.Triangle3 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–capsule")] public readonly struct D3CastCapsule : IRaycast<D.Ray3, D.Capsule3> { public double Cast(in D.Ray3 r, in D.Capsule3 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–OBB")] public readonly struct D3CastObb : IRaycast<D.Ray3, D.Obb3> { public double Cast(in D.Ray3 r, in D.Obb3 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "3D ray cast–half-space")] public readonly struct D3CastHalfSpace : IRaycast<D.Ray3, D.HalfSpace> { public double Cast(in D.Ray3 r, in D.HalfSpace s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–circle")] public readonly struct D2CastCircle : IRaycast<D.Ray2, D.Circle> { public double Cast(in D.Ray2 r, in D.Circle s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–AABB")] public readonly struct D2CastAabb : IRaycast<D.Ray2, D.Aabb2> { public double Cast(in D.Ray2 r, in D.Aabb2 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–triangle")] public readonly struct D2CastTriangle : IRaycast<D.Ray2, D.Triangle2> { public double Cast(in D.Ray2 r, in D.Triangle2 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–capsule")] public readonly struct D2CastCapsule : IRaycast<D.Ray2, D.Capsule2> { public double Cast(in D.Ray2 r, in D.Capsule2 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–OBB")] public readonly struct D2CastObb : IRaycast<D.Ray2, D.Obb2> { public double Cast(in D.Ray2 r, in D.Obb2 s) => DR.Cast(r, s).T; }
    [Case(Library, Precision.Double, "2D ray cast–half-plane")] public readonly struct D2CastHalfPlane : IRaycast<D.Ray2, D.HalfPlane> { public double Cast(in D.Ray2 r, in D.HalfPlane s) => DR.Cast(r, s).T; }

    // ---- the textbook forms, on the baselines' plain structs (Baselines.cs) ----

    public readonly struct RayF { public readonly Vector3 O, D; public RayF(Vector3 o, Vector3 d) { O = o; D = d; } }
    public readonly struct RayD
    {
        public readonly double OX, OY, OZ, DX, DY, DZ;
        public RayD(double ox, double oy, double oz, double dx, double dy, double dz) { OX = ox; OY = oy; OZ = oz; DX = dx; DY = dy; DZ = dz; }

        /// <summary>From the input numbers, the direction normalised.</summary>
        public static RayD Of(double[] v)
        {
            double l = Math.Sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5]);
            return new RayD(v[0], v[1], v[2], v[3] / l, v[4] / l, v[5] / l);
        }
    }
    public readonly struct TriangleF { public readonly Vector3 A, B, C; public TriangleF(Vector3 a, Vector3 b, Vector3 c) { A = a; B = b; C = c; } }
    public readonly struct TriangleD { public readonly PointD A, B, C; public TriangleD(PointD a, PointD b, PointD c) { A = a; B = b; C = c; } }

    /// <summary>The solid n·x ≤ d, n a unit vector.</summary>
    public readonly struct PlaneF
    {
        public readonly Vector3 N;
        public readonly float D;
        public PlaneF(Vector3 n, float d) { N = n; D = d; }
        public static PlaneF Of(Vector3 n, float d) { float l = n.Length(); return new PlaneF(n / l, d / l); }
    }

    /// <summary>The solid n·x ≤ d, n a unit vector.</summary>
    public readonly struct PlaneD
    {
        public readonly double NX, NY, NZ, D;
        public PlaneD(double nx, double ny, double nz, double d) { NX = nx; NY = ny; NZ = nz; D = d; }
        public static PlaneD Of(double[] v) { double l = Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); return new PlaneD(v[0] / l, v[1] / l, v[2] / l, v[3] / l); }
    }

    /// <summary>
    /// The game-engine form (Ericson, Real-Time Collision Detection §5.3.2): m = o − c, b = m·d, c = |m|² − r²; a miss when
    /// the origin is outside and the ray points away (c &gt; 0, b &gt; 0) or the discriminant b² − c is negative; else
    /// t = −b − √(b² − c), clamped to 0 for an origin inside.
    /// </summary>
    [Case(Baseline, Precision.Float, "3D ray cast–sphere")]
    public readonly struct CastSphereF : IRaycast<RayF, SphereF>
    {
        public double Cast(in RayF r, in SphereF s)
        {
            var m = r.O - s.Center;
            float b = Vector3.Dot(m, r.D), c = Vector3.Dot(m, m) - s.Radius * s.Radius;
            if (c > 0 && b > 0) return double.PositiveInfinity;
            float disc = b * b - c;
            if (disc < 0) return double.PositiveInfinity;
            float t = -b - MathF.Sqrt(disc);
            return t < 0 ? 0 : t;
        }
    }

    /// <summary>The slab test, branch-free: per axis the entry and exit parameters by one reciprocal of d, the largest entry against the smallest exit.</summary>
    [Case(Baseline, Precision.Float, "3D ray cast–AABB")]
    public readonly struct CastAabbF : IRaycast<RayF, BoxF>
    {
        public double Cast(in RayF r, in BoxF b)
        {
            var inv = Vector3.One / r.D;
            var t1 = (b.Min - r.O) * inv;
            var t2 = (b.Max - r.O) * inv;
            var lo = Vector3.Min(t1, t2);
            var hi = Vector3.Max(t1, t2);
            float enter = MathF.Max(MathF.Max(MathF.Max(lo.X, lo.Y), lo.Z), 0);
            float exit = MathF.Min(MathF.Min(hi.X, hi.Y), hi.Z);
            return exit >= enter ? enter : double.PositiveInfinity;
        }
    }

    /// <summary>
    /// Möller–Trumbore (1997), two-sided: p = d × e2, det = e1·p (0: the ray is parallel, a miss); barycentric u = s·p/det
    /// and v = d·q/det (q = s × e1) must lie in the triangle, and t = e2·q/det ≥ 0.
    /// </summary>
    [Case(Baseline, Precision.Float, "3D ray cast–triangle")]
    public readonly struct CastTriangleF : IRaycast<RayF, TriangleF>
    {
        public double Cast(in RayF r, in TriangleF tri)
        {
            Vector3 e1 = tri.B - tri.A, e2 = tri.C - tri.A;
            var p = Vector3.Cross(r.D, e2);
            float det = Vector3.Dot(e1, p);
            if (det == 0) return double.PositiveInfinity;
            float inv = 1 / det;
            var s = r.O - tri.A;
            float u = Vector3.Dot(s, p) * inv;
            if (u < 0 || u > 1) return double.PositiveInfinity;
            var q = Vector3.Cross(s, e1);
            float v = Vector3.Dot(r.D, q) * inv;
            if (v < 0 || u + v > 1) return double.PositiveInfinity;
            float t = Vector3.Dot(e2, q) * inv;
            return t >= 0 ? t : double.PositiveInfinity;
        }
    }

    /// <summary>Ray against a solid half-space: 0 when the origin is inside (n·o ≤ d), else (d − n·o)/(n·d) when the ray heads in (n·d &lt; 0).</summary>
    [Case(Baseline, Precision.Float, "3D ray cast–half-space")]
    public readonly struct CastPlaneF : IRaycast<RayF, PlaneF>
    {
        public double Cast(in RayF r, in PlaneF p)
        {
            float above = Vector3.Dot(p.N, r.O) - p.D;
            if (above <= 0) return 0;
            float nd = Vector3.Dot(p.N, r.D);
            return nd < 0 ? -above / nd : double.PositiveInfinity;
        }
    }

    /// <summary>The game-engine ray–sphere form (float's twin) in scalar double.</summary>
    [Case(Baseline, Precision.Double, "3D ray cast–sphere")]
    public readonly struct CastSphereD : IRaycast<RayD, SphereD>
    {
        public double Cast(in RayD r, in SphereD s)
        {
            double mx = r.OX - s.X, my = r.OY - s.Y, mz = r.OZ - s.Z;
            double b = mx * r.DX + my * r.DY + mz * r.DZ, c = mx * mx + my * my + mz * mz - s.R * s.R;
            if (c > 0 && b > 0) return double.PositiveInfinity;
            double disc = b * b - c;
            if (disc < 0) return double.PositiveInfinity;
            double t = -b - Math.Sqrt(disc);
            return t < 0 ? 0 : t;
        }
    }

    /// <summary>The branch-free slab test (float's twin) in scalar double.</summary>
    [Case(Baseline, Precision.Double, "3D ray cast–AABB")]
    public readonly struct CastAabbD : IRaycast<RayD, BoxD>
    {
        public double Cast(in RayD r, in BoxD b)
        {
            double ix = 1 / r.DX, iy = 1 / r.DY, iz = 1 / r.DZ;
            double x1 = (b.MinX - r.OX) * ix, x2 = (b.MaxX - r.OX) * ix;
            double y1 = (b.MinY - r.OY) * iy, y2 = (b.MaxY - r.OY) * iy;
            double z1 = (b.MinZ - r.OZ) * iz, z2 = (b.MaxZ - r.OZ) * iz;
            double enter = Math.Max(Math.Max(Math.Max(Math.Min(x1, x2), Math.Min(y1, y2)), Math.Min(z1, z2)), 0);
            double exit = Math.Min(Math.Min(Math.Max(x1, x2), Math.Max(y1, y2)), Math.Max(z1, z2));
            return exit >= enter ? enter : double.PositiveInfinity;
        }
    }

    /// <summary>Möller–Trumbore (float's twin) in scalar double.</summary>
    [Case(Baseline, Precision.Double, "3D ray cast–triangle")]
    public readonly struct CastTriangleD : IRaycast<RayD, TriangleD>
    {
        public double Cast(in RayD r, in TriangleD tri)
        {
            double e1x = tri.B.X - tri.A.X, e1y = tri.B.Y - tri.A.Y, e1z = tri.B.Z - tri.A.Z;
            double e2x = tri.C.X - tri.A.X, e2y = tri.C.Y - tri.A.Y, e2z = tri.C.Z - tri.A.Z;
            double px = r.DY * e2z - r.DZ * e2y, py = r.DZ * e2x - r.DX * e2z, pz = r.DX * e2y - r.DY * e2x;
            double det = e1x * px + e1y * py + e1z * pz;
            if (det == 0) return double.PositiveInfinity;
            double inv = 1 / det;
            double sx = r.OX - tri.A.X, sy = r.OY - tri.A.Y, sz = r.OZ - tri.A.Z;
            double u = (sx * px + sy * py + sz * pz) * inv;
            if (u < 0 || u > 1) return double.PositiveInfinity;
            double qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
            double v = (r.DX * qx + r.DY * qy + r.DZ * qz) * inv;
            if (v < 0 || u + v > 1) return double.PositiveInfinity;
            double t = (e2x * qx + e2y * qy + e2z * qz) * inv;
            return t >= 0 ? t : double.PositiveInfinity;
        }
    }

    /// <summary>Ray against a solid half-space (float's twin) in scalar double.</summary>
    [Case(Baseline, Precision.Double, "3D ray cast–half-space")]
    public readonly struct CastPlaneD : IRaycast<RayD, PlaneD>
    {
        public double Cast(in RayD r, in PlaneD p)
        {
            double above = p.NX * r.OX + p.NY * r.OY + p.NZ * r.OZ - p.D;
            if (above <= 0) return 0;
            double nd = p.NX * r.DX + p.NY * r.DY + p.NZ * r.DZ;
            return nd < 0 ? -above / nd : double.PositiveInfinity;
        }
    }

    public static partial class Catalog
    {
        /// <summary>
        /// The batch ray casts, one ray against all the targets of the group's inputs (ray k of the inputs in repetition
        /// k), timed per target; in the group of the scalar cast, which answers the inputs' own pairs.
        /// </summary>
        static partial void AddRaycastBatches(InputSet inputs, Action<string, string, int, Func<int, double>> add)
        {
            var rays = Shapes.Of<F.Ray3>(inputs.Side("3D ray cast–sphere", 0));
            var spheres = new SphereSet(Shapes.Of<F.Sphere>(inputs.Side("3D ray cast–sphere", 1)));
            OneToMany(add, "3D ray cast–sphere", rays, spheres.Count, (ray, result) => BatchQuery.Raycasts(ray, spheres, result));
            var boxRays = Shapes.Of<F.Ray3>(inputs.Side("3D ray cast–AABB", 0));
            var boxes = new AabbSet(Shapes.Of<F.Aabb3>(inputs.Side("3D ray cast–AABB", 1)));
            OneToMany(add, "3D ray cast–AABB", boxRays, boxes.Count, (ray, result) => BatchQuery.Raycasts(ray, boxes, result));
            var triangleRays = Shapes.Of<F.Ray3>(inputs.Side("3D ray cast–triangle", 0));
            var triangles = new TriangleSet(Shapes.Of<F.Triangle3>(inputs.Side("3D ray cast–triangle", 1)));
            OneToMany(add, "3D ray cast–triangle", triangleRays, triangles.Count, (ray, result) => BatchQuery.Raycasts(ray, triangles, result));
        }

        private static void OneToMany(Action<string, string, int, Func<int, double>> add, string query, F.Ray3[] rays, int n, Action<F.Ray3, float[]> cast)
        {
            var result = new float[n];
            add("float " + query, "batch one-to-many Raycasts", n, reps =>
            {
                for (int r = 0; r < reps; r++) cast(rays[r % rays.Length], result);
                return result[n / 2];
            });
        }
    }
}
