using NUnit.Framework;
using ProximityLib.Double;

namespace ProximityTests.Support
{
    /// <summary>Assertions for hand-worked cases: exact expected values, compared within a few ulps.</summary>
    public static class Expect
    {
        public const double Tol = 1e-15;

        public static void Result(DistanceResult3 r, double distance, Vector3D pointA, Vector3D pointB, double tol = Tol)
        {
            Assert.That(r.Distance, Is.EqualTo(distance).Within(tol), "Distance " + Show(r));
            Near(r.PointA, pointA, tol, "PointA " + Show(r));
            Near(r.PointB, pointB, tol, "PointB " + Show(r));
        }

        public static void Result(DistanceResult2 r, double distance, Vector2D pointA, Vector2D pointB, double tol = Tol)
        {
            Assert.That(r.Distance, Is.EqualTo(distance).Within(tol), $"Distance {r.Distance:R} {r.PointA} {r.PointB}");
            Near(TestShape.V3(r.PointA), TestShape.V3(pointA), tol, $"PointA {r.PointA} {r.PointB}");
            Near(TestShape.V3(r.PointB), TestShape.V3(pointB), tol, $"PointB {r.PointA} {r.PointB}");
        }

        public static void Near(Vector3D actual, Vector3D expected, double tol, string what) =>
            Assert.That((actual - expected).Length, Is.LessThanOrEqualTo(tol), $"{what}: expected {expected}, got {actual}");

        private static string Show(DistanceResult3 r) => $"D={r.Distance:R} A={r.PointA} B={r.PointB} tA={r.ParameterA:R} tB={r.ParameterB:R}";

        public static Vector3D V(double x, double y, double z) => new Vector3D(x, y, z);
        public static Vector2D V(double x, double y) => new Vector2D(x, y);
    }
}
