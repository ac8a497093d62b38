// Copied from src/ProximityLib.Scenes/Gait/FootModel.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;

namespace ProximityLib.Scenes.Gait
{
    /// <summary>The three primitives of the foot, as the paper's scene has them.</summary>
    public enum FootPart
    {
        /// <summary>The heel sphere.</summary>
        Heel,
        /// <summary>The sole box.</summary>
        Sole,
        /// <summary>The toe sphere.</summary>
        Toe,
    }

    /// <summary>
    /// The foot at one instant: heel sphere, sole box and toe sphere in metres (x forward, y up, z lateral; the foot
    /// moves in z = 0). The sole is an OBB, not the paper's AABB, because the foot pitches by up to ~70° through the
    /// cycle and an axis-aligned box would have to grow to enclose it, touching the ground long before the foot does.
    /// </summary>
    public readonly struct FootPose
    {
        /// <summary>Creates a pose from its three primitives.</summary>
        public FootPose(Sphere heel, Obb3 sole, Sphere toe, float pitch)
        {
            Heel = heel; Sole = sole; Toe = toe; Pitch = pitch;
        }

        /// <summary>The heel sphere.</summary>
        public Sphere Heel { get; }
        /// <summary>The sole box.</summary>
        public Obb3 Sole { get; }
        /// <summary>The toe sphere.</summary>
        public Sphere Toe { get; }
        /// <summary>The sole's pitch in radians (toe up positive; 0 when the sole is flat on the ground).</summary>
        public float Pitch { get; }
    }

    /// <summary>
    /// A rigid foot of three primitives fixed to the heel–toe marker line of <see cref="GaitTrial"/>. The primitives are
    /// placed once, at the recording's stillest stance instant (the least motion of pitch and heel height), so that the
    /// sole lies flat on the floor there and the heel and toe spheres touch it; every other instant moves them rigidly
    /// with the markers. Nothing about when parts touch the ground is put in here: that comes from the queries.
    /// </summary>
    public sealed class FootModel
    {
        /// <summary>Heel sphere radius of the recorded foot (m): roughly the heel pad's curvature.</summary>
        public const double HeelRadius = 0.025;
        /// <summary>Toe sphere radius of the recorded foot (m).</summary>
        public const double ToeRadius = 0.015;
        /// <summary>Sole thickness (m).</summary>
        public const double SoleThickness = 0.010;
        /// <summary>Half the sole's width (m): about half a foot breadth.</summary>
        public const double SoleHalfWidth = 0.045;

        private readonly double[] _heelX, _heelY, _pitch, _length; // metres, radians; one entry per recorded sample
        private readonly Vector2 _heelOffset, _toeOffset, _soleOffset; // from the heel marker, in the reference frame
        private readonly double _referencePitch;
        private readonly float _scale;

        /// <summary>
        /// Builds the foot from the recording, uniformly scaled so its heel–toe marker distance at the reference
        /// instant is <paramref name="footLength"/> metres (null keeps the recorded foot).
        /// </summary>
        public FootModel(double? footLength = null)
        {
            int n = GaitTrial.HeelX.Length;
            _heelX = new double[n];
            _heelY = new double[n];
            _pitch = new double[n];
            _length = new double[n];
            for (int i = 0; i < n; i++)
            {
                double dx = GaitTrial.ToeX[i] - GaitTrial.HeelX[i], dy = GaitTrial.ToeY[i] - GaitTrial.HeelY[i];
                _heelX[i] = GaitTrial.HeelX[i] / 1000;
                _heelY[i] = GaitTrial.HeelY[i] / 1000;
                _pitch[i] = Math.Atan2(dy, dx);
                _length[i] = Math.Sqrt(dx * dx + dy * dy) / 1000;
            }
            ReferenceSample = StillestSample();
            int r = ReferenceSample;
            RecordedFootLength = _length[r];
            if (footLength.HasValue && !(footLength.Value > 0 && footLength.Value < 1))
                throw new ArgumentException($"footLength must be between 0 and 1 m (got {footLength.Value}).", nameof(footLength));
            _scale = (float)((footLength ?? RecordedFootLength) / RecordedFootLength);
            FootLength = RecordedFootLength * _scale;

            // At the reference instant: heel sphere just in front of the heel marker, toe sphere just behind the toe
            // marker, both on the floor, and the sole's bottom face on the floor between their centres.
            double hx = _heelX[r], hy = _heelY[r], tx = GaitTrial.ToeX[r] / 1000;
            _referencePitch = _pitch[r];
            _heelOffset = new Vector2((float)HeelRadius, (float)(HeelRadius - hy));
            _toeOffset = new Vector2((float)(tx - ToeRadius - hx), (float)(ToeRadius - hy));
            _soleOffset = new Vector2((_heelOffset.X + _toeOffset.X) / 2, (float)(SoleThickness / 2 - hy));
            SoleHalfLength = (_toeOffset.X - _heelOffset.X) / 2;
        }

        /// <summary>The recorded sample the primitives were placed at (sole flat on the floor).</summary>
        public int ReferenceSample { get; }
        /// <summary>Heel–toe marker distance of the recorded foot at the reference sample (m).</summary>
        public double RecordedFootLength { get; }
        /// <summary>Heel–toe marker distance of this foot (m).</summary>
        public double FootLength { get; }
        /// <summary>Half the sole's length before scaling (m).</summary>
        public float SoleHalfLength { get; }
        /// <summary>The uniform scale from the recorded foot to this one.</summary>
        public float Scale => _scale;
        /// <summary>Number of recorded samples.</summary>
        public int SampleCount => _heelX.Length;

        /// <summary>Heel marker forward position at a (fractional) sample index, in the recording's frame (m, unscaled).</summary>
        public double HeelXAt(double sample) => Lerp(_heelX, sample);

        /// <summary>The foot at a (fractional) sample index; <paramref name="shiftX"/> is added to every x (m, unscaled).</summary>
        public FootPose PoseAt(double sample, double shiftX = 0)
        {
            var heel = new Vector2((float)(Lerp(_heelX, sample) + shiftX), (float)Lerp(_heelY, sample));
            float pitch = (float)(Lerp(_pitch, sample) - _referencePitch);
            float c = MathF.Cos(pitch), s = MathF.Sin(pitch);
            Vector3 Place(Vector2 offset) => new Vector3(
                (heel.X + c * offset.X - s * offset.Y) * _scale, (heel.Y + s * offset.X + c * offset.Y) * _scale, 0);
            var turn = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, pitch);
            return new FootPose(
                new Sphere(Place(_heelOffset), (float)HeelRadius * _scale),
                new Obb3(Place(_soleOffset), turn, new Vector3(SoleHalfLength, (float)SoleThickness / 2, (float)SoleHalfWidth) * _scale),
                new Sphere(Place(_toeOffset), (float)ToeRadius * _scale),
                pitch);
        }

        // The reference for "flat" is the instant the foot moves least: pitch change (as travel at the toe) plus
        // heel height change between neighbouring samples, the way zero-velocity detectors find mid-stance.
        private int StillestSample()
        {
            int best = 1;
            double least = double.PositiveInfinity;
            for (int i = 1; i + 1 < _pitch.Length; i++)
            {
                double motion = Math.Abs(_pitch[i + 1] - _pitch[i - 1]) * _length[i] + Math.Abs(_heelY[i + 1] - _heelY[i - 1]);
                if (motion < least) { least = motion; best = i; }
            }
            return best;
        }

        private static double Lerp(double[] values, double sample)
        {
            double clamped = Math.Max(0, Math.Min(values.Length - 1, sample));
            int i = Math.Min((int)clamped, values.Length - 2);
            double f = clamped - i;
            return values[i] + (values[i + 1] - values[i]) * f;
        }
    }
}
