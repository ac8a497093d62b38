using System;
using System.Numerics;
using System.Threading;
using NUnit.Framework;
using ProximityLib.Batch;

namespace ProximityTests.Batch
{
    /// <summary>
    /// The multi-core batch: every batch query split over threads gives the one-thread bits (distances) and verdicts, on
    /// counts around the threshold and not multiples of the vector width; every lane is computed once, in chunks that
    /// start on a vector boundary, helpers really take part, and a warm call allocates nothing on the calling thread.
    /// Splitting is forced with four "cores" and threads, so it is exercised on any machine.
    /// </summary>
    public class WorkersTests
    {
        /// <summary>Shapes for every test, sliced to each count (building them is the slow part).</summary>
        private static readonly Lazy<ScalarLanesTests.Sets> Shapes = new Lazy<ScalarLanesTests.Sets>(() => new ScalarLanesTests.Sets(MaxCount, 5));
        private const int MaxCount = 3 * Workers.ChunkLanes * 7 + 5;

        private int _savedCores, _savedThreads;
        private bool _savedVectorized;

        [SetUp]
        public void Save()
        {
            _savedCores = Workers.Cores;
            _savedThreads = BatchQuery.MaxDegreeOfParallelism;
            _savedVectorized = Runner.Vectorized;
            Workers.Cores = 4;
            BatchQuery.MaxDegreeOfParallelism = 4;
        }

        [TearDown]
        public void Restore()
        {
            Workers.Cores = _savedCores;
            BatchQuery.MaxDegreeOfParallelism = _savedThreads;
            Runner.Vectorized = _savedVectorized;
        }

        private static T[] Run<T>(int threads, int n, Action<T[]> query)
        {
            BatchQuery.MaxDegreeOfParallelism = threads;
            var result = new T[n + 1];
            query(result);
            return result;
        }

        private static void SameBits(string name, int n, Action<float[]> query)
        {
            var alone = Run(1, n, query);
            var split = Run(4, n, query);
            // NaN lanes included (the sets reach beyond the batch range): the same code gives the same NaN.
            int i = 0;
            while (i <= n && BitConverter.SingleToInt32Bits(split[i]) == BitConverter.SingleToInt32Bits(alone[i])) i++;
            Assert.That(i, Is.EqualTo(n + 1), () => $"{name}, lane {i} of {n}: split {split[i]:R}, one thread {alone[i]:R}");
        }

        private static void SameVerdicts(string name, int n, Action<bool[]> query)
        {
            var alone = Run<bool>(1, n, query);
            var split = Run<bool>(4, n, query);
            int i = 0;
            while (i <= n && split[i] == alone[i]) i++;
            Assert.That(i, Is.EqualTo(n + 1), () => $"{name}, lane {i} of {n}: split {split[i]}, one thread {alone[i]}");
        }

        [TestCase(Workers.Threshold - 1, true), TestCase(Workers.Threshold, true), TestCase(Workers.Threshold + 1, true),
         TestCase(70001, true), TestCase(70001, false), TestCase(MaxCount, true)]
        public void SplitRunsGiveTheOneThreadResults(int n, bool vectorized)
        {
            Runner.Vectorized = vectorized;
            Shapes.Value.EachQuery(n, n / 3, (name, query) => SameBits(name, n, query), (name, query) => SameVerdicts(name, n, query));
        }

        [Test]
        public void SplitsFromTheThresholdWhenMoreThanOneThreadIsAllowed()
        {
            var kernel = new Recorder(Workers.Threshold, -1);
            Assert.That(Workers.Values(kernel, Workers.Threshold - 1, new float[Workers.Threshold]), Is.False);
            Assert.That(Workers.NonPositive(kernel, Workers.Threshold - 1, new bool[Workers.Threshold]), Is.False);
            Assert.That(Workers.Values(kernel, Workers.Threshold, new float[Workers.Threshold]), Is.True);
            Assert.That(Workers.NonPositive(kernel, Workers.Threshold, new bool[Workers.Threshold]), Is.True);
            BatchQuery.MaxDegreeOfParallelism = 1;
            Assert.That(Workers.Values(kernel, Workers.Threshold, new float[Workers.Threshold]), Is.False);
            BatchQuery.MaxDegreeOfParallelism = 2;
            Workers.Cores = 1;
            Assert.That(Workers.NonPositive(kernel, Workers.Threshold, new bool[Workers.Threshold]), Is.False);
        }

        [TestCase(true), TestCase(false)]
        public void EveryLaneOnceInVectorAlignedChunksWithHelpersTakingPart(bool vectorized)
        {
            Runner.Vectorized = vectorized;
            const int n = Workers.Threshold * 2 + 13;
            var kernel = new Recorder(n, Environment.CurrentManagedThreadId);
            var values = new float[n + 1];
            values[n] = 42;
            Runner.Values(kernel, n, values);
            for (int i = 0; i < n; i++)
            {
                if (kernel.Hits[i] != 1) Assert.Fail($"lane {i} computed {kernel.Hits[i]} times");
                if (values[i] != i) Assert.Fail($"lane {i} holds {values[i]}");
            }
            Assert.That(values[n], Is.EqualTo(42), "a lane past the count");
            Assert.That(kernel.Misaligned[0], Is.Zero, "vector computations not starting on a vector boundary");
            Assert.That(kernel.HelperLanes[0], Is.GreaterThan(0), "lanes computed by a helper thread");

            Array.Clear(kernel.Hits, 0, kernel.Hits.Length);
            kernel.HelperLanes[0] = 0;
            var verdicts = new bool[n];
            Runner.NonPositive(kernel, n, verdicts);
            for (int i = 0; i < n; i++)
            {
                if (kernel.Hits[i] != 1) Assert.Fail($"verdict {i} computed {kernel.Hits[i]} times");
                if (verdicts[i] != (i == 0)) Assert.Fail($"verdict {i} is {verdicts[i]}");
            }
            Assert.That(kernel.HelperLanes[0], Is.GreaterThan(0), "verdicts computed by a helper thread");
        }

        [Test]
        public void AWarmSplitCallAllocatesNothingOnTheCallingThread()
        {
            var s = Shapes.Value;
            var obbs = new ObbSet(s.Obbs);
            var obbs2 = new ObbSet(s.Obbs2);
            var spheres = new SphereSet(s.Spheres);
            var values = new float[MaxCount];
            var verdicts = new bool[MaxCount];
            BatchQuery.MaxDegreeOfParallelism = 4;
            BatchQuery.Overlaps(obbs, obbs2, verdicts);
            BatchQuery.Distances(s.Spheres[0], spheres, values);
            // The least over a few warm attempts: queuing a helper on a busy pool can grow the pool's global queue by a
            // segment (7,744 bytes once in a CI run while other tests ran), an allocation of the runtime's that a later
            // call does not repeat; an allocation of ours would recur on every attempt.
            long least = long.MaxValue;
            for (int attempt = 0; attempt < 5 && least > 0; attempt++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                BatchQuery.Overlaps(obbs, obbs2, verdicts);
                BatchQuery.Distances(s.Spheres[0], spheres, values);
                least = Math.Min(least, GC.GetAllocatedBytesForCurrentThread() - before);
            }
            Assert.That(least, Is.EqualTo(0));
        }

        [Test]
        public void BadArgumentsAreRefusedBeforeTheSplit()
        {
            var s = Shapes.Value;
            var spheres = new SphereSet(s.Spheres);
            var fewer = new SphereSet(s.Spheres2.AsSpan(1));
            Assert.That(() => BatchQuery.Distances(spheres, fewer, new float[MaxCount]), Throws.ArgumentException.With.Property("ParamName").EqualTo("b"));
            Assert.That(() => BatchQuery.Overlaps(s.Spheres[0], spheres, new bool[MaxCount - 1]), Throws.ArgumentException.With.Property("ParamName").EqualTo("result"));
            Assert.That(() => BatchQuery.MaxDegreeOfParallelism = 0, Throws.ArgumentException.With.Property("ParamName").EqualTo("value"));
        }

        /// <summary>
        /// A kernel whose lane i is i − 0 (so only lane 0 is ≤ 0) and which records, across threads, how often each lane
        /// was computed, vector computations off a vector boundary, and lanes computed off the calling thread. The caller
        /// waits in its first chunk (up to 10 s) until a helper has computed something, so a helper must take part.
        /// </summary>
        private readonly struct Recorder : IKernel
        {
            public readonly int[] Hits, Misaligned, HelperLanes;
            private readonly int _caller;

            public Recorder(int n, int caller)
            {
                Hits = new int[n + Vector<float>.Count];
                Misaligned = new int[1];
                HelperLanes = new int[1];
                _caller = caller;
            }

            public Vector<float> Compute(int i)
            {
                if (i % Vector<float>.Count != 0) Interlocked.Increment(ref Misaligned[0]);
                for (int k = 0; k < Vector<float>.Count; k++) Record(i + k);
                Span<float> lanes = stackalloc float[Vector<float>.Count];
                for (int k = 0; k < lanes.Length; k++) lanes[k] = i + k;
                return new Vector<float>(lanes);
            }

            public float Lane(int i)
            {
                Record(i);
                return i;
            }

            public void Values(int start, int end, Span<float> result)
            {
                for (int i = start; i < end; i++) result[i] = Lane(i);
            }

            public void Verdicts(int start, int end, Span<bool> result)
            {
                for (int i = start; i < end; i++) result[i] = Lane(i) <= 0;
            }

            private void Record(int i)
            {
                Interlocked.Increment(ref Hits[i]);
                if (_caller < 0) return;
                if (Environment.CurrentManagedThreadId != _caller)
                {
                    Interlocked.Increment(ref HelperLanes[0]);
                    return;
                }
                if (i != 0) return;
                var wait = System.Diagnostics.Stopwatch.StartNew();
                while (Volatile.Read(ref HelperLanes[0]) == 0 && wait.ElapsedMilliseconds < 10000) Thread.Yield();
            }
        }
    }
}
