using System.Linq;
using System.Numerics;
using BenchmarkDotNet.Attributes;
using ProximityReference;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximityBenchmarks
{
    /// <summary>
    /// What a user would write without the library, in the same run: the paper's formulas as printed (double) and the
    /// System.Numerics one-liners (float). Each method names the query it stands beside in the report.
    /// </summary>
    [MemoryDiagnoser]
    public class Baselines
    {
        [ParamsSource(nameof(DistributionNames))]
        public string Distribution { get; set; } = "mixed";

        public static string[] DistributionNames => Inputs.Distributions;

        // Baselines read plain arrays, as hand-written code would: no shape types, no conversions.
        private D.Vector3D[] _points = null!;
        private D.Segment3[] _pointSegments = null!, _segments = null!, _segmentsB = null!;
        private D.Segment2[] _segments2 = null!, _segments2B = null!;
        private D.Obb3[] _obbs = null!, _obbsB = null!;
        private Vector3[] _ca = null!, _cb = null!, _fpoints = null!, _min = null!, _max = null!, _minB = null!, _maxB = null!;
        private Vector3[] _sc = null!, _sMin = null!, _sMax = null!;
        private float[] _ra = null!, _rb = null!, _sr = null!;

        [GlobalSetup]
        public void Setup()
        {
            (_points, _pointSegments) = Inputs.Typed<D.Vector3D, D.Segment3>("3D point–segment", Distribution, false);
            (_segments, _segmentsB) = Inputs.Typed<D.Segment3, D.Segment3>("3D segment–segment", Distribution, false);
            (_segments2, _segments2B) = Inputs.Typed<D.Segment2, D.Segment2>("2D segment–segment", Distribution, false);
            (_obbs, _obbsB) = Inputs.Typed<D.Obb3, D.Obb3>("3D OBB–OBB", Distribution, false);
            var (sa, sb) = Inputs.Typed<F.Sphere, F.Sphere>("3D sphere–sphere", Distribution, true);
            _ca = sa.Select(x => x.Center).ToArray(); _ra = sa.Select(x => x.Radius).ToArray();
            _cb = sb.Select(x => x.Center).ToArray(); _rb = sb.Select(x => x.Radius).ToArray();
            var (p, box) = Inputs.Typed<Vector3, F.Aabb3>("3D point–AABB", Distribution, true);
            _fpoints = p; _min = box.Select(x => x.Min).ToArray(); _max = box.Select(x => x.Max).ToArray();
            var (ba, bb) = Inputs.Typed<F.Aabb3, F.Aabb3>("3D AABB–AABB", Distribution, true);
            _minB = bb.Select(x => x.Min).ToArray(); _maxB = bb.Select(x => x.Max).ToArray();
            _boxA = (ba.Select(x => x.Min).ToArray(), ba.Select(x => x.Max).ToArray());
            var (ss, sbox) = Inputs.Typed<F.Sphere, F.Aabb3>("3D sphere–AABB", Distribution, true);
            _sc = ss.Select(x => x.Center).ToArray(); _sr = ss.Select(x => x.Radius).ToArray();
            _sMin = sbox.Select(x => x.Min).ToArray(); _sMax = sbox.Select(x => x.Max).ToArray();
            TierUp.Run(() => PaperPointSegment(), () => PaperSegmentSegment(), () => PaperSegmentSegment2(), () => PaperObbObb(),
                () => OneLinerSphereSphere(), () => OneLinerSphereSphereOverlap(), () => OneLinerPointAabb(), () => PaperAabbAabb(),
                () => PaperSphereAabb());
        }

        private (Vector3[] Min, Vector3[] Max) _boxA;

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D point–segment distance | paper Eq. 9–11 (double)")]
        public double PaperPointSegment()
        {
            double sum = 0;
            var p = _points;
            var s = _pointSegments;
            for (int i = 0; i < p.Length; i++) sum += PaperFormulas.PointSegment(p[i], s[i].Start, s[i].End);
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D segment–segment distance | paper Eq. 13, normal equations (double)")]
        public double PaperSegmentSegment()
        {
            double sum = 0;
            var a = _segments;
            var b = _segmentsB;
            for (int i = 0; i < a.Length; i++) sum += PaperFormulas.SegmentSegment(a[i].Start, a[i].End, b[i].Start, b[i].End);
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "2D segment–segment distance | paper Eq. 14–15 (double)")]
        public double PaperSegmentSegment2()
        {
            double sum = 0;
            var a = _segments2;
            var b = _segments2B;
            for (int i = 0; i < a.Length; i++) sum += PaperFormulas.SegmentSegment2(a[i].Start, a[i].End, b[i].Start, b[i].End);
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D OBB–OBB overlap | SAT without ε, paper Eq. 19–20 (double)")]
        public int PaperObbObb()
        {
            int count = 0;
            var a = _obbs;
            var b = _obbsB;
            for (int i = 0; i < a.Length; i++) if (PaperFormulas.ObbObbOverlaps(a[i], b[i])) count++;
            return count;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–sphere distance | Vector3.Distance − ra − rb (float)")]
        public float OneLinerSphereSphere()
        {
            float sum = 0;
            for (int i = 0; i < _ca.Length; i++) sum += Vector3.Distance(_ca[i], _cb[i]) - _ra[i] - _rb[i];
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–sphere overlap | DistanceSquared ≤ (ra + rb)², paper Eq. 24 (float)")]
        public int OneLinerSphereSphereOverlap()
        {
            int count = 0;
            for (int i = 0; i < _ca.Length; i++)
            {
                float r = _ra[i] + _rb[i];
                if (Vector3.DistanceSquared(_ca[i], _cb[i]) <= r * r) count++;
            }
            return count;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D point–AABB distance | Vector3.Distance(p, Vector3.Clamp(p, min, max)) (float)")]
        public float OneLinerPointAabb()
        {
            float sum = 0;
            var p = _fpoints;
            for (int i = 0; i < p.Length; i++) sum += Vector3.Distance(p[i], Vector3.Clamp(p[i], _min[i], _max[i]));
            return sum;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D AABB–AABB overlap | interval tests, paper Eq. 18 (float)")]
        public int PaperAabbAabb()
        {
            int count = 0;
            var (minA, maxA) = _boxA;
            for (int i = 0; i < minA.Length; i++)
            {
                Vector3 amin = minA[i], amax = maxA[i], bmin = _minB[i], bmax = _maxB[i];
                if (amin.X <= bmax.X && amax.X >= bmin.X && amin.Y <= bmax.Y && amax.Y >= bmin.Y && amin.Z <= bmax.Z && amax.Z >= bmin.Z) count++;
            }
            return count;
        }

        [Benchmark(OperationsPerInvoke = Inputs.Count, Description = "3D sphere–AABB overlap | clamp and DistanceSquared ≤ r², paper Eq. 23 (float)")]
        public int PaperSphereAabb()
        {
            int count = 0;
            for (int i = 0; i < _sc.Length; i++)
            {
                var c = _sc[i];
                if (Vector3.DistanceSquared(c, Vector3.Clamp(c, _sMin[i], _sMax[i])) <= _sr[i] * _sr[i]) count++;
            }
            return count;
        }
    }
}
