using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a capsule (3D): negative when they overlap (depth = sum of the radii − distance from the center to the axis); the witnesses lie along the axis normal through the center (a center on the axis: along <c>AnyPerpendicular</c> of the axis, +X for a zero-length axis); ParameterB is the axis parameter. Algorithm: point–segment distance from the center to the axis less both radii (Eberly, robust point–segment; capsule = segment ⊕ ball).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in Capsule3 b, out bool inRange) => Kernels.PointCapsule(a.Center, a.Radius, b.Start, b.End, b.Radius, out inRange);
        /// <summary>Closest distance between a circle and a capsule (2D): negative when they overlap (depth = sum of the radii − distance from the center to the axis); the witnesses lie along the axis normal through the center (a center on the axis: along the axis's normal (y, −x), +X for a zero-length axis); ParameterB is the axis parameter. Algorithm: point–segment distance from the center to the axis less both radii (Eberly, robust point–segment; capsule = segment ⊕ disc).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in Capsule2 b, out bool inRange) => Kernels.PointCapsule(a.Center.To3(), a.Radius, b.Start.To3(), b.End.To3(), b.Radius, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Sphere a, in Capsule3 b, out bool inRange)
        {
            double r = a.Radius + b.Radius, d = Kernels.PointSegmentDistance(a.Center, b.Start, b.End, out inRange) - r;
            inRange &= r <= double.MaxValue;
            return d;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Circle a, in Capsule2 b, out bool inRange)
        {
            double r = a.Radius + b.Radius, d = Kernels.PointSegmentDistance(a.Center.To3(), b.Start.To3(), b.End.To3(), out inRange) - r;
            inRange &= r <= double.MaxValue;
            return d;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in Capsule3 b, out bool inRange) => Kernels.CapsuleTouchesBall(b.Start, b.End, a.Center, a.Radius + b.Radius, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in Capsule2 b, out bool inRange) => Kernels.CapsuleTouchesBall(b.Start.To3(), b.End.To3(), a.Center.To3(), a.Radius + b.Radius, out inRange);
    }
}
