using System;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityTests.Support;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// The whole 30-pair matrix on seeded random configurations (a mix of apart, touching-near and overlapping, with
    /// degenerate shapes mixed in): agreement with the duality oracle, and the contract's properties.
    /// </summary>
    [TestFixture]
    public class PairMatrixTests
    {
        private const int Cases = 40;
        private const double U = 1.0 / (1L << 53);

        private static double Expected(TestShape a, TestShape b, int seed)
        {
            double sd = Oracle.SignedDistance(a, b, seed);
            // Pairs of points and segments are never negative: crossing segments are at distance 0.
            return a.IsSolid || b.IsSolid ? sd : Math.Max(sd, 0);
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void DistanceMatchesDualityOracle(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 0, (i, a, b, r) =>
            {
                double s = Gen.Scale(a, b);
                double expected = Expected(a, b, i);
                Assert.That(r.D, Is.EqualTo(expected).Within(1e-8 * s), $"case {i}: {a} vs {b}: {r}");
                // Every direction's gap is a lower bound, so a positive answer attained by real points cannot undercut it.
                if (r.D > 0) Assert.That(r.D, Is.GreaterThanOrEqualTo(expected - 1e-12 * s), $"case {i}: {a} vs {b}");
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void DistanceOnlyIsTheDistanceOfBetween(int dim, Kind ka, Kind kb)
        {
            // The distance-only entry point against the oracle, and against Between bit for bit (double and float, both orders).
            ForEachCase(dim, ka, kb, 4, (i, a, b, r) =>
            {
                string at = $"case {i}: {a} vs {b}: {r}";
                double d = Call.DistanceOnly(a, b);
                Assert.That(d, Is.EqualTo(Expected(a, b, i)).Within(1e-8 * Gen.Scale(a, b)), at);
                Assert.That(BitConverter.DoubleToInt64Bits(d), Is.EqualTo(BitConverter.DoubleToInt64Bits(r.D)), at);
                Assert.That(BitConverter.DoubleToInt64Bits(Call.DistanceOnly(b, a)), Is.EqualTo(BitConverter.DoubleToInt64Bits(Call.Distance(b, a).D)), "swapped, " + at);
                Assert.That(Call.DistanceOnlyFloat(a, b), Is.EqualTo((float)Call.DistanceFloat(a, b).D), "float, " + at);
                Assert.That(Call.DistanceOnlyFloat(b, a), Is.EqualTo((float)Call.DistanceFloat(b, a).D), "float swapped, " + at);
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void WitnessPointsRealiseTheDistance(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 1, (i, a, b, r) =>
            {
                double s = Gen.Scale(a, b), tol = 1e-12 * s;
                string at = $"case {i}: {a} vs {b}: {r}";
                Assert.That(double.IsNaN(r.D) || double.IsNaN(r.PA.X) || double.IsNaN(r.PB.X), Is.False, at);
                Assert.That(a.Contains(r.PA, r.TA, tol), Is.True, "PointA in A, " + at);
                Assert.That(b.Contains(r.PB, r.TB, tol), Is.True, "PointB in B, " + at);
                Assert.That((r.PA - r.PB).Length, Is.EqualTo(Math.Abs(r.D)).Within(4 * tol), "|PA − PB| = |D|, " + at);
                Assert.That(r.D2, Is.EqualTo(r.D > 0 ? r.D * r.D : 0).Within(1e-12 * s * s), at);
                if (r.D < 0)
                {
                    // Moving A by PB − PA must leave the shapes just touching: that is what makes it the penetration.
                    var moved = a.Translated(r.PB - r.PA);
                    Assert.That(Oracle.SignedDistance(moved, b, i), Is.EqualTo(0).Within(1e-8 * s), "A moved by PB − PA touches B, " + at);
                }
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void SwappedArgumentsSwapTheWitnesses(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 2, (i, a, b, r) =>
            {
                var s = Call.Distance(b, a);
                string at = $"case {i}: {a} vs {b}: {r} / {s}";
                if (ka != kb)
                {
                    Assert.That(s.D, Is.EqualTo(r.D), at);
                    Assert.That(s.PA, Is.EqualTo(r.PB), at);
                    Assert.That(s.PB, Is.EqualTo(r.PA), at);
                    Assert.That(s.TA, Is.EqualTo(r.TB), at);
                }
                else
                {
                    Assert.That(s.D, Is.EqualTo(r.D).Within(64 * U * Gen.Scale(a, b)), at);
                }
                Assert.That(Call.Overlaps(b, a), Is.EqualTo(Call.Overlaps(a, b)), at);
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void OverlapsAgreesWithTheDistanceSign(int dim, Kind ka, Kind kb)
        {
            var rng = new Random(Gen.Seed(dim, ka, kb) + 3);
            int decided = 0;
            for (int i = 0; i < 4 * Cases; i++)
            {
                var a = Gen.Shape(rng, ka, dim);
                var b = Gen.Shape(rng, kb, dim);
                var r = Call.Distance(a, b);
                double band = 32 * U * Gen.Scale(a, b);
                if (Math.Abs(r.D) <= band) continue;
                decided++;
                Assert.That(Call.Overlaps(a, b), Is.EqualTo(r.D <= 0), $"case {i}: {a} vs {b}: {r}");
                Assert.That(Call.OverlapsFloat(a, b), Is.EqualTo(r.D <= 0), $"float, case {i}: {a} vs {b}: {r}");
            }
            Assert.That(decided, Is.GreaterThan(Cases), "enough cases outside the band");
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void TouchingCountsAsOverlapping(int dim, Kind ka, Kind kb)
        {
            // Move B along the oracle's witness direction until the pair just touches, in exact binary steps.
            var rng = new Random(Gen.Seed(dim, ka, kb) + 4);
            for (int i = 0; i < Cases / 4; i++)
            {
                var a = Gen.Shape(rng, ka, dim);
                var b = Gen.Shape(rng, kb, dim);
                var r = Call.Distance(a, b);
                if (r.D <= 0) continue;
                var touching = b.Translated(r.PA - r.PB);
                var t = Call.Distance(a, touching);
                Assert.That(t.D, Is.EqualTo(0).Within(64 * U * Gen.Scale(a, b)), $"case {i}: {a} vs {touching}: {t}");
            }
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void FloatApiIsTheDoubleResultRounded(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 5, (i, a, b, r) =>
            {
                var f = Call.DistanceFloat(a, b);
                // Float OBB axes are the double axes rounded to float, which moves the box by about 2^-24 of its size.
                double tol = 4.0 / (1 << 24) * Gen.Scale(a, b);
                string at = $"case {i}: {a} vs {b}: {r} / {f}";
                Assert.That(f.D, Is.EqualTo(r.D).Within(tol), at);
                Assert.That((f.PA - r.PA).Length, Is.LessThanOrEqualTo(tol * 8 + Math.Abs(r.D)), at);
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void ScalingByPowersOfTwoScalesExactly(int dim, Kind ka, Kind kb)
        {
            var rng = new Random(Gen.Seed(dim, ka, kb) + 6);
            for (int i = 0; i < Cases; i++)
            {
                var a = Gen.Shape(rng, ka, dim);
                var b = Gen.Shape(rng, kb, dim);
                // Rebuilt through the same path as the scaled copies, so both hold bit-identical OBB axes.
                var r = Call.Distance(a.Scaled(1), b.Scaled(1));
                foreach (int k in new[] { -30, -1, 3, 40 })
                {
                    double s = Math.Pow(2, k);
                    var q = Call.Distance(a.Scaled(s), b.Scaled(s));
                    string at = $"case {i}, 2^{k}: {a} vs {b}: {r} / {q}";
                    Assert.That(q.D, Is.EqualTo(r.D * s), at);
                    Assert.That(q.PA, Is.EqualTo(r.PA * s), at);
                    Assert.That(q.PB, Is.EqualTo(r.PB * s), at);
                    Assert.That(Call.Overlaps(a.Scaled(s), b.Scaled(s)), Is.EqualTo(Call.Overlaps(a.Scaled(1), b.Scaled(1))), at);
                }
            }
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void TranslationAddsNoErrorGrowingWithDistanceFromOrigin(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 7, (i, a, b, r) =>
            {
                double bound = 64 * U * Gen.Scale(a, b);
                // Integer offsets up to 2^28 keep the float-valued inputs exact in double, so only the algorithm can add error.
                foreach (double big in new[] { 1 << 10, 1 << 20, 1 << 28 })
                {
                    var t = new Vector3D(big, -big + 3, dim == 3 ? big - 7 : 0);
                    var q = Call.Distance(a.Translated(t), b.Translated(t));
                    Assert.That(q.D, Is.EqualTo(r.D).Within(bound), $"case {i}, T={t}: {a} vs {b}: {r} / {q}");
                }
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void QuarterTurnsChangeNothingBeyondRounding(int dim, Kind ka, Kind kb)
        {
            var rng = new Random(Gen.Seed(dim, ka, kb) + 8);
            Func<Vector3D, Vector3D>[] turns = dim == 3
                ? new Func<Vector3D, Vector3D>[] { v => new Vector3D(-v.Y, v.X, v.Z), v => new Vector3D(v.Y, v.Z, v.X), v => new Vector3D(v.X, -v.Z, v.Y) }
                : new Func<Vector3D, Vector3D>[] { v => new Vector3D(-v.Y, v.X, 0), v => new Vector3D(-v.X, -v.Y, 0) };
            for (int i = 0; i < Cases; i++)
            {
                var a = Gen.Shape(rng, ka, dim);
                var b = Gen.Shape(rng, kb, dim);
                var r = Call.Distance(a, b);
                foreach (var turn in turns)
                {
                    var q = Call.Distance(a.Map(turn, default), b.Map(turn, default));
                    Assert.That(q.D, Is.EqualTo(r.D).Within(64 * U * Gen.Scale(a, b)), $"case {i}: {a} vs {b}: {r} / {q}");
                }
            }
        }

        // An AABB does not stay axis-aligned under a general rotation; quarter turns cover those pairs.
        [TestCaseSource(typeof(Gen), nameof(Gen.PairsWithoutAabb))]
        public void RotationChangesNothingBeyondRounding(int dim, Kind ka, Kind kb)
        {
            ForEachCase(dim, ka, kb, 9, (i, a, b, r) =>
            {
                var axes = Gen.Axes(new Random(i), dim);
                Vector3D Rotate(Vector3D v) => axes[0] * v.X + axes[1] * v.Y + axes[2] * v.Z;
                var q = Call.Distance(a.Map(Rotate, default), b.Map(Rotate, default));
                Assert.That(q.D, Is.EqualTo(r.D).Within(64 * U * Gen.Scale(a, b)), $"case {i}: {a} vs {b}: {r} / {q}");
            });
        }

        [TestCaseSource(typeof(Gen), nameof(Gen.Pairs))]
        public void FullyDegenerateShapesGiveFiniteAnswers(int dim, Kind ka, Kind kb)
        {
            // Zero sizes at one shared point: every branch that divides by a length must have a named fallback.
            var o = new Vector3D(0.5, -0.25, dim == 3 ? 2 : 0);
            TestShape Zero(Kind k) => k switch
            {
                Kind.Point => TestShape.Point(dim, o),
                Kind.Segment => TestShape.Segment(dim, o, o),
                Kind.Sphere => TestShape.Sphere(dim, o, 0),
                Kind.Aabb => TestShape.Aabb(dim, o, o),
                _ => TestShape.Obb(dim, o, new[] { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ }, default),
            };
            var r = Call.Distance(Zero(ka), Zero(kb));
            Assert.That(r.D, Is.EqualTo(0), r.ToString());
            Assert.That(r.PA, Is.EqualTo(o), r.ToString());
            Assert.That(r.PB, Is.EqualTo(o), r.ToString());
            Assert.That(Call.Overlaps(Zero(ka), Zero(kb)), Is.True);
        }

        /// <summary>Runs the check on seeded random configurations of the pair, with the double API's answer.</summary>
        private static void ForEachCase(int dim, Kind ka, Kind kb, int stream, Action<int, TestShape, TestShape, Res> check)
        {
            var rng = new Random(Gen.Seed(dim, ka, kb) + stream);
            for (int i = 0; i < Cases; i++)
            {
                var a = Gen.Shape(rng, ka, dim);
                var b = Gen.Shape(rng, kb, dim);
                check(i, a, b, Call.Distance(a, b));
            }
        }
    }
}
