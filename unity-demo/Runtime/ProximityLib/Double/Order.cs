// Copied from src/ProximityLib/Double/Order.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    /// <summary>
    /// A canonical order between two shapes of one type, so that a query gives the same answer, bit for bit, in either
    /// argument order: kernels whose steps are not symmetric run on the ordered pair and swap the result back; the
    /// symmetric ones use it only to break an exact tie. The order compares the stored doubles' bit patterns field
    /// by field: a total order that tells apart even values == calls equal (0 and −0), and the first field almost
    /// always decides.
    /// </summary>
    internal static class Order
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

        /// <summary>Whether the pair must be swapped into canonical order: b strictly before a.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Segment3 a, in Segment3 b)
        {
            int c = Compare(a.Start.X, b.Start.X);
            return c != 0 ? c > 0 : Tail(a, b) > 0;
        }

        private static int Tail(in Segment3 a, in Segment3 b)
        {
            int c = Compare(a.Start, b.Start);
            return c != 0 ? c : Compare(a.End, b.End);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Segment2 a, in Segment2 b)
        {
            int c = Compare(a.Start.X, b.Start.X);
            return c != 0 ? c > 0 : Tail(a, b) > 0;
        }

        private static int Tail(in Segment2 a, in Segment2 b)
        {
            int c = Compare(a.Start, b.Start);
            return c != 0 ? c : Compare(a.End, b.End);
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Obb3 a, in Obb3 b)
        {
            int c = Compare(a.Center.X, b.Center.X);
            return c != 0 ? c > 0 : Tail(a, b) > 0;
        }

        private static int Tail(in Obb3 a, in Obb3 b)
        {
            int c = Compare(a.Center, b.Center);
            if (c == 0) c = Compare(a.HalfExtents, b.HalfExtents);
            if (c == 0) c = Compare(a.AxisX, b.AxisX);
            if (c == 0) c = Compare(a.AxisY, b.AxisY);
            if (c == 0) c = Compare(a.AxisZ, b.AxisZ);
            return c;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static bool Swap(in Obb2 a, in Obb2 b)
        {
            int c = Compare(a.Center.X, b.Center.X);
            return c != 0 ? c > 0 : Tail(a, b) > 0;
        }

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
