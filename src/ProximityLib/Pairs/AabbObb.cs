using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between an AABB and an OBB (3D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 15 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; when apart, the closed forms on the features that can hold the closest pair (every vertex against the other box; in 3D the edges that descend from both ends).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Aabb3 a, in Obb3 b, out bool inRange) => Kernels.BoxBox(a.ToBox(), b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Aabb3 a, in Obb3 b, out bool inRange) => Kernels.BoxBoxDistance(a.ToBox(), b.ToBox(), out inRange);
        /// <summary>Closest distance between an AABB and an OBB (2D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 4 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; when apart, the closed forms on the features that can hold the closest pair (every vertex against the other box; in 3D the edges that descend from both ends).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Aabb2 a, in Obb2 b, out bool inRange) => Kernels.BoxBox2(a.ToBox2(), b.ToBox2(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Aabb2 a, in Obb2 b, out bool inRange) => Kernels.BoxBoxDistance2(a.ToBox2(), b.ToBox2(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Aabb3 a, in Obb3 b, out bool inRange) => Kernels.AabbObbOverlaps(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Aabb2 a, in Obb2 b, out bool inRange) => Kernels.AabbObbOverlaps2(a, b, out inRange);
    }
}
