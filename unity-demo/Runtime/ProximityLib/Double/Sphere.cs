// Copied from src/ProximityLib/Double/Sphere.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
namespace ProximityLib.Double
{
    /// <summary>A closed solid sphere; radius 0 is a point.</summary>
    public readonly struct Sphere : IScalable<Sphere>
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
            _extreme = !(Range.Moderate(center) && Range.Moderate(radius));
        }

        private readonly bool _extreme;
        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Sphere>.Measure(ref Rescale s) { s.Point(Center); s.Length(Radius); }
        Sphere IScalable<Sphere>.Rescaled(in Rescale s) => new Sphere(s.Apply(Center), s.Apply(Radius));
    }

    /// <summary>A closed solid disc (the paper's circle); radius 0 is a point.</summary>
    public readonly struct Circle : IScalable<Circle>
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
            _extreme = !(Range.Moderate(center) && Range.Moderate(radius));
        }

        private readonly bool _extreme;
        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Circle>.Measure(ref Rescale s) { s.Point(Center); s.Length(Radius); }
        Circle IScalable<Circle>.Rescaled(in Rescale s) => new Circle(s.Apply(Center), s.Apply(Radius));
    }
}
