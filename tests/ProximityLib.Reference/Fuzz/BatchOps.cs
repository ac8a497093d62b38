using System;
using System.Collections.Generic;
using System.Numerics;
using ProximityLib;
using ProximityLib.Batch;

namespace ProximityReference.Fuzz
{
    /// <summary>
    /// The SIMD batch queries of one kind pair, paired (set against set) and one against many, each run twice: on sets
    /// of one, and with the case at index j of larger sets of filler shapes (so tails and lane positions are exercised).
    /// </summary>
    public sealed class BatchOps
    {
        public readonly struct Run
        {
            public string Name { get; init; }
            /// <summary>C# for the call on sets of one (declares d or o).</summary>
            public string Code { get; init; }
            public bool IsDistance { get; init; }
            /// <summary>The result on sets of one (a verdict as 1 or 0).</summary>
            public double Single { get; init; }
            /// <summary>The result at index j of the larger sets.</summary>
            public double InSet { get; init; }
            /// <summary>C# for the call on the larger sets (arrays setA and setB; declares dn or on).</summary>
            public string CodeInSet { get; init; }
        }

        private delegate void Fn<TX, TY, TR>(TX x, TY y, TR[] result);

        private readonly Func<object, object, object[], object[], int, IEnumerable<Run>> _runs;
        private BatchOps(Func<object, object, object[], object[], int, IEnumerable<Run>> runs) { _runs = runs; }

        public IEnumerable<Run> Runs(object a, object b, object[] fillA, object[] fillB, int j) => _runs(a, b, fillA, fillB, j);

        /// <summary>The batch queries for the pair (first kind ≤ second), or null when the batch API has none.</summary>
        public static BatchOps? For(Kind a, Kind b) => (a, b) switch
        {
            (Kind.Sphere, Kind.Sphere) => Make<Sphere, Sphere, SphereSet, SphereSet>("SphereSet", "SphereSet", x => new SphereSet(x), x => new SphereSet(x),
                (x, y, r) => BatchQuery.Distances(x, y, r), (x, y, r) => BatchQuery.Distances(x, y, r),
                (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            (Kind.Point, Kind.Aabb) => Make<Vector3, Aabb3, PointSet, AabbSet>("PointSet", "AabbSet", x => new PointSet(x), x => new AabbSet(x),
                (x, y, r) => BatchQuery.Distances(x, y, r), (x, y, r) => BatchQuery.Distances(x, y, r),
                (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            (Kind.Sphere, Kind.Aabb) => Make<Sphere, Aabb3, SphereSet, AabbSet>("SphereSet", "AabbSet", x => new SphereSet(x), x => new AabbSet(x),
                (x, y, r) => BatchQuery.Distances(x, y, r), (x, y, r) => BatchQuery.Distances(x, y, r),
                (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            (Kind.Aabb, Kind.Aabb) => Make<Aabb3, Aabb3, AabbSet, AabbSet>("AabbSet", "AabbSet", x => new AabbSet(x), x => new AabbSet(x),
                null, null, (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            (Kind.Sphere, Kind.Obb) => Make<Sphere, Obb3, SphereSet, ObbSet>("SphereSet", "ObbSet", x => new SphereSet(x), x => new ObbSet(x),
                (x, y, r) => BatchQuery.Distances(x, y, r), (x, y, r) => BatchQuery.Distances(x, y, r),
                (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            (Kind.Segment, Kind.Segment) => Make<Segment3, Segment3, SegmentSet, SegmentSet>("SegmentSet", "SegmentSet", x => new SegmentSet(x), x => new SegmentSet(x),
                (x, y, r) => BatchQuery.Distances(x, y, r), (x, y, r) => BatchQuery.Distances(x, y, r), null, null),
            (Kind.Obb, Kind.Obb) => Make<Obb3, Obb3, ObbSet, ObbSet>("ObbSet", "ObbSet", x => new ObbSet(x), x => new ObbSet(x),
                null, null, (x, y, r) => BatchQuery.Overlaps(x, y, r), (x, y, r) => BatchQuery.Overlaps(x, y, r)),
            _ => null,
        };

        private static BatchOps Make<TA, TB, SA, SB>(string setA, string setB, Func<TA[], SA> makeA, Func<TB[], SB> makeB,
            Fn<SA, SB, float>? pairedD, Fn<TA, SB, float>? oneD, Fn<SA, SB, bool>? pairedO, Fn<TA, SB, bool>? oneO)
        {
            IEnumerable<Run> Runs(object a, object b, object[] fillA, object[] fillB, int j)
            {
                var ta = (TA)a;
                var tb = (TB)b;
                var arrA = Array.ConvertAll(fillA, x => (TA)x);
                var arrB = Array.ConvertAll(fillB, x => (TB)x);
                arrA[j] = ta;
                arrB[j] = tb;
                var oneA = makeA(new[] { ta });
                var oneB = makeB(new[] { tb });
                var manyA = makeA(arrA);
                var manyB = makeB(arrB);
                int n = arrB.Length;
                string pairedArgs = $"new {setA}(new[] {{ a }}), new {setB}(new[] {{ b }})";
                string oneArgs = $"a, new {setB}(new[] {{ b }})";
                string pairedMany = $"new {setA}(setA), new {setB}(setB)";
                string oneMany = $"a, new {setB}(setB)";
                string InSet(string type, string name, string args, string call) =>
                    $"var {name} = new {type}[{n}]; BatchQuery.{call}({args}, {name}); // {name}[{j}]";
                if (pairedD != null)
                {
                    float[] r1 = new float[1], rn = new float[n];
                    pairedD(oneA, oneB, r1);
                    pairedD(manyA, manyB, rn);
                    yield return new Run { Name = "BatchQuery.Distances (paired)", IsDistance = true, Single = r1[0], InSet = rn[j],
                        Code = $"var d = new float[1]; BatchQuery.Distances({pairedArgs}, d);", CodeInSet = InSet("float", "dn", pairedMany, "Distances") };
                }
                if (oneD != null)
                {
                    float[] r1 = new float[1], rn = new float[n];
                    oneD(ta, oneB, r1);
                    oneD(ta, manyB, rn);
                    yield return new Run { Name = "BatchQuery.Distances (one against many)", IsDistance = true, Single = r1[0], InSet = rn[j],
                        Code = $"var d = new float[1]; BatchQuery.Distances({oneArgs}, d);", CodeInSet = InSet("float", "dn", oneMany, "Distances") };
                }
                if (pairedO != null)
                {
                    bool[] r1 = new bool[1], rn = new bool[n];
                    pairedO(oneA, oneB, r1);
                    pairedO(manyA, manyB, rn);
                    yield return new Run { Name = "BatchQuery.Overlaps (paired)", Single = r1[0] ? 1 : 0, InSet = rn[j] ? 1 : 0,
                        Code = $"var o = new bool[1]; BatchQuery.Overlaps({pairedArgs}, o);", CodeInSet = InSet("bool", "on", pairedMany, "Overlaps") };
                }
                if (oneO != null)
                {
                    bool[] r1 = new bool[1], rn = new bool[n];
                    oneO(ta, oneB, r1);
                    oneO(ta, manyB, rn);
                    yield return new Run { Name = "BatchQuery.Overlaps (one against many)", Single = r1[0] ? 1 : 0, InSet = rn[j] ? 1 : 0,
                        Code = $"var o = new bool[1]; BatchQuery.Overlaps({oneArgs}, o);", CodeInSet = InSet("bool", "on", oneMany, "Overlaps") };
                }
            }
            return new BatchOps(Runs);
        }
    }
}
