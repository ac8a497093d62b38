using System;
using System.Numerics;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityTests.Support
{
    public enum Kind { Point, Segment, Sphere, Aabb, Obb }

    /// <summary>
    /// A test shape: its plain geometry (for the oracle and membership checks, written independently of the library's
    /// algorithms) plus the library objects built from it, in double and, when the inputs are floats, in float.
    /// 2D shapes live in z = 0.
    /// </summary>
    public sealed class TestShape
    {
        public Kind Kind { get; private set; }
        public int Dim { get; private set; }
        public Vector3D P, A, B, C, Half;
        public double R;
        public Vector3D[] Axes = { Vector3D.UnitX, Vector3D.UnitY, Vector3D.UnitZ };

        public object Double { get; private set; } = null!;

        public override string ToString() => Kind switch
        {
            Kind.Point => $"{Dim}D point {P}",
            Kind.Segment => $"{Dim}D segment {A}–{B}",
            Kind.Sphere => $"{Dim}D sphere c={C} r={R:R}",
            Kind.Aabb => $"{Dim}D aabb c={C} h={Half}",
            _ => $"{Dim}D obb c={C} h={Half} x={Axes[0]} y={Axes[1]} z={Axes[2]}",
        };

        public static TestShape Point(int dim, Vector3D p) => Build(new TestShape { Kind = Kind.Point, Dim = dim, P = p });
        public static TestShape Segment(int dim, Vector3D a, Vector3D b) => Build(new TestShape { Kind = Kind.Segment, Dim = dim, A = a, B = b });
        public static TestShape Sphere(int dim, Vector3D c, double r) => Build(new TestShape { Kind = Kind.Sphere, Dim = dim, C = c, R = r });
        public static TestShape Aabb(int dim, Vector3D min, Vector3D max) =>
            Build(new TestShape { Kind = Kind.Aabb, Dim = dim, A = min, B = max, C = (min + max) * 0.5, Half = (max - min) * 0.5 });

        public static TestShape Obb(int dim, Vector3D c, Vector3D[] axes, Vector3D half)
        {
            var s = new TestShape { Kind = Kind.Obb, Dim = dim, C = c, Half = half };
            // The library re-orthonormalises axes; the oracle must see the box the library stores.
            if (dim == 3)
            {
                var o = new Dbl.Obb3(c, axes[0], axes[1], axes[2], half);
                s.Axes = new[] { o.AxisX, o.AxisY, o.AxisZ };
                s.Double = o;
            }
            else
            {
                var o = new Dbl.Obb2(V2(c), V2(axes[0]), V2(half));
                s.Axes = new[] { V3(o.AxisX), V3(o.AxisY), Vector3D.UnitZ };
                s.Double = o;
            }
            return s;
        }

        private static TestShape Build(TestShape s)
        {
            s.Double = (s.Kind, s.Dim) switch
            {
                (Kind.Point, 3) => s.P,
                (Kind.Point, _) => V2(s.P),
                (Kind.Segment, 3) => new Dbl.Segment3(s.A, s.B),
                (Kind.Segment, _) => new Dbl.Segment2(V2(s.A), V2(s.B)),
                (Kind.Sphere, 3) => new Dbl.Sphere(s.C, s.R),
                (Kind.Sphere, _) => new Dbl.Circle(V2(s.C), s.R),
                (Kind.Aabb, 3) => new Dbl.Aabb3(s.A, s.B),
                (Kind.Aabb, _) => new Dbl.Aabb2(V2(s.A), V2(s.B)),
                _ => throw new InvalidOperationException(),
            };
            return s;
        }

        /// <summary>The same shape in the float API; only meaningful when every input is a float.</summary>
        public object ToFloat() => (Kind, Dim) switch
        {
            (Kind.Point, 3) => (Vector3)P,
            (Kind.Point, _) => (Vector2)V2(P),
            (Kind.Segment, 3) => new ProximityLib.Segment3((Vector3)A, (Vector3)B),
            (Kind.Segment, _) => new ProximityLib.Segment2((Vector2)V2(A), (Vector2)V2(B)),
            (Kind.Sphere, 3) => new ProximityLib.Sphere((Vector3)C, (float)R),
            (Kind.Sphere, _) => new ProximityLib.Circle((Vector2)V2(C), (float)R),
            (Kind.Aabb, 3) => new ProximityLib.Aabb3((Vector3)A, (Vector3)B),
            (Kind.Aabb, _) => new ProximityLib.Aabb2((Vector2)V2(A), (Vector2)V2(B)),
            (Kind.Obb, 3) => new ProximityLib.Obb3((Vector3)C, (Vector3)Axes[0], (Vector3)Axes[1], (Vector3)Axes[2], (Vector3)Half),
            _ => new ProximityLib.Obb2((Vector2)V2(C), (Vector2)V2(Axes[0]), (Vector2)V2(Half)),
        };

        /// <summary>max over x in the shape of x·n.</summary>
        public double Support(Vector3D n) => Kind switch
        {
            Kind.Point => Vector3D.Dot(P, n),
            Kind.Segment => Math.Max(Vector3D.Dot(A, n), Vector3D.Dot(B, n)),
            Kind.Sphere => Vector3D.Dot(C, n) + R * n.Length,
            _ => Vector3D.Dot(C, n) + Half.X * Math.Abs(Vector3D.Dot(Axes[0], n)) + Half.Y * Math.Abs(Vector3D.Dot(Axes[1], n))
                 + Half.Z * Math.Abs(Vector3D.Dot(Axes[2], n)),
        };

        /// <summary>Whether x lies in the shape within tol (for a segment, at the reported parameter t).</summary>
        public bool Contains(Vector3D x, double t, double tol)
        {
            if (Dim == 2 && x.Z != 0) return false;
            switch (Kind)
            {
                case Kind.Point: return (x - P).Length <= tol;
                case Kind.Segment:
                    return t >= 0 && t <= 1 && (x - (A + (B - A) * t)).Length <= tol;
                case Kind.Sphere: return (x - C).Length <= R + tol;
                default:
                    var d = x - C;
                    return Math.Abs(Vector3D.Dot(d, Axes[0])) <= Half.X + tol && Math.Abs(Vector3D.Dot(d, Axes[1])) <= Half.Y + tol
                        && Math.Abs(Vector3D.Dot(d, Axes[2])) <= Half.Z + tol;
            }
        }

        public bool IsSolid => Kind == Kind.Sphere || Kind == Kind.Aabb || Kind == Kind.Obb;

        /// <summary>A length scale of the shape: its largest coordinate spread, radius or extent.</summary>
        public double Size => Kind switch
        {
            Kind.Point => 0,
            Kind.Segment => (B - A).Length,
            Kind.Sphere => 2 * R,
            _ => 2 * Half.Length,
        };

        /// <summary>A reference point of the shape.</summary>
        public Vector3D Anchor => Kind switch { Kind.Point => P, Kind.Segment => A, _ => C };

        /// <summary>The shape under x → M·x + t; M must map AABBs to AABBs when the shape is one (a signed permutation).</summary>
        public TestShape Map(Func<Vector3D, Vector3D> linear, Vector3D t, double scale = 1, bool keepAxes = false)
        {
            Vector3D F(Vector3D v) => linear(v) + t;
            switch (Kind)
            {
                case Kind.Point: return Point(Dim, F(P));
                case Kind.Segment: return Segment(Dim, F(A), F(B));
                case Kind.Sphere: return Sphere(Dim, F(C), R * scale);
                case Kind.Aabb:
                    var p = F(A); var q = F(B);
                    return Aabb(Dim, new Vector3D(Math.Min(p.X, q.X), Math.Min(p.Y, q.Y), Math.Min(p.Z, q.Z)),
                        new Vector3D(Math.Max(p.X, q.X), Math.Max(p.Y, q.Y), Math.Max(p.Z, q.Z)));
                default:
                    var axes = new Vector3D[3];
                    for (int i = 0; i < 3; i++) axes[i] = keepAxes ? Axes[i] : linear(Axes[i]);
                    return Obb(Dim, F(C), axes, Half * scale);
            }
        }

        public TestShape Translated(Vector3D t) => Map(v => v, t, 1, true);
        public TestShape Scaled(double s) => Map(v => v * s, default, s, true);

        public static Vector2D V2(Vector3D v) => new Vector2D(v.X, v.Y);
        public static Vector3D V3(Vector2D v) => new Vector3D(v.X, v.Y, 0);
    }
}
