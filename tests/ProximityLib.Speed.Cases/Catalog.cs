using System;

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
                    string op;
                    if (def == typeof(IBetween<,>)) { loop = typeof(BetweenLoop<,,>); op = "Between"; }
                    else if (def == typeof(IDistance<,>)) { loop = typeof(DistanceLoop<,,>); op = "Distance"; }
                    else if (def == typeof(IOverlap<,>)) { loop = typeof(OverlapLoop<,,>); op = "Overlaps"; }
                    else continue;
                    var args = i.GetGenericArguments();
                    var a = Shapes.Of(args[0], inputs.Side(c.Query, 0));
                    var b = Shapes.Of(args[1], inputs.Side(c.Query, 1));
                    var instance = Activator.CreateInstance(loop.MakeGenericType(t, args[0], args[1]), a, b)!;
                    var run = (Func<int, double>)Delegate.CreateDelegate(typeof(Func<int, double>), instance, "Run");
                    string group = c.Precision + " " + c.Query + (op == "Overlaps" ? " overlap" : " distance");
                    add(group, Name(c.Source) + " " + op, a.Length, run);
                }
            }
            BatchCases.Add(inputs, add);
            AddScenes(add);
        }

        private static string Name(Source s) => s == Source.Library ? "library" : s == Source.Baseline ? "baseline" : "paper formula";

        /// <summary>Scene-level cases (GaitCase.cs); left out of builds against another library version.</summary>
        static partial void AddScenes(Action<string, string, int, Func<int, double>> add);
    }
}
