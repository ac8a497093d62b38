// Copied from src/ProximityLib/Pairs/HalfSpaceHalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a half-space and a half-space (3D): exactly opposite normals: the signed gap a.Normal·(b.Point − a.Point) between the parallel boundaries, negative when they overlap (minus the depth), witnessed by the feet on the two boundaries of the midpoint of the stored points. Any other normals: the intersection is unbounded, Distance = −∞ (DistanceSquared 0) and both witnesses are one common point: the midpoint of the stored points when each lies in the other half-space, else the stored point that lies in the other, else a point of both near where the boundaries meet (the midpoint, should that lie beyond the range of the API's precision: float's for the float API). Symmetric: swapping the arguments swaps the witnesses bit for bit. Algorithm: dot products from the stored points; the boundaries' meeting point in a basis built on the accurately formed cross product of the normals (well conditioned however nearly parallel they are), moved inward past its rounding.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in HalfSpace a, in HalfSpace b, double range, out bool inRange) => Kernels.HalfSpaceHalfSpace(a.Normal, a.Point, b.Normal, b.Point, range, out inRange);
        /// <summary>Closest distance between a half-plane and a half-plane (2D): exactly opposite normals: the signed gap a.Normal·(b.Point − a.Point) between the parallel boundaries, negative when they overlap (minus the depth), witnessed by the feet on the two boundaries of the midpoint of the stored points. Any other normals: the intersection is unbounded, Distance = −∞ (DistanceSquared 0) and both witnesses are one common point: the midpoint of the stored points when each lies in the other half-plane, else the stored point that lies in the other, else a point of both near where the boundaries meet (the midpoint, should that lie beyond the range of the API's precision: float's for the float API). Symmetric: swapping the arguments swaps the witnesses bit for bit. Algorithm: dot products from the stored points; the boundaries' meeting point in a basis built on the accurately formed cross product of the normals (well conditioned however nearly parallel they are), moved inward past its rounding.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in HalfPlane a, in HalfPlane b, double range, out bool inRange) => Kernels.HalfSpaceHalfSpace(a.Normal.To3(), a.Point.To3(), b.Normal.To3(), b.Point.To3(), range, out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(HalfSpace a, HalfSpace b, out bool inRange) => Kernels.HalfSpaceHalfSpaceDistance(a.Normal, a.Point, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in HalfPlane a, in HalfPlane b, out bool inRange) => Kernels.HalfSpaceHalfSpaceDistance(a.Normal.To3(), a.Point.To3(), b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(HalfSpace a, HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in HalfPlane a, in HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
