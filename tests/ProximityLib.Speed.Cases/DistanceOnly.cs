using System;
using System.Numerics;
using static ProximitySpeed.Source;
using D = ProximityLib.Double;
using F = ProximityLib;
using DC = ProximityLib.Double.ClosestDistance;
using FC = ProximityLib.ClosestDistance;

namespace ProximitySpeed
{
    // The distance-only entry point, ClosestDistance.Distance, for every pair of Pairs.cs: its groups hold the baselines'
    // distance-only forms and the batch distances. A build against a library version without it leaves this file out
    // (tests/ProximityLib.Speed, Builds.Old), and the report shows those targets as not measurable.
    [Case(Library, Precision.Float, "3D point–point")] public readonly struct F3PointPointDistance : IDistance<Vector3, Vector3> { public double Distance(in Vector3 a, in Vector3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D point–segment")] public readonly struct F3PointSegmentDistance : IDistance<Vector3, F.Segment3> { public double Distance(in Vector3 a, in F.Segment3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D point–sphere")] public readonly struct F3PointSphereDistance : IDistance<Vector3, F.Sphere> { public double Distance(in Vector3 a, in F.Sphere b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D point–AABB")] public readonly struct F3PointAabbDistance : IDistance<Vector3, F.Aabb3> { public double Distance(in Vector3 a, in F.Aabb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D point–OBB")] public readonly struct F3PointObbDistance : IDistance<Vector3, F.Obb3> { public double Distance(in Vector3 a, in F.Obb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D segment–segment")] public readonly struct F3SegmentSegmentDistance : IDistance<F.Segment3, F.Segment3> { public double Distance(in F.Segment3 a, in F.Segment3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D segment–sphere")] public readonly struct F3SegmentSphereDistance : IDistance<F.Segment3, F.Sphere> { public double Distance(in F.Segment3 a, in F.Sphere b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D segment–AABB")] public readonly struct F3SegmentAabbDistance : IDistance<F.Segment3, F.Aabb3> { public double Distance(in F.Segment3 a, in F.Aabb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D segment–OBB")] public readonly struct F3SegmentObbDistance : IDistance<F.Segment3, F.Obb3> { public double Distance(in F.Segment3 a, in F.Obb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D sphere–sphere")] public readonly struct F3SphereSphereDistance : IDistance<F.Sphere, F.Sphere> { public double Distance(in F.Sphere a, in F.Sphere b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D sphere–AABB")] public readonly struct F3SphereAabbDistance : IDistance<F.Sphere, F.Aabb3> { public double Distance(in F.Sphere a, in F.Aabb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D sphere–OBB")] public readonly struct F3SphereObbDistance : IDistance<F.Sphere, F.Obb3> { public double Distance(in F.Sphere a, in F.Obb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D AABB–AABB")] public readonly struct F3AabbAabbDistance : IDistance<F.Aabb3, F.Aabb3> { public double Distance(in F.Aabb3 a, in F.Aabb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D AABB–OBB")] public readonly struct F3AabbObbDistance : IDistance<F.Aabb3, F.Obb3> { public double Distance(in F.Aabb3 a, in F.Obb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "3D OBB–OBB")] public readonly struct F3ObbObbDistance : IDistance<F.Obb3, F.Obb3> { public double Distance(in F.Obb3 a, in F.Obb3 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D point–point")] public readonly struct F2PointPointDistance : IDistance<Vector2, Vector2> { public double Distance(in Vector2 a, in Vector2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D point–segment")] public readonly struct F2PointSegmentDistance : IDistance<Vector2, F.Segment2> { public double Distance(in Vector2 a, in F.Segment2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D point–circle")] public readonly struct F2PointSphereDistance : IDistance<Vector2, F.Circle> { public double Distance(in Vector2 a, in F.Circle b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D point–AABB")] public readonly struct F2PointAabbDistance : IDistance<Vector2, F.Aabb2> { public double Distance(in Vector2 a, in F.Aabb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D point–OBB")] public readonly struct F2PointObbDistance : IDistance<Vector2, F.Obb2> { public double Distance(in Vector2 a, in F.Obb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D segment–segment")] public readonly struct F2SegmentSegmentDistance : IDistance<F.Segment2, F.Segment2> { public double Distance(in F.Segment2 a, in F.Segment2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D segment–circle")] public readonly struct F2SegmentSphereDistance : IDistance<F.Segment2, F.Circle> { public double Distance(in F.Segment2 a, in F.Circle b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D segment–AABB")] public readonly struct F2SegmentAabbDistance : IDistance<F.Segment2, F.Aabb2> { public double Distance(in F.Segment2 a, in F.Aabb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D segment–OBB")] public readonly struct F2SegmentObbDistance : IDistance<F.Segment2, F.Obb2> { public double Distance(in F.Segment2 a, in F.Obb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D circle–circle")] public readonly struct F2SphereSphereDistance : IDistance<F.Circle, F.Circle> { public double Distance(in F.Circle a, in F.Circle b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D circle–AABB")] public readonly struct F2SphereAabbDistance : IDistance<F.Circle, F.Aabb2> { public double Distance(in F.Circle a, in F.Aabb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D circle–OBB")] public readonly struct F2SphereObbDistance : IDistance<F.Circle, F.Obb2> { public double Distance(in F.Circle a, in F.Obb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D AABB–AABB")] public readonly struct F2AabbAabbDistance : IDistance<F.Aabb2, F.Aabb2> { public double Distance(in F.Aabb2 a, in F.Aabb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D AABB–OBB")] public readonly struct F2AabbObbDistance : IDistance<F.Aabb2, F.Obb2> { public double Distance(in F.Aabb2 a, in F.Obb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Float, "2D OBB–OBB")] public readonly struct F2ObbObbDistance : IDistance<F.Obb2, F.Obb2> { public double Distance(in F.Obb2 a, in F.Obb2 b) => FC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D point–point")] public readonly struct D3PointPointDistance : IDistance<D.Vector3D, D.Vector3D> { public double Distance(in D.Vector3D a, in D.Vector3D b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D point–segment")] public readonly struct D3PointSegmentDistance : IDistance<D.Vector3D, D.Segment3> { public double Distance(in D.Vector3D a, in D.Segment3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D point–sphere")] public readonly struct D3PointSphereDistance : IDistance<D.Vector3D, D.Sphere> { public double Distance(in D.Vector3D a, in D.Sphere b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D point–AABB")] public readonly struct D3PointAabbDistance : IDistance<D.Vector3D, D.Aabb3> { public double Distance(in D.Vector3D a, in D.Aabb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D point–OBB")] public readonly struct D3PointObbDistance : IDistance<D.Vector3D, D.Obb3> { public double Distance(in D.Vector3D a, in D.Obb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D segment–segment")] public readonly struct D3SegmentSegmentDistance : IDistance<D.Segment3, D.Segment3> { public double Distance(in D.Segment3 a, in D.Segment3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D segment–sphere")] public readonly struct D3SegmentSphereDistance : IDistance<D.Segment3, D.Sphere> { public double Distance(in D.Segment3 a, in D.Sphere b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D segment–AABB")] public readonly struct D3SegmentAabbDistance : IDistance<D.Segment3, D.Aabb3> { public double Distance(in D.Segment3 a, in D.Aabb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D segment–OBB")] public readonly struct D3SegmentObbDistance : IDistance<D.Segment3, D.Obb3> { public double Distance(in D.Segment3 a, in D.Obb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D sphere–sphere")] public readonly struct D3SphereSphereDistance : IDistance<D.Sphere, D.Sphere> { public double Distance(in D.Sphere a, in D.Sphere b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D sphere–AABB")] public readonly struct D3SphereAabbDistance : IDistance<D.Sphere, D.Aabb3> { public double Distance(in D.Sphere a, in D.Aabb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D sphere–OBB")] public readonly struct D3SphereObbDistance : IDistance<D.Sphere, D.Obb3> { public double Distance(in D.Sphere a, in D.Obb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D AABB–AABB")] public readonly struct D3AabbAabbDistance : IDistance<D.Aabb3, D.Aabb3> { public double Distance(in D.Aabb3 a, in D.Aabb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D AABB–OBB")] public readonly struct D3AabbObbDistance : IDistance<D.Aabb3, D.Obb3> { public double Distance(in D.Aabb3 a, in D.Obb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "3D OBB–OBB")] public readonly struct D3ObbObbDistance : IDistance<D.Obb3, D.Obb3> { public double Distance(in D.Obb3 a, in D.Obb3 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D point–point")] public readonly struct D2PointPointDistance : IDistance<D.Vector2D, D.Vector2D> { public double Distance(in D.Vector2D a, in D.Vector2D b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D point–segment")] public readonly struct D2PointSegmentDistance : IDistance<D.Vector2D, D.Segment2> { public double Distance(in D.Vector2D a, in D.Segment2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D point–circle")] public readonly struct D2PointSphereDistance : IDistance<D.Vector2D, D.Circle> { public double Distance(in D.Vector2D a, in D.Circle b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D point–AABB")] public readonly struct D2PointAabbDistance : IDistance<D.Vector2D, D.Aabb2> { public double Distance(in D.Vector2D a, in D.Aabb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D point–OBB")] public readonly struct D2PointObbDistance : IDistance<D.Vector2D, D.Obb2> { public double Distance(in D.Vector2D a, in D.Obb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D segment–segment")] public readonly struct D2SegmentSegmentDistance : IDistance<D.Segment2, D.Segment2> { public double Distance(in D.Segment2 a, in D.Segment2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D segment–circle")] public readonly struct D2SegmentSphereDistance : IDistance<D.Segment2, D.Circle> { public double Distance(in D.Segment2 a, in D.Circle b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D segment–AABB")] public readonly struct D2SegmentAabbDistance : IDistance<D.Segment2, D.Aabb2> { public double Distance(in D.Segment2 a, in D.Aabb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D segment–OBB")] public readonly struct D2SegmentObbDistance : IDistance<D.Segment2, D.Obb2> { public double Distance(in D.Segment2 a, in D.Obb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D circle–circle")] public readonly struct D2SphereSphereDistance : IDistance<D.Circle, D.Circle> { public double Distance(in D.Circle a, in D.Circle b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D circle–AABB")] public readonly struct D2SphereAabbDistance : IDistance<D.Circle, D.Aabb2> { public double Distance(in D.Circle a, in D.Aabb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D circle–OBB")] public readonly struct D2SphereObbDistance : IDistance<D.Circle, D.Obb2> { public double Distance(in D.Circle a, in D.Obb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D AABB–AABB")] public readonly struct D2AabbAabbDistance : IDistance<D.Aabb2, D.Aabb2> { public double Distance(in D.Aabb2 a, in D.Aabb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D AABB–OBB")] public readonly struct D2AabbObbDistance : IDistance<D.Aabb2, D.Obb2> { public double Distance(in D.Aabb2 a, in D.Obb2 b) => DC.Distance(a, b); }
    [Case(Library, Precision.Double, "2D OBB–OBB")] public readonly struct D2ObbObbDistance : IDistance<D.Obb2, D.Obb2> { public double Distance(in D.Obb2 a, in D.Obb2 b) => DC.Distance(a, b); }

    internal static partial class BatchCases
    {
        static partial void AddScalarDistances(InputSet inputs, Action<string, string, int, Func<int, double>> add)
        {
            var (s1, s2) = Sides<F.Sphere, F.Sphere>(inputs, "3D sphere–sphere");
            Distance(add, "3D sphere–sphere", s1.Length, (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FC.Distance(s1[i], s2[j]); });
            var (p, pb) = Sides<Vector3, F.Aabb3>(inputs, "3D point–AABB");
            Distance(add, "3D point–AABB", p.Length, (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FC.Distance(p[i], pb[j]); });
            var (sa, ab) = Sides<F.Sphere, F.Aabb3>(inputs, "3D sphere–AABB");
            Distance(add, "3D sphere–AABB", sa.Length, (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FC.Distance(sa[i], ab[j]); });
            var (so, ob) = Sides<F.Sphere, F.Obb3>(inputs, "3D sphere–OBB");
            Distance(add, "3D sphere–OBB", so.Length, (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FC.Distance(so[i], ob[j]); });
            var (g1, g2) = Sides<F.Segment3, F.Segment3>(inputs, "3D segment–segment");
            Distance(add, "3D segment–segment", g1.Length, (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FC.Distance(g1[i], g2[j]); });
        }

        private static void Distance(Action<string, string, int, Func<int, double>> add, string query, int n, Action<int, float[]> query2) =>
            ScalarOneToMany(add, "float " + query + " distance", "scalar one-to-many Distance", n, query2, v => v);
    }
}
