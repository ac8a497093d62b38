// Copied from src/ProximityLib/Pairs/PointRay.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a ray (3D): never negative; ParameterB is the projection parameter t = Direction·(point − Origin) clamped at 0 (the origin for a point behind the ray). Algorithm: orthogonal projection clamped at the origin, with the residual formed from the difference to the origin (Eberly, "Distance from a point to a ray").</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(Vector3D a, in Ray3 b, out bool inRange) => Kernels.PointLinear(a, b.Origin, b.Direction, true, out inRange).AsPointFirst(a);
        /// <summary>Closest distance between a point and a ray (2D): never negative; ParameterB is the projection parameter t = Direction·(point − Origin) clamped at 0 (the origin for a point behind the ray). Algorithm: orthogonal projection clamped at the origin, with the residual formed from the difference to the origin (Eberly, "Distance from a point to a ray").</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(Vector2D a, Ray2 b, out bool inRange) => Kernels.PointLinear(a.To3(), b.Origin.To3(), b.Direction.To3(), true, out inRange).AsPointFirst(a.To3()).To2();
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector3D a, in Ray3 b, out bool inRange) => Kernels.PointLinearDistance(a, b.Origin, b.Direction, true, out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(Vector2D a, in Ray2 b, out bool inRange) => Kernels.PointLinearDistance(a.To3(), b.Origin.To3(), b.Direction.To3(), true, out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector3D a, in Ray3 b) => Kernels.PointOnLinear(a, b.Origin, b.Direction, true);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(Vector2D a, in Ray2 b) => Kernels.PointOnLinear(a.To3(), b.Origin.To3(), b.Direction.To3(), true);
    }
}
