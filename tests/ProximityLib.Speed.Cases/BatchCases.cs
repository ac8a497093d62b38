using System;
using System.Numerics;
using ProximityLib.Batch;
using F = ProximityLib;
using FQ = ProximityLib.ProximityQuery;

namespace ProximitySpeed
{
    /// <summary>
    /// Every batch query (ProximityLib.Batch), on the float inputs of its scalar query and in its group, so the harness
    /// can set it beside the scalar API: paired (a[i] against b[i]) and one-to-many (a[r] against all of b), timed per pair.
    /// The one-to-many pairs are not the scalar cases' pairs (one shape against all of b is mostly apart, and its branches
    /// go another way), so each also has the scalar API looped over the same pairs: "scalar one-to-many".
    /// </summary>
    internal static partial class BatchCases
    {
        public static void Add(InputSet inputs, Action<string, string, int, Func<int, double>> add)
        {
            AddScalarDistances(inputs, add);
            var (s1, s2) = Sides<F.Sphere, F.Sphere>(inputs, "3D sphere–sphere");
            SphereSet ss1 = new SphereSet(s1), ss2 = new SphereSet(s2);
            Distances(add, "3D sphere–sphere", s1.Length, r => BatchQuery.Distances(ss1, ss2, r), (i, r) => BatchQuery.Distances(s1[i], ss2, r));
            Overlaps(add, "3D sphere–sphere", s1.Length, r => BatchQuery.Overlaps(ss1, ss2, r), (i, r) => BatchQuery.Overlaps(s1[i], ss2, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(s1[i], s2[j]); });

            var (p, pb) = Sides<Vector3, F.Aabb3>(inputs, "3D point–AABB");
            PointSet ps = new PointSet(p);
            AabbSet pbs = new AabbSet(pb);
            Distances(add, "3D point–AABB", p.Length, r => BatchQuery.Distances(ps, pbs, r), (i, r) => BatchQuery.Distances(p[i], pbs, r));
            Overlaps(add, "3D point–AABB", p.Length, r => BatchQuery.Overlaps(ps, pbs, r), (i, r) => BatchQuery.Overlaps(p[i], pbs, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(p[i], pb[j]); });

            var (sa, ab) = Sides<F.Sphere, F.Aabb3>(inputs, "3D sphere–AABB");
            SphereSet sas = new SphereSet(sa);
            AabbSet abs = new AabbSet(ab);
            Distances(add, "3D sphere–AABB", sa.Length, r => BatchQuery.Distances(sas, abs, r), (i, r) => BatchQuery.Distances(sa[i], abs, r));
            Overlaps(add, "3D sphere–AABB", sa.Length, r => BatchQuery.Overlaps(sas, abs, r), (i, r) => BatchQuery.Overlaps(sa[i], abs, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(sa[i], ab[j]); });

            var (a1, a2) = Sides<F.Aabb3, F.Aabb3>(inputs, "3D AABB–AABB");
            AabbSet as1 = new AabbSet(a1), as2 = new AabbSet(a2);
            Overlaps(add, "3D AABB–AABB", a1.Length, r => BatchQuery.Overlaps(as1, as2, r), (i, r) => BatchQuery.Overlaps(a1[i], as2, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(a1[i], a2[j]); });

            var (so, ob) = Sides<F.Sphere, F.Obb3>(inputs, "3D sphere–OBB");
            SphereSet sos = new SphereSet(so);
            ObbSet obs = new ObbSet(ob);
            Distances(add, "3D sphere–OBB", so.Length, r => BatchQuery.Distances(sos, obs, r), (i, r) => BatchQuery.Distances(so[i], obs, r));
            Overlaps(add, "3D sphere–OBB", so.Length, r => BatchQuery.Overlaps(sos, obs, r), (i, r) => BatchQuery.Overlaps(so[i], obs, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(so[i], ob[j]); });

            var (g1, g2) = Sides<F.Segment3, F.Segment3>(inputs, "3D segment–segment");
            SegmentSet gs1 = new SegmentSet(g1), gs2 = new SegmentSet(g2);
            Distances(add, "3D segment–segment", g1.Length, r => BatchQuery.Distances(gs1, gs2, r), (i, r) => BatchQuery.Distances(g1[i], gs2, r));

            var (o1, o2) = Sides<F.Obb3, F.Obb3>(inputs, "3D OBB–OBB");
            ObbSet os1 = new ObbSet(o1), os2 = new ObbSet(o2);
            Overlaps(add, "3D OBB–OBB", o1.Length, r => BatchQuery.Overlaps(os1, os2, r), (i, r) => BatchQuery.Overlaps(o1[i], os2, r),
                (i, r) => { for (int j = 0; j < r.Length; j++) r[j] = FQ.Overlaps(o1[i], o2[j]); });
        }

        /// <summary>The scalar API's Distance looped over each one-to-many batch query's pairs (DistanceOnly.cs; gone against a library without it).</summary>
        static partial void AddScalarDistances(InputSet inputs, Action<string, string, int, Func<int, double>> add);

        /// <summary>One "scalar one-to-many" case: query(i, result) answers shape i against every shape of the other side.</summary>
        private static void ScalarOneToMany<T>(Action<string, string, int, Func<int, double>> add, string group, string name, int n, Action<int, T[]> query, Func<T, double> value)
        {
            var result = new T[n];
            add(group, name, n, reps =>
            {
                for (int r = 0; r < reps; r++) query(r % n, result);
                return value(result[n / 2]);
            });
        }

        private static (TA[] A, TB[] B) Sides<TA, TB>(InputSet inputs, string query) =>
            (Shapes.Of<TA>(inputs.Side(query, 0)), Shapes.Of<TB>(inputs.Side(query, 1)));

        private static void Distances(Action<string, string, int, Func<int, double>> add, string query, int n, Action<float[]> paired, Action<int, float[]> oneToMany)
        {
            var result = new float[n];
            add("float " + query + " distance", "batch paired Distances", n, reps =>
            {
                for (int r = 0; r < reps; r++) paired(result);
                return result[n / 2];
            });
            add("float " + query + " distance", "batch one-to-many Distances", n, reps =>
            {
                for (int r = 0; r < reps; r++) oneToMany(r % n, result);
                return result[n / 2];
            });
        }

        private static void Overlaps(Action<string, string, int, Func<int, double>> add, string query, int n, Action<bool[]> paired, Action<int, bool[]> oneToMany, Action<int, bool[]> scalarOneToMany)
        {
            var result = new bool[n];
            ScalarOneToMany(add, "float " + query + " overlap", "scalar one-to-many Overlaps", n, scalarOneToMany, v => v ? 1 : 0);
            add("float " + query + " overlap", "batch paired Overlaps", n, reps =>
            {
                for (int r = 0; r < reps; r++) paired(result);
                return result[n / 2] ? 1 : 0;
            });
            add("float " + query + " overlap", "batch one-to-many Overlaps", n, reps =>
            {
                for (int r = 0; r < reps; r++) oneToMany(r % n, result);
                return result[n / 2] ? 1 : 0;
            });
        }
    }
}
