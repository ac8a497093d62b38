using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // 2D line or ray against a box on 2D vectors and Box2: the 3D kernel's steps on a lifted planar box with the z terms
    // left out (they only add exact zeros), so the lifted kernel's answers bit for bit, up to the sign of a zero coordinate.
    internal static partial class Kernels
    {
        /// <summary><see cref="LineBox"/> in the plane: a line (origin o, unit direction u), or a ray, against a solid planar box.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static DistanceResult2 LineBox2(Vector2D o, Vector2D u, bool ray, in Box2 box, out bool inRange)
        {
            var ro = o - box.Origin;
            inRange = Range.Box(Num.Max(Range.MaxAbs(ro), Range.MaxAbs(box.Hi - box.Lo)));
            var c = box.LocalCenter;
            var h = box.Half;
            var m = box.ToLocal(ro) - c;
            var d = box.ToLocal(u);
            double t;
            Vector2D e;
            if (!LineBoxOverlapsLocal2(m, d, h, ray))
            {
                double g = LineBoxNearest2(m, d, h, ray, out t, out e);
                inRange &= Range.In(g);
                return new DistanceResult2(Math.Sqrt(g), g, o + u * t, box.Origin + box.ToWorldOffset(c + ClampLocal2(e, -h, h)), t, 0);
            }
            double depth = Num.Max(LineBoxPenetration2(m, d, h, ray, out var dir), 0);
            LineBoxNearest2(m + dir * depth, d, h, ray, out t, out e);
            var onLine = o + u * t;
            return new DistanceResult2(-depth, 0, onLine, depth > 0 ? box.Origin + box.ToWorldOffset(c + ClampLocal2(e, -h, h)) : onLine, t, 0);
        }

        /// <summary><see cref="LineBoxNearest"/> in the plane: the line clipped to the box's projection, then the segment closed form.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double LineBoxNearest2(Vector2D m, Vector2D d, Vector2D h, bool ray, out double t, out Vector2D e)
        {
            double tc = -Vector2D.Dot(m, d);
            double reach = h.X * Math.Abs(d.X) + h.Y * Math.Abs(d.Y);
            double w = 2 * reach + Math.Abs(tc) * (1.0 / (1L << 40));
            double t0 = tc - w, t1 = tc + w;
            if (ray) { t0 = Math.Max(t0, 0); t1 = Math.Max(t1, 0); }
            double len = t1 - t0;
            var a = m + d * t0;
            var span = d * len;
            double g = SegmentBoxLocal2(a, span, -h, h, out double s);
            t = s <= 0.5 ? t0 + len * s : t1 - len * (1 - s);
            e = a + span * s;
            return g;
        }

        /// <summary><see cref="LineBoxPenetration"/> in the plane: a ray's faces it leaves through, then the line's normal.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static double LineBoxPenetration2(Vector2D m, Vector2D d, Vector2D h, bool ray, out Vector2D dir)
        {
            double best = double.PositiveInfinity;
            dir = default;
            if (ray)
            {
                TryRayFace2(m.X, d.X, h.X, new Vector2D(1, 0), ref best, ref dir);
                TryRayFace2(m.Y, d.Y, h.Y, new Vector2D(0, 1), ref best, ref dir);
            }
            TryNormalAxis2(m, d, h, ref best, ref dir);
            return best;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static void TryRayFace2(double m, double d, double h, Vector2D n, ref double best, ref Vector2D dir)
        {
            if (d >= 0 && h - m < best) { best = h - m; dir = n; }
            if (d <= 0 && m + h < best) { best = m + h; dir = -n; }
        }

        /// <summary><see cref="LineBoxOverlaps"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool LineBoxOverlaps2(Vector2D o, Vector2D u, bool ray, in Box2 box, out bool inRange)
        {
            var ro = o - box.Origin;
            inRange = Range.Box(Num.Max(Range.MaxAbs(ro), Range.MaxAbs(box.Hi - box.Lo)));
            return LineBoxOverlapsLocal2(box.ToLocal(ro) - box.LocalCenter, box.ToLocal(u), box.Half, ray);
        }

        /// <summary><see cref="LineBoxOverlapsLocal"/> in the plane: a ray's slabs, then the line's normal.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static bool LineBoxOverlapsLocal2(Vector2D m, Vector2D d, Vector2D h, bool ray) =>
            !(ray && (RaySlabSeparates(m.X, d.X, h.X) || RaySlabSeparates(m.Y, d.Y, h.Y)))
            && !(Math.Abs(m.X * d.Y - m.Y * d.X) > h.X * Math.Abs(d.Y) + h.Y * Math.Abs(d.X));
    }
}
