using System;
using NUnit.Framework;
using ProximityLib.Double;
using static ProximityTests.Support.Expect;

namespace ProximityTests.Pairs
{
    public class PointObbTests
    {
        private static readonly double S = Math.Sqrt(0.5);
        // A unit cube turned 45° about z: its x-most edge is at x = √2.
        private static readonly Obb3 Diamond = new Obb3(V(0, 0, 0), V(S, S, 0), V(-S, S, 0), V(0, 0, 1), V(1, 1, 1));

        [Test]
        public void OutsideNearAnEdge()
        {
            Result(ClosestDistance.Between(V(2, 0, 0), Diamond), 2 - Math.Sqrt(2), V(2, 0, 0), V(Math.Sqrt(2), 0, 0), 1e-15);
            Assert.That(ProximityQuery.Overlaps(V(2, 0, 0), Diamond), Is.False);
            var box2 = new Obb2(V(0, 0), Math.PI / 4, V(1, 1));
            Result(ClosestDistance.Between(V(0, 2), box2), 2 - Math.Sqrt(2), V(0, 2), V(0, Math.Sqrt(2)), 1e-15);
        }

        [Test]
        public void InsideAtDepth()
        {
            // (0.5, 0.5, 0) is at local (√½, 0, 0): √½ from center, 1 − √½ from the +x' face.
            var r = ClosestDistance.Between(V(0.5, 0.5, 0), Diamond);
            Assert.That(r.Distance, Is.EqualTo(-(1 - S)).Within(1e-15));
            Near(r.PointB, V(S, S, 0), 1e-15, "PointB on the +x' face");
            Assert.That(ProximityQuery.Overlaps(V(0.5, 0.5, 0), Diamond), Is.True);
        }

        [Test]
        public void QuaternionAndAxesDescribeTheSameBox()
        {
            var q = System.Numerics.Quaternion.CreateFromAxisAngle(System.Numerics.Vector3.UnitZ, (float)(Math.PI / 4));
            var fromQ = new Obb3(V(0, 0, 0), q, V(1, 1, 1));
            Assert.That(ClosestDistance.Between(V(2, 0, 0), fromQ).Distance, Is.EqualTo(2 - Math.Sqrt(2)).Within(1e-7));
            // An unnormalised quaternion describes the same rotation.
            var scaled = Obb3.FromQuaternion(V(0, 0, 0), 3.0 * q.X, 3.0 * q.Y, 3.0 * q.Z, 3.0 * q.W, V(1, 1, 1));
            Near(scaled.AxisX, fromQ.AxisX, 1e-15, "AxisX");
        }

        [Test]
        public void DefaultObbIsAPointAtTheOrigin()
        {
            Result(ClosestDistance.Between(V(0, 3, 4), default(Obb3)), 5, V(0, 3, 4), V(0, 0, 0));
            Result(ClosestDistance.Between(V(3, 4), default(Obb2)), 5, V(3, 4), V(0, 0));
        }
    }
}
