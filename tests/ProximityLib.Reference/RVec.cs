using ProximityLib.Double;

namespace ProximityReference
{
    /// <summary>An exact rational 3-vector.</summary>
    public readonly struct RVec
    {
        public readonly Rational X, Y, Z;
        public RVec(Rational x, Rational y, Rational z) { X = x; Y = y; Z = z; }

        public static RVec From(Vector3D v) => new RVec(v.X, v.Y, v.Z);
        public static RVec From(Vector2D v) => new RVec(v.X, v.Y, 0);

        public static readonly RVec Zero = new RVec(0, 0, 0);
        public static readonly RVec UnitX = new RVec(1, 0, 0);
        public static readonly RVec UnitY = new RVec(0, 1, 0);
        public static readonly RVec UnitZ = new RVec(0, 0, 1);

        public static RVec operator +(RVec a, RVec b) => new RVec(a.X + b.X, a.Y + b.Y, a.Z + b.Z);
        public static RVec operator -(RVec a, RVec b) => new RVec(a.X - b.X, a.Y - b.Y, a.Z - b.Z);
        public static RVec operator -(RVec a) => new RVec(-a.X, -a.Y, -a.Z);
        public static RVec operator *(RVec a, Rational s) => new RVec(a.X * s, a.Y * s, a.Z * s);
        public static Rational Dot(RVec a, RVec b) => a.X * b.X + a.Y * b.Y + a.Z * b.Z;
        public static RVec Cross(RVec a, RVec b) => new RVec(a.Y * b.Z - a.Z * b.Y, a.Z * b.X - a.X * b.Z, a.X * b.Y - a.Y * b.X);
        public Rational LengthSquared => Dot(this, this);
        public bool IsZero => X.IsZero && Y.IsZero && Z.IsZero;
        public Vector3D ToDouble() => new Vector3D(X.ToDouble(), Y.ToDouble(), Z.ToDouble());
    }
}
