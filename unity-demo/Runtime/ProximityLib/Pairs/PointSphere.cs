// Copied from src/ProximityLib/Pairs/PointSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a sphere (3D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        public static DistanceResult3 Between(Vector3D a, Sphere b) => Kernels.PointSphere(a, b.Center, b.Radius).AsPointFirst(a);
        /// <summary>Closest distance between a sphere and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        public static DistanceResult3 Between(Sphere a, Vector3D b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a circle (2D): negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X. Algorithm: |a − center| − radius (paper Eq. 12, 21).</summary>
        public static DistanceResult2 Between(Vector2D a, Circle b) => (Kernels.PointSphere(a.To3(), b.Center.To3(), b.Radius).AsPointFirst(a.To3())).To2();
        /// <summary>Closest distance between a circle and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        public static DistanceResult2 Between(Circle a, Vector2D b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a sphere (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Vector3D a, Sphere b) => (a - b.Center).LengthSquared <= b.Radius * b.Radius;
        /// <summary>Whether a sphere and a point (3D) touch or overlap.</summary>
        public static bool Overlaps(Sphere a, Vector3D b) => Overlaps(b, a);
        /// <summary>Whether a point and a circle (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Vector2D a, Circle b) => (a.To3() - b.Center.To3()).LengthSquared <= b.Radius * b.Radius;
        /// <summary>Whether a circle and a point (2D) touch or overlap.</summary>
        public static bool Overlaps(Circle a, Vector2D b) => Overlaps(b, a);
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a sphere (3D), computed in double: negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X.</summary>
        public static DistanceResult3 Between(Vector3 a, Sphere b) => new DistanceResult3(Dbl.ClosestDistance.Between((Dbl.Vector3D)a, b.Inner));
        /// <summary>Closest distance between a sphere and a point (3D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        public static DistanceResult3 Between(Sphere a, Vector3 b) => Between(b, a).Swapped();
        /// <summary>Closest distance between a point and a circle (2D), computed in double: negative inside (depth = radius − |a − center|); a point at the center is pushed out along +X.</summary>
        public static DistanceResult2 Between(Vector2 a, Circle b) => new DistanceResult2(Dbl.ClosestDistance.Between((Dbl.Vector2D)a, b.Inner));
        /// <summary>Closest distance between a circle and a point (2D): the swapped call, with PointA/PointB and parameters swapped.</summary>
        public static DistanceResult2 Between(Circle a, Vector2 b) => Between(b, a).Swapped();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a sphere (3D) touch or overlap.</summary>
        public static bool Overlaps(Vector3 a, Sphere b) => Dbl.ProximityQuery.Overlaps((Dbl.Vector3D)a, b.Inner);
        /// <summary>Whether a sphere and a point (3D) touch or overlap.</summary>
        public static bool Overlaps(Sphere a, Vector3 b) => Overlaps(b, a);
        /// <summary>Whether a point and a circle (2D) touch or overlap.</summary>
        public static bool Overlaps(Vector2 a, Circle b) => Dbl.ProximityQuery.Overlaps((Dbl.Vector2D)a, b.Inner);
        /// <summary>Whether a circle and a point (2D) touch or overlap.</summary>
        public static bool Overlaps(Circle a, Vector2 b) => Overlaps(b, a);
    }
}
