using System;
using System.Numerics;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>The shapes the picker offers, as in the paper's sliding menu.</summary>
    public enum PrimitiveKind
    {
        /// <summary>A point.</summary>
        Point,
        /// <summary>A line segment.</summary>
        Segment,
        /// <summary>A circle (2D) or sphere (3D).</summary>
        Round,
        /// <summary>An axis-aligned box.</summary>
        Aabb,
        /// <summary>An oriented box.</summary>
        Obb,
        /// <summary>A line through the position, along the turned x axis.</summary>
        Line,
        /// <summary>A ray from the position, along the turned x axis.</summary>
        Ray,
        /// <summary>A capsule (2D: a stadium) around the segment, radius half the scale.</summary>
        Capsule,
        /// <summary>A triangle (3D: two-sided, not solid; 2D: solid).</summary>
        Triangle,
        /// <summary>A half-space (2D: half-plane) whose boundary passes through the position, the turned y axis its outward normal.</summary>
        HalfSpace,
    }

    /// <summary>
    /// One primitive of the picker scene: a kind and dimension, its unit-size base shape and the user's transform
    /// (position, rotation about the view axis for 2D or about Y/X for 3D, uniform scale). Immutable: every edit
    /// returns a new primitive.
    /// </summary>
    public sealed class Primitive
    {
        /// <summary>Creates a primitive of a kind and dimension at a position.</summary>
        public Primitive(PrimitiveKind kind, int dimension, Vector3 position, float yaw = 0, float pitch = 0, float scale = 1)
        {
            if (dimension != 2 && dimension != 3) throw new ArgumentException("dimension must be 2 or 3.", nameof(dimension));
            if (!(scale > 0) || float.IsInfinity(scale)) throw new ArgumentException("scale must be positive and finite.", nameof(scale));
            if (!float.IsFinite(position.X) || !float.IsFinite(position.Y) || !float.IsFinite(position.Z))
                throw new ArgumentException("position must be finite.", nameof(position));
            Kind = kind;
            Dimension = dimension;
            Position = dimension == 2 ? new Vector3(position.X, position.Y, 0) : position;
            Yaw = yaw;
            Pitch = dimension == 2 ? 0 : pitch;
            Scale = scale;
        }

        /// <summary>The kind of shape.</summary>
        public PrimitiveKind Kind { get; }
        /// <summary>2 or 3.</summary>
        public int Dimension { get; }
        /// <summary>The center (z = 0 in 2D).</summary>
        public Vector3 Position { get; }
        /// <summary>Rotation in radians about the view axis (2D: z; 3D: y), the paper's L/R keys.</summary>
        public float Yaw { get; }
        /// <summary>Rotation in radians about x (3D only).</summary>
        public float Pitch { get; }
        /// <summary>Uniform scale of the unit-size base shape.</summary>
        public float Scale { get; }

        /// <summary>The display name, e.g. "3D sphere".</summary>
        public string Name => $"{Dimension}D {KindName(Kind, Dimension)}";

        /// <summary>The primitive moved by delta (z ignored in 2D).</summary>
        public Primitive Moved(Vector3 delta) => new Primitive(Kind, Dimension, Position + delta, Yaw, Pitch, Scale);
        /// <summary>The primitive turned by the given angles (radians).</summary>
        public Primitive Rotated(float yaw, float pitch = 0) => new Primitive(Kind, Dimension, Position, Yaw + yaw, Pitch + pitch, Scale);
        /// <summary>The primitive scaled by a positive factor.</summary>
        public Primitive Scaled(float factor) => new Primitive(Kind, Dimension, Position, Yaw, Pitch, Scale * factor);

        /// <summary>The rotation as a quaternion (about y, then x).</summary>
        public Quaternion Rotation => Dimension == 2
            ? Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Yaw)
            : Quaternion.CreateFromYawPitchRoll(Yaw, Pitch, 0);

        /// <summary>
        /// The library shape this primitive stands for (boxed; for display): unit-size base shapes (segment and capsule
        /// axis of length 2 along x, line and ray along x, radius 1, capsule radius 0.5, half-extents 1 × 0.5 × 0.75, the
        /// triangle <see cref="TriangleCorners"/>, the half-space's normal +y) transformed. An AABB ignores rotation: it
        /// stays axis-aligned.
        /// </summary>
        public object Shape => (Dimension, Kind) switch
        {
            (2, PrimitiveKind.Point) => P2(),
            (2, PrimitiveKind.Segment) => Seg2(),
            (2, PrimitiveKind.Round) => Rnd2(),
            (2, PrimitiveKind.Aabb) => Box2(),
            (2, PrimitiveKind.Obb) => Obb2(),
            (2, PrimitiveKind.Line) => Line2(),
            (2, PrimitiveKind.Ray) => Ray2(),
            (2, PrimitiveKind.Capsule) => Cap2(),
            (2, PrimitiveKind.Triangle) => Tri2(),
            (2, _) => Half2(),
            (_, PrimitiveKind.Point) => P3(),
            (_, PrimitiveKind.Segment) => Seg3(),
            (_, PrimitiveKind.Round) => Rnd3(),
            (_, PrimitiveKind.Aabb) => Box3(),
            (_, PrimitiveKind.Obb) => Obb3(),
            (_, PrimitiveKind.Line) => Line3(),
            (_, PrimitiveKind.Ray) => Ray3(),
            (_, PrimitiveKind.Capsule) => Cap3(),
            (_, PrimitiveKind.Triangle) => Tri3(),
            _ => (object)Half3(),
        };

        /// <summary>The triangle's corners before rotation, times Scale: (−1, −0.5), (1, −0.5), (0, 0.75) about the position.</summary>
        public static readonly Vector3[] TriangleCorners = { new Vector3(-1, -0.5f, 0), new Vector3(1, -0.5f, 0), new Vector3(0, 0.75f, 0) };

        /// <summary>The capsule's radius: half the scale (the axis is the segment's, half-length Scale).</summary>
        public float CapsuleRadius => 0.5f * Scale;

        /// <summary>Half-extents of the box kinds before rotation: 1 × 0.5 × 0.75 times Scale (z = 0 in 2D). The segment's half-length and the radius are Scale.</summary>
        public Vector3 HalfExtents => new Vector3(1, 0.5f, Dimension == 3 ? 0.75f : 0) * Scale;

        // Typed shapes for the dispatch table (no boxing).
        private Vector3 Axis => Vector3.Transform(Vector3.UnitX, Rotation) * Scale;
        internal Vector3 P3() => Position;
        internal Segment3 Seg3() => new Segment3(Position - Axis, Position + Axis);
        internal Sphere Rnd3() => new Sphere(Position, Scale);
        internal Aabb3 Box3() => Aabb3.FromCenter(Position, HalfExtents);
        internal Obb3 Obb3() => new Obb3(Position, Rotation, HalfExtents);
        internal Vector2 P2() => new Vector2(Position.X, Position.Y);
        internal Segment2 Seg2() { var a = Axis; return new Segment2(P2() - new Vector2(a.X, a.Y), P2() + new Vector2(a.X, a.Y)); }
        internal Circle Rnd2() => new Circle(P2(), Scale);
        internal Aabb2 Box2() => Aabb2.FromCenter(P2(), new Vector2(HalfExtents.X, HalfExtents.Y));
        internal Obb2 Obb2() => new Obb2(P2(), Yaw, new Vector2(HalfExtents.X, HalfExtents.Y));
        private Vector3 Corner(int i) => Position + Vector3.Transform(TriangleCorners[i], Rotation) * Scale;
        private Vector3 Up => Vector3.Transform(Vector3.UnitY, Rotation);
        internal Line3 Line3() => new Line3(Position, Axis);
        internal Ray3 Ray3() => new Ray3(Position, Axis);
        internal Capsule3 Cap3() => new Capsule3(Position - Axis, Position + Axis, CapsuleRadius);
        internal Triangle3 Tri3() => new Triangle3(Corner(0), Corner(1), Corner(2));
        internal HalfSpace Half3() => HalfSpace.FromPointNormal(Position, Up);
        private static Vector2 Xy(Vector3 v) => new Vector2(v.X, v.Y);
        internal Line2 Line2() => new Line2(P2(), Xy(Axis));
        internal Ray2 Ray2() => new Ray2(P2(), Xy(Axis));
        internal Capsule2 Cap2() { var a = Xy(Axis); return new Capsule2(P2() - a, P2() + a, CapsuleRadius); }
        internal Triangle2 Tri2() => new Triangle2(Xy(Corner(0)), Xy(Corner(1)), Xy(Corner(2)));
        internal HalfPlane Half2() => HalfPlane.FromPointNormal(P2(), Xy(Up));

        internal static string KindName(PrimitiveKind kind, int dimension) => kind switch
        {
            PrimitiveKind.Point => "point",
            PrimitiveKind.Segment => "segment",
            PrimitiveKind.Round => dimension == 2 ? "circle" : "sphere",
            PrimitiveKind.Aabb => "AABB",
            PrimitiveKind.Obb => "OBB",
            PrimitiveKind.Line => "line",
            PrimitiveKind.Ray => "ray",
            PrimitiveKind.Capsule => "capsule",
            PrimitiveKind.Triangle => "triangle",
            _ => dimension == 2 ? "half-plane" : "half-space",
        };
    }
}
