using System;
using System.Globalization;
using System.Linq;
using System.Numerics;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// The shape kinds. The first five keep their original values (a case is drawn from (seed, index) through them, so
    /// recorded repros keep their meaning); issue 12's kinds are appended. <see cref="Kinds.Rank"/> is the library's pair
    /// order (point &lt; segment &lt; line &lt; ray &lt; sphere &lt; capsule &lt; triangle &lt; half-space &lt; AABB &lt; OBB).
    /// </summary>
    public enum Kind { Point, Segment, Sphere, Aabb, Obb, Line, Ray, Capsule, Triangle, HalfSpace }

    public static class Kinds
    {
        /// <summary>The library's pair order (src/ProximityLib/Pairs file names): which kind of a pair comes first.</summary>
        public static int Rank(Kind k) => k switch
        {
            Kind.Point => 0, Kind.Segment => 1, Kind.Line => 2, Kind.Ray => 3, Kind.Sphere => 4, Kind.Capsule => 5,
            Kind.Triangle => 6, Kind.HalfSpace => 7, Kind.Aabb => 8, _ => 9,
        };

        /// <summary>Every kind in the library's pair order.</summary>
        public static readonly Kind[] InOrder =
            { Kind.Point, Kind.Segment, Kind.Line, Kind.Ray, Kind.Sphere, Kind.Capsule, Kind.Triangle, Kind.HalfSpace, Kind.Aabb, Kind.Obb };

        /// <summary>The kinds before issue 12 (their 30 pairs keep the original case index space).</summary>
        public static bool IsOriginal(Kind k) => k <= Kind.Obb;

        /// <summary>Lines and rays: unbounded, with a free parameter t (Point = Origin + t·Direction).</summary>
        public static bool IsLinear(Kind k) => k == Kind.Line || k == Kind.Ray;
    }

    /// <summary>How an OBB is constructed: the constructor the repro must call to rebuild it bit for bit.</summary>
    public enum ObbForm { None, Quaternion, Axes, Angle, Axis }

    /// <summary>
    /// One generated shape as the arguments of a public constructor: building it and printing it as C# go through the
    /// same constructor with the same values, so a printed repro rebuilds the library's shape bit for bit. Float specs
    /// hold float values (exactly, in doubles) and build the float API's shapes.
    /// </summary>
    public sealed class Spec
    {
        public Kind Kind { get; }
        public int Dim { get; }
        public bool Float { get; }
        /// <summary>Point; segment/capsule start; sphere/circle/OBB center; AABB min; line/ray origin; triangle A; half-space point.</summary>
        public Vector3D P { get; }
        /// <summary>Segment/capsule end; AABB max; line/ray direction; triangle B; half-space normal.</summary>
        public Vector3D Q { get; }
        /// <summary>Radius (sphere, capsule); the half-space offset in the offset form.</summary>
        public double R { get; }
        /// <summary>OBB half-extents; triangle C.</summary>
        public Vector3D H { get; }
        public ObbForm Form { get; }
        /// <summary>A half-space built by <c>new HalfSpace(normal, offset)</c> (else <c>HalfSpace.FromPointNormal(point, normal)</c>).</summary>
        public bool ByOffset { get; }
        /// <summary>Quaternion (x, y, z, w); three axes (9 values); an angle; a 2D axis (2 values).</summary>
        public double[] Rot { get; }

        private Spec(Kind kind, int dim, bool isFloat, Vector3D p, Vector3D q, double r, Vector3D h, ObbForm form, double[] rot, bool byOffset = false)
        {
            Kind = kind; Dim = dim; Float = isFloat; P = p; Q = q; R = r; H = h; Form = form; Rot = rot; ByOffset = byOffset;
        }

        private static Vector3D Flat(Vector3D v, int dim) => dim == 2 ? new Vector3D(v.X, v.Y, 0) : v;

        public static Spec Point(int dim, Vector3D p) => new Spec(Kind.Point, dim, false, Flat(p, dim), default, 0, default, ObbForm.None, Array.Empty<double>());
        public static Spec Segment(int dim, Vector3D a, Vector3D b) => new Spec(Kind.Segment, dim, false, Flat(a, dim), Flat(b, dim), 0, default, ObbForm.None, Array.Empty<double>());
        public static Spec Sphere(int dim, Vector3D c, double r) => new Spec(Kind.Sphere, dim, false, Flat(c, dim), default, Math.Abs(r), default, ObbForm.None, Array.Empty<double>());

        /// <summary>An AABB from two corners in any order (sorted per axis, so it is always valid).</summary>
        public static Spec Aabb(int dim, Vector3D a, Vector3D b)
        {
            var min = new Vector3D(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));
            var max = new Vector3D(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));
            return new Spec(Kind.Aabb, dim, false, Flat(min, dim), Flat(max, dim), 0, default, ObbForm.None, Array.Empty<double>());
        }

        public static Spec ObbQuaternion(Vector3D c, double x, double y, double z, double w, Vector3D h) =>
            new Spec(Kind.Obb, 3, false, c, default, 0, Abs(h), ObbForm.Quaternion, new[] { x, y, z, w });

        public static Spec ObbAxes(Vector3D c, Vector3D ax, Vector3D ay, Vector3D az, Vector3D h) =>
            new Spec(Kind.Obb, 3, false, c, default, 0, Abs(h), ObbForm.Axes, new[] { ax.X, ax.Y, ax.Z, ay.X, ay.Y, ay.Z, az.X, az.Y, az.Z });

        public static Spec Obb2Angle(Vector3D c, double angle, Vector3D h) =>
            new Spec(Kind.Obb, 2, false, Flat(c, 2), default, 0, Flat(Abs(h), 2), ObbForm.Angle, new[] { angle });

        public static Spec Obb2Axis(Vector3D c, double ax, double ay, Vector3D h) =>
            new Spec(Kind.Obb, 2, false, Flat(c, 2), default, 0, Flat(Abs(h), 2), ObbForm.Axis, new[] { ax, ay });

        /// <summary>A line through origin along direction (normalised by the constructor; any non-zero vector).</summary>
        public static Spec Line(int dim, Vector3D origin, Vector3D direction) =>
            new Spec(Kind.Line, dim, false, Flat(origin, dim), Flat(direction, dim), 0, default, ObbForm.None, Array.Empty<double>());

        public static Spec Ray(int dim, Vector3D origin, Vector3D direction) =>
            new Spec(Kind.Ray, dim, false, Flat(origin, dim), Flat(direction, dim), 0, default, ObbForm.None, Array.Empty<double>());

        public static Spec Capsule(int dim, Vector3D start, Vector3D end, double radius) =>
            new Spec(Kind.Capsule, dim, false, Flat(start, dim), Flat(end, dim), Math.Abs(radius), default, ObbForm.None, Array.Empty<double>());

        public static Spec Triangle(int dim, Vector3D a, Vector3D b, Vector3D c) =>
            new Spec(Kind.Triangle, dim, false, Flat(a, dim), Flat(b, dim), 0, Flat(c, dim), ObbForm.None, Array.Empty<double>());

        /// <summary>A half-space (half-plane in 2D) {x : normal·(x − point) ≤ 0} through <c>FromPointNormal</c>.</summary>
        public static Spec HalfSpace(int dim, Vector3D point, Vector3D normal) =>
            new Spec(Kind.HalfSpace, dim, false, Flat(point, dim), Flat(normal, dim), 0, default, ObbForm.None, Array.Empty<double>());

        /// <summary>A half-space {x : normal·x ≤ offset} (the normal as given) through the constructor <c>new HalfSpace(normal, offset)</c>.</summary>
        public static Spec HalfSpaceOffset(int dim, Vector3D normal, double offset) =>
            new Spec(Kind.HalfSpace, dim, false, default, Flat(normal, dim), offset, default, ObbForm.None, Array.Empty<double>(), true);

        private static Vector3D Abs(Vector3D v) => new Vector3D(Math.Abs(v.X), Math.Abs(v.Y), Math.Abs(v.Z));

        private Spec With(Vector3D p, Vector3D q, double r, Vector3D h, bool isFloat, double[] rot) =>
            new Spec(Kind, Dim, isFloat, p, q, r, h, Form, rot, ByOffset);

        /// <summary>True when the point fields are positions (translated with the shape), Q included.</summary>
        private bool QIsPosition => Kind == Kind.Segment || Kind == Kind.Aabb || Kind == Kind.Capsule || Kind == Kind.Triangle;

        /// <summary>True when H is a position (a triangle's third vertex).</summary>
        private bool HIsPosition => Kind == Kind.Triangle;

        /// <summary>The boundary point an offset-form half-space stores (what its translation moves).</summary>
        private Vector3D StoredPoint()
        {
            var built = Core.DoubleForm(Build());
            return built is Dbl.HalfSpace h ? h.Point : built is Dbl.HalfPlane g ? new Vector3D(g.Point.X, g.Point.Y, 0) : P;
        }

        /// <summary>The same spec with every value rounded to float (the float API's inputs).</summary>
        public Spec ToFloat()
        {
            static double F(double x) => (float)x;
            static Vector3D V(Vector3D v) => new Vector3D(F(v.X), F(v.Y), F(v.Z));
            return With(V(P), V(Q), F(R), V(H), true, Array.ConvertAll(Rot, F));
        }

        /// <summary>Every position moved by t (t must keep the sums exact for a metamorphic check; the caller verifies).</summary>
        public Spec Translated(Vector3D t)
        {
            t = Flat(t, Dim);
            // An offset-form half-space moves its stored boundary point: the point form with the same normal (normalised
            // the same way) rebuilds the translated shape exactly; its offset would round.
            if (Kind == Kind.HalfSpace && ByOffset)
                return new Spec(Kind, Dim, Float, StoredPoint() + t, Q, 0, default, ObbForm.None, Rot);
            return With(P + t, QIsPosition ? Q + t : Q, R, HIsPosition ? H + t : H, Float, Rot);
        }

        /// <summary>Every length multiplied by 2^k (exact unless it leaves the range); rotations, directions and normals unchanged.</summary>
        public Spec ScaledBy2(int k)
        {
            static Vector3D S(Vector3D v, int k) => new Vector3D(Math.ScaleB(v.X, k), Math.ScaleB(v.Y, k), Math.ScaleB(v.Z, k));
            bool qIsLength = !(Kinds.IsLinear(Kind) || Kind == Kind.HalfSpace);
            return With(S(P, k), qIsLength ? S(Q, k) : Q, Math.ScaleB(R, k), S(H, k), Float, Rot);
        }

        /// <summary>Each input value that is a length or a position (what 2^k scaling multiplies).</summary>
        public double[] Lengths() => Kind switch
        {
            Kind.Point or Kind.Line or Kind.Ray => new[] { P.X, P.Y, P.Z },
            Kind.Segment or Kind.Aabb => new[] { P.X, P.Y, P.Z, Q.X, Q.Y, Q.Z },
            Kind.Sphere => new[] { P.X, P.Y, P.Z, R },
            Kind.Capsule => new[] { P.X, P.Y, P.Z, Q.X, Q.Y, Q.Z, R },
            Kind.Triangle => new[] { P.X, P.Y, P.Z, Q.X, Q.Y, Q.Z, H.X, H.Y, H.Z },
            // The offset form's stored point (normal·offset, rounded) must stay normal too for its scaling to be exact.
            Kind.HalfSpace when ByOffset => new[] { R }.Concat(Coordinates(StoredPoint())).ToArray(),
            Kind.HalfSpace => new[] { P.X, P.Y, P.Z },
            _ => new[] { P.X, P.Y, P.Z, H.X, H.Y, H.Z },
        };

        private static double[] Coordinates(Vector3D v) => new[] { v.X, v.Y, v.Z };

        /// <summary>Position coordinates per axis (what a translation adds to).</summary>
        public Vector3D[] Positions() => Kind switch
        {
            Kind.Triangle => new[] { P, Q, H },
            Kind.HalfSpace when ByOffset => new[] { StoredPoint() },
            _ => QIsPosition ? new[] { P, Q } : new[] { P },
        };

        /// <summary>Builds the library's shape (double or float API) through the constructor the repro prints.</summary>
        public object Build()
        {
            if (!Float)
            {
                var p2 = new Vector2D(P.X, P.Y);
                var q2 = new Vector2D(Q.X, Q.Y);
                var h2 = new Vector2D(H.X, H.Y);
                return (Kind, Dim) switch
                {
                    (Kind.Point, 3) => P,
                    (Kind.Point, _) => p2,
                    (Kind.Segment, 3) => new Dbl.Segment3(P, Q),
                    (Kind.Segment, _) => new Dbl.Segment2(p2, q2),
                    (Kind.Sphere, 3) => new Dbl.Sphere(P, R),
                    (Kind.Sphere, _) => new Dbl.Circle(p2, R),
                    (Kind.Aabb, 3) => new Dbl.Aabb3(P, Q),
                    (Kind.Aabb, _) => new Dbl.Aabb2(p2, q2),
                    (Kind.Line, 3) => new Dbl.Line3(P, Q),
                    (Kind.Line, _) => new Dbl.Line2(p2, q2),
                    (Kind.Ray, 3) => new Dbl.Ray3(P, Q),
                    (Kind.Ray, _) => new Dbl.Ray2(p2, q2),
                    (Kind.Capsule, 3) => new Dbl.Capsule3(P, Q, R),
                    (Kind.Capsule, _) => new Dbl.Capsule2(p2, q2, R),
                    (Kind.Triangle, 3) => new Dbl.Triangle3(P, Q, H),
                    (Kind.Triangle, _) => new Dbl.Triangle2(p2, q2, h2),
                    (Kind.HalfSpace, 3) => ByOffset ? new Dbl.HalfSpace(Q, R) : Dbl.HalfSpace.FromPointNormal(P, Q),
                    (Kind.HalfSpace, _) => ByOffset ? new Dbl.HalfPlane(q2, R) : Dbl.HalfPlane.FromPointNormal(p2, q2),
                    _ => Form switch
                    {
                        ObbForm.Quaternion => Dbl.Obb3.FromQuaternion(P, Rot[0], Rot[1], Rot[2], Rot[3], H),
                        ObbForm.Axes => new Dbl.Obb3(P, new Vector3D(Rot[0], Rot[1], Rot[2]), new Vector3D(Rot[3], Rot[4], Rot[5]),
                            new Vector3D(Rot[6], Rot[7], Rot[8]), H),
                        ObbForm.Angle => new Dbl.Obb2(p2, Rot[0], h2),
                        _ => new Dbl.Obb2(p2, new Vector2D(Rot[0], Rot[1]), h2),
                    },
                };
            }
            var fp = new Vector3((float)P.X, (float)P.Y, (float)P.Z);
            var fq = new Vector3((float)Q.X, (float)Q.Y, (float)Q.Z);
            var fh = new Vector3((float)H.X, (float)H.Y, (float)H.Z);
            var fp2 = new Vector2(fp.X, fp.Y);
            var fq2 = new Vector2(fq.X, fq.Y);
            var fh2 = new Vector2(fh.X, fh.Y);
            return (Kind, Dim) switch
            {
                (Kind.Point, 3) => fp,
                (Kind.Point, _) => fp2,
                (Kind.Segment, 3) => new ProximityLib.Segment3(fp, fq),
                (Kind.Segment, _) => new ProximityLib.Segment2(fp2, fq2),
                (Kind.Sphere, 3) => new ProximityLib.Sphere(fp, (float)R),
                (Kind.Sphere, _) => new ProximityLib.Circle(fp2, (float)R),
                (Kind.Aabb, 3) => new ProximityLib.Aabb3(fp, fq),
                (Kind.Aabb, _) => new ProximityLib.Aabb2(fp2, fq2),
                (Kind.Line, 3) => new ProximityLib.Line3(fp, fq),
                (Kind.Line, _) => new ProximityLib.Line2(fp2, fq2),
                (Kind.Ray, 3) => new ProximityLib.Ray3(fp, fq),
                (Kind.Ray, _) => new ProximityLib.Ray2(fp2, fq2),
                (Kind.Capsule, 3) => new ProximityLib.Capsule3(fp, fq, (float)R),
                (Kind.Capsule, _) => new ProximityLib.Capsule2(fp2, fq2, (float)R),
                (Kind.Triangle, 3) => new ProximityLib.Triangle3(fp, fq, fh),
                (Kind.Triangle, _) => new ProximityLib.Triangle2(fp2, fq2, fh2),
                (Kind.HalfSpace, 3) => ByOffset ? new ProximityLib.HalfSpace(fq, FloatOffset) : ProximityLib.HalfSpace.FromPointNormal(fp, fq),
                (Kind.HalfSpace, _) => ByOffset ? new ProximityLib.HalfPlane(fq2, FloatOffset) : ProximityLib.HalfPlane.FromPointNormal(fp2, fq2),
                _ => Form switch
                {
                    ObbForm.Quaternion => new ProximityLib.Obb3(fp, new Quaternion((float)Rot[0], (float)Rot[1], (float)Rot[2], (float)Rot[3]), fh),
                    ObbForm.Axes => new ProximityLib.Obb3(fp, new Vector3((float)Rot[0], (float)Rot[1], (float)Rot[2]),
                        new Vector3((float)Rot[3], (float)Rot[4], (float)Rot[5]), new Vector3((float)Rot[6], (float)Rot[7], (float)Rot[8]), fh),
                    ObbForm.Angle => new ProximityLib.Obb2(fp2, (float)Rot[0], fh2),
                    _ => new ProximityLib.Obb2(fp2, new Vector2((float)Rot[0], (float)Rot[1]), fh2),
                },
            };
        }

        // ---- C# source -----------------------------------------------------------------------------------------

        /// <summary>A round-trip C# literal: shortest "R" digits, negative zero kept, float literals with f.</summary>
        public static string Literal(double x, bool isFloat)
        {
            if (isFloat)
            {
                float f = (float)x;
                if (f == 0) return float.IsNegative(f) ? "-0f" : "0f";
                return f.ToString("R", CultureInfo.InvariantCulture) + "f";
            }
            if (x == 0) return double.IsNegative(x) ? "-0.0" : "0.0";
            string s = x.ToString("R", CultureInfo.InvariantCulture);
            return s.Contains('.') || s.Contains('E') ? s : s + ".0";
        }

        private string L(double x) => Literal(x, Float);

        /// <summary>The offset as the float API takes it: rounded to float, a value past float's range clamped to its largest (a generated n·p can overflow).</summary>
        private float FloatOffset => (float)Math.Max(-float.MaxValue, Math.Min(float.MaxValue, R));

        private string Vec(Vector3D v) => Dim == 3
            ? $"new {(Float ? "Vector3" : "Vector3D")}({L(v.X)}, {L(v.Y)}, {L(v.Z)})"
            : $"new {(Float ? "Vector2" : "Vector2D")}({L(v.X)}, {L(v.Y)})";

        /// <summary>The constructor call that builds this shape, in the namespace of its API (see <see cref="Usings"/>).</summary>
        public string ToCSharp()
        {
            string d = Dim == 3 ? "3" : "2";
            return Kind switch
            {
                Kind.Point => Vec(P),
                Kind.Segment => $"new Segment{d}({Vec(P)}, {Vec(Q)})",
                Kind.Sphere => $"new {(Dim == 3 ? "Sphere" : "Circle")}({Vec(P)}, {L(R)})",
                Kind.Aabb => $"new Aabb{d}({Vec(P)}, {Vec(Q)})",
                Kind.Line => $"new Line{d}({Vec(P)}, {Vec(Q)})",
                Kind.Ray => $"new Ray{d}({Vec(P)}, {Vec(Q)})",
                Kind.Capsule => $"new Capsule{d}({Vec(P)}, {Vec(Q)}, {L(R)})",
                Kind.Triangle => $"new Triangle{d}({Vec(P)}, {Vec(Q)}, {Vec(H)})",
                Kind.HalfSpace when ByOffset => $"new {(Dim == 3 ? "HalfSpace" : "HalfPlane")}({Vec(Q)}, {L(Float ? FloatOffset : R)})",
                Kind.HalfSpace => $"{(Dim == 3 ? "HalfSpace" : "HalfPlane")}.FromPointNormal({Vec(P)}, {Vec(Q)})",
                _ => Form switch
                {
                    ObbForm.Quaternion when Float => $"new Obb3({Vec(P)}, new Quaternion({L(Rot[0])}, {L(Rot[1])}, {L(Rot[2])}, {L(Rot[3])}), {Vec(H)})",
                    ObbForm.Quaternion => $"Obb3.FromQuaternion({Vec(P)}, {L(Rot[0])}, {L(Rot[1])}, {L(Rot[2])}, {L(Rot[3])}, {Vec(H)})",
                    ObbForm.Axes => $"new Obb3({Vec(P)}, {Vec(new Vector3D(Rot[0], Rot[1], Rot[2]))}, {Vec(new Vector3D(Rot[3], Rot[4], Rot[5]))}, " +
                                    $"{Vec(new Vector3D(Rot[6], Rot[7], Rot[8]))}, {Vec(H)})",
                    ObbForm.Angle => $"new Obb2({Vec(P)}, {L(Rot[0])}, {Vec(H)})",
                    _ => $"new Obb2({Vec(P)}, new Vector2{(Float ? "" : "D")}({L(Rot[0])}, {L(Rot[1])}), {Vec(H)})",
                },
            };
        }

        public static string Usings(bool isFloat) => isFloat
            ? "using System.Numerics;\nusing ProximityLib;"
            : "using ProximityLib.Double;";

        public string KindName => Kind switch
        {
            Kind.Point => "point",
            Kind.Segment => "segment",
            Kind.Sphere => Dim == 3 ? "sphere" : "circle",
            Kind.Aabb => "AABB",
            Kind.Line => "line",
            Kind.Ray => "ray",
            Kind.Capsule => "capsule",
            Kind.Triangle => "triangle",
            Kind.HalfSpace => Dim == 3 ? "half-space" : "half-plane",
            _ => "OBB",
        };

        public static bool Bits(double a, double b) => BitConverter.DoubleToInt64Bits(a) == BitConverter.DoubleToInt64Bits(b);
        public static bool Bits(Vector3D a, Vector3D b) => Bits(a.X, b.X) && Bits(a.Y, b.Y) && Bits(a.Z, b.Z);
    }
}
