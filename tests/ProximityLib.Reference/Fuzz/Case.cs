using System;
using System.Collections.Generic;
using System.Globalization;
using System.Linq;
using System.Text;
using ProximityLib.Double;
using Dbl = ProximityLib.Double;

namespace ProximityReference.Fuzz
{
    /// <summary>One fuzz case: two shapes of an unordered kind pair, in one precision, drawn by one generator from (seed, index).</summary>
    public sealed class FuzzCase
    {
        public long Seed { get; }
        public long Index { get; }
        public string Generator { get; }
        public int Dim { get; }
        public bool Float { get; }
        public Spec A { get; }
        public Spec B { get; }
        /// <summary>The case's generator after the shapes are drawn: the checks draw their own choices from it.</summary>
        public Rng Rng { get; }

        public FuzzCase(long seed, long index, string generator, int dim, bool isFloat, Spec a, Spec b, Rng rng)
        {
            Seed = seed; Index = index; Generator = generator; Dim = dim; Float = isFloat; A = a; B = b; Rng = rng;
        }

        /// <summary>"3D segment–OBB": the kinds in the library's pair order (<see cref="Kinds.Rank"/>).</summary>
        public string Pair => PairName(Dim, First ? A : B, First ? B : A);

        private bool First => Kinds.Rank(A.Kind) <= Kinds.Rank(B.Kind);
        public string PrecisionName => Float ? "float" : "double";

        public static string PairName(int dim, Spec a, Spec b) => $"{dim}D {a.KindName}–{b.KindName}";

        /// <summary>The 30 unordered kind pairs of the original kinds: 15 in 3D, then 15 in 2D (index space 0 ≤ i &lt; <see cref="NewBase"/>).</summary>
        public static readonly (int Dim, Kind A, Kind B)[] Pairs = MakePairs();

        private static (int, Kind, Kind)[] MakePairs()
        {
            var list = new List<(int, Kind, Kind)>();
            foreach (int dim in new[] { 3, 2 })
                for (var a = Kind.Point; a <= Kind.Obb; a++)
                    for (var b = a; b <= Kind.Obb; b++)
                        list.Add((dim, a, b));
            return list.ToArray();
        }

        /// <summary>
        /// The first index of the second index space: issue 12's pairs. Indices below it keep the original scheme (the
        /// 30 pairs above), so CI seeds and recorded repros keep their cases; an index NewBase + k is case k of
        /// <see cref="NewPairs"/> (replay it as SEED:1000000000000+k).
        /// </summary>
        public const long NewBase = 1_000_000_000_000;

        /// <summary>
        /// Every unordered pair with a line, ray, capsule, triangle or half-space (kinds in the library's pair order),
        /// 40 in 3D then 40 in 2D: a fixed list, so case k always names the same pair. A pair the library has no public
        /// overload for yet is skipped (<see cref="Available"/>), so each pair is fuzzed from the commit that adds it.
        /// </summary>
        public static readonly (int Dim, Kind A, Kind B)[] NewPairs = MakeNewPairs();

        private static (int, Kind, Kind)[] MakeNewPairs()
        {
            var list = new List<(int, Kind, Kind)>();
            foreach (int dim in new[] { 3, 2 })
                for (int i = 0; i < Kinds.InOrder.Length; i++)
                    for (int j = i; j < Kinds.InOrder.Length; j++)
                    {
                        Kind a = Kinds.InOrder[i], b = Kinds.InOrder[j];
                        if (!Kinds.IsOriginal(a) || !Kinds.IsOriginal(b)) list.Add((dim, a, b));
                    }
            return list.ToArray();
        }

        /// <summary>
        /// The first index of the third index space: exact tiny gaps (<see cref="Generators.TinyGap"/>) for all 110 pairs,
        /// double only (the float API computes in double, where a float gap's square cannot underflow). A space of its
        /// own, so adding it changed no case of the other two (replay GapBase + k as SEED:2000000000000+k).
        /// </summary>
        public const long GapBase = 2_000_000_000_000;

        /// <summary>Every pair of the gap space: the original pairs, then the new ones.</summary>
        public static readonly (int Dim, Kind A, Kind B)[] GapPairs = Pairs.Concat(NewPairs).ToArray();

        /// <summary>
        /// The first index of the fourth index space: nearly touching cores (<see cref="Generators.NearCore"/>) for the
        /// 110 pairs of <see cref="GapPairs"/> in both precisions, a space of its own so no case of the other three
        /// changed (replay NearBase + k as SEED:3000000000000+k).
        /// </summary>
        public const long NearBase = 3_000_000_000_000;

        /// <summary>
        /// The first index of the fifth index space: edges crossing at shallow angles (<see cref="Generators.ShallowCross"/>)
        /// for the pairs of <see cref="ShallowPairs"/> in both precisions, a space of its own so no case of the other four
        /// changed (replay ShallowBase + k as SEED:4000000000000+k).
        /// </summary>
        public const long ShallowBase = 4_000_000_000_000;

        /// <summary>The pairs of <see cref="GapPairs"/> whose kinds both have edges, not two boxes (<see cref="Generators.Crosses"/>).</summary>
        public static readonly (int Dim, Kind A, Kind B)[] ShallowPairs = GapPairs.Where(x => Generators.Crosses(x.A, x.B)).ToArray();

        /// <summary>The pair and precision of an index: in the original space index mod 60 picks one of 30 pairs × 2
        /// precisions; in the new space (index − NewBase) mod 160 one of 80 pairs × 2; in the gap space (index − GapBase)
        /// mod 110 one of the 110 pairs, double; in the near space (index − NearBase) mod 220 one of the 110 pairs × 2; in
        /// the shallow space (index − ShallowBase) mod 100 one of its 50 pairs × 2. Consecutive blocks rotate the
        /// generators.</summary>
        public static (int Dim, Kind A, Kind B, bool Float, long Round) Slot(long index)
        {
            if (index >= ShallowBase) return BothPrecisions(ShallowPairs, index - ShallowBase);
            if (index >= NearBase) return BothPrecisions(GapPairs, index - NearBase);
            if (index >= GapBase)
            {
                long g = index - GapBase;
                var (dg, ag, bg) = GapPairs[(int)(g % GapPairs.Length)];
                return (dg, ag, bg, false, g / GapPairs.Length);
            }
            if (index < NewBase) return BothPrecisions(Pairs, index);
            return BothPrecisions(NewPairs, index - NewBase);
        }

        /// <summary>Case k of a space over <paramref name="pairs"/> in both precisions: k mod 2n picks the pair (mod n), double then float.</summary>
        private static (int Dim, Kind A, Kind B, bool Float, long Round) BothPrecisions((int Dim, Kind A, Kind B)[] pairs, long k)
        {
            int n = pairs.Length;
            int slot = (int)(k % (2 * n));
            var (dim, a, b) = pairs[slot % n];
            return (dim, a, b, slot >= n, k / (2 * n));
        }

        /// <summary>
        /// Case <paramref name="index"/> of run <paramref name="seed"/>: <see cref="Slot"/> picks the pair and the
        /// precision, so every block of 60 consecutive original cases covers all 200 original overloads and every block
        /// of 160 new ones every new pair; the pair's generators take turns. Throws for a pair the library lacks
        /// (<see cref="Available"/>).
        /// </summary>
        public static FuzzCase Create(long seed, long index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException(nameof(index), "case indices are not negative");
            var (dim, ka, kb, isFloat, round) = Slot(index);
            if (!Available(dim, ka, kb, isFloat))
                throw new ArgumentException($"case {seed}:{index} is {dim}D {ka}–{kb} ({(isFloat ? "float" : "double")}), which the library has no public overloads for yet");
            var rng = Rng.ForCase(seed, index);
            if (index >= ShallowBase)
            {
                var (xa, xb) = Generators.ShallowCross(rng, ka, kb, dim, isFloat ? Precision.Single : Precision.Double);
                return new FuzzCase(seed, index, "shallow-cross", dim, isFloat, xa, xb, rng);
            }
            if (index >= NearBase)
            {
                var (na, nb) = Generators.NearCore(rng, ka, kb, dim, isFloat ? Precision.Single : Precision.Double);
                return new FuzzCase(seed, index, "near-core", dim, isFloat, na, nb, rng);
            }
            if (index >= GapBase)
            {
                var (ga, gb) = Generators.TinyGap(rng, ka, kb, dim, Precision.Double);
                return new FuzzCase(seed, index, "tiny-gap", dim, false, ga, gb, rng);
            }
            var gens = Generators.For(ka, kb);
            int g = gens[(int)(round % gens.Length)];
            var (a, b) = Generators.All[g].Make(rng, ka, kb, dim, isFloat ? Precision.Single : Precision.Double);
            return new FuzzCase(seed, index, Generators.All[g].Name, dim, isFloat, a, b, rng);
        }

        /// <summary>Is case <paramref name="index"/>'s pair in the library (its Between overloads exist in its precision)?</summary>
        public static bool Available(long index)
        {
            var (dim, ka, kb, isFloat, _) = Slot(index);
            return Available(dim, ka, kb, isFloat);
        }

        private static readonly System.Collections.Concurrent.ConcurrentDictionary<(int, Kind, Kind, bool), bool> _available =
            new System.Collections.Concurrent.ConcurrentDictionary<(int, Kind, Kind, bool), bool>();

        /// <summary>
        /// Does the public API answer this pair: ClosestDistance.Between, ClosestDistance.Distance and
        /// ProximityQuery.Overlaps in both argument orders, found by reflection (ProximityLib.Double or, for float,
        /// ProximityLib)? A pair whose overloads are only partly there counts as present, so the checker reports the gap.
        /// </summary>
        public static bool Available(int dim, Kind a, Kind b, bool isFloat) =>
            _available.GetOrAdd((dim, a, b, isFloat), key => Exists(isFloat ? typeof(ProximityLib.ClosestDistance) : typeof(Dbl.ClosestDistance),
                "Between", ShapeType(key.Item1, key.Item2, key.Item4), ShapeType(key.Item1, key.Item3, key.Item4)));

        /// <summary>The public overloads of a query method (Between, Distance, Overlaps) for the pair, both orders.</summary>
        public static bool Exists(Type owner, string method, Type a, Type b) =>
            Api.Find(owner, method, a, b) != null || Api.Find(owner, method, b, a) != null;

        /// <summary>The library type of a kind in a dimension and precision.</summary>
        public static Type ShapeType(int dim, Kind kind, bool isFloat)
        {
            var probe = kind switch
            {
                Kind.Point => Spec.Point(dim, default),
                Kind.Segment => Spec.Segment(dim, default, default),
                Kind.Sphere => Spec.Sphere(dim, default, 0),
                Kind.Aabb => Spec.Aabb(dim, default, default),
                Kind.Obb => dim == 3 ? Spec.ObbQuaternion(default, 0, 0, 0, 1, default) : Spec.Obb2Angle(default, 0, default),
                Kind.Line => Spec.Line(dim, default, Vector3D.UnitX),
                Kind.Ray => Spec.Ray(dim, default, Vector3D.UnitX),
                Kind.Capsule => Spec.Capsule(dim, default, default, 0),
                Kind.Triangle => Spec.Triangle(dim, default, default, default),
                _ => Spec.HalfSpace(dim, default, Vector3D.UnitX),
            };
            return (isFloat ? probe.ToFloat() : probe).Build().GetType();
        }
    }

    /// <summary>One violated invariant, with what a C# repro needs.</summary>
    public sealed class Failure
    {
        public FuzzCase Case { get; }
        public string Invariant { get; }
        public string Message { get; }
        /// <summary>C# statements after <c>var a = …; var b = …;</c> (extra shapes are declared in them).</summary>
        public IReadOnlyList<string> Code { get; }
        public bool Batch { get; }

        public Failure(FuzzCase c, string invariant, string message, IReadOnlyList<string> code, bool batch = false)
        {
            Case = c; Invariant = invariant; Message = message; Code = code; Batch = batch;
        }

        /// <summary>A self-contained C# repro (top-level statements) that rebuilds the shapes bit for bit and makes the call.</summary>
        public string Repro()
        {
            var c = Case;
            var sb = new StringBuilder();
            sb.AppendLine($"// {c.Pair} ({c.PrecisionName}), generator \"{c.Generator}\": invariant {Invariant}");
            foreach (var line in Message.Split('\n')) sb.AppendLine("// " + line);
            sb.AppendLine($"// replay: dotnet run --project tests/ProximityLib.Accuracy -c Release -- --fuzz-replay {c.Seed}:{c.Index}");
            sb.AppendLine(Spec.Usings(c.Float));
            if (Batch) sb.AppendLine("using ProximityLib.Batch;");
            sb.AppendLine($"var a = {c.A.ToCSharp()};");
            sb.AppendLine($"var b = {c.B.ToCSharp()};");
            foreach (var line in Code) sb.AppendLine(line);
            return sb.ToString();
        }
    }

    /// <summary>A query result of either API and dimension, widened exactly to doubles (2D: z = 0).</summary>
    public readonly struct Res
    {
        public readonly double D, D2, TA, TB;
        public readonly Vector3D PA, PB;

        public Res(double d, double d2, Vector3D pa, Vector3D pb, double ta, double tb)
        {
            D = d; D2 = d2; PA = pa; PB = pb; TA = ta; TB = tb;
        }

        public static Res From(object r) => r switch
        {
            Dbl.DistanceResult3 x => new Res(x.Distance, x.DistanceSquared, x.PointA, x.PointB, x.ParameterA, x.ParameterB),
            Dbl.DistanceResult2 x => new Res(x.Distance, x.DistanceSquared, V(x.PointA.X, x.PointA.Y), V(x.PointB.X, x.PointB.Y), x.ParameterA, x.ParameterB),
            ProximityLib.DistanceResult3 x => new Res(x.Distance, x.DistanceSquared, x.PointA, x.PointB, x.ParameterA, x.ParameterB),
            ProximityLib.DistanceResult2 x => new Res(x.Distance, x.DistanceSquared, V(x.PointA.X, x.PointA.Y), V(x.PointB.X, x.PointB.Y), x.ParameterA, x.ParameterB),
            _ => throw new InvalidOperationException(r?.GetType().Name),
        };

        private static Vector3D V(double x, double y) => new Vector3D(x, y, 0);

        public Res Swapped() => new Res(D, D2, PB, PA, TB, TA);

        public string Show(bool isFloat, int dim) =>
            $"Distance = {N(D, isFloat)}, DistanceSquared = {N(D2, isFloat)}, PointA = {P(PA, isFloat, dim)}, PointB = {P(PB, isFloat, dim)}, " +
            $"ParameterA = {N(TA, isFloat)}, ParameterB = {N(TB, isFloat)}";

        public static string N(double x, bool isFloat) =>
            isFloat ? ((float)x).ToString("R", CultureInfo.InvariantCulture) : x.ToString("R", CultureInfo.InvariantCulture);

        public static string P(Vector3D v, bool isFloat, int dim) =>
            dim == 3 ? $"<{N(v.X, isFloat)}, {N(v.Y, isFloat)}, {N(v.Z, isFloat)}>" : $"<{N(v.X, isFloat)}, {N(v.Y, isFloat)}>";
    }
}
