// Copied from src/ProximityLib/Pairs/LineRay.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a ray (3D): never negative; a ray parallel to the line or pointing away from the lines' closest pair: its origin and the origin's projection on the line; ParameterA is the line's t, ParameterB the ray's t ≥ 0. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel shapes (the ray's origin and its projection). Algorithm: the lines' closest parameters from the common normal dA × dB formed with exact products (Dekker), else the ray's origin against the line (Eberly, distance between linear components).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Line3 a, Ray3 b, double range, out bool inRange) => Kernels.UnboundedPair(a.Origin, a.Direction, false, b.Origin, b.Direction, true, range, out inRange);
        /// <summary>Closest distance between a line and a ray (2D): never negative (0 where the ray crosses the line); a ray parallel to the line or pointing away from it: its origin and the origin's projection on the line; ParameterA is the line's t, ParameterB the ray's t ≥ 0. Should a closest point or its parameter lie beyond the range of the API's precision (float's for the float API), or a parameter beyond 2^1022·M (M the origins' largest coordinate magnitude, to its power of two: directions within about 2^-1022 of parallel), no pair of points the result can hold realises the distance: Distance stands, and the witnesses are chosen as for parallel shapes (the ray's origin and its projection). Algorithm: the lines' crossing parameters from the cross product formed with exact products (Dekker), else the ray's origin against the line (Eberly, distance between linear components).</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in Ray2 b, double range, out bool inRange) => Kernels.UnboundedPair(a.Origin.To3(), a.Direction.To3(), false, b.Origin.To3(), b.Direction.To3(), true, range, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Line3 a, Ray3 b, out bool inRange) =>
            Math.Sqrt(Kernels.Unbounded(a.Origin, a.Direction, false, b.Origin, b.Direction, true, out _, out _, out inRange));
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line2 a, in Ray2 b, out bool inRange) =>
            Math.Sqrt(Kernels.Unbounded(a.Origin.To3(), a.Direction.To3(), false, b.Origin.To3(), b.Direction.To3(), true, out _, out _, out inRange));
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in Ray3 b, out bool inRange) => Kernels.Unbounded(a.Origin, a.Direction, false, b.Origin, b.Direction, true, out _, out _, out inRange) == 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in Ray2 b, out bool inRange) => Kernels.Unbounded(a.Origin.To3(), a.Direction.To3(), false, b.Origin.To3(), b.Direction.To3(), true, out _, out _, out inRange) == 0;
    }
}
