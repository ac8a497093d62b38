using System;
using System.Linq;
using NUnit.Framework;
using ProximityReference.Fuzz;

namespace ProximityTests.Fuzz
{
    /// <summary>
    /// The seeded ray-cast fuzz (tests/ProximityLib.Reference/Fuzz/Raycast*.cs) at CI size: every public Raycast.Cast
    /// overload (ten targets, 2D and 3D, double and float, with and without maxDistance) and the batch
    /// BatchQuery.Raycasts, each cast against the exact first hit and the invariants (CastChecker). About 35 s in
    /// Release on two cores (shared). PROXIMITY_CAST_FUZZ_SEED and PROXIMITY_CAST_FUZZ_CASES override the seed and the
    /// number of casts; the long mode is
    /// <c>dotnet run --project tests/ProximityLib.Accuracy -c Release -- --fuzz-casts 1000000 --seed N</c>.
    /// </summary>
    [TestFixture, Category("Fuzz")]
    public class RaycastFuzzTests
    {
        public const long DefaultSeed = 2026;
        /// <summary>A multiple of 40: every block of 40 consecutive cases calls all 40 Cast overloads.</summary>
        public const long DefaultCases = 480_000;

        private static long Setting(string name, long fallback)
        {
            var text = Environment.GetEnvironmentVariable(name);
            if (string.IsNullOrWhiteSpace(text)) return fallback;
            if (!long.TryParse(text, out long value) || value < 0) throw new ArgumentException($"{name} must be a non-negative integer (got '{text}').");
            return value;
        }

        [Test]
        public void EveryCastKeepsEveryInvariant()
        {
            long seed = Setting("PROXIMITY_CAST_FUZZ_SEED", DefaultSeed);
            long cases = Setting("PROXIMITY_CAST_FUZZ_CASES", DefaultCases);
            var report = CastEngine.Run(new CastFuzzOptions { Seed = seed, Count = cases, Threads = Environment.ProcessorCount });
            string text = report.Format(repros: 20, rows: 120);
            TestContext.Progress.WriteLine($"Ray-cast fuzz: {report.Cases} casts (seed {seed}) in {report.Elapsed.TotalSeconds:F1} s, " +
                                           $"{report.FailureCount} violations in {report.FailedCases} cases");
            TestContext.Out.WriteLine(text);
            Assert.That(report.Cases, Is.EqualTo(cases));
            Assert.That(report.Failures, Is.Empty, text);
        }

        /// <summary>
        /// Cases the ray-cast fuzz found (seed:index), each a defect fixed with it (regression tests in
        /// tests/ProximityLib.Tests/Raycasts): zero-radius capsules and spheres whose normal pointed along the ray or out of
        /// an end's outward cone, a ray along a zero-radius capsule's axis from an origin on it reported at the far end, a
        /// zero radius on the surface with a normal along the axis; 3D triangles with a determinant at rounding level (an
        /// exactly collinear triangle missed, an in-plane ray missed, a far sliver's T 1.7e-7 off, a sliver hit at a vertex
        /// off the ray; slivers of tilt factor 7e8 and above hit square-on, T 4e-8 off from the weighted mean); 2D slivers hit past their ends; nearly collinear 2D ray targets with T off the point; 3D line and
        /// ray targets parallel to rounding whose noisy crossing inflated the tolerance until an origin 3.5–14 away was on them;
        /// a ray along a zero-radius capsule from behind it hitting the far end; a 2D segment's T from subnormal side values; a
        /// capsule's side grazed by a ray nearly along its axis, its point on the tangent line 8e-11 off the ray.
        /// </summary>
        [TestCase(1, 885, TestName = "Zero-radius capsule end: normal along the ray")]
        [TestCase(1, 775, TestName = "Zero-radius capsule crossed: normal along the ray")]
        [TestCase(1, 15255, TestName = "Zero-radius capsule end: normal out of the cone")]
        [TestCase(1, 134175, TestName = "Along a zero-radius capsule from an origin on it")]
        [TestCase(2, 158575, TestName = "Zero-radius capsule, origin residual underflows")]
        [TestCase(2, 31166, TestName = "Collinear 3D triangle through its end")]
        [TestCase(2, 98926, TestName = "Ray in a 3D triangle's plane")]
        [TestCase(1, 28326, TestName = "Far 3D sliver, determinant at rounding level")]
        [TestCase(1, 18816, TestName = "2D sliver past its end")]
        [TestCase(1, 12256, TestName = "2D sliver past its end, far origin")]
        [TestCase(2, 2533, TestName = "Nearly collinear 2D ray target")]
        [TestCase(1, 40133, TestName = "Nearly collinear 2D ray target, far along")]
        [TestCase(12, 742522, TestName = "3D line parallel to rounding, origin far off it")]
        [TestCase(12, 186123, TestName = "3D ray parallel to rounding, origin far off it")]
        [TestCase(13, 172385, TestName = "Along a zero-radius capsule from behind it")]
        [TestCase(13, 335771, TestName = "2D segment end a subnormal off the ray's line")]
        [TestCase(2, 29006, TestName = "3D sliver hit at a vertex off the ray")]
        [TestCase(12, 750646, TestName = "Far 3D sliver hit square-on, T from the exact plane")]
        [TestCase(3, 88646, TestName = "Far 3D sliver, tilt factor above 2^20")]
        [TestCase(1, 548925, TestName = "Capsule side grazed by a ray nearly along its axis: the point on the ray")]
        public void CasesTheFuzzFoundKeepEveryInvariant(long seed, long index)
        {
            var failures = CastChecker.Run(CastCase.Create(seed, index));
            Assert.That(failures, Is.Empty, CastEngine.Replay(seed, index));
        }
    }
}
