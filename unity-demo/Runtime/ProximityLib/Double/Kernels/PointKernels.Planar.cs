// Copied from src/ProximityLib/Double/Kernels/PointKernels.Planar.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    // 2D point–box on 2D vectors and the planar Box2: the lifted kernels' steps with the z terms left out. On a lifted
    // planar box they are exact zeros (the point's z is 0 and so are the box's, its third axis is never a nearest face),
    // so these give the lifted kernels' values, up to the sign of a zero coordinate, without the 150-byte Box.
    internal static partial class Kernels
    {
        /// <summary><see cref="PointBoxDistanceSquared(Vector3D, in Box)"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointBoxDistanceSquared2(Vector2D p, in Box2 box)
        {
            var q = box.ToLocal(p - box.Origin);
            double dx = q.X - Num.Clamp(q.X, box.Lo.X, box.Hi.X);
            double dy = q.Y - Num.Clamp(q.Y, box.Lo.Y, box.Hi.Y);
            return dx * dx + dy * dy;
        }

        /// <summary><see cref="PointBoxDistance"/> in the plane (the same operations and <paramref name="inRange"/>).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double PointBoxDistance2(Vector2D p, in Box2 box, out bool inRange)
        {
            var q = box.ToLocal(p - box.Origin);
            var c = new Vector2D(Num.Clamp(q.X, box.Lo.X, box.Hi.X), Num.Clamp(q.Y, box.Lo.Y, box.Hi.Y));
            if (q != c)
            {
                double d2 = ((p - box.Origin) - box.ToWorldOffset(c)).LengthSquared;
                inRange = Range.In(d2);
                return System.Math.Sqrt(d2);
            }
            double depth = NearestFace(new Vector3D(q.X, q.Y, 0), new Vector3D(box.Lo.X, box.Lo.Y, 0), new Vector3D(box.Hi.X, box.Hi.Y, 0), true, out _);
            inRange = depth >= Range.Lo;
            return -depth;
        }

        /// <summary><see cref="PointInBox"/> in the plane.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool PointInBox2(Vector2D p, in Box2 box)
        {
            var q = box.ToLocal(p - box.Origin);
            return q.X >= box.Lo.X && q.X <= box.Hi.X && q.Y >= box.Lo.Y && q.Y <= box.Hi.Y
                && (box.Lo != box.Hi || p == box.Origin + box.ToWorldOffset(box.Lo));
        }
    }
}
