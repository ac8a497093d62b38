// Copied from src/ProximityLib/Pairs/HalfSpaceObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a half-space and an OBB (3D): the height Normal·(x − Point) of the box's lowest point x, negative when the box enters (minus the depth); witnesses the foot of that point on the boundary and the point itself. Where a face or edge is parallel to the boundary the point is the middle of the lowest face or edge. Algorithm: support point of the box along −Normal in the box frame (Ericson RTCD §5.2.3), measured from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in HalfSpace a, in Obb3 b, out bool inRange) => Kernels.HalfSpaceBox(a.Normal, a.Point, b.ToBox(), out inRange);
        /// <summary>Closest distance between a half-plane and an OBB (2D): the height Normal·(x − Point) of the box's lowest point x, negative when the box enters (minus the depth); witnesses the foot of that point on the boundary and the point itself. Where a face or edge is parallel to the boundary the point is the middle of the lowest face or edge. Algorithm: support point of the box along −Normal in the box frame (Ericson RTCD §5.2.3), measured from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in HalfPlane a, in Obb2 b, out bool inRange) => Kernels.HalfSpaceBox(a.Normal.To3(), a.Point.To3(), b.ToBox(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in HalfSpace a, in Obb3 b, out bool inRange) => Kernels.HalfSpaceBoxDistance(a.Normal, a.Point, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in HalfPlane a, in Obb2 b, out bool inRange) => Kernels.HalfSpaceBoxDistance(a.Normal.To3(), a.Point.To3(), b.ToBox(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in HalfSpace a, in Obb3 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in HalfPlane a, in Obb2 b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
