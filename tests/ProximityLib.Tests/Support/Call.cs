using ProximityLib.Double;
using Dbl = ProximityLib.Double;
using Api = ProximityReference.Api;

namespace ProximityTests.Support
{
    /// <summary>A query answer in one shape for both dimensions and precisions (2D results get z = 0).</summary>
    public readonly struct Res
    {
        public readonly double D, D2, TA, TB;
        public readonly Vector3D PA, PB;

        public Res(double d, double d2, Vector3D pa, Vector3D pb, double ta, double tb)
        {
            D = d; D2 = d2; PA = pa; PB = pb; TA = ta; TB = tb;
        }

        public override string ToString() => $"D={D:R} D2={D2:R} PA={PA} PB={PB} tA={TA:R} tB={TB:R}";
    }

    /// <summary>Calls the library's overloads for any pair at run time, so one test body covers the whole matrix.</summary>
    public static class Call
    {
        public static Res Distance(TestShape a, TestShape b) => From(Api.Between(a.Double, b.Double));
        public static bool Overlaps(TestShape a, TestShape b) => Api.Overlaps(a.Double, b.Double);
        public static double DistanceOnly(TestShape a, TestShape b) => Api.Distance(a.Double, b.Double);
        public static float DistanceOnlyFloat(TestShape a, TestShape b) => (float)Api.Distance(a.ToFloat(), b.ToFloat());
        public static Res DistanceFloat(TestShape a, TestShape b) => From(Api.Between(a.ToFloat(), b.ToFloat()));
        public static bool OverlapsFloat(TestShape a, TestShape b) => Api.Overlaps(a.ToFloat(), b.ToFloat());

        private static Res From(object r) => r switch
        {
            Dbl.DistanceResult3 x => new Res(x.Distance, x.DistanceSquared, x.PointA, x.PointB, x.ParameterA, x.ParameterB),
            Dbl.DistanceResult2 x => new Res(x.Distance, x.DistanceSquared, TestShape.V3(x.PointA), TestShape.V3(x.PointB), x.ParameterA, x.ParameterB),
            ProximityLib.DistanceResult3 x => new Res(x.Distance, x.DistanceSquared, x.PointA, x.PointB, x.ParameterA, x.ParameterB),
            ProximityLib.DistanceResult2 x => new Res(x.Distance, x.DistanceSquared, new Vector3D(x.PointA.X, x.PointA.Y, 0),
                new Vector3D(x.PointB.X, x.PointB.Y, 0), x.ParameterA, x.ParameterB),
            _ => throw new System.InvalidOperationException(r?.GetType().Name),
        };
    }
}
