// Copied from src/ProximityLib/Batch/Runner.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;
using System.Runtime.CompilerServices;
using System.Runtime.InteropServices;

namespace ProximityLib.Batch
{
    /// <summary>Runs a kernel over a batch: on <see cref="Vector{T}"/> lanes where they are hardware-accelerated, else lane by lane in scalar float.</summary>
    internal static class Runner
    {
        /// <summary>
        /// Whether the kernels run on <see cref="Vector{T}"/> lanes. Where <see cref="Vector.IsHardwareAccelerated"/> is
        /// false (Mono, Unity's editor) <see cref="Vector{T}"/> is a software loop over four lanes, slower than the scalar
        /// API; there each lane runs as plain scalar float code, with the same bits. Tests switch it off to check that.
        /// </summary>
        internal static bool Vectorized = Vector.IsHardwareAccelerated;

        public static void Values<TK>(TK kernel, int count, Span<float> result) where TK : struct, IKernel
        {
            CheckRoom(count, result.Length);
            if (!Workers.Values(kernel, count, result)) Values(kernel, 0, count, result);
        }

        public static void NonPositive<TK>(TK kernel, int count, Span<bool> result) where TK : struct, IKernel
        {
            CheckRoom(count, result.Length);
            if (!Workers.NonPositive(kernel, count, result)) NonPositive(kernel, 0, count, result);
        }

        private static void CheckRoom(int count, int length)
        {
            if (length < count) throw new ArgumentException($"result needs room for {count} values (has {length}).", "result");
        }

        /// <summary>Lanes start to end − 1 into result[start..end); start is a multiple of <see cref="Vector{T}.Count"/>.</summary>
        internal static void Values<TK>(TK kernel, int start, int end, Span<float> result) where TK : struct, IKernel
        {
            int i = start;
            if (!Vectorized)
            {
                kernel.Values(start, end, result);
                return;
            }
            int w = Vector<float>.Count;
            // Vector<T>.CopyTo(Span<T>) is missing from netstandard2.1; a reinterpreting store does the same.
            for (; i + w <= end; i += w) MemoryMarshal.Cast<float, Vector<float>>(result.Slice(i, w))[0] = kernel.Compute(i);
            if (i < end)
            {
                Span<float> tail = stackalloc float[w];
                MemoryMarshal.Cast<float, Vector<float>>(tail)[0] = kernel.Compute(i);
                tail.Slice(0, end - i).CopyTo(result.Slice(i));
            }
        }

        /// <summary>Verdicts (value ≤ 0) of lanes start to end − 1 into result[start..end); start is a multiple of <see cref="Vector{T}.Count"/>.</summary>
        internal static void NonPositive<TK>(TK kernel, int start, int end, Span<bool> result) where TK : struct, IKernel
        {
            int i = start;
            if (!Vectorized)
            {
                kernel.Verdicts(start, end, result);
                return;
            }
            int w = Vector<float>.Count;
            // Four vectors of lane masks (all ones or zero) narrow to one vector of bytes, stored as bools 1 or 0.
            var bytes = MemoryMarshal.Cast<bool, byte>(result);
            var one = new Vector<byte>(1);
            for (; i + 4 * w <= end; i += 4 * w)
            {
                var low = Vector.Narrow(Mask(kernel.Compute(i)), Mask(kernel.Compute(i + w)));
                var high = Vector.Narrow(Mask(kernel.Compute(i + 2 * w)), Mask(kernel.Compute(i + 3 * w)));
                MemoryMarshal.Cast<byte, Vector<byte>>(bytes.Slice(i, 4 * w))[0] = Vector.Narrow(low, high) & one;
            }
            if (i == end) return;
            // The last few vectors lane by lane through a stack buffer (indexing a Vector<T> by a variable lane is slow).
            Span<float> lanes = stackalloc float[w];
            var asVector = MemoryMarshal.Cast<float, Vector<float>>(lanes);
            for (; i < end; i += w)
            {
                asVector[0] = kernel.Compute(i);
                int n = Math.Min(w, end - i);
                for (int j = 0; j < n; j++) result[i + j] = lanes[j] <= 0;
            }
        }

        /// <summary>The scalar lanes one <see cref="IKernel.Lane"/> call each, for kernels without a loop of their own.</summary>
        internal static void EachLane<TK>(ref TK kernel, int start, int end, Span<float> result) where TK : struct, IKernel
        {
            for (int i = start; i < end; i++) result[i] = kernel.Lane(i);
        }

        /// <summary>The scalar verdicts one <see cref="IKernel.Lane"/> call each.</summary>
        internal static void EachLane<TK>(ref TK kernel, int start, int end, Span<bool> result) where TK : struct, IKernel
        {
            for (int i = start; i < end; i++) result[i] = kernel.Lane(i) <= 0;
        }

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        private static Vector<uint> Mask(Vector<float> x) => Vector.AsVectorUInt32(Vector.LessThanOrEqual(x, Vector<float>.Zero));

        /// <summary>
        /// x clamped to [lo, hi] by <see cref="MaxNative"/> and <see cref="MinNative"/>: the kernels square the clamped
        /// gap or subtract it from x before squaring, so a zero's sign cannot reach a result.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Clamp(Vector<float> x, Vector<float> lo, Vector<float> hi) => MinNative(MaxNative(x, lo), hi);

        // The hardware's maxps/minps. On .NET 9 and later Vector.Max/Min follow IEEE 754-2019 (NaN propagates, +0 > −0):
        // nine instructions each on x64 without AVX-512 where maxps is one, and a batch kernel makes up to 17 such calls
        // per vector (segment–segment; OBB–OBB 14). For operands that are never NaN (every lane inside the batch's
        // range) and values whose zero sign does not matter (clamped gaps that are squared, separations and squared
        // distances that are only compared with 0 or each other) the two agree. netstandard2.1 has only Vector.Max/Min.
#if NET
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> MaxNative(Vector<float> a, Vector<float> b) => Vector.MaxNative(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> MinNative(Vector<float> a, Vector<float> b) => Vector.MinNative(a, b);
#else
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> MaxNative(Vector<float> a, Vector<float> b) => Vector.Max(a, b);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> MinNative(Vector<float> a, Vector<float> b) => Vector.Min(a, b);
#endif

        /// <summary>−x by flipping the sign bit, as .NET's unary minus does: Mono's Vector&lt;T&gt; negation computes 0 − x, which keeps +0 positive, so unary minus would give Mono and .NET results of different sign at 0.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static Vector<float> Negate(Vector<float> x) => Vector.AsVectorSingle(Vector.Xor(Vector.AsVectorUInt32(x), new Vector<uint>(0x80000000u)));

        /// <summary>The scalar lanes' clamp: the vector one's maxps and minps rules (each returns its second operand unless the first is larger, or smaller), so the same bits, NaN included.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Clamp(float x, float lo, float hi) => x > lo ? (x < hi ? x : hi) : (lo < hi ? lo : hi);

        /// <summary>
        /// |x| for the scalar lanes, through double: Mono 6.8 compiles <c>Math.Abs(float)</c> as a call, which spills every
        /// live register around it (the OBB–OBB verdicts took twice as long), and its <c>Math.Abs(double)</c> as one
        /// instruction. The absolute value is exact in either precision, so the bits are <c>Math.Abs(x)</c>'s.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Abs(float x) => (float)Math.Abs((double)x);

        /// <summary>
        /// √x for the scalar lanes, through double for the reason <see cref="Abs(float)"/> gives (Mono 6.8 calls out for
        /// <c>MathF.Sqrt</c>). The double root rounded to float is the correctly rounded float root, as <c>MathF.Sqrt</c>
        /// and the vector lanes' give it: double rounding is innocuous for √ when 53 ≥ 2·24 + 2 (Figueroa 1995).
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Sqrt(float x) => (float)Math.Sqrt(x);

        /// <summary>
        /// The smaller of a and b as <see cref="Vector.Min{T}"/> gives it on .NET 9 and later (IEEE 754-2019 minimum): −0
        /// below +0, NaN if either is NaN. Scalar <c>Math.Min</c> does not do that on every runtime.
        /// </summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        public static float Min(float a, float b) =>
            a < b ? a : b < a ? b : a == b ? BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(a) | BitConverter.SingleToInt32Bits(b)) : a + b;
    }
}
