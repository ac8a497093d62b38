// Copied from src/ProximityLib/Pairs/SegmentSegment.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D): never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint). Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        public static DistanceResult3 Between(Segment3 a, Segment3 b) => Kernels.SegmentSegment(a.Start, a.End, b.Start, b.End);
        /// <summary>Closest distance between a segment and a segment (2D): never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint). Algorithm: interior stationary point with the Lagrange-identity determinant, else the four endpoint–segment candidates (Eberly, robust segment distance; replaces paper Eq. 13–15).</summary>
        public static DistanceResult2 Between(Segment2 a, Segment2 b) => (Kernels.SegmentSegment(a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3())).To2();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Segment3 a, Segment3 b) => Kernels.SegmentSegmentCore(a.Start, a.End, b.Start, b.End, out _, out _) == 0;
        /// <summary>Whether a segment and a segment (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Segment2 a, Segment2 b) => Kernels.SegmentSegmentCore(a.Start.To3(), a.End.To3(), b.Start.To3(), b.End.To3(), out _, out _) == 0;
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a segment and a segment (3D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint).</summary>
        public static DistanceResult3 Between(Segment3 a, Segment3 b) => new DistanceResult3(Dbl.ClosestDistance.Between(a.Inner, b.Inner));
        /// <summary>Closest distance between a segment and a segment (2D), computed in double: never negative; for parallel overlapping segments one of the closest pairs (the first found at an endpoint).</summary>
        public static DistanceResult2 Between(Segment2 a, Segment2 b) => new DistanceResult2(Dbl.ClosestDistance.Between(a.Inner, b.Inner));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a segment and a segment (3D) touch or overlap.</summary>
        public static bool Overlaps(Segment3 a, Segment3 b) => Dbl.ProximityQuery.Overlaps(a.Inner, b.Inner);
        /// <summary>Whether a segment and a segment (2D) touch or overlap.</summary>
        public static bool Overlaps(Segment2 a, Segment2 b) => Dbl.ProximityQuery.Overlaps(a.Inner, b.Inner);
    }
}
