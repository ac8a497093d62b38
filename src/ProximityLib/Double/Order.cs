using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A canonical order between two shapes of one type, so that a query gives the same answer, bit for bit, in either
    /// argument order: kernels whose steps are not symmetric (box – box) run on the ordered pair and swap the result
    /// back; the symmetric ones use it only to break an exact tie. The order compares the first stored double, then
    /// (rarely) every field's bit pattern: a total order that tells apart even values == calls equal (0 and −0).
    /// </summary>
    internal static partial class Order
    {
        /// <summary>-1, 0 or 1 as the bit patterns of x and y compare.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static int Compare(double x, double y) =>
            BitConverter.DoubleToInt64Bits(x).CompareTo(BitConverter.DoubleToInt64Bits(y));

        private static int Compare(Vector3D a, Vector3D b)
        {
            int c = Compare(a.X, b.X);
            if (c == 0) c = Compare(a.Y, b.Y);
            if (c == 0) c = Compare(a.Z, b.Z);
            return c;
        }

        private static int Compare(Vector2D a, Vector2D b)
        {
            int c = Compare(a.X, b.X);
            return c != 0 ? c : Compare(a.Y, b.Y);
        }

        /// <summary>
        /// Whether segment (b0, b1) comes strictly before segment (a0, a1): the tie-break of the segment kernel. By
        /// value and out of line (ties are rare): a reference to a hot local passed to a call would pin it in memory.
        /// </summary>
        [MethodImpl(MethodImplOptions.NoInlining)]
        public static bool Swap(Vector3D a0, Vector3D a1, Vector3D b0, Vector3D b1)
        {
            int c = Compare(a0, b0);
            return (c != 0 ? c : Compare(a1, b1)) > 0;
        }

        /// <summary>Whether the pair must be swapped into canonical order: b strictly before a.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Obb3 a, in Obb3 b)
        {
            double x = a.Center.X, y = b.Center.X;
            return x != y ? x > y : Tail(a, b) > 0;
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static int Tail(in Obb3 a, in Obb3 b)
        {
            int c = Compare(a.Center, b.Center);
            if (c == 0) c = Compare(a.HalfExtents, b.HalfExtents);
            if (c == 0) c = Compare(a.AxisX, b.AxisX);
            if (c == 0) c = Compare(a.AxisY, b.AxisY);
            if (c == 0) c = Compare(a.AxisZ, b.AxisZ);
            return c;
        }

        /// <summary>Whether the pair must be swapped into canonical order: b strictly before a.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Obb2 a, in Obb2 b)
        {
            double x = a.Center.X, y = b.Center.X;
            return x != y ? x > y : Tail(a, b) > 0;
        }

        [MethodImpl(MethodImplOptions.NoInlining)]
        private static int Tail(in Obb2 a, in Obb2 b)
        {
            int c = Compare(a.Center, b.Center);
            if (c == 0) c = Compare(a.HalfExtents, b.HalfExtents);
            if (c == 0) c = Compare(a.AxisX, b.AxisX);
            return c;
        }

        /// <summary>Whether sphere (ca, ra) comes before sphere (cb, rb): the tie-break for coincident centres.</summary>
        public static bool Before(Vector3D ca, double ra, Vector3D cb, double rb)
        {
            int c = Compare(ra, rb);
            return (c != 0 ? c : Compare(ca, cb)) <= 0;
        }

        /// <summary>Whether box [minA, maxA] comes before box [minB, maxB]: the tie-break for equal push-outs.</summary>
        public static bool Before(Vector3D minA, Vector3D maxA, Vector3D minB, Vector3D maxB)
        {
            int c = Compare(minA, minB);
            return (c != 0 ? c : Compare(maxA, maxB)) <= 0;
        }
    }
}
