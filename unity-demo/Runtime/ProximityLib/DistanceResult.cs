// Copied from src/ProximityLib/DistanceResult.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
using System.Numerics;
using Dbl = ProximityLib.Double;

namespace ProximityLib
{
    /// <summary>The answer of a 3D closest-distance query; the contract of <see cref="Dbl.DistanceResult3"/>, rounded to float.</summary>
    public readonly struct DistanceResult3
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly float Distance;
        /// <summary>max(Distance, 0)², rounded from the double computation.</summary>
        public readonly float DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector3 PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector3 PointB;
        /// <summary>When A is a segment, the parameter of PointA on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly float ParameterA;
        /// <summary>When B is a segment, the parameter of PointB on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly float ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult3(in Dbl.DistanceResult3 r)
        {
            Distance = (float)r.Distance; DistanceSquared = (float)r.DistanceSquared;
            PointA = (Vector3)r.PointA; PointB = (Vector3)r.PointB;
            ParameterA = (float)r.ParameterA; ParameterB = (float)r.ParameterB;
        }

        private DistanceResult3(in DistanceResult3 r, bool swap)
        {
            Distance = r.Distance; DistanceSquared = r.DistanceSquared;
            PointA = swap ? r.PointB : r.PointA; PointB = swap ? r.PointA : r.PointB;
            ParameterA = swap ? r.ParameterB : r.ParameterA; ParameterB = swap ? r.ParameterA : r.ParameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult3 Swapped() => new DistanceResult3(this, true);
    }

    /// <summary>The answer of a 2D closest-distance query; the contract of <see cref="Dbl.DistanceResult3"/>, rounded to float.</summary>
    public readonly struct DistanceResult2
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly float Distance;
        /// <summary>max(Distance, 0)², rounded from the double computation.</summary>
        public readonly float DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector2 PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector2 PointB;
        /// <summary>When A is a segment, the parameter of PointA on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly float ParameterA;
        /// <summary>When B is a segment, the parameter of PointB on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly float ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2(in Dbl.DistanceResult2 r)
        {
            Distance = (float)r.Distance; DistanceSquared = (float)r.DistanceSquared;
            PointA = (Vector2)r.PointA; PointB = (Vector2)r.PointB;
            ParameterA = (float)r.ParameterA; ParameterB = (float)r.ParameterB;
        }

        private DistanceResult2(in DistanceResult2 r, bool swap)
        {
            Distance = r.Distance; DistanceSquared = r.DistanceSquared;
            PointA = swap ? r.PointB : r.PointA; PointB = swap ? r.PointA : r.PointB;
            ParameterA = swap ? r.ParameterB : r.ParameterA; ParameterB = swap ? r.ParameterA : r.ParameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult2 Swapped() => new DistanceResult2(this, true);
    }
}
