using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using D = ProximityLib.Double;
using F = ProximityLib;

namespace ProximitySpeed
{
    // A case is a struct implementing one or more of these: the timing loop is generic over it, so each case's loop is
    // compiled for it alone and the query can inline into it, on .NET and on Mono (which has no static abstract members).

    /// <summary>The closest distance with witness points, folded into one number (Fold) so no part of the answer is dead code.</summary>
    public interface IBetween<TA, TB> { double Between(in TA a, in TB b); }

    /// <summary>The closest distance alone.</summary>
    public interface IDistance<TA, TB> { double Distance(in TA a, in TB b); }

    /// <summary>The touch-or-overlap verdict.</summary>
    public interface IOverlap<TA, TB> { bool Overlaps(in TA a, in TB b); }

    /// <summary>
    /// A ray cast: the distance T along the ray's unit direction to its first hit, +∞ for a miss (hit and T in one
    /// number, so a baseline can be checked against the library pair by pair).
    /// </summary>
    public interface IRaycast<TRay, TShape> { double Cast(in TRay ray, in TShape shape); }

    /// <summary>Who wrote the code a case times.</summary>
    public enum Source { Library, Baseline, Paper }

    /// <summary>The precision names a case carries.</summary>
    public static class Precision { public const string Float = "float", Double = "double"; }

    /// <summary>Names a case: its source, "float" or "double", and the query as the inputs name it ("3D sphere–OBB").</summary>
    [AttributeUsage(AttributeTargets.Struct)]
    public sealed class CaseAttribute : Attribute
    {
        public CaseAttribute(Source source, string precision, string query) { Source = source; Precision = precision; Query = query; }
        public Source Source { get; }
        public string Precision { get; }
        public string Query { get; }
    }

    /// <summary>
    /// Folds an answer into one number: the distance plus every witness coordinate, summed as a tree (short dependency
    /// chains). The library's results and the baselines' answers fold the same way.
    /// </summary>
    public static class Fold
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(float d, Vector3 a, Vector3 b) => (d + a.X) + (a.Y + a.Z) + ((b.X + b.Y) + b.Z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(float d, Vector2 a, Vector2 b) => (d + a.X) + (a.Y + (b.X + b.Y));
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(double d, double ax, double ay, double az, double bx, double by, double bz) => (d + ax) + (ay + az) + ((bx + by) + bz);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(double d, double ax, double ay, double bx, double by) => (d + ax) + (ay + (bx + by));
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(in F.DistanceResult3 r) => Of(r.Distance, r.PointA, r.PointB);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(in F.DistanceResult2 r) => Of(r.Distance, r.PointA, r.PointB);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(in D.DistanceResult3 r) => Of(r.Distance, r.PointA.X, r.PointA.Y, r.PointA.Z, r.PointB.X, r.PointB.Y, r.PointB.Z);
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Of(in D.DistanceResult2 r) => Of(r.Distance, r.PointA.X, r.PointA.Y, r.PointB.X, r.PointB.Y);
    }

    // The timing loops: every pair once per repetition, the answers accumulated so nothing is optimised away.

    internal sealed class BetweenLoop<TQ, TA, TB> where TQ : struct, IBetween<TA, TB>
    {
        private readonly TA[] _a;
        private readonly TB[] _b;
        public BetweenLoop(TA[] a, TB[] b) { _a = a; _b = b; }

        public double Run(int reps)
        {
            double acc = 0;
            var a = _a;
            var b = _b;
            var q = default(TQ);
            for (int r = 0; r < reps; r++)
                for (int i = 0; i < a.Length; i++) acc += q.Between(a[i], b[i]);
            return acc;
        }
    }

    internal sealed class DistanceLoop<TQ, TA, TB> where TQ : struct, IDistance<TA, TB>
    {
        private readonly TA[] _a;
        private readonly TB[] _b;
        public DistanceLoop(TA[] a, TB[] b) { _a = a; _b = b; }

        public double Run(int reps)
        {
            double acc = 0;
            var a = _a;
            var b = _b;
            var q = default(TQ);
            for (int r = 0; r < reps; r++)
                for (int i = 0; i < a.Length; i++) acc += q.Distance(a[i], b[i]);
            return acc;
        }
    }

    internal sealed class OverlapLoop<TQ, TA, TB> where TQ : struct, IOverlap<TA, TB>
    {
        private readonly TA[] _a;
        private readonly TB[] _b;
        public OverlapLoop(TA[] a, TB[] b) { _a = a; _b = b; }

        public double Run(int reps)
        {
            int count = 0;
            var a = _a;
            var b = _b;
            var q = default(TQ);
            for (int r = 0; r < reps; r++)
                for (int i = 0; i < a.Length; i++) if (q.Overlaps(a[i], b[i])) count++;
            return count;
        }
    }

    internal sealed class RaycastLoop<TQ, TR, TS> where TQ : struct, IRaycast<TR, TS>
    {
        private readonly TR[] _a;
        private readonly TS[] _b;
        public RaycastLoop(TR[] a, TS[] b) { _a = a; _b = b; }

        /// <summary>Sums T over the hits and counts the misses (−1 each): a missed hit or a wrong T moves the sum.</summary>
        public double Run(int reps)
        {
            double acc = 0;
            var a = _a;
            var b = _b;
            var q = default(TQ);
            for (int r = 0; r < reps; r++)
                for (int i = 0; i < a.Length; i++)
                {
                    double t = q.Cast(a[i], b[i]);
                    acc += t <= double.MaxValue ? t : -1;
                }
            return acc;
        }

        /// <summary>Every pair's answer, for the pair-by-pair agreement check.</summary>
        public double[] Each()
        {
            var result = new double[_a.Length];
            var q = default(TQ);
            for (int i = 0; i < _a.Length; i++) result[i] = q.Cast(_a[i], _b[i]);
            return result;
        }
    }
}
