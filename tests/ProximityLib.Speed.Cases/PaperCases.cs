using ProximityReference;
using static ProximitySpeed.Source;
using D = ProximityLib.Double;

namespace ProximitySpeed
{
    // The paper's formulas as printed (tests/ProximityLib.Reference/PaperFormulas.cs), which docs/accuracy.md measures:
    // the plot places them by speed and error beside the library.
    [Case(Paper, Precision.Double, "3D point–segment")] public readonly struct PaperPointSegment : IDistance<D.Vector3D, D.Segment3> { public double Distance(in D.Vector3D a, in D.Segment3 b) => PaperFormulas.PointSegment(a, b.Start, b.End); }
    [Case(Paper, Precision.Double, "3D segment–segment")] public readonly struct PaperSegmentSegment : IDistance<D.Segment3, D.Segment3> { public double Distance(in D.Segment3 a, in D.Segment3 b) => PaperFormulas.SegmentSegment(a.Start, a.End, b.Start, b.End); }
    [Case(Paper, Precision.Double, "2D segment–segment")] public readonly struct PaperSegmentSegment2 : IDistance<D.Segment2, D.Segment2> { public double Distance(in D.Segment2 a, in D.Segment2 b) => PaperFormulas.SegmentSegment2(a.Start, a.End, b.Start, b.End); }
    [Case(Paper, Precision.Double, "3D OBB–OBB")] public readonly struct PaperObbObb : IOverlap<D.Obb3, D.Obb3> { public bool Overlaps(in D.Obb3 a, in D.Obb3 b) => PaperFormulas.ObbObbOverlaps(a, b); }
}
