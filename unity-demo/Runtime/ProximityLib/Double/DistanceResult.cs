// Copied from src/ProximityLib/Double/DistanceResult.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System.Runtime.CompilerServices;
namespace ProximityLib.Double
{
    /// <summary>
    /// The answer of a 3D closest-distance query between shape A (first argument) and shape B (second argument).
    /// Distance &gt; 0: separated, and PointA, PointB are closest points with |PointA − PointB| = Distance.
    /// Distance = 0: touching. Distance &lt; 0 (only when a solid is involved): overlapping by the penetration depth
    /// −Distance; PointA lies in A, PointB in B, and moving A by PointB − PointA (length −Distance) makes the shapes
    /// just touch: that is the minimum translation.
    /// </summary>
    public readonly struct DistanceResult3
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly double Distance;
        /// <summary>max(Distance, 0)², formed before the square root where the pair allows (point, segment and box pairs).</summary>
        public readonly double DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector3D PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector3D PointB;
        /// <summary>When A is a segment, the parameter of PointA on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly double ParameterA;
        /// <summary>When B is a segment, the parameter of PointB on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly double ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult3(double distance, double distanceSquared, Vector3D pointA, Vector3D pointB, double parameterA, double parameterB)
        {
            Distance = distance; DistanceSquared = distanceSquared; PointA = pointA; PointB = pointB;
            ParameterA = parameterA; ParameterB = parameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult3 Swapped() => new DistanceResult3(Distance, DistanceSquared, PointB, PointA, ParameterB, ParameterA);

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2 To2() =>
            new DistanceResult2(Distance, DistanceSquared, Vector2D.From3(PointA), Vector2D.From3(PointB), ParameterA, ParameterB);
    }

    /// <summary>The answer of a 2D closest-distance query; same contract as <see cref="DistanceResult3"/>.</summary>
    public readonly struct DistanceResult2
    {
        /// <summary>Signed distance: the gap when separated, 0 when touching, minus the penetration depth when overlapping.</summary>
        public readonly double Distance;
        /// <summary>max(Distance, 0)², formed before the square root where the pair allows (point, segment and box pairs).</summary>
        public readonly double DistanceSquared;
        /// <summary>The witness point on (or in) shape A.</summary>
        public readonly Vector2D PointA;
        /// <summary>The witness point on (or in) shape B.</summary>
        public readonly Vector2D PointB;
        /// <summary>When A is a segment, the parameter of PointA on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly double ParameterA;
        /// <summary>When B is a segment, the parameter of PointB on it (0 = Start, 1 = End); otherwise 0.</summary>
        public readonly double ParameterB;

        [MethodImpl(MethodImplOptions.AggressiveInlining)]
        internal DistanceResult2(double distance, double distanceSquared, Vector2D pointA, Vector2D pointB, double parameterA, double parameterB)
        {
            Distance = distance; DistanceSquared = distanceSquared; PointA = pointA; PointB = pointB;
            ParameterA = parameterA; ParameterB = parameterB;
        }

        /// <summary>True when the shapes touch or overlap (Distance ≤ 0).</summary>
        public bool Overlapping => Distance <= 0;

        internal DistanceResult2 Swapped() => new DistanceResult2(Distance, DistanceSquared, PointB, PointA, ParameterB, ParameterA);
    }
}
