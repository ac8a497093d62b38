// Copied from src/ProximityLib/Pairs/PointLine.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a line (3D): never negative; ParameterB is the projection parameter t = Direction·(point − Origin). Algorithm: orthogonal projection with the residual formed from the difference to the origin (Eberly, "Distance from a point to a line").</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Line3 b, out bool inRange) => Kernels.PointLinear(a, b.Origin, b.Direction, false, out inRange).AsPointFirst(a);
        /// <summary>Closest distance between a point and a line (2D): never negative; ParameterB is the projection parameter t = Direction·(point − Origin). Algorithm: orthogonal projection with the residual formed from the difference to the origin (Eberly, "Distance from a point to a line").</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Line2 b, out bool inRange) => Kernels.PointLinear(a.To3(), b.Origin.To3(), b.Direction.To3(), false, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in Line3 b, out bool inRange) => Kernels.PointLinearDistance(a, b.Origin, b.Direction, false, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Line2 b, out bool inRange) => Kernels.PointLinearDistance(a.To3(), b.Origin.To3(), b.Direction.To3(), false, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in Line3 b) => Kernels.PointOnLinear(a, b.Origin, b.Direction, false);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, Line2 b) => Kernels.PointOnLinear(a.To3(), b.Origin.To3(), b.Direction.To3(), false);
    }
}
