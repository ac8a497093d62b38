using System;
using NUnit.Framework;
using ProximityLib;

namespace ProximityTests
{
    public class NumTests
    {
        // m → the exponent e of the expected 2^e; the last four are clamped to the normal range of doubles.
        [TestCase(1.0, 0)]
        [TestCase(1.5, 0)]
        [TestCase(0.75, 1)]
        [TestCase(1024.0, -10)]
        [TestCase(1e-200, 665)]
        [TestCase(double.MaxValue, -1022)]
        [TestCase(2.2250738585072014E-308, 1022)]
        [TestCase(3e-310, 1022)]
        [TestCase(double.Epsilon, 1022)]
        public void InversePowerOfTwoBringsTheValueNearOne(double m, int e)
        {
            double k = Num.InversePowerOfTwo(m);
            Assert.That(k, Is.EqualTo(Math.ScaleB(1.0, e)));
            Assert.That(m * k, Is.InRange(Math.ScaleB(1.0, -52), 4.0));
        }
    }
}
