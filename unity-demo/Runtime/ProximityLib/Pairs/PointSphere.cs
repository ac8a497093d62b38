// Copied from src/ProximityLib/Pairs/PointSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a sphere (3D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Sphere b, out bool inRange) => Kernels.PointSphere(a, b.Center, b.Radius, out inRange).AsPointFirst(a);
        /// <summary>Closest distance between a point and a circle (2D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Circle b, out bool inRange) => Kernels.PointSphere(a.To3(), b.Center.To3(), b.Radius, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in Sphere b, out bool inRange) => Kernels.PointSphereDistance(a, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Circle b, out bool inRange) => Kernels.PointSphereDistance(a.To3(), b.Center.To3(), b.Radius, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in Sphere b, out bool inRange) => Kernels.PointInSphere(a, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Circle b, out bool inRange) => Kernels.PointInSphere(a.To3(), b.Center.To3(), b.Radius, out inRange);
    }
}
