// Copied from src/ProximityLib/Pairs/PointObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and an OBB (3D): negative inside (depth to the nearest face). Algorithm: clamp in the box frame (Ericson RTCD §5.1.4); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Obb3 b, out bool inRange)
        {
            var r = Kernels.PointBox(a, b.ToBox(), out inRange).AsPointFirst(a);
            inRange &= !b.Extreme; // a box whose own numbers leave the fast range (Obb3.Extreme) takes the slow path
            return r;
        }
        /// <summary>Closest distance between a point and an OBB (2D): negative inside (depth to the nearest face). Algorithm: clamp in the box frame (Ericson RTCD §5.1.4); nearest face when inside.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Obb2 b, out bool inRange)
        {
            var r = Kernels.PointBox2(a, b.ToBox2(), out inRange).AsPointFirst(a.To3()).To2();
            inRange &= !b.Extreme;
            return r;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in Obb3 b, out bool inRange)
        {
            double d = Kernels.PointBoxDistance(a, b.ToBox(), out inRange);
            inRange &= !b.Extreme;
            return d;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Obb2 b, out bool inRange)
        {
            double d = Kernels.PointBoxDistance2(a, b.ToBox2(), out inRange);
            inRange &= !b.Extreme;
            return d;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in Obb3 b, out bool inRange)
        {
            inRange = !b.Extreme;
            return Kernels.PointInBox(a, b.ToBox());
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Obb2 b, out bool inRange)
        {
            inRange = !b.Extreme;
            return Kernels.PointInBox2(a, b.ToBox2());
        }
    }
}
