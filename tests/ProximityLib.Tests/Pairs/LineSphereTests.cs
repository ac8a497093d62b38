using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class LineSphereTests
    {
        [Test]
        public void SeparatedAndEntering()
        {
            var x = new Line3(V(0, 0, 0), V(1, 0, 0));
            var r = ClosestDistance.Between(x, new Sphere(V(3, 4, 0), 2));
            Result(r, 2, V(3, 0, 0), V(3, 2, 0));
            Assert.That(r.ParameterA, Is.EqualTo(3));
            Result(ClosestDistance.Between(x, new Sphere(V(3, 4, 0), 5)), -1, V(3, 0, 0), V(3, -1, 0));
            Result(ClosestDistance.Between(new Circle(V(3, 4), 5), new Line2(V(0, 0), V(1, 0))), -1, V(3, -1), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(x, new Sphere(V(3, 4, 0), 4)), Is.True);
            Assert.That(ProximityQuery.Overlaps(x, new Sphere(V(3, 4, 0), 3.5)), Is.False);
        }

        /// <summary>A center on the line: PointB = center − AnyPerpendicular(direction)·radius, with AnyPerpendicular((1, 0, 0)) = (d.y, −d.x, 0) = (0, −1, 0).</summary>
        [Test]
        public void CenterOnTheLine() =>
            Result(ClosestDistance.Between(new Line3(V(0, 0, 0), V(1, 0, 0)), new Sphere(V(3, 0, 0), 2)), -2, V(3, 0, 0), V(3, 2, 0));
        /// <summary>Seeded families (general, nearly parallel 1e-3…1e-14, nearly collinear, origin near the other's line, origins 1e6 away) in 2D and 3D against the exact rational reference (<see cref="LinearExact"/>): E ≤ 32 and the contract's properties.</summary>
        [Test]
        public void FamiliesMeetTheBound() => Assert.That(LinearFamilies.CheckAll("line", "sphere"), Is.LessThanOrEqualTo(32));

        [Test]
        public void ScalesExactlyAndStaysFiniteOverTheDoubleRange() => LinearFamilies.CheckScaling("line", "sphere");
    }
}
