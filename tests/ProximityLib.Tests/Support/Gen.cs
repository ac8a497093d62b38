using System;
using System.Collections.Generic;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;

namespace ProximityTests.Support
{
    /// <summary>Seeded random shapes whose inputs are all floats (so both APIs see the same shape).</summary>
    public static class Gen
    {
        public static readonly Kind[] Kinds = { Kind.Point, Kind.Segment, Kind.Sphere, Kind.Aabb, Kind.Obb };

        /// <summary>The 30 unordered pairs: 15 per dimension.</summary>
        public static IEnumerable<TestCaseData> Pairs()
        {
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < Kinds.Length; i++)
                    for (int j = i; j < Kinds.Length; j++)
                        yield return new TestCaseData(dim, Kinds[i], Kinds[j]).SetArgDisplayNames($"{dim}D", Kinds[i].ToString(), Kinds[j].ToString());
        }

        public static IEnumerable<TestCaseData> PairsWithoutAabb()
        {
            foreach (var pair in Pairs())
                if (!pair.Arguments.Contains(Kind.Aabb)) yield return pair;
        }

        public static int Seed(int dim, Kind a, Kind b) => dim * 1000 + (int)a * 10 + (int)b;

        /// <summary>A value on the 2^-22 grid: a float, and still exact in double after adding an integer below 2^28.</summary>
        public static double F(Random rng, double lo, double hi) => Math.Round((lo + (hi - lo) * rng.NextDouble()) * (1 << 22)) / (1 << 22);

        public static Vector3D Point(Random rng, int dim, double range = 1.5) =>
            new Vector3D(F(rng, -range, range), F(rng, -range, range), dim == 3 ? F(rng, -range, range) : 0);

        /// <summary>A random shape of the kind; one in eight is degenerate (zero length, radius or extent).</summary>
        public static TestShape Shape(Random rng, Kind kind, int dim)
        {
            bool degenerate = rng.Next(8) == 0;
            var c = Point(rng, dim);
            switch (kind)
            {
                case Kind.Point: return TestShape.Point(dim, c);
                case Kind.Segment: return TestShape.Segment(dim, c, degenerate ? c : c + Point(rng, dim, 1));
                case Kind.Sphere: return TestShape.Sphere(dim, c, degenerate ? 0 : F(rng, 0.05, 1));
                case Kind.Aabb:
                    var h = Extents(rng, dim, degenerate);
                    return TestShape.Aabb(dim, c - h, c + h);
                default:
                    return TestShape.Obb(dim, c, Axes(rng, dim), Extents(rng, dim, degenerate));
            }
        }

        private static Vector3D Extents(Random rng, int dim, bool degenerate)
        {
            double x = F(rng, 0.05, 1), y = F(rng, 0.05, 1), z = dim == 3 ? F(rng, 0.05, 1) : 0;
            if (degenerate)
            {
                int which = rng.Next(3);
                if (which == 0) x = 0; else if (which == 1) y = 0; else { x = 0; y = 0; z = 0; }
            }
            return new Vector3D(x, y, z);
        }

        public static Vector3D[] Axes(Random rng, int dim)
        {
            if (dim == 2)
            {
                double angle = rng.NextDouble() * 2 * Math.PI;
                double c = Math.Cos(angle), s = Math.Sin(angle);
                return new[] { new Vector3D(c, s, 0), new Vector3D(-s, c, 0), Vector3D.UnitZ };
            }
            var q = new System.Numerics.Quaternion((float)Normal(rng), (float)Normal(rng), (float)Normal(rng), (float)Normal(rng));
            var o = ProximityLib.Double.Obb3.FromQuaternion(default, q.X, q.Y, q.Z, q.W, default);
            return new[] { o.AxisX, o.AxisY, o.AxisZ };
        }

        private static double Normal(Random rng) =>
            Math.Sqrt(-2 * Math.Log(1 - rng.NextDouble())) * Math.Cos(2 * Math.PI * rng.NextDouble());

        /// <summary>A configuration's local scale: the largest size or distance between the shapes' anchors.</summary>
        public static double Scale(TestShape a, TestShape b) =>
            Math.Max(1e-300, Math.Max(Math.Max(a.Size, b.Size), (a.Anchor - b.Anchor).Length));
    }
}
