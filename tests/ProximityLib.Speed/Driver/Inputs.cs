using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Text;
using ProximityLib.Double;
using ProximityReference;
using Dbl = ProximityLib.Double;

namespace ProximitySpeed
{
    /// <summary>
    /// Seeded query inputs in three distributions (all apart, all overlapping, half and half shuffled), written once per
    /// run to the file every probe reads (ProximityLib.Speed.Cases/InputSet.cs), so every mode, process and library
    /// version measures the same pairs.
    /// </summary>
    public static class Inputs
    {
        public const int Count = 1024;
        public static readonly string[] Distributions = { "mixed", "apart", "overlapping" };

        private static readonly string[] Kinds = { "point", "segment", "sphere", "AABB", "OBB" };

        /// <summary>Every kind since issue 12, in the library's order (the fuzz's): a pair is named smaller kind first.</summary>
        private static readonly string[] AllKinds = { "point", "segment", "line", "ray", "sphere", "capsule", "triangle", "half-space", "AABB", "OBB" };

        /// <summary>The ray casts' targets, by dimension (ProximityLib.Speed.Cases/Raycasts.cs).</summary>
        private static readonly string[] CastTargets = { "sphere", "AABB", "triangle", "capsule", "OBB", "half-space" };

        /// <summary>
        /// Every query of the library: the original pairs "3D point–point" … "2D OBB–OBB", one per unordered pair of
        /// kinds, then issue 12's pairs (those with a line, ray, capsule, triangle or half-space; not yet line or ray
        /// against a triangle, which the library lacks), then the ray casts "3D ray cast–sphere" ….
        /// </summary>
        public static IEnumerable<string> Queries()
        {
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < Kinds.Length; i++)
                    for (int j = i; j < Kinds.Length; j++)
                        yield return $"{dim}D {Name(Kinds[i], dim)}–{Name(Kinds[j], dim)}";
            foreach (var q in NewQueries()) yield return q;
            foreach (int dim in new[] { 3, 2 })
                foreach (var t in CastTargets)
                    yield return $"{dim}D ray cast–{Name(t, dim)}";
        }

        /// <summary>Issue 12's pairs, "3D point–line" … "2D half-plane–OBB".</summary>
        public static IEnumerable<string> NewQueries()
        {
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < AllKinds.Length; i++)
                    for (int j = i; j < AllKinds.Length; j++)
                    {
                        string a = AllKinds[i], b = AllKinds[j];
                        if (Kinds.Contains(a) && Kinds.Contains(b)) continue;
                        yield return $"{dim}D {Name(a, dim)}–{Name(b, dim)}";
                    }
        }

        private static string Name(string kind, int dim) =>
            dim == 3 ? kind : kind == "sphere" ? "circle" : kind == "half-space" ? "half-plane" : kind;

        public static void Write(string path, string distribution, int seed = 7)
        {
            var text = new StringBuilder();
            text.Append($"# ProximityLib speed inputs: {distribution}, seed {seed}, {Count} pairs per query\n");
            foreach (var query in Queries())
            {
                text.Append("query ").Append(query).Append('\n');
                foreach (var (a, b) in Make(query, distribution, seed))
                    text.Append(string.Join(" ", Numbers(a).Select(R))).Append(" | ").Append(string.Join(" ", Numbers(b).Select(R))).Append('\n');
            }
            File.WriteAllText(path, text.ToString());
        }

        private static string R(double x) => x.ToString("R", CultureInfo.InvariantCulture);

        /// <summary>The numbers that define a shape, in the order InputSet documents.</summary>
        private static IEnumerable<double> Numbers(object shape) => shape switch
        {
            Vector3D p => new[] { p.X, p.Y, p.Z },
            Vector2D p => new[] { p.X, p.Y },
            Dbl.Segment3 s => Numbers(s.Start).Concat(Numbers(s.End)),
            Dbl.Segment2 s => Numbers(s.Start).Concat(Numbers(s.End)),
            Dbl.Sphere s => Numbers(s.Center).Append(s.Radius),
            Dbl.Circle s => Numbers(s.Center).Append(s.Radius),
            Dbl.Aabb3 b => Numbers(b.Min).Concat(Numbers(b.Max)),
            Dbl.Aabb2 b => Numbers(b.Min).Concat(Numbers(b.Max)),
            Dbl.Obb3 b => new[] { b.Center, b.AxisX, b.AxisY, b.AxisZ, b.HalfExtents }.SelectMany(v => Numbers(v)),
            Dbl.Obb2 b => new[] { b.Center, b.AxisX, b.HalfExtents }.SelectMany(v => Numbers(v)),
            Dbl.Line3 l => Numbers(l.Origin).Concat(Numbers(l.Direction)),
            Dbl.Line2 l => Numbers(l.Origin).Concat(Numbers(l.Direction)),
            Dbl.Ray3 l => Numbers(l.Origin).Concat(Numbers(l.Direction)),
            Dbl.Ray2 l => Numbers(l.Origin).Concat(Numbers(l.Direction)),
            Dbl.Capsule3 c => Numbers(c.Start).Concat(Numbers(c.End)).Append(c.Radius),
            Dbl.Capsule2 c => Numbers(c.Start).Concat(Numbers(c.End)).Append(c.Radius),
            Dbl.Triangle3 t => Numbers(t.A).Concat(Numbers(t.B)).Concat(Numbers(t.C)),
            Dbl.Triangle2 t => Numbers(t.A).Concat(Numbers(t.B)).Concat(Numbers(t.C)),
            Dbl.HalfSpace h => Numbers(h.Normal).Append(h.Offset),
            Dbl.HalfPlane h => Numbers(h.Normal).Append(h.Offset),
            _ => throw new ArgumentException(shape.GetType().Name),
        };

        /// <summary>Pairs of double-API shapes of the query's kinds ("3D sphere–OBB").</summary>
        private static (object A, object B)[] Make(string query, string distribution, int seed)
        {
            int dim = query[0] - '0';
            if (query.Contains("ray cast–")) return Casts(query, distribution, seed);
            var kinds = query.Substring(3).Split('–');
            string ka = Kind(kinds[0]), kb = Kind(kinds[1]);
            var r = new Random(seed);
            var result = new (object, object)[Count];
            for (int i = 0; i < Count; i++)
            {
                bool overlapping = distribution == "overlapping" || (distribution == "mixed" && r.Next(2) == 0);
                result[i] = overlapping ? Overlapping(r, ka, kb, dim) : Apart(r, ka, kb, dim);
            }
            return result;
        }

        private static string Kind(string name) => name switch { "circle" => "sphere", "half-plane" => "half-space", "AABB" => "aabb", "OBB" => "obb", _ => name };

        private static (object, object) Apart(Random r, string ka, string kb, int dim)
        {
            // Pairs that overlap unless parallel (a line against a half-space or, in the plane, a line; two half-spaces):
            // B is built parallel to A, on its outer side.
            if (NeverApart(ka, kb, dim) || NeverApart(kb, ka, dim))
            {
                bool swap = !NeverApart(ka, kb, dim);
                var first = Shape(r, swap ? kb : ka, dim, Center(r, 3));
                var second = ParallelOutside(r, first, swap ? ka : kb, dim);
                return swap ? (second, first) : (first, second);
            }
            while (true)
            {
                var a = Shape(r, ka, dim, Center(r, 3));
                var b = Shape(r, kb, dim, Center(r, 3));
                if (!Overlaps(a, b)) return (a, b);
            }
        }

        /// <summary>
        /// The double API's Overlaps for two boxed shapes, the overload found by reflection: the runtime binder behind
        /// <c>dynamic</c> does not bind overloads whose shapes are <c>in</c> parameters, and reflection sees either form.
        /// </summary>
        private static bool Overlaps(object a, object b)
        {
            static Type Shape(System.Reflection.ParameterInfo p) => p.ParameterType.IsByRef ? p.ParameterType.GetElementType()! : p.ParameterType;
            var method = typeof(ProximityQuery).GetMethods().Single(m => m.Name == nameof(ProximityQuery.Overlaps)
                && m.GetParameters() is { Length: 2 } ps && Shape(ps[0]) == a.GetType() && Shape(ps[1]) == b.GetType());
            return (bool)method.Invoke(null, new[] { a, b })!;
        }

        /// <summary>B is built around a point of A, so the pair always touches or overlaps.</summary>
        private static (object, object) Overlapping(Random r, string ka, string kb, int dim)
        {
            var a = Shape(r, ka, dim, Center(r, 1));
            var x = PointIn(a, r);
            return (a, Shape(r, kb, dim, x));
        }

        private static Vector3D Center(Random r, double range) =>
            new Vector3D((r.NextDouble() * 2 - 1) * range, (r.NextDouble() * 2 - 1) * range, (r.NextDouble() * 2 - 1) * range);

        private static Vector3D PointIn(object shape, Random r)
        {
            double u = r.NextDouble(), v = r.NextDouble() * 2 - 1, w = r.NextDouble() * 2 - 1, z = r.NextDouble() * 2 - 1;
            return shape switch
            {
                Vector3D p => p,
                Vector2D p => new Vector3D(p.X, p.Y, 0),
                Dbl.Segment3 s => s.PointAt(u),
                Dbl.Segment2 s => new Vector3D(s.PointAt(u).X, s.PointAt(u).Y, 0),
                Dbl.Sphere s => s.Center + new Vector3D(v, w, z) * (s.Radius / 2),
                Dbl.Circle s => new Vector3D(s.Center.X + v * s.Radius / 2, s.Center.Y + w * s.Radius / 2, 0),
                Dbl.Aabb3 b => b.Center + new Vector3D(v * (b.Max.X - b.Min.X), w * (b.Max.Y - b.Min.Y), z * (b.Max.Z - b.Min.Z)) * 0.5,
                Dbl.Aabb2 b => new Vector3D(b.Center.X + v * (b.Max.X - b.Min.X) / 2, b.Center.Y + w * (b.Max.Y - b.Min.Y) / 2, 0),
                Dbl.Obb3 b => b.Center + b.AxisX * (v * b.HalfExtents.X) + b.AxisY * (w * b.HalfExtents.Y) + b.AxisZ * (z * b.HalfExtents.Z),
                Dbl.Obb2 b => new Vector3D(b.Center.X, b.Center.Y, 0) + new Vector3D(b.AxisX.X, b.AxisX.Y, 0) * (v * b.HalfExtents.X)
                              + new Vector3D(b.AxisY.X, b.AxisY.Y, 0) * (w * b.HalfExtents.Y),
                Dbl.Line3 l => l.PointAt(v),
                Dbl.Line2 l => To3(l.PointAt(v)),
                Dbl.Ray3 l => l.PointAt(u),
                Dbl.Ray2 l => To3(l.PointAt(u)),
                Dbl.Capsule3 c => c.Start + (c.End - c.Start) * u + new Vector3D(v, w, z) * (c.Radius / 2),
                Dbl.Capsule2 c => To3(c.Start + (c.End - c.Start) * u + new Vector2D(v, w) * (c.Radius / 2)),
                Dbl.Triangle3 t => Barycentric(t.A, t.B, t.C, r),
                Dbl.Triangle2 t => Barycentric(To3(t.A), To3(t.B), To3(t.C), r),
                Dbl.HalfSpace h => h.Point - h.Normal * u,
                Dbl.HalfPlane h => To3(h.Point - h.Normal * u),
                _ => throw new ArgumentException(shape.GetType().Name),
            };
        }
    
        private static Vector3D To3(Vector2D p) => new Vector3D(p.X, p.Y, 0);
        private static Vector2D To2(Vector3D p) => new Vector2D(p.X, p.Y);
        private static double U(Random r, double lo, double hi) => lo + (hi - lo) * r.NextDouble();

        /// <summary>A random unit vector (in the z = 0 plane for 2D).</summary>
        private static Vector3D Unit(Random r, int dim)
        {
            while (true)
            {
                var v = new Vector3D(U(r, -1, 1), U(r, -1, 1), dim == 3 ? U(r, -1, 1) : 0);
                double l = v.Length;
                if (l > 0.1 && l <= 1) return v / l;
            }
        }

        private static Vector3D Barycentric(Vector3D a, Vector3D b, Vector3D c, Random r)
        {
            double u = r.NextDouble(), v = r.NextDouble();
            if (u + v > 1) { u = 1 - u; v = 1 - v; }
            return a + (b - a) * u + (c - a) * v;
        }

        /// <summary>A random shape of a kind at about unit size around c, which it contains (Families' kinds, and issue 12's).</summary>
        private static object Shape(Random r, string kind, int dim, Vector3D c)
        {
            if (dim == 2) c = new Vector3D(c.X, c.Y, 0);
            switch (kind)
            {
                case "line": { var d = Unit(r, dim); return dim == 3 ? (object)new Dbl.Line3(c, d) : new Dbl.Line2(To2(c), To2(d)); }
                case "ray": { var d = Unit(r, dim); return dim == 3 ? (object)new Dbl.Ray3(c, d) : new Dbl.Ray2(To2(c), To2(d)); }
                case "capsule":
                    {
                        var h = Unit(r, dim) * U(r, 0.1, 0.8);
                        double radius = U(r, 0.05, 0.5);
                        return dim == 3 ? (object)new Dbl.Capsule3(c - h, c + h, radius) : new Dbl.Capsule2(To2(c - h), To2(c + h), radius);
                    }
                case "triangle":
                    {
                        // Corners about c, then moved so that a random point of the triangle is c.
                        Vector3D p = Unit(r, dim) * U(r, 0.3, 1), q = Unit(r, dim) * U(r, 0.3, 1), s = Unit(r, dim) * U(r, 0.3, 1);
                        var shift = c - Barycentric(p, q, s, r);
                        return dim == 3 ? (object)new Dbl.Triangle3(p + shift, q + shift, s + shift)
                            : new Dbl.Triangle2(To2(p + shift), To2(q + shift), To2(s + shift));
                    }
                case "half-space":
                    {
                        // c inside, not on the boundary, where rounding would decide.
                        var n = Unit(r, dim);
                        double offset = Vector3D.Dot(n, c) + U(r, 0.05, 1);
                        return dim == 3 ? (object)new Dbl.HalfSpace(n, offset) : new Dbl.HalfPlane(To2(n), offset);
                    }
                default: return Families.Shape(r, kind, dim, c);
            }
        }

        private static bool NeverApart(string ka, string kb, int dim) =>
            ka == "half-space" && (kb == "line" || kb == "half-space") || dim == 2 && ka == "line" && kb == "line";

        /// <summary>A shape of kind <paramref name="kind"/> (line or half-space) parallel to <paramref name="a"/> (half-space or line) and apart from it.</summary>
        private static object ParallelOutside(Random r, object a, string kind, int dim)
        {
            Vector3D n, p;
            switch (a)
            {
                case Dbl.HalfSpace h: n = h.Normal; p = h.Point; break;
                case Dbl.HalfPlane h: n = To3(h.Normal); p = To3(h.Point); break;
                case Dbl.Line2 l: n = new Vector3D(-l.Direction.Y, l.Direction.X, 0); p = To3(l.Origin); break;
                default: throw new ArgumentException(a.GetType().Name);
            }
            var o = p + n * U(r, 0.2, 2);
            if (kind == "half-space")
                return dim == 3 ? (object)new Dbl.HalfSpace(-n, Vector3D.Dot(-n, o)) : new Dbl.HalfPlane(To2(-n), Vector3D.Dot(-n, o));
            // A direction along the boundary: a random one without its normal part.
            Vector3D d;
            do { var g = Unit(r, dim); d = g - n * Vector3D.Dot(g, n); } while (d.Length < 0.1);
            return dim == 3 ? (object)new Dbl.Line3(o, d) : new Dbl.Line2(To2(o), To2(d));
        }

        /// <summary>
        /// Ray-cast pairs (ray, target): mixed: 40% hits (aimed at a point inside the target from 2–4 units away), 40%
        /// misses (random aims, kept when the library's double cast misses), 20% grazing (tangent to a sphere, circle or
        /// capsule side, or aimed at a point on a box's or triangle's edge, each 0.1% inward or outward; nearly parallel
        /// to a half-space's boundary);
        /// apart: misses only; overlapping: hits only.
        /// </summary>
        private static (object A, object B)[] Casts(string query, string distribution, int seed)
        {
            int dim = query[0] - '0';
            string kind = Kind(query.Substring(query.IndexOf('–') + 1));
            var r = new Random(seed);
            var result = new (object, object)[Count];
            for (int i = 0; i < Count; i++)
            {
                var target = Shape(r, kind, dim, Center(r, 1));
                double x = r.NextDouble();
                string how = distribution == "apart" ? "miss" : distribution == "overlapping" || x < 0.4 ? "hit" : x < 0.8 ? "miss" : "graze";
                var (o, d) = how == "hit" ? Aim(r, PointIn(target, r), dim) : how == "miss" ? Miss(r, target, dim) : Graze(r, target, dim);
                result[i] = (dim == 3 ? (object)new Dbl.Ray3(o, d) : new Dbl.Ray2(To2(o), To2(d)), target);
            }
            return result;
        }

        /// <summary>A ray from 2–4 units away through <paramref name="p"/>.</summary>
        private static (Vector3D, Vector3D) Aim(Random r, Vector3D p, int dim)
        {
            var o = p + Unit(r, dim) * U(r, 2, 4);
            return (o, p - o);
        }

        private static (Vector3D, Vector3D) Miss(Random r, object target, int dim)
        {
            while (true)
            {
                var (o, d) = Aim(r, PointIn(target, r) + Unit(r, dim) * U(r, 0, 2), dim);
                bool hit = dim == 3 ? Raycast.Cast(new Dbl.Ray3(o, d), (dynamic)target).Hit : Raycast.Cast(new Dbl.Ray2(To2(o), To2(d)), (dynamic)target).Hit;
                if (!hit) return (o, d);
            }
        }

        private static (Vector3D, Vector3D) Graze(Random r, object target, int dim)
        {
            double u = r.NextDouble();
            // 0.1% off the tangent or the edge, inward or outward: near-grazing, but hit or miss not left to rounding.
            double off = r.Next(2) == 0 ? -1e-3 : 1e-3;
            Vector3D Perp(Vector3D d)
            {
                // A unit vector perpendicular to d (in the plane for 2D).
                if (dim == 2) return new Vector3D(-d.Y, d.X, 0);
                var g = Unit(r, 3);
                var p = Vector3D.Cross(d, g);
                return p / p.Length;
            }
            (Vector3D, Vector3D) Tangent(Vector3D center, double radius)
            {
                var d = Unit(r, dim);
                var p = center + Perp(d) * (radius * (1 + off));
                return (p - d * U(r, 2, 4), d);
            }
            switch (target)
            {
                case Dbl.Sphere s: return Tangent(s.Center, s.Radius);
                case Dbl.Circle s: return Tangent(To3(s.Center), s.Radius);
                case Dbl.Capsule3 c:
                    {
                        var axis = c.End - c.Start;
                        var d = Unit(r, 3);
                        var side = Vector3D.Cross(d, axis);
                        var p = c.Start + axis * u + side / side.Length * (c.Radius * (1 + off));
                        return (p - d * U(r, 2, 4), d);
                    }
                case Dbl.Capsule2 c:
                    {
                        // Along the side of the capsule's rectangle.
                        var axis = To3(c.End - c.Start);
                        var d = axis / axis.Length;
                        var p = To3(c.Start) + Perp(d) * (c.Radius * (1 + off));
                        return (p - d * U(r, 2, 4), d);
                    }
                case Dbl.Triangle3 t: { var p = t.A + (t.B - t.A) * u; return Aim(r, p + (p - t.C) * off, 3); }
                case Dbl.Triangle2 t: { var p = To3(t.A + (t.B - t.A) * u); return Aim(r, p + (p - To3(t.C)) * off, 2); }
                case Dbl.HalfSpace h: return Skim(h.Normal, h.Point);
                case Dbl.HalfPlane h: return Skim(To3(h.Normal), To3(h.Point));
                default:
                    {
                        // A box (AABB or OBB): a point on one of its edges.
                        var (lo, hi) = Corners(target);
                        var p = new Vector3D(r.Next(2) == 0 ? lo.X : hi.X, r.Next(2) == 0 ? lo.Y : hi.Y, dim == 3 ? (r.Next(2) == 0 ? lo.Z : hi.Z) : 0);
                        int free = r.Next(dim);
                        p = free == 0 ? new Vector3D(U(r, lo.X, hi.X), p.Y, p.Z) : free == 1 ? new Vector3D(p.X, U(r, lo.Y, hi.Y), p.Z) : new Vector3D(p.X, p.Y, U(r, lo.Z, hi.Z));
                        var mid = (lo + hi) * 0.5;
                        return Aim(r, BoxPoint(target, mid + (p - mid) * (1 + off)), dim);
                    }
            }
            (Vector3D, Vector3D) Skim(Vector3D n, Vector3D point)
            {
                // From just outside, nearly parallel to the boundary and slightly inward: a hit far along the ray.
                var along = Perp(n);
                var o = point + n * U(r, 0.01, 0.1);
                return (o, along - n * U(r, 1e-4, 1e-2));
            }
        }

        /// <summary>A box's extent in its own frame (an AABB's bounds; an OBB's ± half-extents).</summary>
        private static (Vector3D, Vector3D) Corners(object box) => box switch
        {
            Dbl.Aabb3 b => (b.Min, b.Max),
            Dbl.Aabb2 b => (To3(b.Min), To3(b.Max)),
            Dbl.Obb3 b => (-b.HalfExtents, b.HalfExtents),
            Dbl.Obb2 b => (-To3(b.HalfExtents), To3(b.HalfExtents)),
            _ => throw new ArgumentException(box.GetType().Name),
        };

        /// <summary>A point given in the box's own frame (Corners), in world coordinates.</summary>
        private static Vector3D BoxPoint(object box, Vector3D p) => box switch
        {
            Dbl.Obb3 b => b.Center + b.AxisX * p.X + b.AxisY * p.Y + b.AxisZ * p.Z,
            Dbl.Obb2 b => To3(b.Center + b.AxisX * p.X + b.AxisY * p.Y),
            _ => p,
        };
    }
}
