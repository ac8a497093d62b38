using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    internal static partial class Kernels
    {
        /// <summary>
        /// AABB against AABB, per axis and exact up to one subtraction per gap. Apart: the per-axis gaps; overlapping axes
        /// put both witnesses at the middle of the shared interval. Overlapping: the axis of least overlap.
        /// </summary>
        /// <remarks>
        /// Branch-free per axis (a branch on which side B lies mispredicts on mixed inputs): with lo, hi the larger min and
        /// the smaller max, the middle m = ½lo + ½hi held in [lo, hi] is the shared interval's middle when the axis
        /// overlaps, and hi when it does not (then lo &gt; hi); clamped into each box it gives the facing faces (A's max
        /// and B's min when B lies above, A's min and B's max when below) and m itself on a shared axis. Inlined: a call
        /// returning the result through memory with an out flag cost 4x without PGO.
        /// <paramref name="inRange"/>: apart, the squared gap lies in the fast range; overlapping, no axis had a positive gap
        /// whose square underflowed (the depths are differences, exact at any magnitude).
        /// </remarks>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static DistanceResult3 AabbAabb(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB, bool planar, out bool inRange)
        {
            double ax = minB.X - maxA.X, bx = minA.X - maxB.X;
            double ay = minB.Y - maxA.Y, by = minA.Y - maxB.Y;
            double az = minB.Z - maxA.Z, bz = minA.Z - maxB.Z;
            double gx = Num.Max(Num.Max(ax, bx), 0), gy = Num.Max(Num.Max(ay, by), 0), gz = Num.Max(Num.Max(az, bz), 0);
            double g2 = gx * gx + gy * gy + gz * gz;
            double mx = Middle(Num.Max(minA.X, minB.X), Num.Min(maxA.X, maxB.X));
            double my = Middle(Num.Max(minA.Y, minB.Y), Num.Min(maxA.Y, maxB.Y));
            double mz = Middle(Num.Max(minA.Z, minB.Z), Num.Min(maxA.Z, maxB.Z));
            var pa = new Vector3D(Num.FastClamp(mx, minA.X, maxA.X), Num.FastClamp(my, minA.Y, maxA.Y), Num.FastClamp(mz, minA.Z, maxA.Z));
            var pb = new Vector3D(Num.FastClamp(mx, minB.X, maxB.X), Num.FastClamp(my, minB.Y, maxB.Y), Num.FastClamp(mz, minB.Z, maxB.Z));
            if (g2 > 0)
            {
                inRange = Range.In(g2);
                return new DistanceResult3(System.Math.Sqrt(g2), g2, pa, pb, 0, 0);
            }
            double depth = LeastOverlap(ax, bx, ay, by, az, bz, planar, minA, maxA, minB, maxB, out int axis, out bool down);
            inRange = depth >= 0;
            // Moving A down along the axis by `depth` puts its max face on B's min face, and vice versa.
            pa = Vec.With(pa, axis, Vec.Get(down ? maxA : minA, axis));
            pb = Vec.With(pb, axis, Vec.Get(down ? minB : maxB, axis));
            return new DistanceResult3(-depth, 0, pa, pb, 0, 0);
        }

        /// <summary>½lo + ½hi (halves first: hi − lo can overflow), held in [lo, hi] (halving a subnormal rounds), or hi when lo &gt; hi.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double Middle(double lo, double hi) => Num.Min(Num.Max(0.5 * lo + 0.5 * hi, lo), hi);

        /// <summary>
        /// Overlapping on every axis: the depth of the axis of least overlap (x before y before z on ties) and whether A
        /// leaves it downward (the push-outs are −a and −b of that axis, A down or up, whichever is shorter). Swapping the
        /// boxes swaps each axis's two push-outs, so a tie between them is broken by the canonical order of the boxes,
        /// which flips too: either argument order gives one answer.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static double LeastOverlap(double ax, double bx, double ay, double by, double az, double bz, bool planar,
            Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB, out int axis, out bool down)
        {
            double depth = Num.Min(-ax, -bx), t = Num.Min(-ay, -by), dn = -ax, up = -bx;
            axis = 0;
            if (t < depth) { depth = t; axis = 1; dn = -ay; up = -by; }
            if (!planar && (t = Num.Min(-az, -bz)) < depth) { depth = t; axis = 2; dn = -az; up = -bz; }
            down = dn < up || (dn == up && Order.Before(minA, maxA, minB, maxB));
            return depth;
        }

        /// <summary>
        /// The distance of <see cref="AabbAabb"/> alone, branch-free per axis: an axis's gap is the larger of its two
        /// one-sided gaps (at most one is positive), and its push-out the smaller of the two negated. The same operations
        /// on the same values (zero signs included), so the same bits and <paramref name="inRange"/>.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double AabbAabbDistance(in Vector3D minA, in Vector3D maxA, in Vector3D minB, in Vector3D maxB, bool planar, out bool inRange)
        {
            double ax = minB.X - maxA.X, bx = minA.X - maxB.X;
            double ay = minB.Y - maxA.Y, by = minA.Y - maxB.Y;
            double az = minB.Z - maxA.Z, bz = minA.Z - maxB.Z;
            double gx = Num.Max(Num.Max(ax, bx), 0), gy = Num.Max(Num.Max(ay, by), 0), gz = Num.Max(Num.Max(az, bz), 0);
            double g2 = gx * gx + gy * gy + gz * gz;
            if (g2 > 0)
            {
                inRange = Range.In(g2);
                return System.Math.Sqrt(g2);
            }
            double depth = Num.Min(Num.Min(-ax, -bx), Num.Min(-ay, -by));
            if (!planar) depth = Num.Min(depth, Num.Min(-az, -bz));
            inRange = depth >= 0;
            return -depth;
        }

        /// <summary>Whether the closed boxes meet: every axis's intervals overlap.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool AabbAabbOverlaps(in Vector3D minA, in Vector3D maxA, in Vector3D minB, in Vector3D maxB) =>
            minA.X <= maxB.X && maxA.X >= minB.X && minA.Y <= maxB.Y && maxA.Y >= minB.Y && minA.Z <= maxB.Z && maxA.Z >= minB.Z;
    }
}
