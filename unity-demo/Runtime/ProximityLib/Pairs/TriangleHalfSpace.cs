// Copied from src/ProximityLib/Pairs/TriangleHalfSpace.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a triangle and a half-space (3D): the lowest vertex's height Normal·(vertex − Point), negative when the triangle enters (minus the depth of its deepest vertex); witnesses that vertex and its foot on the boundary, the first of A, B, C among equally low ones (an edge or the whole triangle parallel to the boundary). Algorithm: the height is linear over the triangle, so a vertex is lowest (solid or not); three dot products from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Triangle3 a, in HalfSpace b, out bool inRange) => Kernels.TriangleHalfSpace(a.A, a.B, a.C, b.Normal, b.Point, out inRange);
        /// <summary>Closest distance between a triangle and a half-plane (2D): the lowest vertex's height Normal·(vertex − Point), negative when the triangle enters (minus the depth of its deepest vertex); witnesses that vertex and its foot on the boundary, the first of A, B, C among equally low ones (an edge or the whole triangle parallel to the boundary). Algorithm: the height is linear over the triangle, so a vertex is lowest (solid or not); three dot products from the stored boundary point.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Triangle2 a, in HalfPlane b, out bool inRange) => Kernels.TriangleHalfSpace(a.A.To3(), a.B.To3(), a.C.To3(), b.Normal.To3(), b.Point.To3(), out inRange).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Triangle3 a, in HalfSpace b, out bool inRange) => Kernels.TriangleHalfSpaceDistance(a.A, a.B, a.C, b.Normal, b.Point, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Triangle2 a, in HalfPlane b, out bool inRange) => Kernels.TriangleHalfSpaceDistance(a.A.To3(), a.B.To3(), a.C.To3(), b.Normal.To3(), b.Point.To3(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Triangle3 a, in HalfSpace b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Triangle2 a, in HalfPlane b, out bool inRange) => ClosestDistance.DistanceCore(a, b, out inRange) <= 0;
    }
}
