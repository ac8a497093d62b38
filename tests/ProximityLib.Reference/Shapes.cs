using System;
using System.Numerics;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>Names, descriptions and float twins of double-API shapes, for reports and the float measurements.</summary>
    public static class Shapes
    {
        public static int Order(object s) => s switch
        {
            Vector3D or Vector2D => 0,
            Dbl.Segment3 or Dbl.Segment2 => 1,
            Dbl.Sphere or Dbl.Circle => 2,
            Dbl.Aabb3 or Dbl.Aabb2 => 3,
            _ => 4,
        };

        public static int Dim(object s) => s is Vector3D or Dbl.Segment3 or Dbl.Sphere or Dbl.Aabb3 or Dbl.Obb3 ? 3 : 2;

        public static string Name(object s) => Order(s) switch
        {
            0 => "point",
            1 => "segment",
            2 => Dim(s) == 3 ? "sphere" : "circle",
            3 => "AABB",
            _ => "OBB",
        };

        /// <summary>The pair's name in the fixed order point < segment < circle/sphere < AABB < OBB.</summary>
        public static string PairKey(object a, object b)
        {
            if (Order(a) > Order(b)) (a, b) = (b, a);
            return $"{Dim(a)}D {Name(a)}–{Name(b)}";
        }

        public static string Describe(object s) => s switch
        {
            Dbl.Segment3 x => $"segment {x.Start}–{x.End}",
            Dbl.Segment2 x => $"segment {x.Start}–{x.End}",
            Dbl.Sphere x => $"sphere {x.Center} r={x.Radius:R}",
            Dbl.Circle x => $"circle {x.Center} r={x.Radius:R}",
            Dbl.Aabb3 x => $"aabb {x.Min}–{x.Max}",
            Dbl.Aabb2 x => $"aabb {x.Min}–{x.Max}",
            Dbl.Obb3 x => $"obb c={x.Center} h={x.HalfExtents} x={x.AxisX} y={x.AxisY} z={x.AxisZ}",
            Dbl.Obb2 x => $"obb c={x.Center} h={x.HalfExtents} x={x.AxisX}",
            _ => $"point {s}",
        };

        /// <summary>The float-API shape with these inputs rounded to float (the float measurement's own geometry).</summary>
        public static object ToFloat(object s) => s switch
        {
            Vector3D p => Finite((Vector3)p),
            Vector2D p => Finite((Vector2)p),
            Dbl.Segment3 x => new ProximityLib.Segment3((Vector3)x.Start, (Vector3)x.End),
            Dbl.Segment2 x => new ProximityLib.Segment2((Vector2)x.Start, (Vector2)x.End),
            Dbl.Sphere x => new ProximityLib.Sphere((Vector3)x.Center, (float)x.Radius),
            Dbl.Circle x => new ProximityLib.Circle((Vector2)x.Center, (float)x.Radius),
            Dbl.Aabb3 x => new ProximityLib.Aabb3((Vector3)x.Min, Vector3.Max((Vector3)x.Min, (Vector3)x.Max)),
            Dbl.Aabb2 x => new ProximityLib.Aabb2((Vector2)x.Min, Vector2.Max((Vector2)x.Min, (Vector2)x.Max)),
            Dbl.Obb3 x => new ProximityLib.Obb3((Vector3)x.Center, (Vector3)x.AxisX, (Vector3)x.AxisY, (Vector3)x.AxisZ, (Vector3)x.HalfExtents),
            Dbl.Obb2 x => new ProximityLib.Obb2((Vector2)x.Center, (Vector2)x.AxisX, (Vector2)x.HalfExtents),
            _ => throw new ArgumentException(s.GetType().Name),
        };

        // Points are plain System.Numerics vectors with no constructor to validate them.
        private static Vector3 Finite(Vector3 v) =>
            float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z) ? v : throw new ArgumentException("outside the float range");
        private static Vector2 Finite(Vector2 v) => float.IsFinite(v.X) && float.IsFinite(v.Y) ? v : throw new ArgumentException("outside the float range");

        /// <summary>
        /// The shape with every length multiplied by s (OBB axes kept). OBBs are rebuilt from their stored axes, so compare
        /// a scaled shape with <c>Scaled(shape, 1)</c>, which takes the same path.
        /// </summary>
        public static object Scaled(object x, double s) => x switch
        {
            Vector3D p => p * s,
            Vector2D p => p * s,
            Dbl.Segment3 v => new Dbl.Segment3(v.Start * s, v.End * s),
            Dbl.Segment2 v => new Dbl.Segment2(v.Start * s, v.End * s),
            Dbl.Sphere v => new Dbl.Sphere(v.Center * s, v.Radius * s),
            Dbl.Circle v => new Dbl.Circle(v.Center * s, v.Radius * s),
            Dbl.Aabb3 v => new Dbl.Aabb3(v.Min * s, v.Max * s),
            Dbl.Aabb2 v => new Dbl.Aabb2(v.Min * s, v.Max * s),
            Dbl.Obb3 v => new Dbl.Obb3(v.Center * s, v.AxisX, v.AxisY, v.AxisZ, v.HalfExtents * s),
            Dbl.Obb2 v => new Dbl.Obb2(v.Center * s, v.AxisX, v.HalfExtents * s),
            _ => throw new ArgumentException(x.GetType().Name),
        };

        /// <summary>Segments with their endpoints swapped; other shapes unchanged.</summary>
        public static object Reversed(object x) => x switch
        {
            Dbl.Segment3 v => new Dbl.Segment3(v.End, v.Start),
            Dbl.Segment2 v => new Dbl.Segment2(v.End, v.Start),
            _ => x,
        };

        /// <summary>The double-API shape a float shape holds (what the float API actually computes on).</summary>
        public static object Widen(object f) => f switch
        {
            Vector3 p => (Vector3D)p,
            Vector2 p => (Vector2D)p,
            ProximityLib.Segment3 x => (Dbl.Segment3)x,
            ProximityLib.Segment2 x => (Dbl.Segment2)x,
            ProximityLib.Sphere x => (Dbl.Sphere)x,
            ProximityLib.Circle x => (Dbl.Circle)x,
            ProximityLib.Aabb3 x => (Dbl.Aabb3)x,
            ProximityLib.Aabb2 x => (Dbl.Aabb2)x,
            ProximityLib.Obb3 x => (Dbl.Obb3)x,
            ProximityLib.Obb2 x => (Dbl.Obb2)x,
            _ => throw new ArgumentException(f.GetType().Name),
        };
    }
}
