using System;
using System.Collections.Generic;
using System.Linq;
using ProximityLib.Double;

namespace ProximityTests.Support
{
    /// <summary>
    /// Signed distance of two convex shapes by duality, independent of the library's case analysis:
    /// sd(A, B) = max over unit n of g(n) = min_B(b·n) − max_A(a·n) (support functions only), which is the gap when
    /// apart and minus the penetration depth when overlapping. Every n gives a lower bound. The maximum is found from
    /// seeds (a direction scan, the shapes' face normals and edge×edge directions, the direction of an alternating-
    /// projection closest pair, and any hint) refined by a fan search in the tangent plane with shrinking steps.
    /// </summary>
    public static class Oracle
    {
        public static double Gap(TestShape a, TestShape b, Vector3D n) => -a.Support(n) - b.Support(-n);

        public static double SignedDistance(TestShape a, TestShape b, int seed = 1, Vector3D? hint = null)
        {
            bool planar = a.Dim == 2;
            var seeds = new List<Vector3D>();
            int count = planar ? 720 : 3000;
            for (int i = 0; i < count; i++) seeds.Add(planar ? Circle(i, count) : Fibonacci(i, count));
            var dirsA = EdgeDirections(a);
            var dirsB = EdgeDirections(b);
            seeds.AddRange(dirsA);
            seeds.AddRange(dirsB);
            if (!planar)
                foreach (var u in dirsA)
                    foreach (var v in dirsB)
                        seeds.Add(Vector3D.Cross(u, v));
            if (planar)
                foreach (var u in dirsA.Concat(dirsB))
                    seeds.Add(new Vector3D(-u.Y, u.X, 0));
            seeds.Add(ProjectionDirection(a, b));
            if (hint.HasValue) seeds.Add(hint.Value);

            var top = new List<(double f, Vector3D n)>();
            foreach (var s0 in seeds)
            {
                foreach (var s in new[] { s0, -s0 })
                {
                    double len = s.Length;
                    if (!(len > 0)) continue;
                    var n = s / len;
                    top.Add((Gap(a, b, n), n));
                }
            }
            top.Sort((x, y) => y.f.CompareTo(x.f));

            var rng = new Random(seed);
            double best = double.NegativeInfinity;
            var ridges = dirsA.Concat(dirsB).ToArray();
            for (int k = 0; k < Math.Min(8, top.Count); k++) best = Math.Max(best, Refine(a, b, top[k].n, planar, ridges, rng));
            return best;
        }

        /// <summary>
        /// Fan search with shrinking steps. Support functions of boxes and segments are kinked across planes normal to
        /// their edges, so the maximum often sits on a ridge that runs along n × edge: those directions join the fan,
        /// since a random fan only rarely lands inside a narrow ascent cone.
        /// </summary>
        private static double Refine(TestShape a, TestShape b, Vector3D n, bool planar, Vector3D[] ridges, Random rng)
        {
            double f = Gap(a, b, n);
            int fan = planar ? 2 : 96;
            for (double step = 0.02; step > 1e-14;)
            {
                Tangents(n, planar, out var t1, out var t2);
                double offset = rng.NextDouble();
                bool improved = false;
                for (int k = 0; k < fan; k++)
                {
                    double angle = 2 * Math.PI * (k + offset) / fan;
                    var trial = n + (t1 * Math.Cos(angle) + t2 * Math.Sin(angle)) * step;
                    trial /= trial.Length;
                    double ft = Gap(a, b, trial);
                    if (ft > f) { f = ft; n = trial; improved = true; }
                }
                if (!planar)
                {
                    foreach (var e in ridges)
                    {
                        var ridge = Vector3D.Cross(n, e);
                        double len = ridge.Length;
                        if (!(len > 0)) continue;
                        foreach (var dir in new[] { ridge / len, -ridge / len })
                        {
                            var trial = n + dir * step;
                            trial /= trial.Length;
                            double ft = Gap(a, b, trial);
                            if (ft > f) { f = ft; n = trial; improved = true; }
                        }
                    }
                }
                if (!improved) step *= 0.5;
            }
            return f;
        }

        private static void Tangents(Vector3D n, bool planar, out Vector3D t1, out Vector3D t2)
        {
            if (planar) { t1 = new Vector3D(-n.Y, n.X, 0); t2 = default; return; }
            var helper = Math.Abs(n.X) < 0.6 ? Vector3D.UnitX : Vector3D.UnitY;
            t1 = Vector3D.Cross(n, helper);
            t1 /= t1.Length;
            t2 = Vector3D.Cross(n, t1);
        }

        private static List<Vector3D> EdgeDirections(TestShape s)
        {
            var list = new List<Vector3D>();
            if (s.Kind == Kind.Segment && s.A != s.B) list.Add(s.B - s.A);
            if (s.Kind == Kind.Aabb || s.Kind == Kind.Obb) list.AddRange(s.Dim == 2 ? new[] { s.Axes[0], s.Axes[1] } : s.Axes);
            return list;
        }

        /// <summary>Alternating projections converge to a closest pair of disjoint convex sets; their difference seeds n.</summary>
        private static Vector3D ProjectionDirection(TestShape a, TestShape b)
        {
            var pa = a.Anchor;
            var pb = b.Anchor;
            for (int i = 0; i < 200; i++)
            {
                pb = Project(b, pa);
                pa = Project(a, pb);
            }
            return pb - pa;
        }

        /// <summary>The nearest point of the shape to x (textbook clamps, written independently of the library).</summary>
        public static Vector3D Project(TestShape s, Vector3D x)
        {
            switch (s.Kind)
            {
                case Kind.Point: return s.P;
                case Kind.Segment:
                    var d = s.B - s.A;
                    double dd = d.LengthSquared;
                    double t = dd > 0 ? Math.Clamp(Vector3D.Dot(x - s.A, d) / dd, 0, 1) : 0;
                    return s.A + d * t;
                case Kind.Sphere:
                    var r = x - s.C;
                    double len = r.Length;
                    return len <= s.R ? x : s.C + r * (s.R / len);
                default:
                    var w = x - s.C;
                    var p = s.C;
                    var h = new[] { s.Half.X, s.Half.Y, s.Half.Z };
                    for (int i = 0; i < 3; i++) p += s.Axes[i] * Math.Clamp(Vector3D.Dot(w, s.Axes[i]), -h[i], h[i]);
                    return p;
            }
        }

        private static Vector3D Fibonacci(int i, int count)
        {
            double z = 1 - (2.0 * i + 1) / count;
            double r = Math.Sqrt(Math.Max(0, 1 - z * z));
            double phi = i * Math.PI * (3 - Math.Sqrt(5));
            return new Vector3D(r * Math.Cos(phi), r * Math.Sin(phi), z);
        }

        private static Vector3D Circle(int i, int count)
        {
            double phi = 2 * Math.PI * i / count;
            return new Vector3D(Math.Cos(phi), Math.Sin(phi), 0);
        }
    }
}
