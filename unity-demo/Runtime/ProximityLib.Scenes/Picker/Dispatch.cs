// Copied from src/ProximityLib.Scenes/Picker/Dispatch.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>
    /// Calls the library for two primitives by kind, with the shapes built on the stack: a picker frame costs its one
    /// query and allocates nothing.
    /// </summary>
    internal static class Dispatch
    {
        internal static DistanceResult3 Distance3(Primitive a, Primitive b) => (a.Kind, b.Kind) switch
        {
            (PrimitiveKind.Point, PrimitiveKind.Point) => ClosestDistance.Between(a.P3(), b.P3()),
            (PrimitiveKind.Point, PrimitiveKind.Segment) => ClosestDistance.Between(a.P3(), b.Seg3()),
            (PrimitiveKind.Point, PrimitiveKind.Round) => ClosestDistance.Between(a.P3(), b.Rnd3()),
            (PrimitiveKind.Point, PrimitiveKind.Aabb) => ClosestDistance.Between(a.P3(), b.Box3()),
            (PrimitiveKind.Point, PrimitiveKind.Obb) => ClosestDistance.Between(a.P3(), b.Obb3()),
            (PrimitiveKind.Segment, PrimitiveKind.Point) => ClosestDistance.Between(a.Seg3(), b.P3()),
            (PrimitiveKind.Segment, PrimitiveKind.Segment) => ClosestDistance.Between(a.Seg3(), b.Seg3()),
            (PrimitiveKind.Segment, PrimitiveKind.Round) => ClosestDistance.Between(a.Seg3(), b.Rnd3()),
            (PrimitiveKind.Segment, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Seg3(), b.Box3()),
            (PrimitiveKind.Segment, PrimitiveKind.Obb) => ClosestDistance.Between(a.Seg3(), b.Obb3()),
            (PrimitiveKind.Round, PrimitiveKind.Point) => ClosestDistance.Between(a.Rnd3(), b.P3()),
            (PrimitiveKind.Round, PrimitiveKind.Segment) => ClosestDistance.Between(a.Rnd3(), b.Seg3()),
            (PrimitiveKind.Round, PrimitiveKind.Round) => ClosestDistance.Between(a.Rnd3(), b.Rnd3()),
            (PrimitiveKind.Round, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Rnd3(), b.Box3()),
            (PrimitiveKind.Round, PrimitiveKind.Obb) => ClosestDistance.Between(a.Rnd3(), b.Obb3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Point) => ClosestDistance.Between(a.Box3(), b.P3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Segment) => ClosestDistance.Between(a.Box3(), b.Seg3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Round) => ClosestDistance.Between(a.Box3(), b.Rnd3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Box3(), b.Box3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Obb) => ClosestDistance.Between(a.Box3(), b.Obb3()),
            (PrimitiveKind.Obb, PrimitiveKind.Point) => ClosestDistance.Between(a.Obb3(), b.P3()),
            (PrimitiveKind.Obb, PrimitiveKind.Segment) => ClosestDistance.Between(a.Obb3(), b.Seg3()),
            (PrimitiveKind.Obb, PrimitiveKind.Round) => ClosestDistance.Between(a.Obb3(), b.Rnd3()),
            (PrimitiveKind.Obb, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Obb3(), b.Box3()),
            (PrimitiveKind.Obb, PrimitiveKind.Obb) => ClosestDistance.Between(a.Obb3(), b.Obb3()),
            _ => throw new InvalidOperationException(),
        };

        internal static bool Overlaps3(Primitive a, Primitive b) => (a.Kind, b.Kind) switch
        {
            (PrimitiveKind.Point, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.P3(), b.P3()),
            (PrimitiveKind.Point, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.P3(), b.Seg3()),
            (PrimitiveKind.Point, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.P3(), b.Rnd3()),
            (PrimitiveKind.Point, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.P3(), b.Box3()),
            (PrimitiveKind.Point, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.P3(), b.Obb3()),
            (PrimitiveKind.Segment, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Seg3(), b.P3()),
            (PrimitiveKind.Segment, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Seg3(), b.Seg3()),
            (PrimitiveKind.Segment, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Seg3(), b.Rnd3()),
            (PrimitiveKind.Segment, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Seg3(), b.Box3()),
            (PrimitiveKind.Segment, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Seg3(), b.Obb3()),
            (PrimitiveKind.Round, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Rnd3(), b.P3()),
            (PrimitiveKind.Round, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Rnd3(), b.Seg3()),
            (PrimitiveKind.Round, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Rnd3(), b.Rnd3()),
            (PrimitiveKind.Round, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Rnd3(), b.Box3()),
            (PrimitiveKind.Round, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Rnd3(), b.Obb3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Box3(), b.P3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Box3(), b.Seg3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Box3(), b.Rnd3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Box3(), b.Box3()),
            (PrimitiveKind.Aabb, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Box3(), b.Obb3()),
            (PrimitiveKind.Obb, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Obb3(), b.P3()),
            (PrimitiveKind.Obb, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Obb3(), b.Seg3()),
            (PrimitiveKind.Obb, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Obb3(), b.Rnd3()),
            (PrimitiveKind.Obb, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Obb3(), b.Box3()),
            (PrimitiveKind.Obb, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Obb3(), b.Obb3()),
            _ => throw new InvalidOperationException(),
        };

        internal static DistanceResult2 Distance2(Primitive a, Primitive b) => (a.Kind, b.Kind) switch
        {
            (PrimitiveKind.Point, PrimitiveKind.Point) => ClosestDistance.Between(a.P2(), b.P2()),
            (PrimitiveKind.Point, PrimitiveKind.Segment) => ClosestDistance.Between(a.P2(), b.Seg2()),
            (PrimitiveKind.Point, PrimitiveKind.Round) => ClosestDistance.Between(a.P2(), b.Rnd2()),
            (PrimitiveKind.Point, PrimitiveKind.Aabb) => ClosestDistance.Between(a.P2(), b.Box2()),
            (PrimitiveKind.Point, PrimitiveKind.Obb) => ClosestDistance.Between(a.P2(), b.Obb2()),
            (PrimitiveKind.Segment, PrimitiveKind.Point) => ClosestDistance.Between(a.Seg2(), b.P2()),
            (PrimitiveKind.Segment, PrimitiveKind.Segment) => ClosestDistance.Between(a.Seg2(), b.Seg2()),
            (PrimitiveKind.Segment, PrimitiveKind.Round) => ClosestDistance.Between(a.Seg2(), b.Rnd2()),
            (PrimitiveKind.Segment, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Seg2(), b.Box2()),
            (PrimitiveKind.Segment, PrimitiveKind.Obb) => ClosestDistance.Between(a.Seg2(), b.Obb2()),
            (PrimitiveKind.Round, PrimitiveKind.Point) => ClosestDistance.Between(a.Rnd2(), b.P2()),
            (PrimitiveKind.Round, PrimitiveKind.Segment) => ClosestDistance.Between(a.Rnd2(), b.Seg2()),
            (PrimitiveKind.Round, PrimitiveKind.Round) => ClosestDistance.Between(a.Rnd2(), b.Rnd2()),
            (PrimitiveKind.Round, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Rnd2(), b.Box2()),
            (PrimitiveKind.Round, PrimitiveKind.Obb) => ClosestDistance.Between(a.Rnd2(), b.Obb2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Point) => ClosestDistance.Between(a.Box2(), b.P2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Segment) => ClosestDistance.Between(a.Box2(), b.Seg2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Round) => ClosestDistance.Between(a.Box2(), b.Rnd2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Box2(), b.Box2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Obb) => ClosestDistance.Between(a.Box2(), b.Obb2()),
            (PrimitiveKind.Obb, PrimitiveKind.Point) => ClosestDistance.Between(a.Obb2(), b.P2()),
            (PrimitiveKind.Obb, PrimitiveKind.Segment) => ClosestDistance.Between(a.Obb2(), b.Seg2()),
            (PrimitiveKind.Obb, PrimitiveKind.Round) => ClosestDistance.Between(a.Obb2(), b.Rnd2()),
            (PrimitiveKind.Obb, PrimitiveKind.Aabb) => ClosestDistance.Between(a.Obb2(), b.Box2()),
            (PrimitiveKind.Obb, PrimitiveKind.Obb) => ClosestDistance.Between(a.Obb2(), b.Obb2()),
            _ => throw new InvalidOperationException(),
        };

        internal static bool Overlaps2(Primitive a, Primitive b) => (a.Kind, b.Kind) switch
        {
            (PrimitiveKind.Point, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.P2(), b.P2()),
            (PrimitiveKind.Point, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.P2(), b.Seg2()),
            (PrimitiveKind.Point, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.P2(), b.Rnd2()),
            (PrimitiveKind.Point, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.P2(), b.Box2()),
            (PrimitiveKind.Point, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.P2(), b.Obb2()),
            (PrimitiveKind.Segment, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Seg2(), b.P2()),
            (PrimitiveKind.Segment, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Seg2(), b.Seg2()),
            (PrimitiveKind.Segment, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Seg2(), b.Rnd2()),
            (PrimitiveKind.Segment, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Seg2(), b.Box2()),
            (PrimitiveKind.Segment, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Seg2(), b.Obb2()),
            (PrimitiveKind.Round, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Rnd2(), b.P2()),
            (PrimitiveKind.Round, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Rnd2(), b.Seg2()),
            (PrimitiveKind.Round, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Rnd2(), b.Rnd2()),
            (PrimitiveKind.Round, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Rnd2(), b.Box2()),
            (PrimitiveKind.Round, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Rnd2(), b.Obb2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Box2(), b.P2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Box2(), b.Seg2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Box2(), b.Rnd2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Box2(), b.Box2()),
            (PrimitiveKind.Aabb, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Box2(), b.Obb2()),
            (PrimitiveKind.Obb, PrimitiveKind.Point) => ProximityQuery.Overlaps(a.Obb2(), b.P2()),
            (PrimitiveKind.Obb, PrimitiveKind.Segment) => ProximityQuery.Overlaps(a.Obb2(), b.Seg2()),
            (PrimitiveKind.Obb, PrimitiveKind.Round) => ProximityQuery.Overlaps(a.Obb2(), b.Rnd2()),
            (PrimitiveKind.Obb, PrimitiveKind.Aabb) => ProximityQuery.Overlaps(a.Obb2(), b.Box2()),
            (PrimitiveKind.Obb, PrimitiveKind.Obb) => ProximityQuery.Overlaps(a.Obb2(), b.Obb2()),
            _ => throw new InvalidOperationException(),
        };
    }
}
