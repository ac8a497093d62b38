// Copied from src/ProximityLib.Scenes/Picker/ShapeSpec.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Globalization;
using System.Numerics;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>
    /// Shapes written as text, for the command line: <c>kind:n1,n2,…</c>. The count of numbers picks the dimension.
    /// <list type="bullet">
    /// <item><c>point:x,y</c> or <c>point:x,y,z</c></item>
    /// <item><c>segment:x1,y1,x2,y2</c> or <c>segment:x1,y1,z1,x2,y2,z2</c></item>
    /// <item><c>circle:x,y,r</c>, <c>sphere:x,y,z,r</c></item>
    /// <item><c>aabb:minX,minY,maxX,maxY</c> or <c>aabb:minX,minY,minZ,maxX,maxY,maxZ</c></item>
    /// <item><c>obb:cx,cy,angle,hx,hy</c> (angle in radians) or <c>obb:cx,cy,cz,qx,qy,qz,qw,hx,hy,hz</c> (quaternion)</item>
    /// </list>
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
                    ("point", _) or ("segment", _) or ("circle", _) or ("sphere", _) or ("aabb", _) or ("obb", _) =>
                        throw new FormatException($"'{text}': {kind} takes {Counts(kind)} numbers, not {n.Length}"),
                    _ => throw new FormatException($"'{text}': unknown kind '{kind}' (point, segment, circle, sphere, aabb, obb)"),
                };
            }
            catch (ArgumentException e)
            {
                throw new FormatException($"'{text}': {e.Message}");
            }
        }

        /// <summary>2 for 2D shapes, 3 for 3D ones.</summary>
        public static int Dimension(object shape) => shape is Vector2 || shape is Segment2 || shape is Circle || shape is Aabb2 || shape is Obb2 ? 2 : 3;

        private static string Counts(string kind) => kind switch
        {
            "point" => "2 or 3",
            "segment" => "4 or 6",
            "circle" => "3",
            "sphere" => "4",
            "aabb" => "4 or 6",
            _ => "5 or 10",
        };
    }
}
