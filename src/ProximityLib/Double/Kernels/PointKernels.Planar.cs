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
            var c = ClampLocal2(q, box.Lo, box.Hi);
            if (q != c)
            {
                double d2 = ((p - box.Origin) - box.ToWorldOffset(c)).LengthSquared;
                inRange = Range.In(d2);
                return System.Math.Sqrt(d2);
            }
            double depth = NearestFace(q.To3(), box.Lo.To3(), box.Hi.To3(), true, out _);
            inRange = depth >= Range.Lo;
            return -depth;
        }

        /// <summary>
        /// <see cref="PointBox"/> in the plane, as a <see cref="PointContact"/> with z = 0. A point within 2^-26 of the box
        /// (the near-touch normal, rare) is handed to the lifted kernel on <see cref="Lift"/>, which answers as before.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static PointContact PointBox2(Vector2D p, in Box2 box, out bool inRange)
        {
            var q = box.ToLocal(p - box.Origin);
            var c = ClampLocal2(q, box.Lo, box.Hi);
            if (q != c)
            {
                var offset = box.ToWorldOffset(c);
                var diff = (p - box.Origin) - offset;
                double d2 = diff.LengthSquared;
                if (d2 < NearTouch2 * c.LengthSquared) return PointBoxNear2(p, box, q, c, out inRange);
                double d = System.Math.Sqrt(d2);
                var normal = d > 0 ? (diff * (1 / d)).To3() : box.ToWorldOffset(Vector2D.From3(Unit(new Vector3D(q.X - c.X, q.Y - c.Y, 0)))).To3();
                inRange = Range.In(d2);
                return new PointContact(d, d2, (box.Origin + offset).To3(), normal, 0);
            }
            double depth = NearestFace(q.To3(), box.Lo.To3(), box.Hi.To3(), true, out int face);
            inRange = depth >= Range.Lo;
            // The face's point and normal written out: through the lifted FacePoint and FaceNormal (calls returning a
            // Vector3D) the query measured 1.2–1.3× slower.
            var onFace = face switch { 0 => new Vector2D(box.Lo.X, q.Y), 1 => new Vector2D(box.Hi.X, q.Y), 2 => new Vector2D(q.X, box.Lo.Y), _ => new Vector2D(q.X, box.Hi.Y) };
            var n = face switch { 0 => new Vector2D(-1, 0), 1 => new Vector2D(1, 0), 2 => new Vector2D(0, -1), _ => new Vector2D(0, 1) };
            return new PointContact(-depth, 0, (box.Origin + box.ToWorldOffset(onFace)).To3(), box.ToWorldOffset(n).To3(), 0);
        }

        /// <summary>The near-touch case of <see cref="PointBox2"/>: the lifted kernel's, out of line.</summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        private static PointContact PointBoxNear2(Vector2D p, in Box2 box, Vector2D q, Vector2D c, out bool inRange) =>
            PointBoxNear(p.To3(), Lift(box), q.To3(), c.To3(), out inRange);

        /// <summary>The planar <see cref="Box"/> this Box2 drops the z parts of (Obb2.ToBox, Aabb2.ToBox).</summary>
        internal static Box Lift(in Box2 box) =>
            new Box(box.Origin.To3(), box.X.To3(), box.Y.To3(), Vector3D.UnitZ, box.Lo.To3(), box.Hi.To3(), true);

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
