using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a capsule and a half-space (3D): the lower axis end's height Normal·(end − Point) less the radius, negative when overlapping; witnesses that end moved down by the radius (end − Normal·radius, ParameterA 0 or 1) and the end's foot on the boundary. An axis parallel to the boundary is witnessed at Start. Algorithm: the height is linear along the axis, so an end is lowest; two dot products from the stored boundary point, less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Capsule3 a, HalfSpace b, out bool inRange) => Kernels.CapsuleHalfSpace(a.Start, a.End, a.Radius, b.Normal, b.Point, out inRange);
        /// <summary>Closest distance between a capsule and a half-plane (2D): the lower axis end's height Normal·(end − Point) less the radius, negative when overlapping; witnesses that end moved down by the radius (end − Normal·radius, ParameterA 0 or 1) and the end's foot on the boundary. An axis parallel to the boundary is witnessed at Start. Algorithm: the height is linear along the axis, so an end is lowest; two dot products from the stored boundary point, less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Capsule2 a, in HalfPlane b, out bool inRange) => Kernels.CapsuleHalfSpace(a.Start.To3(), a.End.To3(), a.Radius, b.Normal.To3(), b.Point.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule3 a, in HalfSpace b, out bool inRange) => Kernels.CapsuleHalfSpaceDistance(a.Start, a.End, a.Radius, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Capsule2 a, in HalfPlane b, out bool inRange) => Kernels.CapsuleHalfSpaceDistance(a.Start.To3(), a.End.To3(), a.Radius, b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule3 a, in HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule2 a, in HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
