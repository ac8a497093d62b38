using System;
using NUnit.Framework;
using ProximityLib;

namespace ProximityTests
{
    public class SpansTests
    {
        [Test]
        public void AtReadsEachElementAndChecksTheRangeLikeTheIndexer()
        {
            var values = new[] { 3, 1, 4 };
            Assert.That(new[] { Spans.At<int>(values, 0), Spans.At<int>(values, 1), Spans.At<int>(values, 2) }, Is.EqualTo(values));
            Assert.That(Spans.At<int>(values.AsSpan(1), 1), Is.EqualTo(4));
            Assert.Throws<ArgumentOutOfRangeException>(() => Spans.At<int>(values, 3));
            Assert.Throws<ArgumentOutOfRangeException>(() => Spans.At<int>(values, -1));
        }
    }
}
