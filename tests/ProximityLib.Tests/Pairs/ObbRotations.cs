using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using static ProximityTests.Pairs.HalfSpaceBoxChecks;
using static ProximityTests.Support.Expect;
using Flt = ProximityLib;
using Num = System.Numerics;

namespace ProximityTests.Pairs
{
    /// <summary>
    /// OBB references for the line/ray/capsule pairs: an OBB whose axes are an exact signed permutation of the world
    /// axes is the AABB of its corners, so the exact AABB reference applies to it exactly; random rotations are checked
    /// by invariants and against the same configuration expressed in the box frame as an AABB (rotation rounding only).
    /// </summary>
    internal static class ObbRotations
    {
        public static Vector3D[] Permuted(Random rng, int dim)
        {
            if (dim == 2) return rng.Next(2) == 0 ? new[] { V(0, 1, 0), V(-1, 0, 0), V(0, 0, 1) } : new[] { V(-1, 0, 0), V(0, -1, 0), V(0, 0, 1) };
            return new[] { V(0, 1, 0), V(0, 0, 1), V(1, 0, 0) };
        }

        /// <summary>Check on a line/ray/capsule (made by <paramref name="shape"/>) against an OBB; E against the exact AABB reference when the axes are permutations.</summary>
        public static double Measure(int dim, Func<double, object> shape, Vector3D c, Vector3D[] axes, Vector3D h, Func<Vector3D, Vector3D, Rational> exact, Vector3D[] defining, double length, bool exactFrame)
        {
            var r = Check(f => (shape(f), Rand.Ob(dim, c * f, axes, h * f)));
            if (!exactFrame) return 0;
            var (cc, ax, hh) = Rand.Frame(Rand.Ob(dim, c, axes, h));
            var ext = ax[0].Abs3() * hh.X + ax[1].Abs3() * hh.Y + (dim == 3 ? ax[2].Abs3() * hh.Z : default);
            var lo = cc - ext; var hi = cc + ext;
            return E(r.D, exact(lo, hi), Scale(HalfSpaceAabbTests.Corners(lo, hi).Concat(defining), length));
        }
    }
}
