using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a sphere (3D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is. Algorithm: |cb − ca| − (ra + rb) (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in Sphere b, out bool inRange) => Kernels.SphereSphere(a.Center, a.Radius, b.Center, b.Radius, out inRange);
        /// <summary>Closest distance between a circle and a circle (2D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push the smaller sphere along +X (the larger along −X), whichever argument it is. Algorithm: |cb − ca| − (ra + rb) (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in Circle b, out bool inRange) => Kernels.SphereSphere(a.Center.To3(), a.Radius, b.Center.To3(), b.Radius, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Sphere a, in Sphere b, out bool inRange) => Kernels.SphereSphereDistance(a.Center, a.Radius, b.Center, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Circle a, in Circle b, out bool inRange) => Kernels.SphereSphereDistance(a.Center.To3(), a.Radius, b.Center.To3(), b.Radius, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in Sphere b, out bool inRange) => Kernels.PointInSphere(b.Center, a.Center, a.Radius + b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in Circle b, out bool inRange) => Kernels.PointInSphere(b.Center.To3(), a.Center.To3(), a.Radius + b.Radius, out inRange);
    }
}
