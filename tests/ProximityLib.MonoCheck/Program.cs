using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Reflection;
using System.Text;
using ProximityLib.Batch;
using F = ProximityLib;
using D = ProximityLib.Double;
using FC = ProximityLib.ClosestDistance;
using FQ = ProximityLib.ProximityQuery;
using DC = ProximityLib.Double.ClosestDistance;
using DQ = ProximityLib.Double.ProximityQuery;

// The Mono smoke test's program (run.sh): every public query overload, factory, constructor and batch method of
// ProximityLib on fixed inputs (touching, overlapping, degenerate, far from the origin), every result field printed
// exactly. run.sh runs it on .NET 10 and on Mono and requires the outputs to be identical. It keeps to C# 9 and to
// what Mono 6.8's class libraries offer, since the same file is compiled against them.
namespace ProximityMonoCheck
{
    internal static class Program
    {
        private static readonly StringBuilder Out = new StringBuilder();
        private static readonly HashSet<string> Called = new HashSet<string>(StringComparer.Ordinal);
        private static readonly bool OnMono = Type.GetType("Mono.Runtime") != null;
        private static int _failures;

        private static int Main()
        {
            Run("float 3D queries", Float3);
            Run("float 2D queries", Float2);
            Run("double 3D queries", Double3);
            Run("double 2D queries", Double2);
            Run("queries with the lines, rays, capsules, triangles and half-spaces", NewShapePairs);
            Run("double factories", DoubleFactories);
            Run("float factories", FloatFactories);
            Run("batch", Batch);
            Run("large batch", LargeBatch);
            Run("ray casts", Raycasts);
            Run("coverage", Coverage);
            Console.Out.Write(Out.ToString());
            if (_failures > 0) Console.Error.WriteLine($"mono smoke: {_failures} failure(s), see the lines starting with FAIL");
            return _failures == 0 ? 0 : 1;
        }

        /// <summary>One section; a section that throws (on Mono: a MissingMethodException when its code is compiled) is reported and the rest still run.</summary>
        private static void Run(string name, Action section)
        {
            Line($"== {name}");
            try { section(); }
            catch (Exception e) { Fail($"{name}: {e.GetType().Name}: {e.Message}"); }
        }

        private static void Line(string text) => Out.Append(text).Append('\n');

        private static void Fail(string text)
        {
            _failures++;
            Line("FAIL " + text);
            Console.Error.WriteLine("FAIL " + text);
        }

        // ---- Inputs: four shapes of each kind, chosen so the 16 pairings touch, overlap, separate and degenerate;
        //      the last of each kind sits far from the origin, beside the last of every other kind. ----

        private static readonly Vector3 Far3 = new Vector3(1e6f, -2e6f, 3e5f);
        private static readonly Vector2 Far2 = new Vector2(1e6f, -2e6f);

        private static readonly Vector3[] P3 = { Vector3.Zero, new Vector3(1, 0, 0), new Vector3(0.5f, 2, -0.25f), Far3 + new Vector3(0.5f, 0, 0) };
        private static readonly F.Sphere[] S3 =
        {
            new F.Sphere(Vector3.Zero, 1), new F.Sphere(new Vector3(2, 0, 0), 1), new F.Sphere(new Vector3(0.25f, 0.25f, 0.25f), 0), new F.Sphere(Far3, 0.5f),
        };
        private static readonly F.Segment3[] G3 =
        {
            new F.Segment3(new Vector3(-1, 0, 0), new Vector3(1, 0, 0)), new F.Segment3(new Vector3(1.5f, -1, 0.5f), new Vector3(1.5f, 1, 0.5f)),
            new F.Segment3(new Vector3(3, 0, 0), new Vector3(3, 0, 0)), new F.Segment3(Far3 + new Vector3(-1, 0.5f, 0), Far3 + new Vector3(1, 0.5f, 0)),
        };
        private static readonly F.Aabb3[] A3 =
        {
            new F.Aabb3(Vector3.Zero, Vector3.One), F.Aabb3.FromCenter(new Vector3(2.5f, 0, 0), new Vector3(0.5f)),
            new F.Aabb3(new Vector3(-1, -1, 0), new Vector3(1, 1, 0)), F.Aabb3.FromCenter(Far3 + new Vector3(0, 0, 1), new Vector3(1, 1, 0.5f)),
        };
        // Quaternions are written out: CreateFromAxisAngle would bring the runtimes' own float sine into the inputs.
        private static readonly F.Obb3[] B3 =
        {
            new F.Obb3(Vector3.Zero, new Quaternion(0, 0, 0.38268343f, 0.9238795f), new Vector3(1, 0.5f, 0.25f)),
            new F.Obb3(Vector3.One, new Quaternion(0.1f, 0.2f, 0.3f, 0.9f), new Vector3(0.5f)),
            new F.Obb3(new Vector3(2, 0, 0), Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ, Vector3.Zero),
            new F.Obb3(Far3, new Quaternion(0.25881904f, 0, 0, 0.9659258f), new Vector3(1, 2, 0.5f)),
        };

        private static readonly Vector2[] P2 = { Vector2.Zero, new Vector2(1, 0), new Vector2(0.5f, 2), Far2 + new Vector2(0.5f, 0) };
        private static readonly F.Circle[] C2 =
        {
            new F.Circle(Vector2.Zero, 1), new F.Circle(new Vector2(2, 0), 1), new F.Circle(new Vector2(0.25f, 0.25f), 0), new F.Circle(Far2, 0.5f),
        };
        private static readonly F.Segment2[] G2 =
        {
            new F.Segment2(new Vector2(-1, 0), new Vector2(1, 0)), new F.Segment2(new Vector2(1.5f, -1), new Vector2(1.5f, 1)),
            new F.Segment2(new Vector2(3, 0), new Vector2(3, 0)), new F.Segment2(Far2 + new Vector2(-1, 0.5f), Far2 + new Vector2(1, 0.5f)),
        };
        private static readonly F.Aabb2[] A2 =
        {
            new F.Aabb2(Vector2.Zero, Vector2.One), F.Aabb2.FromCenter(new Vector2(2.5f, 0), new Vector2(0.5f)),
            new F.Aabb2(new Vector2(-1, 0), new Vector2(1, 0)), F.Aabb2.FromCenter(Far2 + new Vector2(0, 1), new Vector2(1, 0.5f)),
        };
        private static readonly F.Obb2[] B2 =
        {
            new F.Obb2(Vector2.Zero, 0.7853982f, new Vector2(1, 0.5f)), new F.Obb2(Vector2.One, new Vector2(0.6f, 0.8f), new Vector2(0.5f)),
            new F.Obb2(new Vector2(2, 0), Vector2.UnitX, Vector2.Zero), new F.Obb2(Far2, 0.5235988f, new Vector2(1, 2)),
        };

        // ---- The 300 query overloads: every ordered pair of kinds, Between, Distance and Overlaps, float and double. ----

        private static void Float3() => EveryPair(typeof(FC), typeof(FQ), P3, G3, S3, A3, B3);

        private static void Float2() => EveryPair(typeof(FC), typeof(FQ), P2, G2, C2, A2, B2);

        private static void Double3() => EveryPair(typeof(DC), typeof(DQ), Array.ConvertAll(P3, x => (D.Vector3D)x), Array.ConvertAll(G3, x => (D.Segment3)x),
            Array.ConvertAll(S3, x => (D.Sphere)x), Array.ConvertAll(A3, x => (D.Aabb3)x), Array.ConvertAll(B3, x => (D.Obb3)x));

        private static void Double2() => EveryPair(typeof(DC), typeof(DQ), Array.ConvertAll(P2, x => (D.Vector2D)x), Array.ConvertAll(G2, x => (D.Segment2)x),
            Array.ConvertAll(C2, x => (D.Circle)x), Array.ConvertAll(A2, x => (D.Aabb2)x), Array.ConvertAll(B2, x => (D.Obb2)x));

        /// <summary><see cref="Pairs"/> on every ordered pair of the sample sets, in the order given.</summary>
        private static void EveryPair(Type distance, Type proximity, params Array[] sets)
        {
            foreach (var a in sets)
                foreach (var b in sets)
                    Pairs(distance, proximity, a, b);
        }

        // ---- The pairs with the shapes of issue 12: every such public overload, found by reflection, on four inputs per
        //      shape (the float ones and the double forms they hold), so a pair is covered the moment it exists. ----

        private static readonly Vector3[] Dir3 = { Vector3.UnitX, new Vector3(1, 1, 0), new Vector3(-1, 2, 0.5f), new Vector3(0, 0, -1) };
        private static readonly Vector2[] Dir2 = { Vector2.UnitX, new Vector2(1, 1), new Vector2(-1, 2), new Vector2(0, -1) };

        private static readonly Dictionary<Type, object[]> FloatSamples = new Dictionary<Type, object[]>
        {
            [typeof(Vector3)] = P3.Cast<object>().ToArray(), [typeof(F.Segment3)] = G3.Cast<object>().ToArray(),
            [typeof(F.Sphere)] = S3.Cast<object>().ToArray(), [typeof(F.Aabb3)] = A3.Cast<object>().ToArray(), [typeof(F.Obb3)] = B3.Cast<object>().ToArray(),
            [typeof(Vector2)] = P2.Cast<object>().ToArray(), [typeof(F.Segment2)] = G2.Cast<object>().ToArray(),
            [typeof(F.Circle)] = C2.Cast<object>().ToArray(), [typeof(F.Aabb2)] = A2.Cast<object>().ToArray(), [typeof(F.Obb2)] = B2.Cast<object>().ToArray(),
            [typeof(F.Line3)] = Enumerable.Range(0, 4).Select(i => (object)new F.Line3(P3[i] + new Vector3(0, 0.5f, 0), Dir3[i])).ToArray(),
            [typeof(F.Ray3)] = Enumerable.Range(0, 4).Select(i => (object)new F.Ray3(P3[i] + new Vector3(-2, 0, 0), Dir3[i])).ToArray(),
            [typeof(F.Capsule3)] = Enumerable.Range(0, 4).Select(i => (object)new F.Capsule3(G3[i].Start, G3[i].End, 0.25f * i)).ToArray(),
            [typeof(F.Triangle3)] = Enumerable.Range(0, 4).Select(i => (object)new F.Triangle3(P3[i], P3[i] + Dir3[i], P3[i] + new Vector3(0, 1, 1))).ToArray(),
            [typeof(F.HalfSpace)] = Enumerable.Range(0, 4).Select(i => (object)F.HalfSpace.FromPointNormal(P3[i], Dir3[(i + 1) % 4])).ToArray(),
            [typeof(F.Line2)] = Enumerable.Range(0, 4).Select(i => (object)new F.Line2(P2[i] + new Vector2(0, 0.5f), Dir2[i])).ToArray(),
            [typeof(F.Ray2)] = Enumerable.Range(0, 4).Select(i => (object)new F.Ray2(P2[i] + new Vector2(-2, 0), Dir2[i])).ToArray(),
            [typeof(F.Capsule2)] = Enumerable.Range(0, 4).Select(i => (object)new F.Capsule2(G2[i].Start, G2[i].End, 0.25f * i)).ToArray(),
            [typeof(F.Triangle2)] = Enumerable.Range(0, 4).Select(i => (object)new F.Triangle2(P2[i], P2[i] + Dir2[i], P2[i] + new Vector2(-1, 1))).ToArray(),
            [typeof(F.HalfPlane)] = Enumerable.Range(0, 4).Select(i => (object)F.HalfPlane.FromPointNormal(P2[i], Dir2[(i + 1) % 4])).ToArray(),
        };

        private static readonly Type[] NewShapes =
        {
            typeof(F.Line3), typeof(F.Ray3), typeof(F.Capsule3), typeof(F.Triangle3), typeof(F.HalfSpace),
            typeof(F.Line2), typeof(F.Ray2), typeof(F.Capsule2), typeof(F.Triangle2), typeof(F.HalfPlane),
        };

        /// <summary>The double form of a float sample: the vector cast, or the shape's implicit conversion.</summary>
        private static object Widen(object x) => x switch
        {
            Vector3 v => (D.Vector3D)v,
            Vector2 v => (D.Vector2D)v,
            _ => x.GetType().GetMethods(BindingFlags.Public | BindingFlags.Static).First(m => m.Name == "op_Implicit" && m.GetParameters()[0].ParameterType == x.GetType()).Invoke(null, new[] { x })!,
        };

        private static void NewShapePairs()
        {
            var doubleSamples = FloatSamples.ToDictionary(kv => Widen(kv.Value[0]).GetType(), kv => kv.Value.Select(Widen).ToArray());
            var newTypes = new HashSet<Type>(NewShapes.Concat(NewShapes.Select(t => Widen(FloatSamples[t][0]).GetType())));
            foreach (var (type, samples) in new[] { (typeof(FC), FloatSamples), (typeof(FQ), FloatSamples), (typeof(DC), doubleSamples), (typeof(DQ), doubleSamples) })
            {
                var methods = type.GetMethods(BindingFlags.Public | BindingFlags.Static | BindingFlags.DeclaredOnly)
                    .Where(m => (m.Name == "Between" || m.Name == "Distance" || m.Name == "Overlaps") && m.GetParameters().Length == 2
                                && m.GetParameters().Any(p => newTypes.Contains(Shape(p))))
                    .OrderBy(Signature, StringComparer.Ordinal);
                foreach (var m in methods)
                {
                    var ps = m.GetParameters();
                    if (!samples.TryGetValue(Shape(ps[0]), out var a) || !samples.TryGetValue(Shape(ps[1]), out var b))
                    {
                        Fail($"no samples for {Signature(m)}");
                        continue;
                    }
                    Called.Add(Signature(m));
                    for (int i = 0; i < a.Length; i++)
                        for (int j = 0; j < b.Length; j++)
                            Line($"{Signature(m)} [{i},{j}] {Show(m.Invoke(null, new[] { a[i], b[j] }))}");
                }
            }
        }

        /// <summary>
        /// Between, Distance and Overlaps on every pairing of a and b. A shape may be an <c>in</c> parameter (the double
        /// API's always are, the float API's where the kernel takes it so), and a method group of such an overload does
        /// not convert to a Func of by-value parameters, so the overloads are found by reflection (the ones the compiler
        /// would pick: the shape types exactly) and invoked.
        /// </summary>
        private static void Pairs(Type distanceOwner, Type proximityOwner, Array a, Array b)
        {
            Type ta = a.GetType().GetElementType()!, tb = b.GetType().GetElementType()!;
            MethodInfo Find(Type owner, string name) => owner.GetMethods(BindingFlags.Public | BindingFlags.Static | BindingFlags.DeclaredOnly)
                .Single(m => m.Name == name && m.GetParameters() is var ps && ps.Length == 2 && Shape(ps[0]) == ta && Shape(ps[1]) == tb);
            MethodInfo between = Find(distanceOwner, "Between"), distance = Find(distanceOwner, "Distance"), overlaps = Find(proximityOwner, "Overlaps");
            Called.Add(Signature(between));
            Called.Add(Signature(distance));
            Called.Add(Signature(overlaps));
            string kinds = $"({ta.Name}, {tb.Name})";
            for (int i = 0; i < a.Length; i++)
            {
                for (int j = 0; j < b.Length; j++)
                {
                    var args = new[] { a.GetValue(i)!, b.GetValue(j)! };
                    Line($"Between{kinds} [{i},{j}] {Show(between.Invoke(null, args))}");
                    Line($"Distance{kinds} [{i},{j}] {Show(distance.Invoke(null, args))}");
                    Line($"Overlaps{kinds} [{i},{j}] {Show(overlaps.Invoke(null, args))}");
                }
            }
        }

        /// <summary>A parameter's shape type: the element type of an <c>in</c> parameter.</summary>
        private static Type Shape(ParameterInfo p) => p.ParameterType.IsByRef ? p.ParameterType.GetElementType()! : p.ParameterType;

        // ---- Factories and constructors, valid and invalid input. ----

        private static D.Vector3D V(double x, double y, double z) => new D.Vector3D(x, y, z);
        private static D.Vector2D V(double x, double y) => new D.Vector2D(x, y);

        private static void DoubleFactories()
        {
            var h = V(1, 2, 0.5);
            Make(typeof(D.Vector3D), ".ctor", new[] { typeof(double), typeof(double), typeof(double) }, () => V(1, -2, 3e-300));
            Make(typeof(D.Vector2D), ".ctor", new[] { typeof(double), typeof(double) }, () => V(1e300, -0.0));
            Make(typeof(D.Segment3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Segment3(V(1, 2, 3), V(1, 2, 3)), () => new D.Segment3(V(0, 0, 0), V(double.NaN, 0, 0)));
            Make(typeof(D.Segment2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Segment2(V(1, 2), V(-3, 4)), () => new D.Segment2(V(double.PositiveInfinity, 0), V(0, 0)));
            Make(typeof(D.Sphere), ".ctor", new[] { typeof(D.Vector3D), typeof(double) },
                () => new D.Sphere(V(1, 2, 3), 0), () => new D.Sphere(V(1, 2, 3), -1e-300));
            Make(typeof(D.Circle), ".ctor", new[] { typeof(D.Vector2D), typeof(double) },
                () => new D.Circle(V(1, 2), 1e300), () => new D.Circle(V(1, 2), double.NaN));
            Make(typeof(D.Aabb3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Aabb3(V(0, 0, 0), V(0, 1, 2)), () => new D.Aabb3(V(0, 2, 0), V(1, 1, 1)));
            Make(typeof(D.Aabb3), "FromOrigin", new[] { typeof(D.Vector3D), typeof(double), typeof(double), typeof(double) },
                () => D.Aabb3.FromOrigin(V(1, 1, 1), 1, 2, 3), () => D.Aabb3.FromOrigin(V(1, 1, 1), 1, -2, 3));
            Make(typeof(D.Aabb3), "FromCenter", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => D.Aabb3.FromCenter(V(1e6, 0, 0), V(0.1, 0, 3)), () => D.Aabb3.FromCenter(V(0, 0, 0), V(0, -1, 0)));
            Make(typeof(D.Aabb2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Aabb2(V(-1, -1), V(1, 1)), () => new D.Aabb2(V(0, 0), V(-1, 1)));
            Make(typeof(D.Aabb2), "FromOrigin", new[] { typeof(D.Vector2D), typeof(double), typeof(double) },
                () => D.Aabb2.FromOrigin(V(1, 1), 0, 2), () => D.Aabb2.FromOrigin(V(1, 1), double.NaN, 2));
            Make(typeof(D.Aabb2), "FromCenter", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => D.Aabb2.FromCenter(V(0.5, 0.25), V(3, 0)), () => D.Aabb2.FromCenter(V(0, 0), V(-3, 0)));
            double r = Math.Sqrt(0.5);
            Make(typeof(D.Obb3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D), typeof(D.Vector3D), typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Obb3(V(1, 2, 3), V(r, r, 0), V(-r, r, 0), V(0, 0, 1), h),
                () => new D.Obb3(V(1, 2, 3), V(1.00004, 0, 0), V(0, 0.99996, 0.00002), V(0, 0, 1), h),
                () => new D.Obb3(V(1, 2, 3), V(2, 0, 0), V(0, 0.5, 0), V(0, 0, 1e-200), h),
                () => new D.Obb3(V(0, 0, 0), V(1, 0, 0), V(0.001, 1, 0), V(0, 0, 1), h),
                () => new D.Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 0), h),
                () => new D.Obb3(V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, -1, 1)));
            Make(typeof(D.Obb3), ".ctor", new[] { typeof(D.Vector3D), typeof(Quaternion), typeof(D.Vector3D) },
                () => new D.Obb3(V(1, 2, 3), new Quaternion(0.1f, 0.2f, 0.3f, 0.9f), h),
                () => new D.Obb3(V(1, 2, 3), new Quaternion(0, 0, 0, 0), h),
                () => new D.Obb3(V(1, 2, 3), new Quaternion(0, float.NaN, 0, 1), h));
            Make(typeof(D.Obb3), "FromQuaternion", new[] { typeof(D.Vector3D), typeof(double), typeof(double), typeof(double), typeof(double), typeof(D.Vector3D) },
                () => D.Obb3.FromQuaternion(V(-1e6, 0, 0), 1, 2, 3, 4, h),
                () => D.Obb3.FromQuaternion(V(0, 0, 0), 1e-200, 2e-200, 3e-200, 4e-200, h),
                () => D.Obb3.FromQuaternion(V(0, 0, 0), 1e200, 2e200, 3e200, 4e200, h),
                () => D.Obb3.FromQuaternion(V(0, 0, 0), 0, 0, 0, 0, h),
                () => D.Obb3.FromQuaternion(V(0, 0, 0), 0, 0, double.PositiveInfinity, 1, h));
            Make(typeof(D.Obb3), "FromCorners", new[] { typeof(ReadOnlySpan<D.Vector3D>), typeof(D.Vector3D), typeof(D.Vector3D), typeof(D.Vector3D) },
                () => D.Obb3.FromCorners(new[] { V(0, 0, 0), V(2, 0, 0), V(0, 1, 0), V(2, 1, 0), V(0, 0, 3), V(2, 0, 3), V(0, 1, 3), V(2, 1, 3) }, V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)),
                () => D.Obb3.FromCorners(new[] { V(1e6, 0, 0), V(1e6 + r, r, 0), V(1e6 - r, r, 0), V(1e6, 2 * r, 0), V(1e6, 0, 1), V(1e6 + r, r, 1), V(1e6 - r, r, 1), V(1e6, 2 * r, 1) }, V(r, r, 0), V(-r, r, 0), V(0, 0, 1)),
                () => D.Obb3.FromCorners(new D.Vector3D[7], V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)),
                () => D.Obb3.FromCorners(new D.Vector3D[8], V(1, 0, 0), V(1, 0, 0), V(0, 0, 1)));
            Make(typeof(D.Obb2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Obb2(V(1, 2), V(0.6, 0.8), V(1, 2)), () => new D.Obb2(V(1, 2), V(3, 4), V(1, 2)),
                () => new D.Obb2(V(1, 2), V(0, 0), V(1, 2)), () => new D.Obb2(V(1, 2), V(1, 0), V(1, -2)));
            Make(typeof(D.Obb2), ".ctor", new[] { typeof(D.Vector2D), typeof(double), typeof(D.Vector2D) },
                () => new D.Obb2(V(1, 2), 0.25, V(1, 2)), () => new D.Obb2(V(1, 2), double.NaN, V(1, 2)));
            Make(typeof(D.Obb2), "FromCorners", new[] { typeof(ReadOnlySpan<D.Vector2D>), typeof(D.Vector2D), typeof(D.Vector2D) },
                () => D.Obb2.FromCorners(new[] { V(0, 0), V(2, 0), V(2, 1), V(0, 1) }, V(1, 0), V(0, 1)),
                () => D.Obb2.FromCorners(new[] { V(0, 0), V(0.6, 0.8), V(-1.0, 2.0), V(-1.6, 1.2) }, V(0.6, 0.8), V(-0.8, 0.6)),
                () => D.Obb2.FromCorners(new D.Vector2D[3], V(1, 0), V(0, 1)));
            Make(typeof(D.Line3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Line3(V(1, 2, 3), V(3e-300, 4e-300, 0)), () => new D.Line3(V(1, 2, 3), V(0, 0, 0)));
            Make(typeof(D.Line2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Line2(V(1, 2), V(3e300, -4e300)), () => new D.Line2(V(double.NaN, 2), V(1, 0)));
            Make(typeof(D.Ray3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Ray3(V(-1, 0, 0), V(1, 1, 1)), () => new D.Ray3(V(0, 0, 0), V(double.PositiveInfinity, 0, 0)));
            Make(typeof(D.Ray2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Ray2(V(0, 0), V(0, -2)), () => new D.Ray2(V(0, 0), V(0, 0)));
            Make(typeof(D.Capsule3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D), typeof(double) },
                () => new D.Capsule3(V(0, 0, 0), V(0, 2, 0), 0.5), () => new D.Capsule3(V(0, 0, 0), V(0, 2, 0), -0.5));
            Make(typeof(D.Capsule2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D), typeof(double) },
                () => new D.Capsule2(V(1, 1), V(1, 1), 0), () => new D.Capsule2(V(1, 1), V(1, double.NaN), 1));
            Make(typeof(D.Triangle3), ".ctor", new[] { typeof(D.Vector3D), typeof(D.Vector3D), typeof(D.Vector3D) },
                () => new D.Triangle3(V(0, 0, 0), V(1, 0, 0), V(2, 0, 0)), () => new D.Triangle3(V(0, 0, 0), V(1, 0, 0), V(0, double.NaN, 0)));
            Make(typeof(D.Triangle2), ".ctor", new[] { typeof(D.Vector2D), typeof(D.Vector2D), typeof(D.Vector2D) },
                () => new D.Triangle2(V(0, 0), V(1, 0), V(0, 1)), () => new D.Triangle2(V(0, 0), V(1, 0), V(double.NegativeInfinity, 1)));
            Make(typeof(D.HalfSpace), ".ctor", new[] { typeof(D.Vector3D), typeof(double) },
                () => new D.HalfSpace(V(0, 3, 4), 10), () => new D.HalfSpace(V(1e-300, 0, 0), 1e300), () => new D.HalfSpace(V(0, 0, 0), 1));
            Make(typeof(D.HalfSpace), "FromPointNormal", new[] { typeof(D.Vector3D), typeof(D.Vector3D) },
                () => D.HalfSpace.FromPointNormal(V(1e6, 0, 1), V(0, 0, 2)), () => D.HalfSpace.FromPointNormal(V(1, 0, 1), V(0, double.NaN, 2)));
            Make(typeof(D.HalfPlane), ".ctor", new[] { typeof(D.Vector2D), typeof(double) },
                () => new D.HalfPlane(V(-3, 4), 1), () => new D.HalfPlane(V(1, 0), double.NaN));
            Make(typeof(D.HalfPlane), "FromPointNormal", new[] { typeof(D.Vector2D), typeof(D.Vector2D) },
                () => D.HalfPlane.FromPointNormal(V(2, 3), V(0, 1e-310)), () => D.HalfPlane.FromPointNormal(V(2, 3), V(0, 0)));
        }

        private static void FloatFactories()
        {
            var h = new Vector3(1, 2, 0.5f);
            Make(typeof(F.Segment3), ".ctor", new[] { typeof(Vector3), typeof(Vector3) },
                () => new F.Segment3(new Vector3(1, 2, 3), new Vector3(4, 5, 6)), () => new F.Segment3(new Vector3(float.NaN), Vector3.Zero));
            Make(typeof(F.Segment2), ".ctor", new[] { typeof(Vector2), typeof(Vector2) },
                () => new F.Segment2(new Vector2(1, 2), new Vector2(1, 2)), () => new F.Segment2(Vector2.Zero, new Vector2(float.NegativeInfinity, 0)));
            Make(typeof(F.Sphere), ".ctor", new[] { typeof(Vector3), typeof(float) },
                () => new F.Sphere(Far3, 3.5f), () => new F.Sphere(Vector3.Zero, -1));
            Make(typeof(F.Circle), ".ctor", new[] { typeof(Vector2), typeof(float) },
                () => new F.Circle(Far2, 0), () => new F.Circle(new Vector2(float.NaN, 0), 1));
            Make(typeof(F.Aabb3), ".ctor", new[] { typeof(Vector3), typeof(Vector3) },
                () => new F.Aabb3(Vector3.Zero, Vector3.One), () => new F.Aabb3(Vector3.One, Vector3.Zero));
            Make(typeof(F.Aabb3), "FromOrigin", new[] { typeof(Vector3), typeof(float), typeof(float), typeof(float) },
                () => F.Aabb3.FromOrigin(Far3, 1, 0, 0.1f), () => F.Aabb3.FromOrigin(Vector3.Zero, 1, 1, -1));
            Make(typeof(F.Aabb3), "FromCenter", new[] { typeof(Vector3), typeof(Vector3) },
                () => F.Aabb3.FromCenter(Vector3.One, new Vector3(0.1f)), () => F.Aabb3.FromCenter(Vector3.One, new Vector3(-0.1f)));
            Make(typeof(F.Aabb2), ".ctor", new[] { typeof(Vector2), typeof(Vector2) },
                () => new F.Aabb2(Vector2.Zero, Vector2.Zero), () => new F.Aabb2(Vector2.One, Vector2.Zero));
            Make(typeof(F.Aabb2), "FromOrigin", new[] { typeof(Vector2), typeof(float), typeof(float) },
                () => F.Aabb2.FromOrigin(Far2, 2, 3), () => F.Aabb2.FromOrigin(Vector2.Zero, 1, -1));
            Make(typeof(F.Aabb2), "FromCenter", new[] { typeof(Vector2), typeof(Vector2) },
                () => F.Aabb2.FromCenter(Vector2.One, new Vector2(0.1f)), () => F.Aabb2.FromCenter(Vector2.One, new Vector2(float.NaN)));
            Make(typeof(F.Obb3), ".ctor", new[] { typeof(Vector3), typeof(Quaternion), typeof(Vector3) },
                () => new F.Obb3(Far3, new Quaternion(0.1f, 0.2f, 0.3f, 0.9f), h), () => new F.Obb3(Vector3.Zero, new Quaternion(1e-30f, 0, 0, 1e-30f), h),
                () => new F.Obb3(Vector3.Zero, default(Quaternion), h));
            Make(typeof(F.Obb3), ".ctor", new[] { typeof(Vector3), typeof(Vector3), typeof(Vector3), typeof(Vector3), typeof(Vector3) },
                () => new F.Obb3(Vector3.One, Vector3.UnitY, Vector3.UnitZ, Vector3.UnitX, h),
                () => new F.Obb3(Vector3.One, new Vector3(0.6f, 0.8f, 0), new Vector3(-0.8f, 0.6f, 0), Vector3.UnitZ, h),
                () => new F.Obb3(Vector3.One, Vector3.UnitX, Vector3.UnitX, Vector3.UnitZ, h));
            var corners = new[]
            {
                new Vector3(0, 0, 0), new Vector3(2, 0, 0), new Vector3(0, 1, 0), new Vector3(2, 1, 0),
                new Vector3(0, 0, 3), new Vector3(2, 0, 3), new Vector3(0, 1, 3), new Vector3(2, 1, 3),
            };
            Make(typeof(F.Obb3), "FromCorners", new[] { typeof(ReadOnlySpan<Vector3>), typeof(Vector3), typeof(Vector3), typeof(Vector3) },
                () => F.Obb3.FromCorners(corners, Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ),
                () => F.Obb3.FromCorners(corners.AsSpan(0, 4), Vector3.UnitX, Vector3.UnitY, Vector3.UnitZ));
            Make(typeof(F.Obb2), ".ctor", new[] { typeof(Vector2), typeof(Vector2), typeof(Vector2) },
                () => new F.Obb2(Far2, new Vector2(0.6f, 0.8f), Vector2.One), () => new F.Obb2(Vector2.Zero, new Vector2(float.NaN, 1), Vector2.One));
            Make(typeof(F.Obb2), ".ctor", new[] { typeof(Vector2), typeof(float), typeof(Vector2) },
                () => new F.Obb2(Far2, 1.5f, Vector2.One), () => new F.Obb2(Vector2.Zero, 0, -Vector2.One));
            Make(typeof(F.Obb2), "FromCorners", new[] { typeof(ReadOnlySpan<Vector2>), typeof(Vector2), typeof(Vector2) },
                () => F.Obb2.FromCorners(new[] { Vector2.Zero, new Vector2(2, 0), new Vector2(2, 1), new Vector2(0, 1) }, Vector2.UnitX, Vector2.UnitY),
                () => F.Obb2.FromCorners(new Vector2[5], Vector2.UnitX, Vector2.UnitY));
            Make(typeof(F.Line3), ".ctor", new[] { typeof(Vector3), typeof(Vector3) },
                () => new F.Line3(Far3, new Vector3(0, 0, 1e-30f)), () => new F.Line3(Vector3.One, Vector3.Zero));
            Make(typeof(F.Line2), ".ctor", new[] { typeof(Vector2), typeof(Vector2) },
                () => new F.Line2(Vector2.One, new Vector2(3, 4)), () => new F.Line2(new Vector2(float.NaN), Vector2.UnitX));
            Make(typeof(F.Ray3), ".ctor", new[] { typeof(Vector3), typeof(Vector3) },
                () => new F.Ray3(Vector3.Zero, new Vector3(1e30f, 1e30f, 0)), () => new F.Ray3(Vector3.Zero, new Vector3(0, float.NaN, 1)));
            Make(typeof(F.Ray2), ".ctor", new[] { typeof(Vector2), typeof(Vector2) },
                () => new F.Ray2(Far2, -Vector2.UnitY), () => new F.Ray2(Far2, Vector2.Zero));
            Make(typeof(F.Capsule3), ".ctor", new[] { typeof(Vector3), typeof(Vector3), typeof(float) },
                () => new F.Capsule3(Vector3.Zero, Vector3.UnitY, 0.25f), () => new F.Capsule3(Vector3.Zero, Vector3.UnitY, float.PositiveInfinity));
            Make(typeof(F.Capsule2), ".ctor", new[] { typeof(Vector2), typeof(Vector2), typeof(float) },
                () => new F.Capsule2(Far2, Far2, 1), () => new F.Capsule2(Vector2.Zero, Vector2.UnitY, -1));
            Make(typeof(F.Triangle3), ".ctor", new[] { typeof(Vector3), typeof(Vector3), typeof(Vector3) },
                () => new F.Triangle3(Vector3.Zero, Vector3.UnitX, Vector3.UnitY), () => new F.Triangle3(Vector3.Zero, new Vector3(float.NaN), Vector3.UnitY));
            Make(typeof(F.Triangle2), ".ctor", new[] { typeof(Vector2), typeof(Vector2), typeof(Vector2) },
                () => new F.Triangle2(Vector2.One, Vector2.One, Vector2.One), () => new F.Triangle2(Vector2.One, Vector2.One, new Vector2(0, float.PositiveInfinity)));
            Make(typeof(F.HalfSpace), ".ctor", new[] { typeof(Vector3), typeof(float) },
                () => new F.HalfSpace(new Vector3(0, 2, 0), -1), () => new F.HalfSpace(Vector3.Zero, 0));
            Make(typeof(F.HalfSpace), "FromPointNormal", new[] { typeof(Vector3), typeof(Vector3) },
                () => F.HalfSpace.FromPointNormal(Far3, new Vector3(1, 1, 1)), () => F.HalfSpace.FromPointNormal(new Vector3(float.NaN), Vector3.UnitY));
            Make(typeof(F.HalfPlane), ".ctor", new[] { typeof(Vector2), typeof(float) },
                () => new F.HalfPlane(new Vector2(1, 1), 2), () => new F.HalfPlane(Vector2.UnitX, float.NaN));
            Make(typeof(F.HalfPlane), "FromPointNormal", new[] { typeof(Vector2), typeof(Vector2) },
                () => F.HalfPlane.FromPointNormal(Far2, new Vector2(0, -3)), () => F.HalfPlane.FromPointNormal(Far2, Vector2.Zero));
        }

        /// <summary>Marks the member with this exact signature as called and prints what each case makes (or the parameter it is refused for).</summary>
        private static void Make(Type type, string member, Type[] signature, params Func<object>[] cases)
        {
            MethodBase? m = member == ".ctor" ? (MethodBase?)type.GetConstructor(signature) : type.GetMethod(member, signature);
            if (m == null) throw new MissingMemberException(type.FullName, member);
            Called.Add(Signature(m));
            for (int i = 0; i < cases.Length; i++) Line($"{Signature(m)} [{i}] {Attempt(cases[i])}");
        }

        private static string Attempt(Func<object> make)
        {
            try { return Show(make()); }
            catch (ArgumentException e) { return $"throws {e.GetType().Name} ({e.ParamName})"; }
        }

        // ---- Batch queries: 11 shapes per set, so the lanes end in a partial vector on every SIMD width. ----

        private delegate void Into<TA, TB, TR>(TA a, TB b, Span<TR> result);

        private const int N = 11;

        private static float Grid(int i, int mul, int mod, float step, float offset) => (i * mul % mod) * step + offset;

        private static Vector3 At(int i, int salt) => new Vector3(Grid(i + salt, 7, 11, 0.5f, -2.5f), Grid(i + salt, 3, 5, 0.5f, -1), Grid(i + salt, 1, 4, 0.5f, -0.75f));

        private static void Batch()
        {
            var points = Enumerable.Range(0, N).Select(i => At(i, 0)).ToArray();
            var spheres = Enumerable.Range(0, N).Select(i => new F.Sphere(At(i, 3), (i % 3) * 0.75f)).ToArray();
            var boxes = Enumerable.Range(0, N).Select(i => F.Aabb3.FromCenter(At(i, 5), new Vector3(0.5f + (i % 2) * 0.5f, 0.25f, 1))).ToArray();
            var segments = Enumerable.Range(0, N).Select(i => new F.Segment3(At(i, 1), At(i, 7))).ToArray();
            var obbs = Enumerable.Range(0, N)
                .Select(i => new F.Obb3(At(i, 2), new Quaternion((i % 3) * 0.25f, (i % 5) * 0.125f, (i % 2) * 0.1f, 1), new Vector3(1, 0.5f, 0.25f * (i % 4))))
                .ToArray();

            var pointSet = Set(typeof(PointSet), typeof(Vector3), new PointSet(points));
            var sphereSet = Set(typeof(SphereSet), typeof(F.Sphere), new SphereSet(spheres));
            var boxSet = Set(typeof(AabbSet), typeof(F.Aabb3), new AabbSet(boxes));
            var segmentSet = Set(typeof(SegmentSet), typeof(F.Segment3), new SegmentSet(segments));
            var obbSet = Set(typeof(ObbSet), typeof(F.Obb3), new ObbSet(obbs));
            // Set replaces one shape in place: here the sixth, with a copy of the first (a coincident pair for the paired queries).
            pointSet.Set(5, points[0]);
            sphereSet.Set(5, spheres[0]);
            boxSet.Set(5, boxes[0]);
            segmentSet.Set(5, segments[0]);
            obbSet.Set(5, obbs[0]);
            var second = new SphereSet(spheres.Reverse().ToArray());
            var secondBoxes = new AabbSet(boxes.Reverse().ToArray());
            var secondSegments = new SegmentSet(segments.Reverse().ToArray());
            var secondObbs = new ObbSet(obbs.Reverse().ToArray());

            var sphere = new F.Sphere(new Vector3(0.25f, -0.5f, 0), 1);
            var point = new Vector3(0.25f, 0.5f, 0);
            var box = new F.Aabb3(new Vector3(-1, -1, -1), new Vector3(1, 0.5f, 1));
            var segment = new F.Segment3(new Vector3(-2, 0, 0), new Vector3(2, 0.5f, 0.25f));
            var obb = new F.Obb3(Vector3.Zero, new Quaternion(0, 0, 0.38268343f, 0.9238795f), new Vector3(1, 0.5f, 0.25f));

            Distances(BatchQuery.Distances, sphereSet, second);
            Distances(BatchQuery.Distances, sphere, second);
            Overlaps(BatchQuery.Overlaps, sphereSet, second);
            Overlaps(BatchQuery.Overlaps, sphere, second);
            Distances(BatchQuery.Distances, pointSet, boxSet);
            Distances(BatchQuery.Distances, point, boxSet);
            Overlaps(BatchQuery.Overlaps, pointSet, boxSet);
            Overlaps(BatchQuery.Overlaps, point, boxSet);
            Distances(BatchQuery.Distances, sphereSet, boxSet);
            Distances(BatchQuery.Distances, sphere, boxSet);
            Overlaps(BatchQuery.Overlaps, sphereSet, boxSet);
            Overlaps(BatchQuery.Overlaps, sphere, boxSet);
            Overlaps(BatchQuery.Overlaps, boxSet, secondBoxes);
            Overlaps(BatchQuery.Overlaps, box, secondBoxes);
            Distances(BatchQuery.Distances, sphereSet, obbSet);
            Distances(BatchQuery.Distances, sphere, obbSet);
            Overlaps(BatchQuery.Overlaps, sphereSet, obbSet);
            Overlaps(BatchQuery.Overlaps, sphere, obbSet);
            Distances(BatchQuery.Distances, segmentSet, secondSegments);
            Distances(BatchQuery.Distances, segment, secondSegments);
            Overlaps(BatchQuery.Overlaps, obbSet, secondObbs);
            Overlaps(BatchQuery.Overlaps, obb, secondObbs);

            var few = new SphereSet(spheres.Take(3).ToArray());
            Line($"paired sets of unequal size: {Attempt(() => { BatchQuery.Distances(few, second, new float[N]); return "no error"; })}");
            Line($"result too short: {Attempt(() => { BatchQuery.Overlaps(sphere, second, new bool[N - 1]); return "no error"; })}");
            Line($"empty set: {Attempt(() => { BatchQuery.Distances(sphere, new SphereSet(ReadOnlySpan<F.Sphere>.Empty), Span<float>.Empty); return "no error"; })}");
        }

        /// <summary>
        /// Batches above the multi-core threshold (65,536 shapes), one against many and paired: the split run must give
        /// the one-thread run's bits, and a digest of them is printed (the same on every runtime).
        /// </summary>
        private static void LargeBatch()
        {
            const int n = 70001;
            var spheres = new SphereSet(Enumerable.Range(0, n).Select(i => new F.Sphere(At(i, 3), (i % 3) * 0.75f)).ToArray());
            var segments = new SegmentSet(Enumerable.Range(0, n).Select(i => new F.Segment3(At(i, 1), At(i, 7))).ToArray());
            var obbs = Enumerable.Range(0, n)
                .Select(i => new F.Obb3(At(i, 2), new Quaternion((i % 3) * 0.25f, (i % 5) * 0.125f, (i % 2) * 0.1f, 1), new Vector3(1, 0.5f, 0.25f * (i % 4))))
                .ToArray();
            var obbSet = new ObbSet(obbs);
            var secondObbs = new ObbSet(obbs.Reverse().ToArray());
            var sphere = new F.Sphere(new Vector3(0.25f, -0.5f, 0), 1);
            var segment = new F.Segment3(new Vector3(-2, 0, 0), new Vector3(2, 0.5f, 0.25f));
            Split<float>("Distances(Sphere, SphereSet)", n, r => BatchQuery.Distances(sphere, spheres, r), f => BitConverter.ToInt32(BitConverter.GetBytes(f), 0));
            Split<float>("Distances(SegmentSet, SegmentSet)", n, r => BatchQuery.Distances(segments, segments, r), f => BitConverter.ToInt32(BitConverter.GetBytes(f), 0));
            Split<float>("Distances(Segment3, SegmentSet)", n, r => BatchQuery.Distances(segment, segments, r), f => BitConverter.ToInt32(BitConverter.GetBytes(f), 0));
            Split<bool>("Overlaps(ObbSet, ObbSet)", n, r => BatchQuery.Overlaps(obbSet, secondObbs, r), b => b ? 1 : 0);
            Split<bool>("Overlaps(Sphere, SphereSet)", n, r => BatchQuery.Overlaps(sphere, spheres, r), b => b ? 1 : 0);
        }

        /// <summary>Runs a large batch split (the default degree of parallelism) and on one thread; prints whether they agree and an FNV-1a digest.</summary>
        private static void Split<T>(string name, int n, Action<T[]> query, Func<T, int> bits)
        {
            var split = new T[n];
            query(split);
            int saved = BatchQuery.MaxDegreeOfParallelism;
            var alone = new T[n];
            try
            {
                BatchQuery.MaxDegreeOfParallelism = 1;
                query(alone);
            }
            finally { BatchQuery.MaxDegreeOfParallelism = saved; }
            uint digest = 2166136261;
            int differ = 0;
            for (int i = 0; i < n; i++)
            {
                digest = (digest ^ (uint)bits(split[i])) * 16777619;
                if (bits(split[i]) != bits(alone[i])) differ++;
            }
            Line($"{name} over {n}: digest {digest:x8}");
            if (differ > 0) Fail($"{name} over {n}: {differ} lane(s) split over cores differ from one thread");
        }

        /// <summary>Marks the set's constructor (from a span of <paramref name="shape"/>) and its Set method as called.</summary>
        private static T Set<T>(Type type, Type shape, T set)
        {
            Called.Add(Signature(type.GetConstructor(new[] { typeof(ReadOnlySpan<>).MakeGenericType(shape) }) ?? throw new MissingMemberException(type.Name, ".ctor")));
            Called.Add(Signature(type.GetMethod("Set", new[] { typeof(int), shape }) ?? throw new MissingMemberException(type.Name, "Set")));
            return set;
        }

        private static void Distances<TA, TB>(Into<TA, TB, float> query, TA a, TB b)
        {
            var result = new float[N + 1];
            result[N] = 42; // a lane past the set's count must stay untouched
            query(a, b, result);
            Called.Add(Signature(query.Method));
            Line($"{Signature(query.Method)} {Show(result)}");
        }

        private static void Overlaps<TA, TB>(Into<TA, TB, bool> query, TA a, TB b)
        {
            var result = new bool[N + 1];
            result[N] = true;
            query(a, b, result);
            Called.Add(Signature(query.Method));
            Line($"{Signature(query.Method)} {Show(result)}");
        }

        // ---- Ray casts: every Cast overload (double and float, 2D and 3D) from a few rays, and the batch ray casts. ----

        private static void Raycasts()
        {
            void Casts<TR, TS, TM, TH>(Func<TR, TS, TM, TH> cast, TR[] rays, TS[] shapes, TM max)
            {
                Called.Add(Signature(cast.Method));
                for (int i = 0; i < rays.Length; i++)
                    for (int j = 0; j < shapes.Length; j++)
                        Line($"Cast({typeof(TR).Name}, {typeof(TS).Name}) [{i},{j}] {Show(cast(rays[i], shapes[j], max))}");
            }
            var r3 = new[] { new F.Ray3(new Vector3(-3, 0.25f, 0.5f), Vector3.UnitX), new F.Ray3(new Vector3(0.5f, 3, -0.25f), new Vector3(0, -1, 0.125f)), new F.Ray3(Far3 + new Vector3(0, 0, 5), -Vector3.UnitZ) };
            var r2 = new[] { new F.Ray2(new Vector2(-3, 0.25f), Vector2.UnitX), new F.Ray2(new Vector2(0.5f, 3), new Vector2(0.125f, -1)), new F.Ray2(Far2 + new Vector2(0, 5), -Vector2.UnitY) };
            var k3 = new[] { new F.Capsule3(Vector3.Zero, Vector3.UnitX, 0.5f), new F.Capsule3(Far3, Far3 + Vector3.UnitY, 1) };
            var t3 = new[] { new F.Triangle3(new Vector3(0, -1, -1), new Vector3(0, 1, -1), new Vector3(0, 0, 2)), new F.Triangle3(Far3 - Vector3.UnitX, Far3 + Vector3.UnitX, Far3 + Vector3.UnitY) };
            var h3 = new[] { F.HalfSpace.FromPointNormal(Vector3.Zero, new Vector3(-1, 0, 0)), F.HalfSpace.FromPointNormal(Far3, Vector3.UnitZ) };
            // 3D lines and rays as targets: one crossing the first ray's path (x = 1), one along the third ray, one far off.
            var l3 = new[] { new F.Line3(new Vector3(1, 0.25f, -1), Vector3.UnitZ), new F.Line3(Far3, Vector3.UnitZ), new F.Line3(new Vector3(0, 9, 9), Vector3.UnitX) };
            var y3 = new[] { new F.Ray3(new Vector3(1, 0.25f, -1), Vector3.UnitZ), new F.Ray3(Far3 + new Vector3(0, 0, 1), Vector3.UnitZ), new F.Ray3(new Vector3(1, 0.25f, 1), Vector3.UnitZ) };
            var l2 = new[] { new F.Line2(Vector2.Zero, Vector2.UnitY), new F.Line2(Far2, Vector2.UnitX) };
            var y2 = new[] { new F.Ray2(new Vector2(1, -1), Vector2.UnitY), new F.Ray2(Far2 + Vector2.UnitX, -Vector2.UnitX) };
            var k2 = new[] { new F.Capsule2(Vector2.Zero, Vector2.UnitX, 0.5f), new F.Capsule2(Far2, Far2 + Vector2.UnitY, 1) };
            var t2 = new[] { new F.Triangle2(new Vector2(0, -1), new Vector2(0, 1), new Vector2(2, 0)), new F.Triangle2(Far2 - Vector2.UnitX, Far2 + Vector2.UnitX, Far2 + Vector2.UnitY) };
            var h2 = new[] { F.HalfPlane.FromPointNormal(Vector2.Zero, new Vector2(-1, 0)), F.HalfPlane.FromPointNormal(Far2, Vector2.UnitY) };
            Casts<F.Ray3, Vector3, float, F.RayHit3>(F.Raycast.Cast, r3, P3, float.PositiveInfinity);
            Casts<F.Ray3, F.Segment3, float, F.RayHit3>(F.Raycast.Cast, r3, G3, 4);
            Casts<F.Ray3, F.Sphere, float, F.RayHit3>(F.Raycast.Cast, r3, S3, float.PositiveInfinity);
            Casts<F.Ray3, F.Capsule3, float, F.RayHit3>(F.Raycast.Cast, r3, k3, float.PositiveInfinity);
            Casts<F.Ray3, F.Triangle3, float, F.RayHit3>(F.Raycast.Cast, r3, t3, float.PositiveInfinity);
            Casts<F.Ray3, F.HalfSpace, float, F.RayHit3>(F.Raycast.Cast, r3, h3, float.PositiveInfinity);
            Casts<F.Ray3, F.Aabb3, float, F.RayHit3>(F.Raycast.Cast, r3, A3, 3);
            Casts<F.Ray3, F.Obb3, float, F.RayHit3>(F.Raycast.Cast, r3, B3, float.PositiveInfinity);
            Casts<F.Ray3, F.Line3, float, F.RayHit3>(F.Raycast.Cast, r3, l3, float.PositiveInfinity);
            Casts<F.Ray3, F.Ray3, float, F.RayHit3>(F.Raycast.Cast, r3, y3, float.PositiveInfinity);
            Casts<F.Ray2, Vector2, float, F.RayHit2>(F.Raycast.Cast, r2, P2, float.PositiveInfinity);
            Casts<F.Ray2, F.Segment2, float, F.RayHit2>(F.Raycast.Cast, r2, G2, float.PositiveInfinity);
            Casts<F.Ray2, F.Line2, float, F.RayHit2>(F.Raycast.Cast, r2, l2, float.PositiveInfinity);
            Casts<F.Ray2, F.Ray2, float, F.RayHit2>(F.Raycast.Cast, r2, y2, float.PositiveInfinity);
            Casts<F.Ray2, F.Circle, float, F.RayHit2>(F.Raycast.Cast, r2, C2, 2);
            Casts<F.Ray2, F.Capsule2, float, F.RayHit2>(F.Raycast.Cast, r2, k2, float.PositiveInfinity);
            Casts<F.Ray2, F.Triangle2, float, F.RayHit2>(F.Raycast.Cast, r2, t2, float.PositiveInfinity);
            Casts<F.Ray2, F.HalfPlane, float, F.RayHit2>(F.Raycast.Cast, r2, h2, float.PositiveInfinity);
            Casts<F.Ray2, F.Aabb2, float, F.RayHit2>(F.Raycast.Cast, r2, A2, float.PositiveInfinity);
            Casts<F.Ray2, F.Obb2, float, F.RayHit2>(F.Raycast.Cast, r2, B2, float.PositiveInfinity);

            D.Ray3[] dr3 = Array.ConvertAll(r3, x => (D.Ray3)x);
            D.Ray2[] dr2 = Array.ConvertAll(r2, x => (D.Ray2)x);
            Casts<D.Ray3, D.Vector3D, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(P3, x => (D.Vector3D)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Segment3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(G3, x => (D.Segment3)x), 4);
            Casts<D.Ray3, D.Sphere, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(S3, x => (D.Sphere)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Capsule3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(k3, x => (D.Capsule3)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Triangle3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(t3, x => (D.Triangle3)x), double.PositiveInfinity);
            Casts<D.Ray3, D.HalfSpace, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(h3, x => (D.HalfSpace)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Aabb3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(A3, x => (D.Aabb3)x), 3);
            Casts<D.Ray3, D.Obb3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(B3, x => (D.Obb3)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Line3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(l3, x => (D.Line3)x), double.PositiveInfinity);
            Casts<D.Ray3, D.Ray3, double, D.RayHit3>(D.Raycast.Cast, dr3, Array.ConvertAll(y3, x => (D.Ray3)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Vector2D, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(P2, x => (D.Vector2D)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Segment2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(G2, x => (D.Segment2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Line2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(l2, x => (D.Line2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Ray2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(y2, x => (D.Ray2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Circle, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(C2, x => (D.Circle)x), 2);
            Casts<D.Ray2, D.Capsule2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(k2, x => (D.Capsule2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Triangle2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(t2, x => (D.Triangle2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.HalfPlane, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(h2, x => (D.HalfPlane)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Aabb2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(A2, x => (D.Aabb2)x), double.PositiveInfinity);
            Casts<D.Ray2, D.Obb2, double, D.RayHit2>(D.Raycast.Cast, dr2, Array.ConvertAll(B2, x => (D.Obb2)x), double.PositiveInfinity);
            Line($"maxDistance NaN: {Attempt(() => D.Raycast.Cast(dr3[0], (D.Sphere)S3[0], double.NaN))}");
            Line($"maxDistance -1: {Attempt(() => F.Raycast.Cast(r2[0], C2[0], -1))}");

            var triangles = Enumerable.Range(0, N).Select(i => new F.Triangle3(At(i, 0), At(i, 4), At(i, 9))).ToArray();
            var triangleSet = Set(typeof(TriangleSet), typeof(F.Triangle3), new TriangleSet(triangles));
            triangleSet.Set(5, triangles[0]);
            var spheres = new SphereSet(Enumerable.Range(0, N).Select(i => new F.Sphere(At(i, 3), (i % 3) * 0.75f)).ToArray());
            var boxes = new AabbSet(Enumerable.Range(0, N).Select(i => F.Aabb3.FromCenter(At(i, 5), new Vector3(0.5f + (i % 2) * 0.5f, 0.25f, 1))).ToArray());
            foreach (var ray in new[] { new F.Ray3(new Vector3(-3, 0.25f, 0.5f), new Vector3(1, 0.125f, 0)), new F.Ray3(new Vector3(0.5f, 3, -0.25f), -Vector3.UnitY) })
            {
                Distances<F.Ray3, SphereSet>((a, b, x) => BatchQuery.Raycasts(a, b, x), ray, spheres);
                Distances<F.Ray3, AabbSet>((a, b, x) => BatchQuery.Raycasts(a, b, x, 4), ray, boxes);
                Distances<F.Ray3, TriangleSet>((a, b, x) => BatchQuery.Raycasts(a, b, x), ray, triangleSet);
            }
            foreach (var set in new Type[] { typeof(SphereSet), typeof(AabbSet), typeof(TriangleSet) })
                Called.Add(Signature(typeof(BatchQuery).GetMethod("Raycasts", new[] { typeof(F.Ray3), set, typeof(Span<float>), typeof(float) })!));
        }

        // ---- Coverage: the public API by reflection against what was called. ----

        private static void Coverage()
        {
            var expected = new List<MethodBase>();
            foreach (var type in typeof(F.Sphere).Assembly.GetExportedTypes())
            {
                expected.AddRange(type.GetConstructors());
                expected.AddRange(type.GetMethods(BindingFlags.Public | BindingFlags.Static | BindingFlags.DeclaredOnly)
                    .Where(m => m.Name == "Between" || (m.Name == "Distance" && type.Name == "ClosestDistance") || m.Name == "Overlaps" || m.Name == "Distances" || m.Name == "Cast" || m.Name == "Raycasts" || m.Name.StartsWith("From", StringComparison.Ordinal)));
                if (type.IsSubclassOf(typeof(ShapeSet)))
                    expected.AddRange(type.GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly).Where(m => !m.IsSpecialName));
            }
            int queries = expected.Count(m => m.DeclaringType!.Name == "ClosestDistance" || m.DeclaringType.Name == "ProximityQuery");
            int batch = expected.Count(m => m.DeclaringType == typeof(BatchQuery));
            Line($"public query overloads (Between, Distance, Overlaps; float and double): {queries}");
            Line($"public batch queries: {batch}; factories, constructors and set members: {expected.Count - queries - batch}");
            foreach (var missing in expected.Select(Signature).Where(s => !Called.Contains(s)).OrderBy(s => s, StringComparer.Ordinal))
                Fail($"not called by the smoke test: {missing}");
        }

        // ---- Printing: exact, and the same text on every runtime. ----

        private static string Signature(MethodBase m) =>
            $"{TypeName(m.DeclaringType!)}.{m.Name}({string.Join(", ", m.GetParameters().Select(p => TypeName(p.ParameterType)))})";

        /// <summary>Namespace-qualified, generic arguments included, no assembly names (they differ between the runtimes).</summary>
        private static string TypeName(Type t) =>
            t.IsGenericType
                ? $"{t.Namespace}.{t.Name.Substring(0, t.Name.IndexOf('`'))}<{string.Join(", ", t.GetGenericArguments().Select(TypeName))}>"
                : $"{t.Namespace}.{t.Name}";

        private static string Show(object? value)
        {
            switch (value)
            {
                case null: return "null";
                case bool b: return b ? "true" : "false";
                case int i: return i.ToString(CultureInfo.InvariantCulture);
                case float f: return Number(f, 9);
                case double d: return Number(d, 17);
                case string s: return s;
                case Vector2 v: return $"({Number(v.X, 9)}, {Number(v.Y, 9)})";
                case Vector3 v: return $"({Number(v.X, 9)}, {Number(v.Y, 9)}, {Number(v.Z, 9)})";
                case D.Vector2D v: return $"({Number(v.X, 17)}, {Number(v.Y, 17)})";
                case D.Vector3D v: return $"({Number(v.X, 17)}, {Number(v.Y, 17)}, {Number(v.Z, 17)})";
                case Array a: return "[" + string.Join(" ", a.Cast<object>().Select(Show)) + "]";
            }
            // A ProximityLib struct or class: its public fields and properties by name.
            var type = value.GetType();
            var members = type.GetFields(BindingFlags.Public | BindingFlags.Instance).Select(f => (f.Name, Value: f.GetValue(value)))
                .Concat(type.GetProperties(BindingFlags.Public | BindingFlags.Instance).Where(p => p.GetIndexParameters().Length == 0)
                    .Select(p => (p.Name, Value: p.GetValue(value))))
                .OrderBy(m => m.Name, StringComparer.Ordinal);
            return "{" + string.Join(", ", members.Select(m => $"{m.Name}={Show(m.Value)}")) + "}";
        }

        /// <summary>
        /// The number as .NET Core 3.0+ writes it with "G17" (double) or "G9" (float): the exact binary value rounded to
        /// that many significant digits, ties to even. It is computed here because Mono's formatter rounds some decimal
        /// ties the other way and drops the sign of −0, which would make equal bits print differently; on .NET the text
        /// is checked against the runtime's own.
        /// </summary>
        private static string Number(double value, int digits)
        {
            string text = ExactDigits(value, digits);
            string native = digits == 9 ? ((float)value).ToString("G9", CultureInfo.InvariantCulture) : value.ToString("G17", CultureInfo.InvariantCulture);
            if (!OnMono && text != native) Fail($"the smoke test's formatter wrote {text} where .NET writes {native}");
            return text;
        }

        private static string ExactDigits(double value, int digits)
        {
            if (double.IsNaN(value)) return "NaN";
            if (double.IsInfinity(value)) return value > 0 ? "Infinity" : "-Infinity";
            long bits = BitConverter.DoubleToInt64Bits(value);
            string sign = bits < 0 ? "-" : "";
            if (value == 0) return sign + "0";
            // |value| = mantissa · 2^exponent exactly.
            int biased = (int)((bits >> 52) & 0x7FF);
            long mantissa = bits & 0xFFFFFFFFFFFFFL;
            if (biased == 0) biased = 1;
            else mantissa |= 1L << 52;
            int exponent = biased - 1075;
            BigInteger num = mantissa, den = BigInteger.One;
            if (exponent > 0) num <<= exponent;
            else den <<= -exponent;
            // Find the decimal exponent k with 10^(digits-1) <= |value| · 10^(digits-1-k) < 10^digits, then round half to even.
            var low = BigInteger.Pow(10, digits - 1);
            var high = low * 10;
            int k = (int)Math.Floor(Math.Log10(Math.Abs(value)));
            BigInteger q, rem, n, d;
            while (true)
            {
                int shift = digits - 1 - k;
                n = shift >= 0 ? num * BigInteger.Pow(10, shift) : num;
                d = shift >= 0 ? den : den * BigInteger.Pow(10, -shift);
                q = BigInteger.DivRem(n, d, out rem);
                if (q < low) k--;
                else if (q >= high) k++;
                else break;
            }
            var twice = rem * 2;
            if (twice > d || (twice == d && !q.IsEven)) q += 1;
            if (q == high) { q = low; k++; }
            string all = q.ToString(CultureInfo.InvariantCulture).TrimEnd('0');
            if (k < -4 || k >= digits)
            {
                string mant = all.Length == 1 ? all : all.Substring(0, 1) + "." + all.Substring(1);
                return $"{sign}{mant}E{(k < 0 ? "-" : "+")}{Math.Abs(k):00}";
            }
            if (k < 0) return sign + "0." + new string('0', -k - 1) + all;
            if (all.Length <= k + 1) return sign + all + new string('0', k + 1 - all.Length);
            return sign + all.Substring(0, k + 1) + "." + all.Substring(k + 1);
        }
    }
}
