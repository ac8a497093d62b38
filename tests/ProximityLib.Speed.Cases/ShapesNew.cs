using System;
using System.Collections.Generic;
using System.Numerics;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximitySpeed
{
    internal static partial class Shapes
    {
        /// <summary>
        /// Issue 12's shapes from their numbers (InputSet): line and ray: origin, direction; capsule: start, end, radius;
        /// triangle: the three corners; half-space and half-plane: normal, offset (normal·x ≤ offset).
        /// </summary>
        static partial void AddNew(Dictionary<Type, Func<double[], object>> makers)
        {
            makers[typeof(D.Line3)] = v => new D.Line3(V3(v, 0), V3(v, 3));
            makers[typeof(D.Line2)] = v => new D.Line2(V2(v, 0), V2(v, 2));
            makers[typeof(D.Ray3)] = v => new D.Ray3(V3(v, 0), V3(v, 3));
            makers[typeof(D.Ray2)] = v => new D.Ray2(V2(v, 0), V2(v, 2));
            makers[typeof(D.Capsule3)] = v => new D.Capsule3(V3(v, 0), V3(v, 3), v[6]);
            makers[typeof(D.Capsule2)] = v => new D.Capsule2(V2(v, 0), V2(v, 2), v[4]);
            makers[typeof(D.Triangle3)] = v => new D.Triangle3(V3(v, 0), V3(v, 3), V3(v, 6));
            makers[typeof(D.Triangle2)] = v => new D.Triangle2(V2(v, 0), V2(v, 2), V2(v, 4));
            makers[typeof(D.HalfSpace)] = v => new D.HalfSpace(V3(v, 0), v[3]);
            makers[typeof(D.HalfPlane)] = v => new D.HalfPlane(V2(v, 0), v[2]);
            makers[typeof(F.Line3)] = v => new F.Line3(F3(v, 0), F3(v, 3));
            makers[typeof(F.Line2)] = v => new F.Line2(F2(v, 0), F2(v, 2));
            makers[typeof(F.Ray3)] = v => new F.Ray3(F3(v, 0), F3(v, 3));
            makers[typeof(F.Ray2)] = v => new F.Ray2(F2(v, 0), F2(v, 2));
            makers[typeof(F.Capsule3)] = v => new F.Capsule3(F3(v, 0), F3(v, 3), (float)v[6]);
            makers[typeof(F.Capsule2)] = v => new F.Capsule2(F2(v, 0), F2(v, 2), (float)v[4]);
            makers[typeof(F.Triangle3)] = v => new F.Triangle3(F3(v, 0), F3(v, 3), F3(v, 6));
            makers[typeof(F.Triangle2)] = v => new F.Triangle2(F2(v, 0), F2(v, 2), F2(v, 4));
            makers[typeof(F.HalfSpace)] = v => new F.HalfSpace(F3(v, 0), (float)v[3]);
            makers[typeof(F.HalfPlane)] = v => new F.HalfPlane(F2(v, 0), (float)v[2]);
            // The baselines' plain structs: a ray's direction normalised in its own precision, as its user would.
            makers[typeof(RayF)] = v => new RayF(F3(v, 0), Vector3.Normalize(F3(v, 3)));
            makers[typeof(RayD)] = v => RayD.Of(v);
            makers[typeof(TriangleF)] = v => new TriangleF(F3(v, 0), F3(v, 3), F3(v, 6));
            makers[typeof(TriangleD)] = v => new TriangleD(new PointD(v[0], v[1], v[2]), new PointD(v[3], v[4], v[5]), new PointD(v[6], v[7], v[8]));
            makers[typeof(PlaneF)] = v => PlaneF.Of(F3(v, 0), (float)v[3]);
            makers[typeof(PlaneD)] = v => PlaneD.Of(v);
            makers[typeof(CapsuleF)] = v => new CapsuleF(new SegmentF(F3(v, 0), F3(v, 3)), (float)v[6]);
            makers[typeof(CapsuleD)] = v => new CapsuleD(new SegmentD(v[0], v[1], v[2], v[3], v[4], v[5]), v[6]);
        }
    }
}
