using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class LineLineTests
    {
        [Test]
        public void SkewLines()
        {
            var a = new Line3(V(0, 0, 0), V(1, 0, 0));
            var b = new Line3(V(5, -7, 3), V(0, 1, 0));
            var r = ClosestDistance.Between(a, b);
            Result(r, 3, V(5, 0, 0), V(5, 0, 3));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((5.0, 7.0)));
            Assert.That(ProximityQuery.Overlaps(a, b), Is.False);
        }

        /// <summary>Parallel lines: the canonically first line's origin (lower x first) and its projection, in either order.</summary>
        [Test]
        public void ParallelLinesAnswerTheCanonicalOrigin()
        {
            var a = new Line3(V(0, 0, 0), V(1, 0, 0));
            var b = new Line3(V(1, 2, 0), V(-1, 0, 0));
            Result(ClosestDistance.Between(a, b), 2, V(0, 0, 0), V(0, 2, 0));
            Result(ClosestDistance.Between(b, a), 2, V(0, 2, 0), V(0, 0, 0));
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(ClosestDistance.Between(a, b).Swapped()));
        }

        [Test]
        public void CrossingLines2DMeetAtOnePoint()
        {
            var r = ClosestDistance.Between(new Line2(V(0, 0), V(1, 1)), new Line2(V(4, 0), V(0, 1)));
            Result(r, 0, V(4, 4), V(4, 4), 1e-14);
            Assert.That(r.PointA, Is.EqualTo(r.PointB));
            Assert.That(r.ParameterB, Is.EqualTo(4).Within(1e-14));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 1)), new Line2(V(4, 0), V(0, 1))), Is.True);
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 0)), new Line2(V(4, 1), V(-1, 0))), Is.False);
        }
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "line"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "line");

        /// <summary>
        /// Lines turned 1e-205 apart with origins 1e100 apart cross 1e305 away: 0 at the crossing point (2D), the
        /// out-of-plane gap 1 (3D). The kernel once counted parameters past 1e300 as parallel and answered 1e100.
        /// </summary>
        [Test]
        public void LinesMeetingFarAwayAreMeasuredWhereTheyMeet()
        {
            var r = ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Line2(V(0, 1e100), V(1, 1e-205)));
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.PointA.X, Is.EqualTo(-1e305).Within(1e-12).Percent);
            Assert.That(r.PointA.Y, Is.EqualTo(0));
            Assert.That(r.PointB, Is.EqualTo(r.PointA));
            var g = ClosestDistance.Between(new Line3(V(0, 0, 0), V(1, 0, 0)), new Line3(V(0, 1e100, 1), V(1, 1e-205, 0)));
            Assert.That(g.Distance, Is.EqualTo(1));
            Assert.That(g.PointA.X, Is.EqualTo(-1e305).Within(1e-12).Percent);
            Assert.That(g.PointB.X, Is.EqualTo(g.PointA.X));
            Assert.That(g.PointB.Z, Is.EqualTo(1));
            Assert.That(Math.Abs(g.PointB.Y), Is.LessThan(1e100 * 1e-15), "B's point lies over A's line, up to the rounding of its 1e100 origin");
        }

        /// <summary>Directions 1e-300 and 1e-310 (subnormal) apart still cross, at 1e300 and 1e307: not parallel (below 1e-270 they once were, Distance 1 and 1e-3).</summary>
        [Test]
        public void DirectionsSubnormallyApartStillCross()
        {
            var r = ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Line2(V(0, 1), V(1, 1e-300)));
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.PointA.X, Is.EqualTo(-1e300).Within(1e-12).Percent);
            // 1e-3 / 1e-310 = 1e307 ahead: within 2^1022 times the origins' magnitude (1), so the point is formed.
            var s = ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Line2(V(1, 1e-3), V(1, 1e-310)));
            Assert.That(s.Distance, Is.EqualTo(0));
            Assert.That(s.PointA.X, Is.EqualTo(-1e307).Within(1e-8).Percent, "1e-310 is subnormal: ten digits");
            var g = ClosestDistance.Between(new Line3(V(0, 0, 0), V(1, 0, 0)), new Line3(V(1, 1e-3, 2), V(1, 1e-310, 0)));
            Assert.That(g.Distance, Is.EqualTo(2));
            Assert.That(g.PointA.X, Is.EqualTo(-1e307).Within(1e-8).Percent);
        }

        /// <summary>
        /// Lines crossing past the precision's range (2D: 1e315 in double, 1e67 in float) have no representable
        /// crossing point: Distance 0 stands, and the witnesses are those of parallel lines, the canonically first
        /// line's origin and its projection on the other, finite and the same in either order. 3D with a gap: 1.
        /// </summary>
        [Test]
        public void LinesMeetingBeyondTheRangeAnswerTheParallelWitnesses()
        {
            var a = new Line2(V(0, 0), V(1, 0));
            var b = new Line2(V(0, 1e100), V(1, 1e-215));
            var r = ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(0));
            OriginAndProjection(r.PointA.To3(), r.ParameterA, a.Origin.To3(), r.PointB.To3(), r.ParameterB, b.Origin.To3(), b.Direction.To3());
            Assert.That(ClosestDistance.Between(b, a), Is.EqualTo(r.Swapped()));

            var fa = new Flt.Line2(new Num.Vector2(0, 0), new Num.Vector2(1, 0));
            var fb = new Flt.Line2(new Num.Vector2(0, 1e30f), new Num.Vector2(1, 1e-37f));
            var f = Flt.ClosestDistance.Between(fa, fb);
            Assert.That(f.Distance, Is.EqualTo(0));
            OriginAndProjection(V(f.PointA.X, f.PointA.Y, 0), f.ParameterA, V(0, 0, 0), V(f.PointB.X, f.PointB.Y, 0), f.ParameterB, V(0, 1e30f, 0), ((Line2)fb).Direction.To3(), 1e-6);

            var f3 = Flt.ClosestDistance.Between(new Flt.Line3(new Num.Vector3(0, 1e30f, 1), new Num.Vector3(1, -1e-20f, 0)), new Flt.Line3(new Num.Vector3(0, 0, 0), new Num.Vector3(1, 0, 0)));
            Assert.That(f3.Distance, Is.EqualTo(1));
            Assert.That(float.IsFinite(f3.PointA.X) && float.IsFinite(f3.PointB.X) && float.IsFinite(f3.ParameterA) && float.IsFinite(f3.ParameterB), Is.True, f3.ToString());
            Assert.That(f3.ParameterA == 0 || f3.ParameterB == 0, Is.True, "one witness is a line's origin");
        }

        /// <summary>One witness an origin (parameter 0), the other that origin's projection on its line (u the unit direction), either way round.</summary>
        private static void OriginAndProjection(Vector3D pa, double ta, Vector3D oa, Vector3D pb, double tb, Vector3D ob, Vector3D ub, double rel = 1e-14)
        {
            if (ta == 0)
            {
                Assert.That(pa, Is.EqualTo(oa), "PointA is A's origin");
                double t = Vector3D.Dot(oa - ob, ub);
                Assert.That(tb, Is.EqualTo(t).Within(rel * 100).Percent, "B's parameter projects A's origin");
                Assert.That((pb - (ob + ub * t)).Length, Is.LessThanOrEqualTo(rel * Math.Max(ob.Length, oa.Length)));
            }
            else Assert.That(tb, Is.EqualTo(0), "one witness is a line's origin");
        }

        /// <summary>
        /// Subnormally turned lines in a tiny configuration, and the same scaled by 2^-527 (the rescaled slow path):
        /// both answers fall back alike, or neither does, so every output scales exactly (fuzz 2033:1000000126570).
        /// </summary>
        [Test]
        public void FarWitnessesScaleExactlyAcrossThePaths()
        {
            var a = new Line3(V(4.96410135240813E-07, -7.673202070499498E-06, -2.6305814053157926E-06), V(-1, 0, 0));
            var b = new Line3(V(8.673287854818019E-07, -1.1387011710015534E-05, -8.324285572887434E-06), V(-1.0, 3.887388961196E-312, 7.52434995814E-313));
            var r = ClosestDistance.Between(a, b);
            double k = Math.ScaleB(1, -527);
            var rs = ClosestDistance.Between(new Line3(a.Origin * k, a.Direction), new Line3(b.Origin * k, b.Direction));
            Assert.That(rs.PointA, Is.EqualTo(r.PointA * k));
            Assert.That(rs.PointB, Is.EqualTo(r.PointB * k));
            Assert.That((rs.ParameterA, rs.ParameterB), Is.EqualTo((r.ParameterA * k, r.ParameterB * k)));
            Assert.That(rs.Distance, Is.EqualTo(r.Distance * k));
        }
    }
}
