// Copied from src/ProximityLib/Pairs/TriangleAabb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a triangle and an AABB (3D): negative when the triangle enters the box (minimum translation of the triangle over the 13 separating axes); apart, the first minimum among the triangle's edges AB, BC, CA against the box, then the box's edges against the triangle. Algorithm: separating-axis test in the box frame (Akenine-Möller 2001, triangle–box overlap) with an exactly formed triangle normal; segment–box closed form and segment–triangle distances when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Triangle3 a, in Aabb3 b, out bool inRange) => Kernels.TriangleBox(a.A, a.B, a.C, b.ToBox(), out inRange);
        /// <summary>Closest distance between a triangle and an AABB (2D): negative when the solid triangle and the box overlap (minimum translation of the triangle over the box's and the triangle's edge normals); apart, the first minimum among the triangle's edges AB, BC, CA against the box. Algorithm: separating-axis test in the box frame (Akenine-Möller 2001, in 2D); segment–box closed form when apart.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Triangle2 a, in Aabb2 b, out bool inRange) => Kernels.TriangleBox(a.A.To3(), a.B.To3(), a.C.To3(), b.ToBox(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Triangle3 a, in Aabb3 b, out bool inRange) => Kernels.TriangleBoxOverlaps(a.A, a.B, a.C, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Triangle2 a, in Aabb2 b, out bool inRange) => Kernels.TriangleBoxOverlaps(a.A.To3(), a.B.To3(), a.C.To3(), b.ToBox(), out inRange);
    }
}
