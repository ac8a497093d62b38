using System.Linq;
using System.Numerics;
using BenchmarkDotNet.Attributes;
using ProximityLib.Batch;
using F = ProximityLib;

namespace ProximityBenchmarks
{
    /// <summary>The SIMD batch queries, paired, data in cache: time per pair, beside the scalar float query in the report.</summary>
    [MemoryDiagnoser]
    public class BatchBenchmarks
    {
        [ParamsSource(nameof(DistributionNames))]
        public string Distribution { get; set; } = "mixed";

        public static string[] DistributionNames => Inputs.Distributions;

        private SphereSet _spheres = null!, _spheresB = null!, _spheresAabb = null!, _spheresObb = null!;
        private PointSet _points = null!;
        private AabbSet _aabbsP = null!, _aabbsS = null!, _aabbsA = null!, _aabbsB = null!;
        private ObbSet _obbs = null!, _obbsA = null!, _obbsB = null!;
        private SegmentSet _segA = null!, _segB = null!;
        private readonly float[] _distances = new float[Inputs.Count];
        private readonly bool[] _verdicts = new bool[Inputs.Count];

        [GlobalSetup]
        public void Setup()
        {
            var (s1, s2) = Inputs.Typed<F.Sphere, F.Sphere>("3D sphere–sphere", Distribution, true);
            _spheres = new SphereSet(s1); _spheresB = new SphereSet(s2);
            var (p, pb) = Inputs.Typed<Vector3, F.Aabb3>("3D point–AABB", Distribution, true);
            _points = new PointSet(p); _aabbsP = new AabbSet(pb);
            var (sa, sab) = Inputs.Typed<F.Sphere, F.Aabb3>("3D sphere–AABB", Distribution, true);
            _spheresAabb = new SphereSet(sa); _aabbsS = new AabbSet(sab);
            var (a, b) = Inputs.Typed<F.Aabb3, F.Aabb3>("3D AABB–AABB", Distribution, true);
            _aabbsA = new AabbSet(a); _aabbsB = new AabbSet(b);
            var (so, o) = Inputs.Typed<F.Sphere, F.Obb3>("3D sphere–OBB", Distribution, true);
            _spheresObb = new SphereSet(so); _obbs = new ObbSet(o);
            var (sg1, sg2) = Inputs.Typed<F.Segment3, F.Segment3>("3D segment–segment", Distribution, true);
            _segA = new SegmentSet(sg1); _segB = new SegmentSet(sg2);
            var (o1, o2) = Inputs.Typed<F.Obb3, F.Obb3>("3D OBB–OBB", Distribution, true);
            _obbsA = new ObbSet(o1); _obbsB = new ObbSet(o2);
            TierUp.Run(() => SphereSphere(), () => PointAabb(), () => SphereAabb(), () => AabbAabb(), () => SphereObb(),
                () => SegmentSegment(), () => ObbObb());
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–sphere distance | ours, batch")]
        public float SphereSphere() { BatchQuery.Distances(_spheres, _spheresB, _distances); return _distances[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D point–AABB distance | ours, batch")]
        public float PointAabb() { BatchQuery.Distances(_points, _aabbsP, _distances); return _distances[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–AABB distance | ours, batch")]
        public float SphereAabb() { BatchQuery.Distances(_spheresAabb, _aabbsS, _distances); return _distances[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D AABB–AABB overlap | ours, batch")]
        public bool AabbAabb() { BatchQuery.Overlaps(_aabbsA, _aabbsB, _verdicts); return _verdicts[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–OBB distance | ours, batch")]
        public float SphereObb() { BatchQuery.Distances(_spheresObb, _obbs, _distances); return _distances[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D segment–segment distance | ours, batch")]
        public float SegmentSegment() { BatchQuery.Distances(_segA, _segB, _distances); return _distances[7]; }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D OBB–OBB overlap | ours, batch")]
        public bool ObbObb() { BatchQuery.Overlaps(_obbsA, _obbsB, _verdicts); return _verdicts[7]; }
    }
}
