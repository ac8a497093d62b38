using System;
using System.Collections.Generic;
using ProximityLib.Double;

namespace ProximityReference
{
    public enum RKind { Point, Segment, Sphere, Box }

    /// <summary>
    /// A shape as exact rationals: the library's double inputs taken at face value. A box is the parallelepiped
    /// center ± Σ h_i·axis_i with the axes exactly as stored (orthonormal only to rounding), listed as vertices, edges
    /// and faces. 2D shapes are planar: z = 0, and only in-plane directions count.
    /// </summary>
    public sealed class RShape
    {
        public RKind Kind { get; private set; }
        public bool Planar { get; private set; }
        public RVec Center { get; private set; }
        public Rational Radius { get; private set; }
        public List<RVec> Vertices { get; } = new List<RVec>();
        public List<(RVec Origin, RVec Dir)> Edges { get; } = new List<(RVec, RVec)>();
        public List<(RVec Origin, RVec U, RVec V)> Faces { get; } = new List<(RVec, RVec, RVec)>();
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

        /// <summary>The same shape moved by t, exactly (no rounding: the moved shape need not have double coordinates).</summary>
        public RShape Translated(RVec t)
        {
            var s = new RShape { Kind = Kind, Planar = Planar, Center = Kind == RKind.Segment ? Center : Center + t, Radius = Radius };
            foreach (var v in Vertices) s.Vertices.Add(v + t);
            foreach (var e in Edges) s.Edges.Add((e.Origin + t, e.Dir));
            foreach (var f in Faces) s.Faces.Add((f.Origin + t, f.U, f.V));
            s.Directions.AddRange(Directions);
            foreach (var d in Defining) s.Defining.Add(d + t);
            return s;
        }

        public bool IsSolid => Kind == RKind.Sphere || Kind == RKind.Box;

        /// <summary>True when the shape spans fewer dimensions than its space (point, segment, flat box).</summary>
        public bool IsDegenerate => Kind == RKind.Point || Kind == RKind.Segment
            || (Kind == RKind.Box && Directions.Count < (Planar ? 2 : 3));

        public static RShape Point(Vector3D p, bool planar = false)
        {
            var s = new RShape { Kind = RKind.Point, Planar = planar, Center = RVec.From(p) };
            s.Vertices.Add(s.Center);
            s.Defining.Add(s.Center);
            return s;
        }

        public static RShape Point(Vector2D p) => Point(new Vector3D(p.X, p.Y, 0), true);

        public static RShape Segment(Vector3D a, Vector3D b, bool planar = false)
        {
            var s = new RShape { Kind = RKind.Segment, Planar = planar };
            var ra = RVec.From(a);
            var rb = RVec.From(b);
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
                        if ((mask & ((1 << i) | (1 << j))) == 0) s.Faces.Add((s.Vertices[mask], e[i] * 2, e[j] * 2));
                }
            return s;
        }
    }
}
