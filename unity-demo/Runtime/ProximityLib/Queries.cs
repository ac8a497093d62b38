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
