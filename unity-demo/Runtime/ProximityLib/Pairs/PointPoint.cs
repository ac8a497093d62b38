// Copied from src/ProximityLib/Pairs/PointPoint.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a point (3D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        public static DistanceResult3 Between(Vector3D a, Vector3D b) => Kernels.PointSphere(a, b, 0).AsPointFirst(a);
        /// <summary>Closest distance between a point and a point (2D): never negative; Distance = |b − a|. Algorithm: Euclidean distance (paper Eq. 7–8).</summary>
        public static DistanceResult2 Between(Vector2D a, Vector2D b) => (Kernels.PointSphere(a.To3(), b.To3(), 0).AsPointFirst(a.To3())).To2();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a point (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Vector3D a, Vector3D b) => a == b;
        /// <summary>Whether a point and a point (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Vector2D a, Vector2D b) => a == b;
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a point and a point (3D), computed in double: never negative; Distance = |b − a|.</summary>
        public static DistanceResult3 Between(Vector3 a, Vector3 b) => new DistanceResult3(Dbl.ClosestDistance.Between((Dbl.Vector3D)a, (Dbl.Vector3D)b));
        /// <summary>Closest distance between a point and a point (2D), computed in double: never negative; Distance = |b − a|.</summary>
        public static DistanceResult2 Between(Vector2 a, Vector2 b) => new DistanceResult2(Dbl.ClosestDistance.Between((Dbl.Vector2D)a, (Dbl.Vector2D)b));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a point and a point (3D) touch or overlap.</summary>
        public static bool Overlaps(Vector3 a, Vector3 b) => Dbl.ProximityQuery.Overlaps((Dbl.Vector3D)a, (Dbl.Vector3D)b);
        /// <summary>Whether a point and a point (2D) touch or overlap.</summary>
        public static bool Overlaps(Vector2 a, Vector2 b) => Dbl.ProximityQuery.Overlaps((Dbl.Vector2D)a, (Dbl.Vector2D)b);
    }
}
