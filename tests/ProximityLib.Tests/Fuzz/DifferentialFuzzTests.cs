using System;
using NUnit.Framework;
using ProximityReference.Fuzz;

namespace ProximityTests.Fuzz
{
    /// <summary>
    /// The seeded differential fuzz (tests/ProximityLib.Reference/Fuzz) at CI size: every generator, every kind pair in
    /// both dimensions and precisions (all 200 public Between/Overlaps overloads, both argument orders), and the SIMD
    /// batch queries, against the invariants and, on a sample, the exact reference; and issue 12's pairs (lines, rays,
    /// capsules, triangles, half-spaces) in their own index space, each pair from the commit whose overloads add it.
    /// About two minutes in Release on two cores. PROXIMITY_FUZZ_SEED, PROXIMITY_FUZZ_CASES and PROXIMITY_FUZZ_NEW_CASES
    /// override the seed and the numbers of cases; the long mode is
    /// <c>dotnet run --project tests/ProximityLib.Accuracy -c Release -- --fuzz 2000000 --seed N</c>.
    /// </summary>
    [TestFixture, Category("Fuzz")]
    public class DifferentialFuzzTests
    {
        public const long DefaultSeed = 2026;
        /// <summary>A multiple of 60: every block of 60 consecutive cases covers all 30 pairs in both precisions.</summary>
        public const long DefaultCases = 120_000;
        /// <summary>A multiple of 160: every block of 160 consecutive new-space cases covers all 80 new pairs in both precisions.</summary>
        public const long DefaultNewCases = 64_000;

        private static long Setting(string name, long fallback)
        {
            var text = Environment.GetEnvironmentVariable(name);
            if (string.IsNullOrWhiteSpace(text)) return fallback;
            if (!long.TryParse(text, out long value) || value < 0) throw new ArgumentException($"{name} must be a non-negative integer (got '{text}').");
            return value;
        }

        [Test]
        public void EveryQueryKeepsEveryInvariant()
        {
            long seed = Setting("PROXIMITY_FUZZ_SEED", DefaultSeed);
            long cases = Setting("PROXIMITY_FUZZ_CASES", DefaultCases);
            long newCases = Setting("PROXIMITY_FUZZ_NEW_CASES", DefaultNewCases);
            var report = Engine.Run(new FuzzOptions { Seed = seed, Count = cases, NewCount = newCases, Threads = Environment.ProcessorCount });
            string text = report.Format(repros: 20, rows: 120);
            TestContext.Progress.WriteLine($"Fuzz: {report.Cases} cases (seed {seed}; {report.Skipped} skipped: pairs not in the library yet) in " +
                                           $"{report.Elapsed.TotalSeconds:F1} s, {report.FailureCount} violations in {report.FailedCases} cases");
            TestContext.Out.WriteLine(text);
            Assert.That(report.Failures, Is.Empty, text);
        }

        /// <summary>
        /// Cases the long mode found (seed:index), replayed with the exact reference: 11:280751 (E 4.33, a zero-radius
        /// sphere touching a rotated OBB) and 11:1579269 (E 4.02, sphere–sphere with the centres 1.5·S apart) broke the
        /// bound of 4 once promised for those pairs (docs/design.md, Error bounds).
        /// </summary>
        [TestCase(11, 280751)]
        [TestCase(11, 1579269)]
        public void CasesTheLongModeFoundKeepEveryInvariant(long seed, long index)
        {
            var failures = Checker.Run(FuzzCase.Create(seed, index), exact: true);
            Assert.That(failures, Is.Empty, Engine.Replay(seed, index));
        }
    }
}
