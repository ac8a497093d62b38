// Copied from src/ProximityLib/Pairs/LineHalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and a half-space (3D): a line not exactly parallel to the boundary (by the exact sign of Normal·Direction) crosses it, so the penetration is unbounded: Distance = −∞ (DistanceSquared 0) with both witnesses at the origin (ParameterA 0) when it lies inside or on the boundary, else at the crossing point Origin + t·Direction, t = −Normal·(Origin − Point) / Normal·Direction (ParameterA t; should that point or t lie beyond the range of the API's precision, float's for the float API, or t beyond 2^1022·M, M the largest coordinate magnitude of Origin and Point to its power of two, the origin, t = 0). Parallel: the constant height Normal·(Origin − Point), negative inside, witnessed at the origin (ParameterA 0) and its foot on the boundary. Algorithm: two dot products from the stored boundary point and one division.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Line3 a, in HalfSpace b, double range, out bool inRange) => Kernels.LineHalfSpace(a.Origin, a.Direction, false, b.Normal, b.Point, range, out inRange);
        /// <summary>Closest distance between a line and a half-plane (2D): a line not exactly parallel to the boundary (by the exact sign of Normal·Direction) crosses it, so the penetration is unbounded: Distance = −∞ (DistanceSquared 0) with both witnesses at the origin (ParameterA 0) when it lies inside or on the boundary, else at the crossing point Origin + t·Direction, t = −Normal·(Origin − Point) / Normal·Direction (ParameterA t; should that point or t lie beyond the range of the API's precision, float's for the float API, or t beyond 2^1022·M, M the largest coordinate magnitude of Origin and Point to its power of two, the origin, t = 0). Parallel: the constant height Normal·(Origin − Point), negative inside, witnessed at the origin (ParameterA 0) and its foot on the boundary. Algorithm: two dot products from the stored boundary point and one division.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in HalfPlane b, double range, out bool inRange) => Kernels.LineHalfSpace(a.Origin.To3(), a.Direction.To3(), false, b.Normal.To3(), b.Point.To3(), range, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line3 a, in HalfSpace b, out bool inRange) => Kernels.LineHalfSpaceDistance(a.Origin, a.Direction, false, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Line2 a, in HalfPlane b, out bool inRange) => Kernels.LineHalfSpaceDistance(a.Origin.To3(), a.Direction.To3(), false, b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in HalfSpace b, out bool inRange) => Kernels.LineHalfSpaceOverlaps(a.Origin, a.Direction, false, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in HalfPlane b, out bool inRange) => Kernels.LineHalfSpaceOverlaps(a.Origin.To3(), a.Direction.To3(), false, b.Normal.To3(), b.Point.To3(), out inRange);
    }
}
