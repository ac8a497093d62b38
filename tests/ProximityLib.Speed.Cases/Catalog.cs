using System;
using System.Collections.Generic;
using System.Globalization;

namespace ProximitySpeed
{
    /// <summary>
    /// The cases, handed to the harness through BCL types only, so a copy of this assembly compiled against another
    /// library version (the harness's A/B mode) plugs into the same harness.
    /// </summary>
    public static partial class Catalog
    {
        /// <summary>
        /// Builds every case on the inputs at <paramref name="inputsPath"/> and hands each to <paramref name="add"/> as
        /// (group, name, queries per repetition, run): run(reps) does reps × that many queries and returns a checksum.
        /// A group is "precision query distance|overlap" ("float 3D sphere–sphere distance"); the harness runs a group's
        /// cases back to back, so ratios within a group are taken between neighbours in time. Names are "source op":
        /// "library Between", "baseline Distance", "paper formula Overlaps", "batch paired Distances".
        /// </summary>
        public static void Load(string inputsPath, Action<string, string, int, Func<int, double>> add)
        {
            var inputs = InputSet.Read(inputsPath);
            foreach (var (group, name, count, instance) in Instances(inputs))
                add(group, name, count, (Func<int, double>)Delegate.CreateDelegate(typeof(Func<int, double>), instance, "Run"));
            BatchCases.Add(inputs, add);
            AddRaycastBatches(inputs, add);
            AddScenes(add);
        }

        /// <summary>
        /// Every ray-cast baseline against the library's cast of the same group, pair by pair: a pair disagrees when one
        /// hits and the other misses, or T differs by more than <paramref name="tolerance"/>·(1 + T) (the precision's
        /// rounding, amplified near grazing). Returns (group, pairs, disagreeing pairs, the worst pair's two answers).
        /// </summary>
        public static List<(string Group, int Pairs, int Disagreeing, string Worst)> RaycastAgreement(string inputsPath)
        {
            var inputs = InputSet.Read(inputsPath);
            var each = new Dictionary<string, double[]>(StringComparer.Ordinal);
            foreach (var (group, name, _, instance) in Instances(inputs))
                if (name.EndsWith(" Cast", StringComparison.Ordinal))
                    each[group + " | " + name] = (double[])instance.GetType().GetMethod("Each")!.Invoke(instance, null)!;
            var result = new List<(string, int, int, string)>();
            foreach (var key in each.Keys)
            {
                if (!key.EndsWith(" | baseline Cast", StringComparison.Ordinal)) continue;
                string group = key.Substring(0, key.Length - " | baseline Cast".Length);
                if (!each.TryGetValue(group + " | library Cast", out var library)) continue;
                var baseline = each[key];
                double tolerance = group.StartsWith(Precision.Float, StringComparison.Ordinal) ? 1e-3 : 1e-9;
                int disagreeing = 0;
                double worst = 0;
                string worstText = "";
                for (int i = 0; i < library.Length; i++)
                {
                    double a = library[i], b = baseline[i];
                    bool hitA = a <= double.MaxValue, hitB = b <= double.MaxValue;
                    double off = hitA != hitB ? double.PositiveInfinity : hitA ? Math.Abs(a - b) / (tolerance * (1 + Math.Abs(a))) : 0;
                    if (off <= 1) continue;
                    disagreeing++;
                    if (off >= worst) { worst = off; worstText = "pair " + i + ": library " + a.ToString("R", CultureInfo.InvariantCulture) + ", baseline " + b.ToString("R", CultureInfo.InvariantCulture); }
                }
                result.Add((group, library.Length, disagreeing, worstText));
            }
            return result;
        }

        /// <summary>Every [Case] struct's timing loop on its inputs: (group, name, queries per repetition, loop).</summary>
        private static IEnumerable<(string Group, string Name, int Count, object Loop)> Instances(InputSet inputs)
        {
            var types = typeof(Catalog).Assembly.GetTypes();
            Array.Sort(types, (x, y) => string.CompareOrdinal(x.FullName, y.FullName));
            foreach (var t in types)
            {
                var c = (CaseAttribute?)Attribute.GetCustomAttribute(t, typeof(CaseAttribute));
                if (c == null) continue;
                foreach (var i in t.GetInterfaces())
                {
                    if (!i.IsGenericType) continue;
                    var def = i.GetGenericTypeDefinition();
                    Type loop;
                    string op, suffix;
                    if (def == typeof(IBetween<,>)) { loop = typeof(BetweenLoop<,,>); op = "Between"; suffix = " distance"; }
                    else if (def == typeof(IDistance<,>)) { loop = typeof(DistanceLoop<,,>); op = "Distance"; suffix = " distance"; }
                    else if (def == typeof(IOverlap<,>)) { loop = typeof(OverlapLoop<,,>); op = "Overlaps"; suffix = " overlap"; }
                    else if (def == typeof(IRaycast<,>)) { loop = typeof(RaycastLoop<,,>); op = "Cast"; suffix = ""; }
                    else continue;
                    var args = i.GetGenericArguments();
                    var a = Shapes.Of(args[0], inputs.Side(c.Query, 0));
                    var b = Shapes.Of(args[1], inputs.Side(c.Query, 1));
                    var instance = Activator.CreateInstance(loop.MakeGenericType(t, args[0], args[1]), a, b)!;
                    yield return (c.Precision + " " + c.Query + suffix, Name(c.Source) + " " + op, a.Length, instance);
                }
            }
        }

        private static string Name(Source s) => s == Source.Library ? "library" : s == Source.Baseline ? "baseline" : "paper formula";

        /// <summary>Scene-level cases (GaitCase.cs); left out of builds against another library version.</summary>
        static partial void AddScenes(Action<string, string, int, Func<int, double>> add);

        /// <summary>The batch ray casts (Raycasts.cs); left out of builds against a library version without them.</summary>
        static partial void AddRaycastBatches(InputSet inputs, Action<string, string, int, Func<int, double>> add);
    }
}
