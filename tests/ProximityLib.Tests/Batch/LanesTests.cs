using System.Numerics;
using NUnit.Framework;
using ProximityLib.Batch;

namespace ProximityTests.Batch
{
    public class LanesTests
    {
        [TestCase(0f, -0f)]
        [TestCase(-0f, 0f)]
        [TestCase(1.5f, -1.5f)]
        [TestCase(-3e38f, 3e38f)]
        [TestCase(float.PositiveInfinity, float.NegativeInfinity)]
        public void NegateFlipsTheSignBitOfEveryLane(float x, float expected)
        {
            var negated = Runner.Negate(new Vector<float>(x));
            for (int i = 0; i < Vector<float>.Count; i++)
                Assert.That(System.BitConverter.SingleToInt32Bits(negated[i]), Is.EqualTo(System.BitConverter.SingleToInt32Bits(expected)));
        }
    }
}
