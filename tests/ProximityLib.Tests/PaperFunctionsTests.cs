using System;
using System.IO;
using System.Linq;
using System.Text.RegularExpressions;
using NUnit.Framework;
using ProximityLib;

namespace ProximityTests
{
    /// <summary>docs/paper-functions.md maps each of the paper's 20 functions to a call and a file: both must exist.</summary>
    public class PaperFunctionsTests
    {
        private static readonly Regex Call = new Regex(@"`(ClosestDistance\.Between|ProximityQuery\.Overlaps)\((\w+), (\w+)\)`");
        private static readonly Regex Factory = new Regex(@"`(\w+)\.(FromOrigin|FromCorners)`");
        private static readonly Regex File = new Regex(@"`(\w+\.cs)` \|\s*$");

        [Test]
        public void EveryMappedCallAndFileExistsInBothPrecisions()
        {
            string root = RepositoryRoot();
            var rows = System.IO.File.ReadAllLines(Path.Combine(root, "docs", "paper-functions.md")).Where(l => Call.IsMatch(l)).ToList();
            Assert.That(rows.Count(r => r.StartsWith("| distance", StringComparison.Ordinal)), Is.EqualTo(12), "Table 3 has 12 functions");
            Assert.That(rows.Count(r => r.StartsWith("| proximity", StringComparison.Ordinal)), Is.EqualTo(8), "Table 4 has 8 functions");
            foreach (var row in rows)
            {
                var m = Call.Match(row);
                string method = m.Groups[1].Value.Split('.')[1];
                Assert.That(Find(typeof(ClosestDistance).Namespace!, m.Groups[1].Value, method, m.Groups[2].Value, m.Groups[3].Value), Is.Not.Null, row);
                Assert.That(Find("ProximityLib.Double", m.Groups[1].Value, method, Wide(m.Groups[2].Value), Wide(m.Groups[3].Value)), Is.Not.Null, "double: " + row);
                foreach (Match f in Factory.Matches(row))
                    Assert.That(Shape(f.Groups[1].Value).GetMethod(f.Groups[2].Value), Is.Not.Null, row);
                var file = File.Match(row);
                Assert.That(file.Success, row);
                Assert.That(System.IO.File.Exists(Path.Combine(root, "src", "ProximityLib", "Pairs", file.Groups[1].Value)), row);
            }
        }

        private static System.Reflection.MethodInfo? Find(string ns, string qualified, string method, string a, string b)
        {
            var type = typeof(ClosestDistance).Assembly.GetType($"{ns}.{qualified.Split('.')[0]}", true)!;
            // A shape may be an in parameter (the double API's always are; the float API's where the kernel takes it so):
            // its signature then has the by-reference type.
            Type ta = Type(ns, a), tb = Type(ns, b);
            return new[] { (ta, tb), (ta.MakeByRefType(), tb), (ta, tb.MakeByRefType()), (ta.MakeByRefType(), tb.MakeByRefType()) }
                .Select(p => type.GetMethod(method, new[] { p.Item1, p.Item2 })).FirstOrDefault(x => x != null);
        }

        private static Type Type(string ns, string name) => name switch
        {
            "Vector2" => typeof(System.Numerics.Vector2),
            "Vector3" => typeof(System.Numerics.Vector3),
            _ => typeof(ClosestDistance).Assembly.GetType($"{ns}.{name}", true)!,
        };

        private static Type Shape(string name) => Type("ProximityLib", name);

        private static string Wide(string name) => name == "Vector2" ? "Vector2D" : name == "Vector3" ? "Vector3D" : name;

        private static string RepositoryRoot()
        {
            var dir = new DirectoryInfo(TestContext.CurrentContext.TestDirectory);
            while (dir != null && !System.IO.File.Exists(Path.Combine(dir.FullName, "ProximityLib.sln"))) dir = dir.Parent;
            return dir?.FullName ?? throw new DirectoryNotFoundException("no ProximityLib.sln above the test directory");
        }
    }
}
