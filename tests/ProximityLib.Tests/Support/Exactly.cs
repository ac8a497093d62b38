using ProximityLib.Double;
using ProximityReference;

namespace ProximityTests.Support
{
    /// <summary>Double-API answers measured against the exact rational reference (tests/ProximityLib.Reference).</summary>
    public static class Exactly
    {
        /// <summary>The unit roundoff of double.</summary>
        public const double U = 1.0 / (1L << 53);

        /// <summary>The exact signed distance of two double-API shapes, rounded for reporting.</summary>
        public static double Distance(object a, object b) => Exact.SignedDistance(RShape.FromAny(a), RShape.FromAny(b)).ToDouble();

        /// <summary>The configuration's local scale S (largest coordinate difference between defining points, or radius).</summary>
        public static double Scale(object a, object b) => Exact.Scale(RShape.FromAny(a), RShape.FromAny(b));

        /// <summary>E = |d − d*|/(u·S) for a distance d computed for the pair (a, b).</summary>
        public static double Error(object a, object b, double d)
        {
            var ra = RShape.FromAny(a);
            var rb = RShape.FromAny(b);
            return Exact.Error(d, Exact.SignedDistance(ra, rb), U, Exact.Scale(ra, rb));
        }

        /// <summary>E of the library's own answer, ClosestDistance.Between(a, b).Distance.</summary>
        public static double Error(object a, object b) => Error(a, b, Api.BetweenDistance(a, b));
    }
}
