// Copied from src/ProximityLib/Pairs/SphereSphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a sphere (3D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push along +X. Algorithm: |ca − cb| − ra − rb (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        public static DistanceResult3 Between(Sphere a, Sphere b) => Kernels.PointSphere(a.Center, b.Center, b.Radius).AsSphereFirst(a.Center, a.Radius);
        /// <summary>Closest distance between a circle and a circle (2D): negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push along +X. Algorithm: |ca − cb| − ra − rb (paper Eq. 17); overlap compares squares (paper Eq. 24).</summary>
        public static DistanceResult2 Between(Circle a, Circle b) => (Kernels.PointSphere(a.Center.To3(), b.Center.To3(), b.Radius).AsSphereFirst(a.Center.To3(), a.Radius)).To2();
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and a sphere (3D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Sphere a, Sphere b) => (a.Center - b.Center).LengthSquared <= (a.Radius + b.Radius) * (a.Radius + b.Radius);
        /// <summary>Whether a circle and a circle (2D) touch or overlap; agrees with ClosestDistance (Distance ≤ 0) outside the documented tolerance band.</summary>
        public static bool Overlaps(Circle a, Circle b) => (a.Center.To3() - b.Center.To3()).LengthSquared <= (a.Radius + b.Radius) * (a.Radius + b.Radius);
    }
}

namespace ProximityLib
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and a sphere (3D), computed in double: negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push along +X.</summary>
        public static DistanceResult3 Between(Sphere a, Sphere b) => new DistanceResult3(Dbl.ClosestDistance.Between(a.Inner, b.Inner));
        /// <summary>Closest distance between a circle and a circle (2D), computed in double: negative when overlapping (depth = ra + rb − |ca − cb|); coincident centers push along +X.</summary>
        public static DistanceResult2 Between(Circle a, Circle b) => new DistanceResult2(Dbl.ClosestDistance.Between(a.Inner, b.Inner));
    }

    public static partial class ProximityQuery
    {
        /// <summary>Whether a sphere and a sphere (3D) touch or overlap.</summary>
        public static bool Overlaps(Sphere a, Sphere b) => Dbl.ProximityQuery.Overlaps(a.Inner, b.Inner);
        /// <summary>Whether a circle and a circle (2D) touch or overlap.</summary>
        public static bool Overlaps(Circle a, Circle b) => Dbl.ProximityQuery.Overlaps(a.Inner, b.Inner);
    }
}
