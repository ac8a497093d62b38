// Copied from src/ProximityLib/Queries.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
namespace ProximityLib
{
    /// <summary>
    /// Closest-distance queries between float shapes: <c>ClosestDistance.Between(a, b)</c> (witnesses) and
    /// <c>ClosestDistance.Distance(a, b)</c> (the signed distance alone) for the pairs of 2D and 3D shapes listed in
    /// docs/api.md, in either argument order. Computed in double and rounded once.
    /// </summary>
    public static partial class ClosestDistance { }

    /// <summary>Boolean touch-or-overlap tests between float shapes: <c>ProximityQuery.Overlaps(a, b)</c>, closed shapes, no square roots.</summary>
    public static partial class ProximityQuery { }
}

namespace ProximityLib.Double
{
    /// <summary>
    /// Closest-distance queries in double precision: <c>ClosestDistance.Between(a, b)</c> (witnesses) and
    /// <c>ClosestDistance.Distance(a, b)</c> (the signed distance alone) for the pairs of 2D and 3D shapes listed in
    /// docs/api.md, in either argument order.
    /// </summary>
    public static partial class ClosestDistance { }

    /// <summary>Boolean touch-or-overlap tests in double precision: <c>ProximityQuery.Overlaps(a, b)</c>, closed shapes, no square roots.</summary>
    public static partial class ProximityQuery { }
}

namespace ProximityLib.Double
{
    /// <summary>
    /// Ray casts in double precision: <c>Raycast.Cast(ray, shape[, maxDistance])</c>, the first point of the ray on the
    /// shape (<see cref="RayHit3"/>, <see cref="RayHit2"/>), for every 2D and 3D shape kind (3D lines and rays excepted).
    /// Solids are closed: a ray grazing one hits at the touch point, an origin on the surface is a hit at T = 0, an origin
    /// strictly inside gives T = 0 with StartsInside. A hit farther than maxDistance (default +∞; negative or NaN throws
    /// <see cref="System.ArgumentException"/>), or beyond the double range, is a miss.
    /// </summary>
    public static partial class Raycast
    {
        /// <summary>2^-40: a point or 3D segment, having no thickness, is hit when the ray passes within this fraction of its local scale (its largest coordinate offset from the ray's origin) of it.</summary>
        public const double PassThroughTolerance = Kernels.PassThrough;
    }
}

namespace ProximityLib
{
    /// <summary>
    /// Ray casts between float shapes: <c>Raycast.Cast(ray, shape[, maxDistance])</c>, computed in double (the contract
    /// of <see cref="ProximityLib.Double.Raycast"/>) and rounded once.
    /// </summary>
    public static partial class Raycast
    {
        /// <summary>2^-40: a point or 3D segment, having no thickness, is hit when the ray passes within this fraction of its local scale (its largest coordinate offset from the ray's origin) of it.</summary>
        public const double PassThroughTolerance = ProximityLib.Double.Raycast.PassThroughTolerance;
    }
}
