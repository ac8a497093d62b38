using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointAabbTests
    {
        private static readonly Aabb3 Box = new Aabb3(V(0, 0, 0), V(2, 2, 2));

        [Test]
        public void FaceEdgeAndCornerRegions()
        {
            Result(ClosestDistance.Between(V(3, 1, 1), Box), 1, V(3, 1, 1), V(2, 1, 1));
            Result(ClosestDistance.Between(V(3, 3, 1), Box), Math.Sqrt(2), V(3, 3, 1), V(2, 2, 1));
            Result(ClosestDistance.Between(V(-1, -1, -1), Box), Math.Sqrt(3), V(-1, -1, -1), V(0, 0, 0));
            Assert.That(ClosestDistance.Between(V(-1, -1, -1), Box).DistanceSquared, Is.EqualTo(3));
            Result(ClosestDistance.Between(V(1, 5), new Aabb2(V(0, 0), V(2, 2))), 3, V(1, 5), V(1, 2));
        }

        [Test]
        public void InsidePushesOutThroughTheNearestFace()
        {
            Result(ClosestDistance.Between(V(0.5, 1, 1), Box), -0.5, V(0.5, 1, 1), V(0, 1, 1));
            Result(ClosestDistance.Between(V(1, 1.75, 1), Box), -0.25, V(1, 1.75, 1), V(1, 2, 1));
            Result(ClosestDistance.Between(V(1.5, 1), new Aabb2(V(0, 0), V(2, 4))), -0.5, V(1.5, 1), V(2, 1));
            Assert.That(ProximityQuery.Overlaps(V(0.5, 1, 1), Box), Is.True);
        }

        [Test]
        public void CenterTieGoesToTheLowerAxisMinFace()
        {
            Result(ClosestDistance.Between(V(1, 1, 1), Box), -1, V(1, 1, 1), V(0, 1, 1));
        }

        [Test]
        public void BoundaryTouchesAndOneUlpOutsideDoesNot()
        {
            Assert.That(ClosestDistance.Between(V(2, 1, 1), Box).Distance, Is.EqualTo(0));
            Assert.That(ProximityQuery.Overlaps(V(2, 1, 1), Box), Is.True);
            double outside = BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(2.0) + 1);
            Assert.That(ProximityQuery.Overlaps(V(outside, 1, 1), Box), Is.False);
            Assert.That(ClosestDistance.Between(V(outside, 1, 1), Box).Distance, Is.EqualTo(outside - 2));
        }

        [Test]
        public void PaperFormOriginLengthHeightWidth()
        {
            var box = Aabb3.FromOrigin(V(1, 2, 3), 4, 5, 6);
            Assert.That(box.Min, Is.EqualTo(V(1, 2, 3)));
            Assert.That(box.Max, Is.EqualTo(V(5, 7, 9)));
            Assert.That(ProximityQuery.Overlaps(V(5, 7, 9), box), Is.True);
        }
    }
}
