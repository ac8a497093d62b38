// Copied from src/ProximityLib/Num.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Runtime.CompilerServices;

namespace ProximityLib
{
    internal static class Num
    {
        // Math.Clamp throws when lo > hi; queries must never throw, and callers guarantee lo <= hi anyway.
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static double Clamp(double x, double lo, double hi) => Math.Min(Math.Max(x, lo), hi);

        public static void Finite(double value, string name)
        {
            if (!double.IsFinite(value)) throw new ArgumentException($"{name} must be finite (got {value}).", name);
        }

        public static void NonNegative(double value, string name)
        {
            Finite(value, name);
            if (value < 0) throw new ArgumentException($"{name} must be non-negative (got {value}).", name);
        }

        public static void Finite(Double.Vector3D v, string name)
        {
            if (!v.IsFinite) throw new ArgumentException($"{name} must have finite components (got {v}).", name);
        }

        public static void Finite(Double.Vector2D v, string name)
        {
            if (!v.IsFinite) throw new ArgumentException($"{name} must have finite components (got {v}).", name);
        }
    }
}
