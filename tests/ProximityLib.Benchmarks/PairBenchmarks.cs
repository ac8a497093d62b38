using System.Numerics;
using BenchmarkDotNet.Attributes;
using D = ProximityLib.Double;
using F = ProximityLib;
using Vector3D = ProximityLib.Double.Vector3D;
using Vector2D = ProximityLib.Double.Vector2D;

namespace ProximityBenchmarks
{
    /// <summary>
    /// Every query of the library, float and double API, in three input distributions. Each invocation runs the query
    /// over 1024 prepared pairs (OperationsPerInvoke), accumulating results so nothing is optimised away; the pair is
    /// a struct type argument, so the query is called directly and can inline.
    /// </summary>
    [MemoryDiagnoser]
    [GenericTypeArguments(typeof(F3PointPoint), typeof(Vector3), typeof(Vector3))]
    [GenericTypeArguments(typeof(F3PointSegment), typeof(Vector3), typeof(F.Segment3))]
    [GenericTypeArguments(typeof(F3PointSphere), typeof(Vector3), typeof(F.Sphere))]
    [GenericTypeArguments(typeof(F3PointAabb), typeof(Vector3), typeof(F.Aabb3))]
    [GenericTypeArguments(typeof(F3PointObb), typeof(Vector3), typeof(F.Obb3))]
    [GenericTypeArguments(typeof(F3SegmentSegment), typeof(F.Segment3), typeof(F.Segment3))]
    [GenericTypeArguments(typeof(F3SegmentSphere), typeof(F.Segment3), typeof(F.Sphere))]
    [GenericTypeArguments(typeof(F3SegmentAabb), typeof(F.Segment3), typeof(F.Aabb3))]
    [GenericTypeArguments(typeof(F3SegmentObb), typeof(F.Segment3), typeof(F.Obb3))]
    [GenericTypeArguments(typeof(F3SphereSphere), typeof(F.Sphere), typeof(F.Sphere))]
    [GenericTypeArguments(typeof(F3SphereAabb), typeof(F.Sphere), typeof(F.Aabb3))]
    [GenericTypeArguments(typeof(F3SphereObb), typeof(F.Sphere), typeof(F.Obb3))]
    [GenericTypeArguments(typeof(F3AabbAabb), typeof(F.Aabb3), typeof(F.Aabb3))]
    [GenericTypeArguments(typeof(F3AabbObb), typeof(F.Aabb3), typeof(F.Obb3))]
    [GenericTypeArguments(typeof(F3ObbObb), typeof(F.Obb3), typeof(F.Obb3))]
    [GenericTypeArguments(typeof(F2PointPoint), typeof(Vector2), typeof(Vector2))]
    [GenericTypeArguments(typeof(F2PointSegment), typeof(Vector2), typeof(F.Segment2))]
    [GenericTypeArguments(typeof(F2PointSphere), typeof(Vector2), typeof(F.Circle))]
    [GenericTypeArguments(typeof(F2PointAabb), typeof(Vector2), typeof(F.Aabb2))]
    [GenericTypeArguments(typeof(F2PointObb), typeof(Vector2), typeof(F.Obb2))]
    [GenericTypeArguments(typeof(F2SegmentSegment), typeof(F.Segment2), typeof(F.Segment2))]
    [GenericTypeArguments(typeof(F2SegmentSphere), typeof(F.Segment2), typeof(F.Circle))]
    [GenericTypeArguments(typeof(F2SegmentAabb), typeof(F.Segment2), typeof(F.Aabb2))]
    [GenericTypeArguments(typeof(F2SegmentObb), typeof(F.Segment2), typeof(F.Obb2))]
    [GenericTypeArguments(typeof(F2SphereSphere), typeof(F.Circle), typeof(F.Circle))]
    [GenericTypeArguments(typeof(F2SphereAabb), typeof(F.Circle), typeof(F.Aabb2))]
    [GenericTypeArguments(typeof(F2SphereObb), typeof(F.Circle), typeof(F.Obb2))]
    [GenericTypeArguments(typeof(F2AabbAabb), typeof(F.Aabb2), typeof(F.Aabb2))]
    [GenericTypeArguments(typeof(F2AabbObb), typeof(F.Aabb2), typeof(F.Obb2))]
    [GenericTypeArguments(typeof(F2ObbObb), typeof(F.Obb2), typeof(F.Obb2))]
    [GenericTypeArguments(typeof(D3PointPoint), typeof(D.Vector3D), typeof(D.Vector3D))]
    [GenericTypeArguments(typeof(D3PointSegment), typeof(D.Vector3D), typeof(D.Segment3))]
    [GenericTypeArguments(typeof(D3PointSphere), typeof(D.Vector3D), typeof(D.Sphere))]
    [GenericTypeArguments(typeof(D3PointAabb), typeof(D.Vector3D), typeof(D.Aabb3))]
    [GenericTypeArguments(typeof(D3PointObb), typeof(D.Vector3D), typeof(D.Obb3))]
    [GenericTypeArguments(typeof(D3SegmentSegment), typeof(D.Segment3), typeof(D.Segment3))]
    [GenericTypeArguments(typeof(D3SegmentSphere), typeof(D.Segment3), typeof(D.Sphere))]
    [GenericTypeArguments(typeof(D3SegmentAabb), typeof(D.Segment3), typeof(D.Aabb3))]
    [GenericTypeArguments(typeof(D3SegmentObb), typeof(D.Segment3), typeof(D.Obb3))]
    [GenericTypeArguments(typeof(D3SphereSphere), typeof(D.Sphere), typeof(D.Sphere))]
    [GenericTypeArguments(typeof(D3SphereAabb), typeof(D.Sphere), typeof(D.Aabb3))]
    [GenericTypeArguments(typeof(D3SphereObb), typeof(D.Sphere), typeof(D.Obb3))]
    [GenericTypeArguments(typeof(D3AabbAabb), typeof(D.Aabb3), typeof(D.Aabb3))]
    [GenericTypeArguments(typeof(D3AabbObb), typeof(D.Aabb3), typeof(D.Obb3))]
    [GenericTypeArguments(typeof(D3ObbObb), typeof(D.Obb3), typeof(D.Obb3))]
    [GenericTypeArguments(typeof(D2PointPoint), typeof(D.Vector2D), typeof(D.Vector2D))]
    [GenericTypeArguments(typeof(D2PointSegment), typeof(D.Vector2D), typeof(D.Segment2))]
    [GenericTypeArguments(typeof(D2PointSphere), typeof(D.Vector2D), typeof(D.Circle))]
    [GenericTypeArguments(typeof(D2PointAabb), typeof(D.Vector2D), typeof(D.Aabb2))]
    [GenericTypeArguments(typeof(D2PointObb), typeof(D.Vector2D), typeof(D.Obb2))]
    [GenericTypeArguments(typeof(D2SegmentSegment), typeof(D.Segment2), typeof(D.Segment2))]
    [GenericTypeArguments(typeof(D2SegmentSphere), typeof(D.Segment2), typeof(D.Circle))]
    [GenericTypeArguments(typeof(D2SegmentAabb), typeof(D.Segment2), typeof(D.Aabb2))]
    [GenericTypeArguments(typeof(D2SegmentObb), typeof(D.Segment2), typeof(D.Obb2))]
    [GenericTypeArguments(typeof(D2SphereSphere), typeof(D.Circle), typeof(D.Circle))]
    [GenericTypeArguments(typeof(D2SphereAabb), typeof(D.Circle), typeof(D.Aabb2))]
    [GenericTypeArguments(typeof(D2SphereObb), typeof(D.Circle), typeof(D.Obb2))]
    [GenericTypeArguments(typeof(D2AabbAabb), typeof(D.Aabb2), typeof(D.Aabb2))]
    [GenericTypeArguments(typeof(D2AabbObb), typeof(D.Aabb2), typeof(D.Obb2))]
    [GenericTypeArguments(typeof(D2ObbObb), typeof(D.Obb2), typeof(D.Obb2))]
    public class PairBenchmarks<TPair, TA, TB> where TPair : struct, IPair<TA, TB>
    {
        private TA[] _a = null!;
        private TB[] _b = null!;

        [ParamsSource(nameof(DistributionNames))]
        public string Distribution { get; set; } = "mixed";

        public static string[] DistributionNames => Inputs.Distributions;

        [GlobalSetup]
        public void Setup()
        {
            (_a, _b) = Inputs.Typed<TA, TB>(TPair.Query, Distribution, TPair.IsFloat);
            TierUp.Run(() => Distance(), () => Overlaps());
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count)]
        public double Distance()
        {
            double sum = 0;
            var a = _a;
            var b = _b;
            for (int i = 0; i < a.Length; i++) sum += TPair.Distance(a[i], b[i]);
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count)]
        public int Overlaps()
        {
            int count = 0;
            var a = _a;
            var b = _b;
            for (int i = 0; i < a.Length; i++) if (TPair.Overlaps(a[i], b[i])) count++;
            return count;
        }
    }
}
