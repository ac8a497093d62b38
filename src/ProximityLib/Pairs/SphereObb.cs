using System.Runtime.CompilerServices;

namespace ProximityLib.Double
{
    public static partial class ClosestDistance
    {
        /// <summary>Closest distance between a sphere and an OBB (3D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–box from the center in the box frame, less the radius; overlap by Arvo's squared test.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult3 Core(in Sphere a, in Obb3 b, out bool inRange)
        {
            var r = Kernels.PointBox(a.Center, b.ToBox(), out inRange).AsSphereFirst(a.Center, a.Radius);
            inRange &= !b.Extreme;
            return r;
        }
        /// <summary>Closest distance between a circle and an OBB (2D): negative when overlapping (depth = radius − gap, or radius + face depth when the center is inside). Algorithm: point–box from the center in the box frame, less the radius; overlap by Arvo's squared test.</summary>
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static DistanceResult2 Core(in Circle a, in Obb2 b, out bool inRange)
        {
            var r = Kernels.PointBox2(a.Center, b.ToBox2(), out inRange).AsSphereFirst(a.Center.To3(), a.Radius).To2();
            inRange &= !b.Extreme;
            return r;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Sphere a, in Obb3 b, out bool inRange)
        {
            double d = Kernels.PointBoxDistance(a.Center, b.ToBox(), out inRange) - a.Radius;
            inRange &= !b.Extreme;
            return d;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static double DistanceCore(in Circle a, in Obb2 b, out bool inRange)
        {
            double d = Kernels.PointBoxDistance2(a.Center, b.ToBox2(), out inRange) - a.Radius;
            inRange &= !b.Extreme;
            return d;
        }
    }

    public static partial class ProximityQuery
    {
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Sphere a, in Obb3 b, out bool inRange)
        {
            bool r = Kernels.WithinRadius(Kernels.PointBoxDistanceSquared(a.Center, b.ToBox()), a.Radius, out inRange);
            inRange &= !b.Extreme;
            return r;
        }
        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal static bool Core(in Circle a, in Obb2 b, out bool inRange)
        {
            bool r = Kernels.WithinRadius(Kernels.PointBoxDistanceSquared2(a.Center, b.ToBox2()), a.Radius, out inRange);
            inRange &= !b.Extreme;
            return r;
        }
    }
}
