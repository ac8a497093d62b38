using System;
using System.Diagnostics;
using System.Threading;

namespace ProximityBenchmarks
{
    /// <summary>
    /// Brings the code a benchmark calls to its steady state (tier-1 with dynamic PGO) before BenchmarkDotNet measures:
    /// in-process runs JIT new code for every case, and the runtime promotes hot methods only after a quiet spell with
    /// no new tier-0 code, which short warmups never give it.
    /// </summary>
    public static class TierUp
    {
        public static void Run(params Action[] workloads)
        {
            Spin(workloads, 60);
            Thread.Sleep(250);
            Spin(workloads, 30);
            Thread.Sleep(150);
        }

        private static void Spin(Action[] workloads, int milliseconds)
        {
            var clock = Stopwatch.StartNew();
            while (clock.ElapsedMilliseconds < milliseconds)
                foreach (var w in workloads) w();
        }
    }
}
