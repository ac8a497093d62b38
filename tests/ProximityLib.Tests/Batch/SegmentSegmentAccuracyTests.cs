using System;
using System.Linq;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Batch;
using ProximityReference;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximityTests.Batch
{
    /// <summary>
    /// Batch segment–segment against the exact reference where the lines' stationary point is ill-conditioned: nearly
    /// parallel or crossing segments whose closest points lie inside both, and short segments against long ones, 3D and
    /// 2D (z = 0), across the batch range. E = |d − d*|/(u·S) must stay within the documented bound.
    /// </summary>
    public class SegmentSegmentAccuracyTests
    {
        private const double UFloat = 1.0 / (1 << 24);
        private const double Bound = 8;

        private static double Error(F.Segment3 a, F.Segment3 b, float d)
        {
            var ra = RShape.FromAny(Shapes.Widen(a));
            var rb = RShape.FromAny(Shapes.Widen(b));
            return Exact.Error(d, Exact.SignedDistance(ra, rb), UFloat, Exact.Scale(ra, rb));
        }

        /// <summary>The worst configurations of a seeded search; the comment gives E before the fix.</summary>
        private static readonly object[] Worst =
        {
            // E 1127: nearly parallel 3D, lines 4e-10 apart, closest points inside both.
            new object[] { new Vector3(0.010577156f, -0.08941986f, 0.009468203f), new Vector3(-0.07413811f, -0.028661964f, 0.037479717f),
                new Vector3(-0.09483998f, -0.0137498835f, 0.04429757f), new Vector3(0.06601216f, -0.12924403f, -0.008833716f) },
            // E 1623: the same, at S = 7e-9.
            new object[] { new Vector3(-4.4417195E-10f, 2.5381641E-09f, -2.973188E-09f), new Vector3(4.379681E-10f, -4.180792E-09f, 1.5072447E-09f),
                new Vector3(4.1384024E-10f, -3.988981E-09f, 1.3812855E-09f), new Vector3(-1.5619508E-10f, 3.4104033E-10f, -1.508967E-09f) },
            // E 1811: nearly parallel 2D, crossing inside both.
            new object[] { new Vector3(-27.649212f, 172.01071f, 0f), new Vector3(103.72845f, 286.34457f, 0f),
                new Vector3(102.12774f, 284.9973f, 0f), new Vector3(15.122408f, 209.19545f, 0f) },
            // E 1199: crossing 3D, lines 1e-12 apart.
            new object[] { new Vector3(0.0001469318f, 0.0002017485f, 0.00019326803f), new Vector3(-2.2934732E-05f, -3.1491127E-05f, -3.0167403E-05f),
                new Vector3(8.650824E-05f, 0.00011875709f, 0.00011386819f), new Vector3(-3.452748E-05f, -4.7398753E-05f, -4.544748E-05f) },
            // E 1369: crossing 2D.
            new object[] { new Vector3(-1196.3414f, -946.31335f, 0f), new Vector3(246.1174f, 329.69376f, 0f),
                new Vector3(-228.1065f, -89.964615f, 0f), new Vector3(180.19862f, 271.65756f, 0f) },
            // E 858: a short segment nearly parallel to a long one, 3D.
            new object[] { new Vector3(7.8317676f, -2.4485836f, 6.4152827f), new Vector3(4.8003697f, -40.459152f, -28.672726f),
                new Vector3(6.4163194f, -20.197739f, -9.975056f), new Vector3(5.8750157f, -26.983757f, -16.23048f) },
            // E 890: the same in 2D.
            new object[] { new Vector3(-0.030471563f, 0.039878685f, 0f), new Vector3(-0.03720481f, 0.04571483f, 0f),
                new Vector3(-0.024632957f, 0.034814734f, 0f), new Vector3(-0.04014989f, 0.048270013f, 0f) },
            // E 320: a 1e-12-long segment against one 6e-9 long, 3D: the fourth powers are subnormal unless scaled.
            new object[] { new Vector3(5.310773E-08f, 4.8037432E-08f, -1.1736101E-08f), new Vector3(4.9754096E-08f, 4.8983004E-08f, -1.6985227E-08f),
                new Vector3(5.2102383E-08f, 4.832122E-08f, -1.331089E-08f), new Vector3(5.2101676E-08f, 4.8320963E-08f, -1.3310295E-08f) },
            // E 176: 8e-13 against 1e-8, 2D.
            new object[] { new Vector3(6.334502E-08f, -9.302138E-08f, 0f), new Vector3(5.2999205E-08f, -9.4512004E-08f, 0f),
                new Vector3(6.001451E-08f, -9.3501725E-08f, 0f), new Vector3(6.0015E-08f, -9.350106E-08f, 0f) },
        };

        [TestCaseSource(nameof(Worst))]
        public void WorstConfigurationsFoundMeetTheBound(Vector3 a0, Vector3 a1, Vector3 b0, Vector3 b1)
        {
            var a = new F.Segment3(a0, a1);
            var b = new F.Segment3(b0, b1);
            var paired = new float[1];
            var one = new float[1];
            BatchQuery.Distances(new SegmentSet(new[] { a }), new SegmentSet(new[] { b }), paired);
            BatchQuery.Distances(a, new SegmentSet(new[] { b }), one);
            Assert.That(Error(a, b, paired[0]), Is.LessThanOrEqualTo(Bound), $"paired: {paired[0]:R}");
            Assert.That(Error(a, b, one[0]), Is.LessThanOrEqualTo(Bound), $"one against many: {one[0]:R}");
        }

        /// <summary>A family's segment pairs as float batch inputs (2D ones in the z = 0 plane), within the batch range.</summary>
        private static (F.Segment3 A, F.Segment3 B)[] Pairs(string family, int count, int seed) =>
            Families.Get(family, count, seed)
                .Select(c => (Lift(Shapes.ToFloat(c.A)), Lift(Shapes.ToFloat(c.B))))
                .Where(p =>
                {
                    double s = Exact.Scale(RShape.FromAny(Shapes.Widen(p.Item1)), RShape.FromAny(Shapes.Widen(p.Item2)));
                    return s >= Measure.BatchMinScale && s <= Measure.BatchMaxScale;
                })
                .ToArray();

        private static F.Segment3 Lift(object s) => s is F.Segment2 flat ? Measure.Flat(flat) : (F.Segment3)s;

        [TestCase("crossing-lines", 20), TestCase("tiny-against-long", 10), TestCase("nearly-parallel", 10)]
        public void SeededFamilyMeetsTheBound(string family, int count)
        {
            var pairs = Pairs(family, count, 41);
            Assert.That(pairs.Count(p => p.A.Start.Z == 0 && p.A.End.Z == 0 && p.B.Start.Z == 0 && p.B.End.Z == 0), Is.GreaterThan(pairs.Length / 4), "2D cases");
            var d = new float[pairs.Length];
            BatchQuery.Distances(new SegmentSet(pairs.Select(p => p.A).ToArray()), new SegmentSet(pairs.Select(p => p.B).ToArray()), d);
            var worst = Enumerable.Range(0, pairs.Length).Select(i => (E: Error(pairs[i].A, pairs[i].B, d[i]), i)).Max();
            Assert.That(worst.E, Is.LessThanOrEqualTo(Bound), $"{pairs.Length} cases; worst lane {worst.i}: {pairs[worst.i].A} vs {pairs[worst.i].B}, batch {d[worst.i]:R}");
        }
    }
}
