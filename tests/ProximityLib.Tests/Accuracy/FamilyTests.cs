using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Accuracy
{
    /// <summary>
    /// Every hard-case family at a CI-sized count, against the exact reference: each query within its promised bound in
    /// both argument orders, the float API within E ≤ 2, booleans right outside the band; plus the metamorphic checks
    /// (exact 2^k scaling, reversed segment endpoints). The offline run (tests/ProximityLib.Accuracy) draws more cases.
    /// </summary>
    public class FamilyTests
    {
        private const int Count = 3;
        private const int Seed = 17;

        public static string[] Names => Families.Names;

        [TestCaseSource(nameof(Names))]
        public void EveryQueryMeetsItsBound(string family)
        {
            foreach (var c in Families.Get(family, Count, Seed))
            {
                var m = Measure.Run(c);
                double bound = Measure.Bound(m.Pair);
                Assert.That(m.ErrorDouble, Is.LessThanOrEqualTo(bound), $"E double, {m.Pair}: {c}");
                Assert.That(m.ErrorDoubleSwapped, Is.LessThanOrEqualTo(bound), $"E double swapped, {m.Pair}: {c}");
                Assert.That(m.ErrorFloat, Is.LessThanOrEqualTo(2), $"E float, {m.Pair}: {c}");
                if (!double.IsNaN(m.ErrorBatch)) Assert.That(m.ErrorBatch, Is.LessThanOrEqualTo(8), $"E batch, {m.Pair}: {c}");
                Assert.That(m.WrongOverlapDouble, Is.False, $"overlap verdict (double), {m.Pair}: {c}, exact {m.Exact:R}");
                Assert.That(m.WrongOverlapFloat, Is.False, $"overlap verdict (float), {m.Pair}: {c}");
            }
        }

        [TestCaseSource(nameof(Names))]
        public void ScalingByPowersOfTwoIsExact(string family)
        {
            foreach (var c in Families.Get(family, Count, Seed + 1))
            {
                var a = Shapes.Scaled(c.A, 1);
                var b = Shapes.Scaled(c.B, 1);
                double d = Api.BetweenDistance(a, b);
                bool o = Api.Overlaps(a, b);
                // Inside the documented safe range (2^±480) for the range-limits family, wider elsewhere.
                foreach (int k in family == "range-limits" ? new[] { -8, 8 } : new[] { -200, -9, 5, 200 })
                {
                    double s = Math.Pow(2, k);
                    var sa = Shapes.Scaled(c.A, s);
                    var sb = Shapes.Scaled(c.B, s);
                    Assert.That(Api.BetweenDistance(sa, sb), Is.EqualTo(d * s), $"2^{k}: {c}");
                    Assert.That(Api.Overlaps(sa, sb), Is.EqualTo(o), $"2^{k}: {c}");
                }
            }
        }

        [TestCaseSource(nameof(Names))]
        public void ReversingSegmentEndpointsChangesNothingBeyondTheBound(string family)
        {
            foreach (var c in Families.Get(family, Count, Seed + 2).Where(c => Shapes.Order(c.A) == 1 || Shapes.Order(c.B) == 1))
            {
                var m = Measure.Run(new Case(c.Family, Shapes.Reversed(c.A), Shapes.Reversed(c.B)));
                Assert.That(m.ErrorDouble, Is.LessThanOrEqualTo(Measure.Bound(m.Pair)), $"reversed, {m.Pair}: {c}");
            }
        }
    }
}
