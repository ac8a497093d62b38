// Copied from src/ProximityLib/Batch/Workers.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using System.Threading;

namespace ProximityLib.Batch
{
    /// <summary>
    /// Runs a large batch on several cores: the lanes are cut into chunks that the calling thread and thread-pool helpers
    /// claim one at a time, so a helper that starts late (a busy pool, a shared machine) only takes fewer chunks and the
    /// call never waits for a helper that has not started. Every lane runs the same kernel code as on one thread, so the
    /// results are the same bits.
    /// </summary>
    internal static class Workers
    {
        /// <summary>
        /// Batches below this many lanes stay on the calling thread. Measured on two cores (docs/design.md): at 16k lanes
        /// the cheap kernels ran slower split even with a core free, at 64k none did and the heavy ones gained.
        /// </summary>
        internal const int Threshold = 1 << 16;

        /// <summary>
        /// Lanes per claim: a multiple of four <see cref="Vector{T}"/> widths up to 1024 lanes (the verdicts' narrowing
        /// step), small enough that the last claims balance the threads, large enough that claiming costs nothing.
        /// </summary>
        internal const int ChunkLanes = 4096;

        /// <summary>The cores a call may use at most; tests raise it to split batches on any machine.</summary>
        internal static int Cores = Environment.ProcessorCount;

        /// <summary>The most threads, the caller included, that one call uses (<see cref="BatchQuery.MaxDegreeOfParallelism"/>).</summary>
        internal static int MaxThreads = Environment.ProcessorCount;

        /// <summary>Computes result[0..count) on several threads and returns true, or returns false for the caller to run it alone.</summary>
        public static unsafe bool Values<TK>(TK kernel, int count, Span<float> result) where TK : struct, IKernel
        {
            int threads = Threads(count);
            if (threads < 2) return false;
            // The caller waits for every helper that entered before it returns, so the pinned span outlives their use of it.
            fixed (float* values = result) Job<TK>.Run(kernel, count, values, null, threads);
            return true;
        }

        /// <summary>Computes the verdicts result[0..count) on several threads and returns true, or returns false for the caller to run it alone.</summary>
        public static unsafe bool NonPositive<TK>(TK kernel, int count, Span<bool> result) where TK : struct, IKernel
        {
            int threads = Threads(count);
            if (threads < 2) return false;
            fixed (bool* verdicts = result) Job<TK>.Run(kernel, count, null, verdicts, threads);
            return true;
        }

        private static int Threads(int count)
        {
            if (count < Threshold) return 1;
            int chunks = (int)(((long)count + ChunkLanes - 1) / ChunkLanes);
            return Math.Min(Math.Min(MaxThreads, Cores), chunks);
        }

        /// <summary>
        /// One call's shared state, kept per calling thread and kernel type so that a call allocates nothing once warm. A
        /// helper queued by an earlier call may start during a later call of the same thread: it then helps that call
        /// (the fields are written before the job opens, and that call counts it as one of its helpers), or finds the
        /// job closed and leaves.
        /// </summary>
        private sealed unsafe class Job<TK>
#if NET
            : IThreadPoolWorkItem
#endif
            where TK : struct, IKernel
        {
            [ThreadStatic] private static Job<TK>? _mine;

            /// <summary>Helpers inside the open job, or <see cref="Closed"/>: entering and closing are one compare-exchange each, so no helper enters a closed job.</summary>
            private int _inside = Closed;
            private const int Closed = -1;

            /// <summary>Pulsed when the last helper inside leaves, for a caller that found a helper still working.</summary>
            private readonly object _gate = new object();

            /// <summary>Helpers queued and not started yet: a call queues only as many more as its threads need, so short calls on a busy pool do not pile up work items.</summary>
            private int _queued;

            private int _nextChunk;
            private TK _kernel;
            private int _count;
            private float* _values;
            private bool* _verdicts;

            public static void Run(TK kernel, int count, float* values, bool* verdicts, int threads)
            {
                var job = _mine ??= new Job<TK>();
                job._kernel = kernel;
                job._count = count;
                job._values = values;
                job._verdicts = verdicts;
                job._nextChunk = 0;
                Interlocked.Exchange(ref job._inside, 0);
                for (int t = Volatile.Read(ref job._queued) + 1; t < threads; t++)
                {
                    Interlocked.Increment(ref job._queued);
                    job.Queue();
                }
                job.Work();
                job.Close();
                job._kernel = default; // the sets are the caller's: do not keep them alive
                job._values = null;
                job._verdicts = null;
            }

#if NET
            private void Queue() => ThreadPool.UnsafeQueueUserWorkItem(this, preferLocal: false);

            void IThreadPoolWorkItem.Execute() => Help();
#else
            private static readonly WaitCallback HelpCallback = job => ((Job<TK>)job!).Help();

            // netstandard2.1 has no IThreadPoolWorkItem: the pool wraps the callback in a small object per helper.
            private void Queue() => ThreadPool.UnsafeQueueUserWorkItem(HelpCallback, this);
#endif

            /// <summary>
            /// Closes the job once no helper is inside (each finishes at most the one chunk it claimed): spinning briefly,
            /// then blocking, since a helper descheduled on a busy machine can take milliseconds. A helper leaving takes
            /// the gate before pulsing, so it cannot pulse between the caller's check and its wait.
            /// </summary>
            private void Close()
            {
                var spin = new SpinWait();
                while (!spin.NextSpinWillYield)
                {
                    if (Interlocked.CompareExchange(ref _inside, Closed, 0) == 0) return;
                    spin.SpinOnce();
                }
                lock (_gate)
                {
                    while (Interlocked.CompareExchange(ref _inside, Closed, 0) != 0) Monitor.Wait(_gate);
                }
            }

            private void Help()
            {
                Interlocked.Decrement(ref _queued);
                int inside;
                do
                {
                    inside = Volatile.Read(ref _inside);
                    if (inside == Closed) return;
                }
                while (Interlocked.CompareExchange(ref _inside, inside + 1, inside) != inside);
                Work();
                if (Interlocked.Decrement(ref _inside) == 0)
                {
                    lock (_gate) Monitor.Pulse(_gate);
                }
            }

            private void Work()
            {
                var kernel = _kernel;
                int count = _count;
                float* values = _values;
                bool* verdicts = _verdicts;
                int chunks = (int)(((long)count + ChunkLanes - 1) / ChunkLanes);
                int chunk;
                while ((chunk = Interlocked.Increment(ref _nextChunk) - 1) < chunks)
                {
                    int start = chunk * ChunkLanes;
                    int end = (int)Math.Min((long)start + ChunkLanes, count);
                    if (values != null) Runner.Values(kernel, start, end, new Span<float>(values, count));
                    else Runner.NonPositive(kernel, start, end, new Span<bool>(verdicts, count));
                }
            }
        }
    }
}
