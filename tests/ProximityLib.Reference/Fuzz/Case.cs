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

        /// <summary>"3D segment–OBB": the kinds in the fixed order point &lt; segment &lt; sphere &lt; AABB &lt; OBB.</summary>
        public string Pair => PairName(Dim, A.Kind <= B.Kind ? A : B, A.Kind <= B.Kind ? B : A);
        public string PrecisionName => Float ? "float" : "double";

        public static string PairName(int dim, Spec a, Spec b) => $"{dim}D {a.KindName}–{b.KindName}";

        /// <summary>The 30 unordered kind pairs: 15 in 3D, then 15 in 2D.</summary>
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
        /// Case <paramref name="index"/> of run <paramref name="seed"/>: index mod 60 picks the pair (30) and the precision
        /// (2), so every block of 60 consecutive cases covers all 200 overloads; the pair's generators take turns.
        /// </summary>
        public static FuzzCase Create(long seed, long index)
        {
            int slot = (int)(index % 60);
            var (dim, ka, kb) = Pairs[slot % 30];
            bool isFloat = slot >= 30;
            var gens = Generators.For(ka, kb);
            int g = gens[(int)(index / 60 % gens.Length)];
            var rng = Rng.ForCase(seed, index);
            var (a, b) = Generators.All[g].Make(rng, ka, kb, dim, isFloat ? Precision.Single : Precision.Double);
            return new FuzzCase(seed, index, Generators.All[g].Name, dim, isFloat, a, b, rng);
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
