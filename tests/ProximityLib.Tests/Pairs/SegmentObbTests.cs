using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class SegmentObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        [Test]
        public void ApartFromTheNearestEdge()
        {
            var r = ClosestDistance.Between(new Segment3(V(3, -1, 0), V(3, 1, 0)), Diamond);
            Result(r, 3 - Math.Sqrt(2), V(3, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(r.ParameterA, Is.EqualTo(0.5).Within(1e-15));
            Assert.That(ProximityQuery.Overlaps(new Segment3(V(3, -1, 0), V(3, 1, 0)), Diamond), Is.False);
        }

        [Test]
        public void TwoDimensionalDiamond()
        {
            var box = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            Result(ClosestDistance.Between(new Segment2(V(-1, 3), V(1, 3)), box), 3 - Math.Sqrt(2), V(0, 3), V(0, Math.Sqrt(2)), 1e-15);
            var through = new Segment2(V(-3, 0), V(3, 0));
            Assert.That(ProximityQuery.Overlaps(through, box), Is.True);
            // The segment spans the diamond, so only a sideways move clears it: by √2, past the top or bottom vertex.
            Assert.That(ClosestDistance.Between(through, box).Distance, Is.EqualTo(-Math.Sqrt(2)).Within(1e-15));
        }
    }
}
