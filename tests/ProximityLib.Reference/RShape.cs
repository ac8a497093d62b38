using System;
using System.Collections.Generic;
using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>The reference's shape kinds (Line and Ray are unbounded; HalfSpace is the 3D half-space or the 2D half-plane).</summary>
    public enum RKind { Point, Segment, Sphere, Box, Line, Ray, Capsule, Triangle, HalfSpace }

    /// <summary>
    /// A shape as exact rationals: the library's double inputs taken at face value. A box is the parallelepiped
    /// center ± Σ h_i·axis_i with the axes exactly as stored (orthonormal only to rounding), listed as vertices, edges
    /// and faces. A triangle is the convex hull of its three vertices (three edges and one triangular face; collinear or
    /// coincident vertices leave only the segment or point it is). A capsule is its axis segment plus Radius, as a
    /// sphere is its center plus Radius. A line or ray is Center + t·Direction (all t, or t ≥ 0) with the stored
    /// Direction, which is unit only to rounding; a half-space is exactly {x : Normal·(x − Center) ≤ 0} with the stored
    /// Normal and boundary point. 2D shapes are planar: z = 0, and only in-plane directions count.
    /// </summary>
    public sealed class RShape
    {
        public RKind Kind { get; private set; }
        public bool Planar { get; private set; }
        /// <summary>Sphere/box center, point, line/ray origin, half-space boundary point (zero for the others).</summary>
        public RVec Center { get; private set; } = RVec.Zero;
        /// <summary>Sphere or capsule radius; zero for every other kind.</summary>
        public Rational Radius { get; private set; } = Rational.Zero;
        /// <summary>A line's or ray's stored direction (not exactly unit); zero for the others.</summary>
        public RVec Direction { get; private set; } = RVec.Zero;
        /// <summary>A half-space's stored outward normal (not exactly unit); zero for the others.</summary>
        public RVec Normal { get; private set; } = RVec.Zero;
        public List<RVec> Vertices { get; } = new List<RVec>();
        public List<(RVec Origin, RVec Dir)> Edges { get; } = new List<(RVec, RVec)>();
        /// <summary>Origin + z0·U + z1·V with z in [0, 1]² (a parallelogram), or z0, z1 ≥ 0, z0 + z1 ≤ 1 when Triangular.</summary>
        public List<(RVec Origin, RVec U, RVec V, bool Triangular)> Faces { get; } = new List<(RVec, RVec, RVec, bool)>();
        /// <summary>Edge directions (non-zero), for separating-axis candidates.</summary>
        public List<RVec> Directions { get; } = new List<RVec>();
        /// <summary>Coordinates of the defining points, for the local scale S.</summary>
        public List<RVec> Defining { get; } = new List<RVec>();

        /// <summary>A point at c, in this shape's plane mode (stands in for a sphere's center).</summary>
        public RShape WithCenter(RVec c)
        {
            var s = new RShape { Kind = RKind.Point, Planar = Planar, Center = c };
            s.Vertices.Add(c);
            s.Defining.Add(c);
            return s;
        }

        /// <summary>
        /// The bounded polytope part without the radius: a sphere's center point, a capsule's axis segment, the shape
        /// itself otherwise (lines, rays and half-spaces have none; callers handle them first).
        /// </summary>
        public RShape Core()
        {
            if (Kind == RKind.Sphere) return WithCenter(Center);
            if (Kind != RKind.Capsule) return this;
            var s = new RShape { Kind = RKind.Segment, Planar = Planar };
            s.Vertices.AddRange(Vertices);
            s.Edges.AddRange(Edges);
            s.Directions.AddRange(Directions);
            s.Defining.AddRange(Vertices);
            return s;
        }

        /// <summary>The same shape moved by t, exactly (no rounding: the moved shape need not have double coordinates).</summary>
        public RShape Translated(RVec t)
        {
            bool centered = Kind == RKind.Point || Kind == RKind.Sphere || Kind == RKind.Box || Kind == RKind.Line
                || Kind == RKind.Ray || Kind == RKind.HalfSpace;
            var s = new RShape
            {
                Kind = Kind, Planar = Planar, Center = centered ? Center + t : Center, Radius = Radius,
                Direction = Direction, Normal = Normal,
            };
            foreach (var v in Vertices) s.Vertices.Add(v + t);
            foreach (var e in Edges) s.Edges.Add((e.Origin + t, e.Dir));
            foreach (var f in Faces) s.Faces.Add((f.Origin + t, f.U, f.V, f.Triangular));
            s.Directions.AddRange(Directions);
            foreach (var d in Defining) s.Defining.Add(d + t);
            return s;
        }

        /// <summary>
        /// Solids: sphere/circle, capsule, box, half-space/half-plane, and a 2D triangle that is not degenerate (a
        /// degenerate one is answered as the segment or point it is, which is not solid).
        /// </summary>
        public bool IsSolid => Kind == RKind.Sphere || Kind == RKind.Box || Kind == RKind.Capsule || Kind == RKind.HalfSpace
            || (Kind == RKind.Triangle && Planar && Faces.Count > 0);

        /// <summary>True when the shape spans fewer dimensions than its space (point, segment, line, ray, 3D or degenerate triangle, flat box).</summary>
        public bool IsDegenerate => Kind == RKind.Point || Kind == RKind.Segment || Kind == RKind.Line || Kind == RKind.Ray
            || (Kind == RKind.Triangle && (!Planar || Faces.Count == 0))
            || (Kind == RKind.Box && Directions.Count < (Planar ? 2 : 3));

        /// <summary>True for lines and rays (unbounded 1D shapes).</summary>
        public bool IsLinear => Kind == RKind.Line || Kind == RKind.Ray;

        public static RShape Point(Vector3D p, bool planar = false)
        {
            var s = new RShape { Kind = RKind.Point, Planar = planar, Center = RVec.From(p) };
            s.Vertices.Add(s.Center);
            s.Defining.Add(s.Center);
            return s;
        }

        public static RShape Point(Vector2D p) => Point(new Vector3D(p.X, p.Y, 0), true);

        public static RShape Segment(Vector3D a, Vector3D b, bool planar = false) => Segment(RVec.From(a), RVec.From(b), planar);

        /// <summary>The segment ra–rb (exact rational endpoints).</summary>
        public static RShape Segment(RVec ra, RVec rb, bool planar)
        {
            var s = new RShape { Kind = RKind.Segment, Planar = planar };
            s.Vertices.Add(ra);
            s.Vertices.Add(rb);
            s.Defining.Add(ra);
            s.Defining.Add(rb);
            var d = rb - ra;
            if (!d.IsZero) { s.Edges.Add((ra, d)); s.Directions.Add(d); }
            return s;
        }

        public static RShape From(Segment3 x) => Segment(x.Start, x.End);
        public static RShape From(Segment2 x) => Segment(new Vector3D(x.Start.X, x.Start.Y, 0), new Vector3D(x.End.X, x.End.Y, 0), true);

        public static RShape From(Sphere x) => SphereOf(RVec.From(x.Center), x.Radius, false);
        public static RShape From(Circle x) => SphereOf(RVec.From(x.Center), x.Radius, true);

        private static RShape SphereOf(RVec c, double r, bool planar)
        {
            var s = new RShape { Kind = RKind.Sphere, Planar = planar, Center = c, Radius = r };
            s.Defining.Add(c);
            s.Defining.Add(c + new RVec(r, 0, 0));
            return s;
        }

        public static RShape From(Aabb3 x)
        {
            var min = RVec.From(x.Min);
            var max = RVec.From(x.Max);
            var half = (max - min) * new Rational(1, 2);
            return BoxOf(min + half, new[] { RVec.UnitX, RVec.UnitY, RVec.UnitZ }, new[] { half.X, half.Y, half.Z }, false);
        }

        public static RShape From(Aabb2 x)
        {
            var min = RVec.From(x.Min);
            var max = RVec.From(x.Max);
            var half = (max - min) * new Rational(1, 2);
            return BoxOf(min + half, new[] { RVec.UnitX, RVec.UnitY }, new[] { half.X, half.Y }, true);
        }

        public static RShape From(Obb3 x) =>
            BoxOf(RVec.From(x.Center), new[] { RVec.From(x.AxisX), RVec.From(x.AxisY), RVec.From(x.AxisZ) },
                new Rational[] { x.HalfExtents.X, x.HalfExtents.Y, x.HalfExtents.Z }, false);

        public static RShape From(Obb2 x) =>
            BoxOf(RVec.From(x.Center), new[] { RVec.From(x.AxisX), RVec.From(x.AxisY) },
                new Rational[] { x.HalfExtents.X, x.HalfExtents.Y }, true);

        public static RShape From(Line3 x) => LinearOf(RKind.Line, RVec.From(x.Origin), RVec.From(x.Direction), false);
        public static RShape From(Line2 x) => LinearOf(RKind.Line, RVec.From(x.Origin), RVec.From(x.Direction), true);
        public static RShape From(Ray3 x) => LinearOf(RKind.Ray, RVec.From(x.Origin), RVec.From(x.Direction), false);
        public static RShape From(Ray2 x) => LinearOf(RKind.Ray, RVec.From(x.Origin), RVec.From(x.Direction), true);

        /// <summary>A line or ray Origin + t·Direction with the stored (unit only to rounding) direction; S counts the origin.</summary>
        public static RShape LinearOf(RKind kind, RVec origin, RVec direction, bool planar)
        {
            if (kind != RKind.Line && kind != RKind.Ray) throw new ArgumentException("a line or ray kind", nameof(kind));
            if (direction.IsZero) throw new ArgumentException("zero direction", nameof(direction));
            var s = new RShape { Kind = kind, Planar = planar, Center = origin, Direction = direction };
            s.Defining.Add(origin);
            return s;
        }

        public static RShape From(Capsule3 x) => CapsuleOf(RVec.From(x.Start), RVec.From(x.End), x.Radius, false);
        public static RShape From(Capsule2 x) => CapsuleOf(RVec.From(x.Start), RVec.From(x.End), x.Radius, true);

        /// <summary>
        /// The axis segment plus a radius. S counts both endpoints and, like a sphere's, Start + (r, 0, 0), so a
        /// zero-length capsule has exactly a sphere's S.
        /// </summary>
        public static RShape CapsuleOf(RVec start, RVec end, Rational radius, bool planar)
        {
            var s = Segment(start, end, planar);
            s.Kind = RKind.Capsule;
            s.Radius = radius;
            s.Defining.Add(start + new RVec(radius, 0, 0));
            return s;
        }

        public static RShape From(Triangle3 x) => TriangleOf(RVec.From(x.A), RVec.From(x.B), RVec.From(x.C), false);
        public static RShape From(Triangle2 x) => TriangleOf(RVec.From(x.A), RVec.From(x.B), RVec.From(x.C), true);

        /// <summary>
        /// The convex hull of a, b, c: three vertices, three edges and one triangular face; when the vertices are
        /// collinear (exactly) only the longest of the three edges (all three vertices stay: the middle one lies on it),
        /// when they coincide only the point.
        /// </summary>
        public static RShape TriangleOf(RVec a, RVec b, RVec c, bool planar)
        {
            var s = new RShape { Kind = RKind.Triangle, Planar = planar };
            foreach (var v in new[] { a, b, c }) { s.Vertices.Add(v); s.Defining.Add(v); }
            var ab = b - a;
            var ac = c - a;
            var bc = c - b;
            if (!RVec.Cross(ab, ac).IsZero)
            {
                s.Edges.Add((a, ab));
                s.Edges.Add((b, bc));
                s.Edges.Add((a, ac));
                s.Directions.Add(ab);
                s.Directions.Add(bc);
                s.Directions.Add(ac);
                s.Faces.Add((a, ab, ac, true));
                return s;
            }
            var longest = (Origin: a, Dir: ab);
            if (ac.LengthSquared > longest.Dir.LengthSquared) longest = (a, ac);
            if (bc.LengthSquared > longest.Dir.LengthSquared) longest = (b, bc);
            if (!longest.Dir.IsZero) { s.Edges.Add(longest); s.Directions.Add(longest.Dir); }
            return s;
        }

        public static RShape From(HalfSpace x) => HalfSpaceOf(RVec.From(x.Point), RVec.From(x.Normal), false);
        public static RShape From(HalfPlane x) => HalfSpaceOf(RVec.From(x.Point), RVec.From(x.Normal), true);

        /// <summary>Exactly {x : normal·(x − point) ≤ 0} with the stored normal (unit only to rounding); S counts the point.</summary>
        public static RShape HalfSpaceOf(RVec point, RVec normal, bool planar)
        {
            if (normal.IsZero) throw new ArgumentException("zero normal", nameof(normal));
            var s = new RShape { Kind = RKind.HalfSpace, Planar = planar, Center = point, Normal = normal };
            s.Defining.Add(point);
            return s;
        }

        /// <summary>Any library shape (double API), including Vector2D/Vector3D points.</summary>
        public static RShape FromAny(object shape) => shape switch
        {
            Vector3D p => Point(p),
            Vector2D p => Point(p),
            Segment3 s => From(s),
            Segment2 s => From(s),
            Sphere s => From(s),
            Circle c => From(c),
            Aabb3 b => From(b),
            Aabb2 b => From(b),
            Obb3 b => From(b),
            Obb2 b => From(b),
            Line3 l => From(l),
            Line2 l => From(l),
            Ray3 r => From(r),
            Ray2 r => From(r),
            Capsule3 c => From(c),
            Capsule2 c => From(c),
            Triangle3 t => From(t),
            Triangle2 t => From(t),
            HalfSpace h => From(h),
            HalfPlane h => From(h),
            _ => throw new ArgumentException(shape.GetType().Name),
        };

        private static RShape BoxOf(RVec c, RVec[] axes, Rational[] half, bool planar)
        {
            var s = new RShape { Kind = RKind.Box, Planar = planar, Center = c };
            int n = axes.Length;
            var e = new RVec[n];
            for (int i = 0; i < n; i++) e[i] = axes[i] * half[i];
            for (int mask = 0; mask < (1 << n); mask++)
            {
                var v = c;
                for (int i = 0; i < n; i++) v = (mask & (1 << i)) != 0 ? v + e[i] : v - e[i];
                s.Vertices.Add(v);
                s.Defining.Add(v);
            }
            for (int i = 0; i < n; i++)
            {
                if (half[i].IsZero) continue;
                s.Directions.Add(axes[i]);
                // Edges along axis i: every vertex whose bit i is clear, to its partner with the bit set.
                for (int mask = 0; mask < (1 << n); mask++)
                    if ((mask & (1 << i)) == 0) s.Edges.Add((s.Vertices[mask], e[i] * 2));
            }
            // Faces: for each pair of axes (i, j), every vertex with both bits clear spans a parallelogram.
            for (int i = 0; i < n; i++)
                for (int j = i + 1; j < n; j++)
                {
                    if (half[i].IsZero || half[j].IsZero) continue;
                    for (int mask = 0; mask < (1 << n); mask++)
                        if ((mask & ((1 << i) | (1 << j))) == 0) s.Faces.Add((s.Vertices[mask], e[i] * 2, e[j] * 2, false));
                }
            return s;
        }
    }
}
