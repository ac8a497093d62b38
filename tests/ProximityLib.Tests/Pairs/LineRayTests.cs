using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    public class LineRayTests
    {
        [Test]
        public void PointingAwayAndCrossing()
        {
            var x = new Line3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(x, new Ray3(V(3, 2, 1), V(0, 1, 0)));
            Result(r, Math.Sqrt(5), V(3, 0, 0), V(3, 2, 1));
            Assert.That((r.ParameterA, r.ParameterB), Is.EqualTo((3.0, 0.0)));
            var c = ClosestDistance.Between(x, new Ray3(V(3, 2, 1), V(0, -1, 0)));
            Result(c, 1, V(3, 0, 0), V(3, 0, 1));
            Assert.That(c.ParameterB, Is.EqualTo(2));
            Result(ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(0, -1))), 0, V(3, 0), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(0, 1))), Is.False);
        }

        [Test]
        public void ParallelRayAnswersItsOrigin() =>
            Result(ClosestDistance.Between(new Line2(V(0, 0), V(1, 0)), new Ray2(V(3, 2), V(-1, 0))), 2, V(3, 0), V(3, 2));
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "ray"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "ray");

        /// <summary>
        /// Float: a line and a ray 1e-6 apart in direction, origins 3e33 apart, meet about 1e39 away, past float's range
        /// (fuzz 2033:1000000136291): Distance 0 with the ray's origin and its projection on the line, finite in
        /// float. The parameters once came back infinite (the double points fit, the float ones did not).
        /// </summary>
        [Test]
        public void FloatRayMeetingTheLineBeyondFloatRangeAnswersItsOrigin()
        {
            var a = new Flt.Line2(new Num.Vector2(-6.1064855E+31f, -6.8740706E+32f), new Num.Vector2(0.54839057f, -0.83622235f));
            var b = new Flt.Ray2(new Num.Vector2(-1.813974E+33f, 2.6381118E+33f), new Num.Vector2(0.5483897f, -0.8362229f));
            var r = Flt.ClosestDistance.Between(a, b);
            Assert.That(r.Distance, Is.EqualTo(0));
            Assert.That(r.ParameterB, Is.EqualTo(0));
            Assert.That(r.PointB, Is.EqualTo(new Num.Vector2(-1.813974E+33f, 2.6381118E+33f)));
            var line = (Line2)a;
            Assert.That(r.ParameterA, Is.EqualTo(Vector2D.Dot(((Ray2)b).Origin - line.Origin, line.Direction)).Within(1e-5).Percent);
            Assert.That(float.IsFinite(r.PointA.X) && float.IsFinite(r.PointA.Y), Is.True, r.ToString());
            Assert.That(Flt.ClosestDistance.Between(b, a).ParameterA, Is.EqualTo(0));
        }
    }
}
