using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a capsule (3D): negative inside (depth = radius − distance from the point to the axis); PointB lies on the surface along the axis normal through the point (a point on the axis: along <c>AnyPerpendicular</c> of the axis, +X for a zero-length axis); ParameterB is the axis parameter. Algorithm: point–segment distance to the axis less the radius (Eberly, robust point–segment; capsule = segment ⊕ ball).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Capsule3 b, out bool inRange) => Kernels.PointCapsule(a, 0, b.Start, b.End, b.Radius, out inRange);
        /// <summary>Closest distance between a point and a capsule (2D): negative inside (depth = radius − distance from the point to the axis); PointB lies on the boundary along the axis normal through the point (a point on the axis: along the axis's left-hand normal (y, −x), +X for a zero-length axis); ParameterB is the axis parameter. Algorithm: point–segment distance to the axis less the radius (Eberly, robust point–segment; capsule = segment ⊕ disc).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, in Capsule2 b, out bool inRange) => Kernels.PointCapsule(a.To3(), 0, b.Start.To3(), b.End.To3(), b.Radius, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in Capsule3 b, out bool inRange) => Kernels.PointSegmentDistance(a, b.Start, b.End, out inRange) - b.Radius;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Capsule2 b, out bool inRange) => Kernels.PointSegmentDistance(a.To3(), b.Start.To3(), b.End.To3(), out inRange) - b.Radius;
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in Capsule3 b, out bool inRange) => Kernels.SegmentInSphere(b.Start, b.End, a, b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Capsule2 b, out bool inRange) => Kernels.SegmentInSphere(b.Start.To3(), b.End.To3(), a.To3(), b.Radius, out inRange);
    }
}
