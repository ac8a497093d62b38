// Copied from src/ProximityLib/Pairs/ObbObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        // The separating-axis steps work in A's frame: the pair runs in canonical order and the result is swapped back.
        /// <summary>Closest distance between an OBB and an OBB (3D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 15 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; when apart, the closed forms on the features that can hold the closest pair (every vertex against the other box; in 3D the edges that descend from both ends).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Obb3 a, in Obb3 b, out bool inRange) => Kernels.ObbObb(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Obb3 a, in Obb3 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.BoxBoxDistance(b.ToBox(), a.ToBox(), out inRange) : Kernels.BoxBoxDistance(a.ToBox(), b.ToBox(), out inRange);
        /// <summary>Closest distance between an OBB and an OBB (2D): negative when overlapping (minimum translation over the separating-axis candidates). Algorithm: SAT with 4 axes (Gottschalk et al. 1996; paper Eq. 19–20) for overlap and depth; when apart, the closed forms on the features that can hold the closest pair (every vertex against the other box; in 3D the edges that descend from both ends).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Obb2 a, in Obb2 b, out bool inRange) => Kernels.ObbObb2(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Obb2 a, in Obb2 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.BoxBoxDistance2(b.ToBox2(), a.ToBox2(), out inRange) : Kernels.BoxBoxDistance2(a.ToBox2(), b.ToBox2(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Obb3 a, in Obb3 b, out bool inRange) => // by reference: on Mono each copy of an OBB (128 bytes) is a memcpy call
            Order.Swap(a, b) ? Kernels.ObbObbOverlaps(b, a, out inRange) : Kernels.ObbObbOverlaps(a, b, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Obb2 a, in Obb2 b, out bool inRange) =>
            Order.Swap(a, b) ? Kernels.ObbObbOverlaps2(b, a, out inRange) : Kernels.ObbObbOverlaps2(a, b, out inRange);
    }
}
