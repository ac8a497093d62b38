namespace ProximityLib.Double
{
    /// <summary>A closed 3D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    public readonly struct Segment3 : IScalable<Segment3>
    {
        /// <summary>The endpoint at parameter 0.</summary>
        public readonly Vector3D Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public readonly Vector3D End;

        /// <summary>Creates a segment; throws <see cref="System.ArgumentException"/> on non-finite endpoints.</summary>
        public Segment3(Vector3D start, Vector3D end)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Start = start; End = end;
            _extreme = !(Range.Moderate(start) && Range.Moderate(end));
        }

        private readonly bool _extreme;
        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Segment3>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); }
        Segment3 IScalable<Segment3>.Rescaled(in Rescale s) => new Segment3(s.Apply(Start), s.Apply(End));

        /// <summary>The point at parameter t (0 = Start, 1 = End), evaluated from the nearer endpoint.</summary>
        public Vector3D PointAt(double t) => t <= 0.5 ? Start + (End - Start) * t : End - (End - Start) * (1 - t);

        /// <summary>The segment's length.</summary>
        public double Length => (End - Start).Length;
    }

    /// <summary>A closed 2D line segment from <see cref="Start"/> (parameter 0) to <see cref="End"/> (parameter 1); may have zero length.</summary>
    public readonly struct Segment2 : IScalable<Segment2>
    {
        /// <summary>The endpoint at parameter 0.</summary>
        public readonly Vector2D Start;
        /// <summary>The endpoint at parameter 1.</summary>
        public readonly Vector2D End;

        /// <summary>Creates a segment; throws <see cref="System.ArgumentException"/> on non-finite endpoints.</summary>
        public Segment2(Vector2D start, Vector2D end)
        {
            Num.Finite(start, nameof(start));
            Num.Finite(end, nameof(end));
            Start = start; End = end;
            _extreme = !(Range.Moderate(start) && Range.Moderate(end));
        }

        private readonly bool _extreme;
        /// <summary>Whether a value lies outside the fast path's range (<see cref="Range"/>).</summary>
        internal bool Extreme => _extreme;

        void IScalable<Segment2>.Measure(ref Rescale s) { s.Point(Start); s.Point(End); }
        Segment2 IScalable<Segment2>.Rescaled(in Rescale s) => new Segment2(s.Apply(Start), s.Apply(End));

        /// <summary>The point at parameter t (0 = Start, 1 = End), evaluated from the nearer endpoint.</summary>
        public Vector2D PointAt(double t) => t <= 0.5 ? Start + (End - Start) * t : End - (End - Start) * (1 - t);

        /// <summary>The segment's length.</summary>
        public double Length => (End - Start).Length;
    }
}
