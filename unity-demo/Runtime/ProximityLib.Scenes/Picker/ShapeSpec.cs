// Copied from src/ProximityLib.Scenes/Picker/ShapeSpec.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Collections.Generic;
using System.Globalization;
using System.Numerics;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>
    /// Shapes written as text, for the command line: <c>kind:n1,n2,…</c>, one of <see cref="Forms"/>. The count of
    /// numbers picks the dimension.
    /// </summary>
    public static class ShapeSpec
    {
        /// <summary>The float-API shape the text describes; <see cref="FormatException"/> naming the bad token otherwise.</summary>
        public static object Parse(string text)
        {
            if (text is null) throw new ArgumentNullException(nameof(text));
            int colon = text.IndexOf(':');
            if (colon <= 0) throw new FormatException($"'{text}': expected kind:numbers, e.g. sphere:0,0,0,1");
            string kind = text.Substring(0, colon).Trim().ToLowerInvariant();
            var parts = text.Substring(colon + 1).Split(',');
            var n = new float[parts.Length];
            for (int i = 0; i < parts.Length; i++)
                if (!float.TryParse(parts[i].Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out n[i]) || !float.IsFinite(n[i]))
                    throw new FormatException($"'{text}': '{parts[i]}' is not a finite number");
            try
            {
                return (kind, n.Length) switch
                {
                    ("point", 2) => new Vector2(n[0], n[1]),
                    ("point", 3) => new Vector3(n[0], n[1], n[2]),
                    ("segment", 4) => new Segment2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3])),
                    ("segment", 6) => new Segment3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5])),
                    ("circle", 3) => new Circle(new Vector2(n[0], n[1]), n[2]),
                    ("sphere", 4) => new Sphere(new Vector3(n[0], n[1], n[2]), n[3]),
                    ("aabb", 4) => new Aabb2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3])),
                    ("aabb", 6) => new Aabb3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5])),
                    ("obb", 5) => new Obb2(new Vector2(n[0], n[1]), n[2], new Vector2(n[3], n[4])),
                    ("obb", 10) => (object)new Obb3(new Vector3(n[0], n[1], n[2]), new Quaternion(n[3], n[4], n[5], n[6]), new Vector3(n[7], n[8], n[9])),
                    ("line", 4) => new Line2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3])),
                    ("line", 6) => new Line3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5])),
                    ("ray", 4) => new Ray2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3])),
                    ("ray", 6) => new Ray3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5])),
                    ("capsule", 5) => new Capsule2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3]), n[4]),
                    ("capsule", 7) => new Capsule3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5]), n[6]),
                    ("triangle", 6) => new Triangle2(new Vector2(n[0], n[1]), new Vector2(n[2], n[3]), new Vector2(n[4], n[5])),
                    ("triangle", 9) => new Triangle3(new Vector3(n[0], n[1], n[2]), new Vector3(n[3], n[4], n[5]), new Vector3(n[6], n[7], n[8])),
                    ("halfplane", 3) => new HalfPlane(new Vector2(n[0], n[1]), n[2]),
                    ("halfspace", 4) => new HalfSpace(new Vector3(n[0], n[1], n[2]), n[3]),
                    _ when Known(kind) => throw new FormatException($"'{text}': {kind} takes {Counts(kind)} numbers, not {n.Length}"),
                    _ => throw new FormatException($"'{text}': unknown kind '{kind}' ({string.Join(", ", Kinds())})"),
                };
            }
            catch (ArgumentException e)
            {
                throw new FormatException($"'{text}': {e.Message}");
            }
        }

        /// <summary>2 for 2D shapes, 3 for 3D ones.</summary>
        public static int Dimension(object shape) =>
            shape is Vector2 || shape is Segment2 || shape is Circle || shape is Aabb2 || shape is Obb2
            || shape is Line2 || shape is Ray2 || shape is Capsule2 || shape is Triangle2 || shape is HalfPlane ? 2 : 3;

        /// <summary>Every form <see cref="Parse"/> accepts, with what its numbers mean and an example; the picker's help lists them.</summary>
        public static IReadOnlyList<ShapeForm> Forms { get; } = new[]
        {
            new ShapeForm("point:x,y", "2D point", "point:1,2"),
            new ShapeForm("point:x,y,z", "3D point", "point:1,2,3"),
            new ShapeForm("segment:x1,y1,x2,y2", "2D segment from (x1,y1) to (x2,y2)", "segment:0,0,4,0"),
            new ShapeForm("segment:x1,y1,z1,x2,y2,z2", "3D segment from (x1,y1,z1) to (x2,y2,z2)", "segment:0,0,0,1,2,3"),
            new ShapeForm("circle:x,y,r", "disc: centre, radius (>= 0)", "circle:0,0,1"),
            new ShapeForm("sphere:x,y,z,r", "ball: centre, radius (>= 0)", "sphere:0,0,0,1"),
            new ShapeForm("aabb:minX,minY,maxX,maxY", "axis-aligned rectangle: min corner, max corner", "aabb:2,0,3,1"),
            new ShapeForm("aabb:minX,minY,minZ,maxX,maxY,maxZ", "axis-aligned box: min corner, max corner", "aabb:2,0,0,3,1,1"),
            new ShapeForm("obb:cx,cy,angle,hx,hy",
                "oriented rectangle: centre, angle in radians (counter-clockwise from +x), half-extents", "obb:3,0,0.7853982,1,0.5"),
            new ShapeForm("obb:cx,cy,cz,qx,qy,qz,qw,hx,hy,hz",
                "oriented box: centre, rotation quaternion in x,y,z,w order (w last; normalised here), half-extents",
                "obb:3,0,0,0,0,0.3826834,0.9238795,1,1,1"),
            new ShapeForm("line:x,y,dx,dy", "2D line: a point on it, a direction (any non-zero length)", "line:0,2,1,0"),
            new ShapeForm("line:x,y,z,dx,dy,dz", "3D line: a point on it, a direction (any non-zero length)", "line:0,2,0,1,0,0"),
            new ShapeForm("ray:x,y,dx,dy", "2D ray: origin, direction (any non-zero length)", "ray:-3,0,1,0"),
            new ShapeForm("ray:x,y,z,dx,dy,dz", "3D ray: origin, direction (any non-zero length)", "ray:-3,0,0,1,0,0"),
            new ShapeForm("capsule:x1,y1,x2,y2,r", "2D capsule (stadium): axis from (x1,y1) to (x2,y2), radius (>= 0)", "capsule:0,0,2,0,0.5"),
            new ShapeForm("capsule:x1,y1,z1,x2,y2,z2,r", "3D capsule: axis from (x1,y1,z1) to (x2,y2,z2), radius (>= 0)", "capsule:0,0,0,0,2,0,0.5"),
            new ShapeForm("triangle:ax,ay,bx,by,cx,cy", "2D solid triangle: three vertices", "triangle:0,0,2,0,0,2"),
            new ShapeForm("triangle:ax,ay,az,bx,by,bz,cx,cy,cz", "3D triangle (two-sided, not solid): three vertices", "triangle:0,0,0,2,0,0,0,2,0"),
            new ShapeForm("halfplane:nx,ny,d", "2D half-plane: the solid nx·x + ny·y <= d (normal any non-zero length)", "halfplane:0,1,0"),
            new ShapeForm("halfspace:nx,ny,nz,d", "3D half-space: the solid n·p <= d (normal any non-zero length)", "halfspace:0,1,0,0"),
        };

        private static bool Known(string kind)
        {
            foreach (var form in Forms)
                if (form.Kind == kind) return true;
            return false;
        }

        private static IEnumerable<string> Kinds()
        {
            var seen = new List<string>();
            foreach (var form in Forms)
                if (!seen.Contains(form.Kind)) seen.Add(form.Kind);
            return seen;
        }

        private static string Counts(string kind)
        {
            var counts = new List<string>();
            foreach (var form in Forms)
                if (form.Kind == kind) counts.Add(form.Count.ToString(CultureInfo.InvariantCulture));
            return string.Join(" or ", counts);
        }
    }

    /// <summary>One form of a shape spec: its syntax, what its numbers mean and an example.</summary>
    public sealed class ShapeForm
    {
        internal ShapeForm(string syntax, string meaning, string example)
        {
            Syntax = syntax; Meaning = meaning; Example = example;
            int colon = syntax.IndexOf(':');
            Kind = syntax.Substring(0, colon);
            Count = syntax.Substring(colon + 1).Split(',').Length;
        }

        /// <summary>The kind before the colon (point, segment, circle, sphere, aabb, obb, line, ray, capsule, triangle, halfplane, halfspace).</summary>
        public string Kind { get; }
        /// <summary>The form, e.g. <c>circle:x,y,r</c>.</summary>
        public string Syntax { get; }
        /// <summary>What the numbers are, with units where they matter.</summary>
        public string Meaning { get; }
        /// <summary>A spec of this form.</summary>
        public string Example { get; }
        /// <summary>How many numbers the form takes.</summary>
        public int Count { get; }
    }
}
