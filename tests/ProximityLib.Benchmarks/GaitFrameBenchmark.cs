using BenchmarkDotNet.Attributes;
using ProximityLib.Scenes.Gait;

namespace ProximityBenchmarks
{
    /// <summary>One frame of the gait scene: placing the foot and its 6 queries (3 distances, 3 overlaps), over a whole cycle.</summary>
    [MemoryDiagnoser]
    public class GaitFrameBenchmark
    {
        private const int Frames = 200;
        private readonly GaitSimulation _sim = new GaitSimulation(frames: Frames);

        // The report keys every row by input distribution; a gait cycle mixes apart and touching parts.
        [ParamsSource(nameof(DistributionNames))]
        public string Distribution { get; set; } = "mixed";

        public static string[] DistributionNames => new[] { "mixed" };

        [Benchmark(OperationsPerInvoke = Frames, Description = "gait frame | pose + 3 distance + 3 overlap queries")]
        public float Frame()
        {
            float sum = 0;
            for (int k = 0; k < Frames; k++)
            {
                var f = _sim.Frame(k);
                sum += f.Distances.X + f.Distances.Y + f.Distances.Z + (f.ToeContact ? 1 : 0);
            }
            return sum;
        }
    }
}
