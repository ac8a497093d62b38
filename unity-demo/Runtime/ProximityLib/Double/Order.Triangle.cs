// Copied from src/ProximityLib/Double/Order.Triangle.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
namespace ProximityLib.Double
{
    internal static partial class Order
    {
        /// <summary>Whether the pair must be swapped into canonical order: triangle b strictly before triangle a (vertices A, B, C by bit pattern).</summary>
        public static bool Swap(Triangle3 a, Triangle3 b)
        {
            int c = Compare(a.A, b.A);
            if (c == 0) c = Compare(a.B, b.B);
            if (c == 0) c = Compare(a.C, b.C);
            return c > 0;
        }

        /// <summary>Whether the pair must be swapped into canonical order: triangle b strictly before triangle a (vertices A, B, C by bit pattern).</summary>
        public static bool Swap(Triangle2 a, Triangle2 b)
        {
            int c = Compare(a.A, b.A);
            if (c == 0) c = Compare(a.B, b.B);
            if (c == 0) c = Compare(a.C, b.C);
            return c > 0;
        }
    }
}
