using System;
using System.Diagnostics;
using System.Runtime.InteropServices;

namespace ProximitySpeed
{
    /// <summary>
    /// The probe's clock: the CPU time of the calling thread (Linux, clock_gettime(CLOCK_THREAD_CPUTIME_ID)), so time
    /// the thread spends descheduled while other processes run is not counted; elsewhere the wall clock (Stopwatch).
    /// </summary>
    internal static class Clock
    {
        private const int ThreadCpuTimeId = 3; // CLOCK_THREAD_CPUTIME_ID in Linux's <time.h>

        private struct Timespec
        {
            public long Seconds;
            public long Nanoseconds;
        }

        [DllImport("libc", EntryPoint = "clock_gettime")]
        private static extern int ClockGetTime(int clock, out Timespec time);

        /// <summary>True when the thread's CPU time is available (otherwise the wall clock is used).</summary>
        public static readonly bool ThreadCpu = Probe();

        /// <summary>"thread CPU time" or "wall clock".</summary>
        public static string Kind => ThreadCpu ? "thread CPU time" : "wall clock";

        private static bool Probe()
        {
            if (!RuntimeInformation.IsOSPlatform(OSPlatform.Linux)) return false;
            try { return ClockGetTime(ThreadCpuTimeId, out _) == 0; }
            catch (DllNotFoundException) { return false; }
            catch (EntryPointNotFoundException) { return false; }
        }

        /// <summary>Nanoseconds on the clock; only differences mean anything.</summary>
        public static long Now()
        {
            if (!ThreadCpu) return (long)(Stopwatch.GetTimestamp() * (1e9 / Stopwatch.Frequency));
            ClockGetTime(ThreadCpuTimeId, out var t);
            return t.Seconds * 1_000_000_000L + t.Nanoseconds;
        }
    }
}
