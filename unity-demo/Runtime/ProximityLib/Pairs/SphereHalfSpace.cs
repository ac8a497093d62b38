// Copied from src/ProximityLib/Pairs/SphereHalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a half-space (3D): the center's height Normal·(center − Point) less the radius, negative when overlapping; witnesses the sphere's lowest point center − Normal·radius and the center's foot on the boundary. Algorithm: one dot product from the stored boundary point (Ericson RTCD §5.2.2).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in HalfSpace b, out bool inRange) => Kernels.BallHalfSpace(a.Center, a.Radius, b.Normal, b.Point, 0, out inRange);
        /// <summary>Closest distance between a circle and a half-plane (2D): the center's height Normal·(center − Point) less the radius, negative when overlapping; witnesses the circle's lowest point center − Normal·radius and the center's foot on the boundary. Algorithm: one dot product from the stored boundary point (Ericson RTCD §5.2.2).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in HalfPlane b, out bool inRange) => Kernels.BallHalfSpace(a.Center.To3(), a.Radius, b.Normal.To3(), b.Point.To3(), 0, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Sphere a, HalfSpace b, out bool inRange) => Kernels.BallHalfSpaceDistance(a.Center, a.Radius, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Circle a, in HalfPlane b, out bool inRange) => Kernels.BallHalfSpaceDistance(a.Center.To3(), a.Radius, b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
