using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Text;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>
    /// Draws a picker view as SVG, looking along +z as the Unity sample's camera does (x right, y up): both shapes'
    /// outlines (a 3D shape as the outline of its projection), the yellow closest-point line and the orange text, or
    /// red shapes when they collide. For documentation and the command line; it allocates, unlike a frame.
    /// </summary>
    public static class PickerSvg
    {
        /// <summary>The SVG of a picker scene after its latest change.</summary>
        public static string Render(PickerScene scene)
        {
            if (scene == null) throw new ArgumentNullException(nameof(scene));
            var view = scene.Evaluate();
            return Render(scene.First.Shape, scene.Second.Shape, view);
        }

        /// <summary>The SVG of two library shapes (as returned by <see cref="ShapeSpec.Parse"/>) and their view.</summary>
        public static string Render(object first, object second, PickerView view)
        {
            var outlines = new[] { Outline(first), Outline(second) };
            var all = outlines.SelectMany(o => o).ToList();
            if (view.Mode == PickerMode.ClosestDistance) { all.Add(Xy(view.PointA)); all.Add(Xy(view.PointB)); }
            float minX = all.Min(p => p.X), maxX = all.Max(p => p.X), minY = all.Min(p => p.Y), maxY = all.Max(p => p.Y);
            float span = Math.Max(Math.Max(maxX - minX, maxY - minY), 1e-3f);
            const float width = 640, height = 400, top = 56, margin = 24;
            float scale = Math.Min((width - 2 * margin) / span, (height - top - margin) / span);
            float cx = (minX + maxX) / 2, cy = (minY + maxY) / 2;
            string X(float x) => F(width / 2 + (x - cx) * scale);
            string Y(float y) => F(top + (height - top - margin) / 2 - (y - cy) * scale);

            var svg = new StringBuilder();
            svg.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{F(width)}\" height=\"{F(height)}\" viewBox=\"0 0 {F(width)} {F(height)}\">\n");
            svg.Append($"<rect width=\"{F(width)}\" height=\"{F(height)}\" fill=\"#1e2430\"/>\n");
            string fill = view.Colliding ? "#e64545" : "#c0cbd8";
            foreach (var outline in outlines)
            {
                if (outline.Count == 1)
                    svg.Append($"<circle cx=\"{X(outline[0].X)}\" cy=\"{Y(outline[0].Y)}\" r=\"4\" fill=\"{fill}\"/>\n");
                else
                    svg.Append($"<polygon points=\"{string.Join(" ", outline.Select(p => X(p.X) + "," + Y(p.Y)))}\" fill=\"{fill}\" fill-opacity=\"0.55\" stroke=\"{fill}\" stroke-width=\"2\"/>\n");
            }
            string text = view.Text;
            if (view.Mode == PickerMode.ClosestDistance)
            {
                svg.Append($"<line x1=\"{X(view.PointA.X)}\" y1=\"{Y(view.PointA.Y)}\" x2=\"{X(view.PointB.X)}\" y2=\"{Y(view.PointB.Y)}\" stroke=\"#ffeb04\" stroke-width=\"3\"/>\n");
                svg.Append($"<text x=\"{F(width / 2)}\" y=\"34\" font-family=\"sans-serif\" font-size=\"22\" text-anchor=\"middle\" fill=\"#ff8c00\">{text}</text>\n");
            }
            else
            {
                svg.Append($"<text x=\"{F(width / 2)}\" y=\"34\" font-family=\"sans-serif\" font-size=\"22\" text-anchor=\"middle\" fill=\"{(view.Colliding ? "#e64545" : "#ffffff")}\">{text}</text>\n");
            }
            svg.Append("</svg>\n");
            return svg.ToString();
        }

        private static Vector2 Xy(Vector3 p) => new Vector2(p.X, p.Y);

        /// <summary>The outline of a shape's projection on z = 0: one point, a segment's (line's, ray's) two ends, or a convex polygon.</summary>
        private static List<Vector2> Outline(object shape)
        {
            switch (shape)
            {
                case Vector3 p: return new List<Vector2> { Xy(p) };
                case Vector2 p: return new List<Vector2> { p };
                case Segment3 s: return new List<Vector2> { Xy(s.Start), Xy(s.End) };
                case Segment2 s: return new List<Vector2> { s.Start, s.End };
                case Sphere s: return Circle(Xy(s.Center), s.Radius);
                case Circle c: return Circle(c.Center, c.Radius);
                case Aabb3 b: return Hull(Corners(b.Min, b.Max));
                case Aabb2 b: return Hull(Corners(new Vector3(b.Min, 0), new Vector3(b.Max, 0)));
                case Obb3 b: return Hull(Corners(b.Center, b.AxisX * b.HalfExtents.X, b.AxisY * b.HalfExtents.Y, b.AxisZ * b.HalfExtents.Z));
                case Obb2 b: return Hull(Corners(new Vector3(b.Center, 0), new Vector3(b.AxisX * b.HalfExtents.X, 0), new Vector3(b.AxisY * b.HalfExtents.Y, 0), Vector3.Zero));
                // Unbounded shapes are drawn over a stretch of Reach around their stored point (the view frames the
                // closest points too, so the part that matters is in it).
                case Line3 l: return new List<Vector2> { Xy(l.Origin - l.Direction * Reach), Xy(l.Origin + l.Direction * Reach) };
                case Line2 l: return new List<Vector2> { l.Origin - l.Direction * Reach, l.Origin + l.Direction * Reach };
                case Ray3 r: return new List<Vector2> { Xy(r.Origin), Xy(r.Origin + r.Direction * Reach) };
                case Ray2 r: return new List<Vector2> { r.Origin, r.Origin + r.Direction * Reach };
                case Capsule3 c: return Hull(Circle(Xy(c.Start), c.Radius).Concat(Circle(Xy(c.End), c.Radius)));
                case Capsule2 c: return Hull(Circle(c.Start, c.Radius).Concat(Circle(c.End, c.Radius)));
                case Triangle3 t: return Hull(new[] { Xy(t.A), Xy(t.B), Xy(t.C) });
                case Triangle2 t: return Hull(new[] { t.A, t.B, t.C });
                case HalfPlane h: return HalfPlaneOutline(h.Point, h.Normal);
                case HalfSpace h: return HalfSpaceOutline(h.Point, h.Normal);
                default: throw new ArgumentException($"not a ProximityLib shape: {shape?.GetType().Name ?? "null"}", nameof(shape));
            }
        }

        /// <summary>How far an unbounded shape is drawn from its stored point, in the shapes' units.</summary>
        private const float Reach = 4;

        /// <summary>A half-plane as a Reach-wide strip of its boundary, Reach/2 deep into the solid.</summary>
        private static List<Vector2> HalfPlaneOutline(Vector2 point, Vector2 normal)
        {
            var along = new Vector2(-normal.Y, normal.X) * Reach;
            var down = -normal * (Reach / 2);
            return new List<Vector2> { point - along, point + along, point + along + down, point - along + down };
        }

        /// <summary>A half-space as the projection of a slab of it: a square of its boundary, Reach on a side, and Reach/2 below.</summary>
        private static List<Vector2> HalfSpaceOutline(Vector3 point, Vector3 normal)
        {
            var u = Vector3.Normalize(Math.Abs(normal.X) < 0.9f ? Vector3.Cross(normal, Vector3.UnitX) : Vector3.Cross(normal, Vector3.UnitY));
            var v = Vector3.Cross(normal, u);
            return Hull(Corners(point - normal * (Reach / 4), u * Reach, v * Reach, normal * (Reach / 4)));
        }

        private static List<Vector2> Circle(Vector2 c, float r) =>
            Enumerable.Range(0, 48).Select(i => c + r * new Vector2((float)Math.Cos(i * Math.PI / 24), (float)Math.Sin(i * Math.PI / 24))).ToList();

        private static IEnumerable<Vector2> Corners(Vector3 min, Vector3 max) =>
            Corners((min + max) / 2, new Vector3((max.X - min.X) / 2, 0, 0), new Vector3(0, (max.Y - min.Y) / 2, 0), new Vector3(0, 0, (max.Z - min.Z) / 2));

        private static IEnumerable<Vector2> Corners(Vector3 c, Vector3 u, Vector3 v, Vector3 w)
        {
            for (int i = 0; i < 8; i++)
                yield return Xy(c + ((i & 1) == 0 ? -u : u) + ((i & 2) == 0 ? -v : v) + ((i & 4) == 0 ? -w : w));
        }

        /// <summary>Convex hull, counter-clockwise (Andrew's monotone chain); collinear and repeated points dropped.</summary>
        private static List<Vector2> Hull(IEnumerable<Vector2> points)
        {
            var p = points.Distinct().OrderBy(q => q.X).ThenBy(q => q.Y).ToList();
            if (p.Count < 3) return p;
            static float Cross(Vector2 o, Vector2 a, Vector2 b) => (a.X - o.X) * (b.Y - o.Y) - (a.Y - o.Y) * (b.X - o.X);
            var hull = new List<Vector2>();
            foreach (var pass in new[] { p, Enumerable.Reverse(p).ToList() })
            {
                int start = hull.Count;
                foreach (var q in pass)
                {
                    while (hull.Count >= start + 2 && Cross(hull[hull.Count - 2], hull[hull.Count - 1], q) <= 0) hull.RemoveAt(hull.Count - 1);
                    hull.Add(q);
                }
                hull.RemoveAt(hull.Count - 1);
            }
            return hull;
        }

        private static string F(float v) => v.ToString("0.##", CultureInfo.InvariantCulture);
    }
}
