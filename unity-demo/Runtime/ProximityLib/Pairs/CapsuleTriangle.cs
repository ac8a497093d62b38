// Copied from src/ProximityLib/Pairs/CapsuleTriangle.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a capsule and a triangle (3D): the axis's solid signed distance to the triangle less the radius: apart, the segment–triangle gap less the radius; an axis through the triangle adds the depth of that crossing (the least push over the triangle's normal and the axis × edge directions), an axis touching or lying in the plane none (equal pushes: the first of N then the axis × edge directions AB, AC, BC, toward −axis first). ParameterA is the axis parameter of the point nearest PointA. Algorithm: segment–triangle distance (see the segment–triangle query) and separating-axis depth of the axis–triangle prism (Ericson RTCD §5.5.7 style sweep), less the radius.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Capsule3 a, in Triangle3 b, out bool inRange) => Kernels.CapsuleTriangle(a.Start, a.End, a.Radius, b.A, b.B, b.C, out inRange);
        /// <summary>Closest distance between a capsule and a triangle (2D): the axis's solid signed distance to the solid triangle (the separating-axis depth when the axis enters it, including a degenerate triangle it crosses) less the radius. ParameterA is the axis parameter of the point nearest PointA. Algorithm: the segment–triangle query, less the radius (sd(K ⊕ disc) = sd(K) − r).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Capsule2 a, in Triangle2 b, out bool inRange) => Kernels.CapsuleTriangle2(a.Start.To3(), a.End.To3(), a.Radius, b.A.To3(), b.B.To3(), b.C.To3(), out inRange).To2();
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule3 a, in Triangle3 b, out bool inRange) => Kernels.SegmentTriangle(a.Start, a.End, b.A, b.B, b.C, out inRange).Distance - a.Radius <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Capsule2 a, in Triangle2 b, out bool inRange) => Kernels.CapsuleTriangle2(a.Start.To3(), a.End.To3(), a.Radius, b.A.To3(), b.B.To3(), b.C.To3(), out inRange).Distance <= 0;
    }
}
