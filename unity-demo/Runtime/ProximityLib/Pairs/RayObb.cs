// Copied from src/ProximityLib/Pairs/RayObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a ray and an OBB (3D): negative when the ray enters the box: minus the least translation that clears it, sideways (perpendicular to the ray) or back past the face it leaves through. Witnesses: ParameterA t ≥ 0 with PointA = Origin + t·Direction; where the closest points are not unique (the ray parallel to a face or an edge), the end of the stretch of closest points where the bracketing of the convex distance function first lands (a breakpoint where the ray crosses a slab plane of the box). Algorithm: in the box frame relative to its centre, the ray clipped to the box's projection onto it (widened, cut at 0) and minimised as a segment (convex piecewise quadratic); separating axes (Ericson RTCD §5.3.3): box normals and Direction × box axis.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Ray3 a, in Obb3 b, out bool inRange) => Kernels.LineBox(a.Origin, a.Direction, true, b.ToBox(), out inRange);
        /// <summary>Closest distance between a ray and an OBB (2D): negative when the ray enters the box: minus the least translation that clears it, sideways (perpendicular to the ray) or back past the face it leaves through. Witnesses: ParameterA t ≥ 0 with PointA = Origin + t·Direction; where the closest points are not unique (the ray parallel to a face or an edge), the end of the stretch of closest points where the bracketing of the convex distance function first lands (a breakpoint where the ray crosses a slab plane of the box). Algorithm: in the box frame relative to its centre, the ray clipped to the box's projection onto it (widened, cut at 0) and minimised as a segment (convex piecewise quadratic); separating axes (Ericson RTCD §5.3.3): box normals and Direction × box axis.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Ray2 a, in Obb2 b, out bool inRange) => Kernels.LineBox2(a.Origin, a.Direction, true, b.ToBox2(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray3 a, in Obb3 b, out bool inRange) => Kernels.LineBoxOverlaps(a.Origin, a.Direction, true, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Ray2 a, in Obb2 b, out bool inRange) => Kernels.LineBoxOverlaps2(a.Origin, a.Direction, true, b.ToBox2(), out inRange);
    }
}
