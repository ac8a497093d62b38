// Copied from src/ProximityLib/Double/Sphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
namespace ProximityLib.Double
{
    /// <summary>A closed solid sphere; radius 0 is a point.</summary>
    public readonly struct Sphere
    {
        /// <summary>The center.</summary>
        public readonly Vector3D Center;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a sphere; throws <see cref="System.ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Sphere(Vector3D center, double radius)
        {
            Num.Finite(center, nameof(center));
            Num.NonNegative(radius, nameof(radius));
            Center = center; Radius = radius;
        }
    }

    /// <summary>A closed solid disc (the paper's circle); radius 0 is a point.</summary>
    public readonly struct Circle
    {
        /// <summary>The center.</summary>
        public readonly Vector2D Center;
        /// <summary>The radius (non-negative).</summary>
        public readonly double Radius;

        /// <summary>Creates a circle; throws <see cref="System.ArgumentException"/> on a non-finite center or a negative or non-finite radius.</summary>
        public Circle(Vector2D center, double radius)
        {
            Num.Finite(center, nameof(center));
            Num.NonNegative(radius, nameof(radius));
            Center = center; Radius = radius;
        }
    }
}
