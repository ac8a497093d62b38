using System;
using NUnit.Framework;
using ProximityLib.Double;
using K = ProximityLib.Double.Kernels;

namespace ProximityTests.Double.Kernels
{
    /// <summary>
    /// The witness helpers written on plain doubles for Mono (<c>SegmentPoint</c>, <c>SegmentPoint2</c>,
    /// <c>Box.ToWorldOffset</c>, <c>Box2.ToWorldOffset</c>, <c>Linear.PointAt</c>) against the Vector3D/Vector2D
    /// expressions they replaced, written out here: every component bit for bit, signed zeros included, so the
    /// rewrite cannot move any answer. Inputs: general values, small integers and halves (exact ties, t at 0, ½ and 1,
    /// zeros of both signs), and magnitudes 2^-1000 … 2^1000 mixed within one case.
    /// </summary>
    public class PointKernelsTests
    {
        private const int Cases = 20000;

        [Test]
        public void SegmentPointMatchesTheVectorFormBitForBit()
        {
            var g = new Inputs(8100);
            for (int i = 0; i < Cases; i++)
            {
                Vector3D a = g.Vector(i), b = g.Vector(i);
                double t = g.Parameter(i);
                var expected = t <= 0.5 ? a + (b - a) * t : b - (b - a) * (1 - t);
                Same(K.SegmentPoint(a, b, t), expected, $"SegmentPoint({a:R}, {b:R}, {t:R}), case {i}, seed 8100");
            }
        }

        [Test]
        public void SegmentPoint2MatchesTheVectorFormBitForBit()
        {
            var g = new Inputs(8101);
            for (int i = 0; i < Cases; i++)
            {
                Vector2D a = g.Vector2(i), b = g.Vector2(i);
                double t = g.Parameter(i);
                var expected = t <= 0.5 ? a + (b - a) * t : b - (b - a) * (1 - t);
                Same(K.SegmentPoint2(a, b, t), expected, $"SegmentPoint2({a:R}, {b:R}, {t:R}), case {i}, seed 8101");
            }
        }

        [Test]
        public void BoxToWorldOffsetMatchesTheVectorFormBitForBit()
        {
            var g = new Inputs(8102);
            for (int i = 0; i < Cases; i++)
            {
                Vector3D x = g.Vector(i), y = g.Vector(i), z = g.Vector(i), local = g.Vector(i);
                var box = new Box(g.Vector(i), x, y, z, default, default, false);
                var expected = x * local.X + y * local.Y + z * local.Z;
                Same(box.ToWorldOffset(local), expected, $"axes {x:R}, {y:R}, {z:R}, local {local:R}, case {i}, seed 8102");
            }
        }

        [Test]
        public void Box2ToWorldOffsetMatchesTheVectorFormBitForBit()
        {
            var g = new Inputs(8103);
            for (int i = 0; i < Cases; i++)
            {
                Vector2D x = g.Vector2(i), y = g.Vector2(i), local = g.Vector2(i);
                var box = new Box2(g.Vector2(i), x, y, default, default);
                var expected = x * local.X + y * local.Y;
                Same(box.ToWorldOffset(local), expected, $"axes {x:R}, {y:R}, local {local:R}, case {i}, seed 8103");
            }
        }

        [Test]
        public void LinearPointAtMatchesTheVectorFormBitForBit()
        {
            var g = new Inputs(8104);
            for (int i = 0; i < Cases; i++)
            {
                Vector3D o = g.Vector(i), d = g.Vector(i), e = g.Vector(i);
                double s = i % 3 == 0 ? g.Parameter(i) : g.Scalar(i);
                Same(Linear.Line(o, d).PointAt(s), o + d * s, $"line ({o:R}, {d:R}) at {s:R}, case {i}, seed 8104");
                Same(Linear.Ray(o, d).PointAt(s), o + d * s, $"ray ({o:R}, {d:R}) at {s:R}, case {i}, seed 8104");
                double t = g.Parameter(i);
                var segment = t <= 0.5 ? o + (e - o) * t : e - (e - o) * (1 - t);
                Same(Linear.Segment(o, e).PointAt(t), segment, $"segment ({o:R}, {e:R}) at {t:R}, case {i}, seed 8104");
            }
        }

        private static void Same(Vector3D actual, Vector3D expected, string repro)
        {
            if (Bits(actual.X) != Bits(expected.X) || Bits(actual.Y) != Bits(expected.Y) || Bits(actual.Z) != Bits(expected.Z))
                Assert.Fail($"{repro}\n  plain  {actual:R}\n  vector {expected:R}");
        }

        private static void Same(Vector2D actual, Vector2D expected, string repro)
        {
            if (Bits(actual.X) != Bits(expected.X) || Bits(actual.Y) != Bits(expected.Y))
                Assert.Fail($"{repro}\n  plain  {actual:R}\n  vector {expected:R}");
        }

        private static long Bits(double x) => BitConverter.DoubleToInt64Bits(x);

        /// <summary>Case i's kind is i mod 3: 0 general values in [−4, 4], 1 small integers and halves with signed zeros, 2 mixed magnitudes.</summary>
        private sealed class Inputs
        {
            private readonly Random _r;
            public Inputs(int seed) { _r = new Random(seed); }

            public double Scalar(int i)
            {
                switch (i % 3)
                {
                    case 0: return _r.NextDouble() * 8 - 4;
                    case 1:
                        int k = _r.Next(-6, 7);
                        return k == 0 ? (_r.Next(2) == 0 ? 0.0 : -0.0) : k * 0.5;
                    default:
                        double m = Math.Pow(2, _r.Next(-1000, 1001)) * (1 + _r.NextDouble());
                        return _r.Next(2) == 0 ? m : -m;
                }
            }

            /// <summary>A segment parameter in [0, 1]: the ends, ½ and its neighbours, or uniform.</summary>
            public double Parameter(int i)
            {
                switch (_r.Next(6))
                {
                    case 0: return 0;
                    case 1: return 1;
                    case 2: return 0.5;
                    case 3: return _r.Next(2) == 0 ? 0.49999999999999994 : 0.5000000000000001;
                    default: return i % 3 == 2 ? Math.Pow(2, -_r.Next(1, 1000)) : _r.NextDouble();
                }
            }

            public Vector3D Vector(int i) => new Vector3D(Scalar(i), Scalar(i), Scalar(i));
            public Vector2D Vector2(int i) => new Vector2D(Scalar(i), Scalar(i));
        }
    }
}
