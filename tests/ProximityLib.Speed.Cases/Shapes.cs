using System;
using System.Collections.Generic;
using System.Numerics;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximitySpeed
{
    /// <summary>
    /// Builds the arrays a case reads from the input numbers (InputSet): the library's shapes in both precisions and the
    /// baselines' plain structs. Float shapes are the double numbers rounded to float, as a float user would hold them.
    /// </summary>
    internal static partial class Shapes
    {
        static Shapes() { AddNew(Makers); }

        /// <summary>The makers of issue 12's shapes (ShapesNew.cs); left out of builds against a library version without them.</summary>
        static partial void AddNew(Dictionary<Type, Func<double[], object>> makers);

        private static readonly Dictionary<Type, Func<double[], object>> Makers = new Dictionary<Type, Func<double[], object>>
        {
            [typeof(D.Vector3D)] = v => V3(v, 0),
            [typeof(D.Vector2D)] = v => V2(v, 0),
            [typeof(D.Segment3)] = v => new D.Segment3(V3(v, 0), V3(v, 3)),
            [typeof(D.Segment2)] = v => new D.Segment2(V2(v, 0), V2(v, 2)),
            [typeof(D.Sphere)] = v => new D.Sphere(V3(v, 0), v[3]),
            [typeof(D.Circle)] = v => new D.Circle(V2(v, 0), v[2]),
            [typeof(D.Aabb3)] = v => new D.Aabb3(V3(v, 0), V3(v, 3)),
            [typeof(D.Aabb2)] = v => new D.Aabb2(V2(v, 0), V2(v, 2)),
            [typeof(D.Obb3)] = v => new D.Obb3(V3(v, 0), V3(v, 3), V3(v, 6), V3(v, 9), V3(v, 12)),
            [typeof(D.Obb2)] = v => new D.Obb2(V2(v, 0), V2(v, 2), V2(v, 4)),
            [typeof(Vector3)] = v => F3(v, 0),
            [typeof(Vector2)] = v => F2(v, 0),
            [typeof(F.Segment3)] = v => new F.Segment3(F3(v, 0), F3(v, 3)),
            [typeof(F.Segment2)] = v => new F.Segment2(F2(v, 0), F2(v, 2)),
            [typeof(F.Sphere)] = v => new F.Sphere(F3(v, 0), (float)v[3]),
            [typeof(F.Circle)] = v => new F.Circle(F2(v, 0), (float)v[2]),
            // Rounding can swap a thin box's bounds; keep max ≥ min as the float user would have to.
            [typeof(F.Aabb3)] = v => new F.Aabb3(F3(v, 0), Vector3.Max(F3(v, 0), F3(v, 3))),
            [typeof(F.Aabb2)] = v => new F.Aabb2(F2(v, 0), Vector2.Max(F2(v, 0), F2(v, 2))),
            [typeof(F.Obb3)] = v => new F.Obb3(F3(v, 0), F3(v, 3), F3(v, 6), F3(v, 9), F3(v, 12)),
            [typeof(F.Obb2)] = v => new F.Obb2(F2(v, 0), F2(v, 2), F2(v, 4)),
            [typeof(SphereF)] = v => new SphereF(F3(v, 0), (float)v[3]),
            [typeof(BoxF)] = v => new BoxF(F3(v, 0), Vector3.Max(F3(v, 0), F3(v, 3))),
            [typeof(SegmentF)] = v => new SegmentF(F3(v, 0), F3(v, 3)),
            [typeof(Segment2F)] = v => new Segment2F(F2(v, 0), F2(v, 2)),
            [typeof(CircleF)] = v => new CircleF(F2(v, 0), (float)v[2]),
            [typeof(CircleD)] = v => new CircleD(v[0], v[1], v[2]),
            [typeof(PointD)] = v => new PointD(v[0], v[1], v[2]),
            [typeof(SphereD)] = v => new SphereD(v[0], v[1], v[2], v[3]),
            [typeof(BoxD)] = v => new BoxD(v[0], v[1], v[2], v[3], v[4], v[5]),
            [typeof(SegmentD)] = v => new SegmentD(v[0], v[1], v[2], v[3], v[4], v[5]),
            [typeof(Segment2D)] = v => new Segment2D(v[0], v[1], v[2], v[3]),
        };

        /// <summary>The shapes of one side of a query's pairs, as an array of <paramref name="type"/>.</summary>
        public static Array Of(Type type, double[][] numbers)
        {
            if (!Makers.TryGetValue(type, out var make)) throw new ArgumentException("no maker for " + type.Name, nameof(type));
            var result = Array.CreateInstance(type, numbers.Length);
            for (int i = 0; i < numbers.Length; i++) result.SetValue(make(numbers[i]), i);
            return result;
        }

        /// <summary>The shapes of one side of a query's pairs.</summary>
        public static T[] Of<T>(double[][] numbers) => (T[])Of(typeof(T), numbers);

        internal static D.Vector3D V3(double[] v, int i) => new D.Vector3D(v[i], v[i + 1], v[i + 2]);
        internal static D.Vector2D V2(double[] v, int i) => new D.Vector2D(v[i], v[i + 1]);
        internal static Vector3 F3(double[] v, int i) => new Vector3((float)v[i], (float)v[i + 1], (float)v[i + 2]);
        internal static Vector2 F2(double[] v, int i) => new Vector2((float)v[i], (float)v[i + 1]);
    }
}
