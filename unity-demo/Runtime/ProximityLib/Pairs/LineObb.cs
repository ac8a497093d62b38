// Copied from src/ProximityLib/Pairs/LineObb.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a line and an OBB (3D): negative when the line passes through the box: minus the least sideways translation (perpendicular to the line) that clears it. Witnesses: ParameterA t with PointA = Origin + t·Direction; where the closest points are not unique (the line parallel to a face or an edge), the end of the stretch of closest points where the bracketing of the convex distance function first lands (a breakpoint where the line crosses a slab plane of the box). Algorithm: in the box frame relative to its centre, the line clipped to the box's projection onto it (widened) and minimised as a segment (convex piecewise quadratic, Ericson RTCD §5.3.3 for the separating axes); depth over the axes Direction × box axis.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Line3 a, in Obb3 b, out bool inRange) => Kernels.LineBox(a.Origin, a.Direction, false, b.ToBox(), out inRange);
        /// <summary>Closest distance between a line and an OBB (2D): negative when the line passes through the box: minus the least sideways translation (perpendicular to the line) that clears it. Witnesses: ParameterA t with PointA = Origin + t·Direction; where the closest points are not unique (the line parallel to a face or an edge), the end of the stretch of closest points where the bracketing of the convex distance function first lands (a breakpoint where the line crosses a slab plane of the box). Algorithm: in the box frame relative to its centre, the line clipped to the box's projection onto it (widened) and minimised as a segment (convex piecewise quadratic, Ericson RTCD §5.3.3 for the separating axes); depth over the axes Direction × box axis.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Line2 a, in Obb2 b, out bool inRange) => Kernels.LineBox2(a.Origin, a.Direction, false, b.ToBox2(), out inRange);
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line3 a, in Obb3 b, out bool inRange) => Kernels.LineBoxOverlaps(a.Origin, a.Direction, false, b.ToBox(), out inRange);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Line2 a, in Obb2 b, out bool inRange) => Kernels.LineBoxOverlaps2(a.Origin, a.Direction, false, b.ToBox2(), out inRange);
    }
}
