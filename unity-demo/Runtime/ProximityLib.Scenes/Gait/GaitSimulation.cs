// Copied from src/ProximityLib.Scenes/Gait/GaitSimulation.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;

namespace ProximityLib.Scenes.Gait
{
    /// <summary>One frame of the gait scene: where the foot is, each part's distance to the ground and its contact state.</summary>
    public readonly struct GaitFrame
    {
        /// <summary>Creates a frame.</summary>
        public GaitFrame(double percent, double time, FootPose pose, Vector3 distances, bool heelContact, bool soleContact, bool toeContact)
        {
            Percent = percent; Time = time; Pose = pose; Distances = distances;
            HeelContact = heelContact; SoleContact = soleContact; ToeContact = toeContact;
        }

        /// <summary>Position in the gait cycle (0 = heel strike, 100 = the next one).</summary>
        public double Percent { get; }
        /// <summary>Seconds since heel strike.</summary>
        public double Time { get; }
        /// <summary>The foot's three primitives.</summary>
        public FootPose Pose { get; }
        /// <summary>Signed closest distances to the ground (m) of heel, sole and toe, in X, Y, Z.</summary>
        public Vector3 Distances { get; }
        /// <summary>Whether the heel is within the contact tolerance of the ground.</summary>
        public bool HeelContact { get; }
        /// <summary>Whether the sole is within the contact tolerance of the ground.</summary>
        public bool SoleContact { get; }
        /// <summary>Whether the toe is within the contact tolerance of the ground.</summary>
        public bool ToeContact { get; }

        /// <summary>The distance of one part (m).</summary>
        public float Distance(FootPart part) => part == FootPart.Heel ? Distances.X : part == FootPart.Sole ? Distances.Y : Distances.Z;
        /// <summary>The contact state of one part.</summary>
        public bool Contact(FootPart part) => part == FootPart.Heel ? HeelContact : part == FootPart.Sole ? SoleContact : ToeContact;
    }

    /// <summary>The gait events found from the contact timelines, in percent of the cycle (heel strike is 0 by definition).</summary>
    public readonly struct GaitEvents
    {
        /// <summary>Creates the event set.</summary>
        public GaitEvents(double footFlat, double heelOff, double toeOff, double minToeClearance, double minToeClearancePercent)
        {
            FootFlat = footFlat; HeelOff = heelOff; ToeOff = toeOff;
            MinToeClearance = minToeClearance; MinToeClearancePercent = minToeClearancePercent;
        }

        /// <summary>The forefoot (toe sphere) reaches the ground after heel strike.</summary>
        public double FootFlat { get; }
        /// <summary>The heel leaves the ground.</summary>
        public double HeelOff { get; }
        /// <summary>The last part of the foot leaves the ground.</summary>
        public double ToeOff { get; }
        /// <summary>The toe sphere's smallest distance to the ground in mid swing (m).</summary>
        public double MinToeClearance { get; }
        /// <summary>Where in the cycle that minimum is.</summary>
        public double MinToeClearancePercent { get; }
    }

    /// <summary>
    /// The paper's foot–ground scene, replaying the recorded right stride of <see cref="GaitTrial"/>: each frame places
    /// the <see cref="FootModel"/> and asks ProximityLib for each part's distance to the ground AABB (what the plot
    /// shows) and for the contact verdict with the cheap overlap query against the ground raised by the contact
    /// tolerance. The cycle runs from one heel strike to the next, both found by the same queries, and every other
    /// event is read off the contact timelines; none is written into the kinematics.
    /// </summary>
    public sealed class GaitSimulation
    {
        /// <summary>
        /// The default contact tolerance (m): how close to the ground a part counts as touching it. Below the 4–6 mm at
        /// which this rigid heel hovers over the floor in the last ~80 ms before it lands (a sphere is not a shoe's
        /// heel), above the sub-millimetre scatter of the parts during foot flat; docs/demos.md shows the events for
        /// other tolerances.
        /// </summary>
        public const double DefaultContactTolerance = 0.002;

        /// <summary>The default number of frames per cycle.</summary>
        public const int DefaultFrames = 200;

        // Time resolution of the event search, in recorded samples (1/60 s): far below a frame.
        private const double EventResolution = 1e-6;
        // Debouncing, as foot-switch processing does: a contact must last 50 ms and the swing 100 ms to count.
        private const double ContactHold = 3, SwingHold = 6;

        private readonly Aabb3 _contactGround;
        private readonly double _strikeSample, _nextStrikeSample, _beltSpeed;

        /// <summary>
        /// Sets up the scene. Give at most one of <paramref name="cadence"/> (steps per minute) and
        /// <paramref name="speed"/> (m/s): the stride is the recorded one, scaled with the foot, so each sets the other;
        /// with neither, the recording's own timing is used. <paramref name="footLength"/> scales the whole foot and its
        /// path uniformly (heel–toe marker distance, m). <paramref name="frames"/> frames cover one cycle.
        /// </summary>
        public GaitSimulation(double? cadence = null, double? speed = null, double? footLength = null, int frames = DefaultFrames,
            double contactTolerance = DefaultContactTolerance)
        {
            if (cadence.HasValue && speed.HasValue)
                throw new ArgumentException("give cadence or speed, not both: with the recorded stride each sets the other.", nameof(speed));
            if (cadence.HasValue && !(cadence.Value >= 20 && cadence.Value <= 250))
                throw new ArgumentException($"cadence must be between 20 and 250 steps/min (got {cadence.Value}).", nameof(cadence));
            if (speed.HasValue && !(speed.Value >= 0.1 && speed.Value <= 5))
                throw new ArgumentException($"speed must be between 0.1 and 5 m/s (got {speed.Value}).", nameof(speed));
            if (frames < 10 || frames > 1_000_000)
                throw new ArgumentException($"frames must be between 10 and 1000000 (got {frames}).", nameof(frames));
            if (!(contactTolerance >= 0 && contactTolerance <= 0.05))
                throw new ArgumentException($"contactTolerance must be between 0 and 0.05 m (got {contactTolerance}).", nameof(contactTolerance));

            Foot = new FootModel(footLength);
            FrameCount = frames;
            ContactTolerance = contactTolerance;
            Ground = new Aabb3(new Vector3(-20, -0.1f, -1), new Vector3(20, 0, 1));
            _contactGround = new Aabb3(new Vector3(-20, -0.1f, -1), new Vector3(20, (float)contactTolerance, 1));

            // The cycle: the first heel strike in the recording, the moment the whole foot is off the ground after it,
            // and the next heel strike. Inside the stance, foot flat is the first toe contact and heel off the heel's
            // last lift before toe off, so a brief touch-and-lift while the heel settles does not count as heel off.
            int last = Foot.SampleCount - 1;
            _strikeSample = Crossing(s => Gap(FootPart.Heel, s), 0, last, onset: true, first: true, ContactHold)
                ?? throw new InvalidOperationException("no heel strike in the recording at this contact tolerance.");
            double footOff = Crossing(FootGap, _strikeSample, last, onset: false, first: true, SwingHold) ?? double.NaN;
            _nextStrikeSample = Crossing(s => Gap(FootPart.Heel, s), footOff, last, onset: true, first: true, ContactHold) ?? double.NaN;
            double footFlat = Crossing(s => Gap(FootPart.Toe, s), _strikeSample, footOff, onset: true, first: true, ContactHold) ?? double.NaN;
            double heelOff = Crossing(s => Gap(FootPart.Heel, s), _strikeSample, footOff, onset: false, first: false, 0) ?? double.NaN;
            if (double.IsNaN(_nextStrikeSample) || double.IsNaN(footFlat) || double.IsNaN(heelOff))
                throw new InvalidOperationException("the recording holds no complete heel-strike-to-heel-strike cycle at this contact tolerance.");

            double samples = _nextStrikeSample - _strikeSample;
            // The stance foot moves backward with the ground in the recording's frame: its speed between foot flat and
            // heel off is the walking speed, and one cycle of it is the stride.
            _beltSpeed = (Foot.HeelXAt(footFlat) - Foot.HeelXAt(heelOff)) / ((heelOff - footFlat) / GaitTrial.SampleRate);
            RecordedStrideDuration = samples / GaitTrial.SampleRate;
            StrideLength = _beltSpeed * RecordedStrideDuration * Foot.Scale;
            StrideDuration = cadence.HasValue ? 120 / cadence.Value : speed.HasValue ? StrideLength / speed.Value : RecordedStrideDuration;

            double Percent(double sample) => (sample - _strikeSample) / samples * 100;
            var (clearance, at) = MinToeClearanceInMidSwing();
            Events = new GaitEvents(Percent(footFlat), Percent(heelOff), Percent(footOff), clearance, at);
        }

        /// <summary>The foot.</summary>
        public FootModel Foot { get; }
        /// <summary>The ground: an AABB whose top face is y = 0.</summary>
        public Aabb3 Ground { get; }
        /// <summary>Frames per cycle.</summary>
        public int FrameCount { get; }
        /// <summary>How close to the ground a part counts as touching it (m).</summary>
        public double ContactTolerance { get; }
        /// <summary>The events read off the contact timelines.</summary>
        public GaitEvents Events { get; }
        /// <summary>Duration of the recorded stride (s).</summary>
        public double RecordedStrideDuration { get; }
        /// <summary>Duration of one stride (s) at the chosen cadence or speed.</summary>
        public double StrideDuration { get; }
        /// <summary>Length of one stride (m): the recorded one, scaled with the foot.</summary>
        public double StrideLength { get; }
        /// <summary>Steps per minute.</summary>
        public double Cadence => 120 / StrideDuration;
        /// <summary>Walking speed (m/s).</summary>
        public double Speed => StrideLength / StrideDuration;

        /// <summary>The foot at a point of the cycle (percent, wrapped into [0, 100)), moving forward over the ground.</summary>
        public FootPose PoseAt(double percent)
        {
            double p = percent - 100 * Math.Floor(percent / 100);
            double sample = _strikeSample + p / 100 * (_nextStrikeSample - _strikeSample);
            return Foot.PoseAt(sample, _beltSpeed * (sample - _strikeSample) / GaitTrial.SampleRate);
        }

        /// <summary>Frame k of the cycle (k / FrameCount of the way from heel strike); allocates nothing.</summary>
        public GaitFrame Frame(int k)
        {
            if ((uint)k >= (uint)FrameCount) throw new ArgumentOutOfRangeException(nameof(k), k, $"frames are 0..{FrameCount - 1}.");
            return Evaluate(100.0 * k / FrameCount);
        }

        /// <summary>The scene at a point of the cycle (percent, wrapped): its pose, three distance and three overlap queries; allocates nothing.</summary>
        public GaitFrame Evaluate(double percent)
        {
            double p = percent - 100 * Math.Floor(percent / 100);
            var pose = PoseAt(p);
            var distances = new Vector3(Distance(pose, FootPart.Heel), Distance(pose, FootPart.Sole), Distance(pose, FootPart.Toe));
            return new GaitFrame(p, p / 100 * StrideDuration, pose, distances,
                ProximityQuery.Overlaps(pose.Heel, _contactGround),
                ProximityQuery.Overlaps(pose.Sole, _contactGround),
                ProximityQuery.Overlaps(pose.Toe, _contactGround));
        }

        // The part's distance to the ground less the tolerance, at a recorded (fractional) sample: ≤ 0 is contact.
        private double Gap(FootPart part, double sample) => Distance(Foot.PoseAt(sample), part) - ContactTolerance;

        private float Distance(in FootPose pose, FootPart part) => part switch
        {
            FootPart.Heel => ClosestDistance.Distance(pose.Heel, Ground),
            FootPart.Sole => ClosestDistance.Distance(pose.Sole, Ground),
            _ => ClosestDistance.Distance(pose.Toe, Ground),
        };

        private double FootGap(double sample) =>
            Math.Min(Gap(FootPart.Heel, sample), Math.Min(Gap(FootPart.Sole, sample), Gap(FootPart.Toe, sample)));

        /// <summary>
        /// The first (or last) contact onset (gap from &gt; 0 to ≤ 0) or end (≤ 0 to &gt; 0) in [from, to] after which the
        /// new state holds for <paramref name="hold"/> samples, located by bisection between recorded samples; null when
        /// there is none.
        /// </summary>
        private static double? Crossing(Func<double, double> gap, double from, double to, bool onset, bool first, double hold)
        {
            if (double.IsNaN(from) || double.IsNaN(to)) return null;
            bool Touching(double s) => gap(s) <= 0;
            double? found = null;
            double a = from;
            while (a < to)
            {
                double b = Math.Min(Math.Floor(a) + 1, to);
                if (Touching(a) != onset && Touching(b) == onset)
                {
                    double lo = a, hi = b;
                    while (hi - lo > EventResolution)
                    {
                        double m = (lo + hi) / 2;
                        if (Touching(m) == onset) hi = m; else lo = m;
                    }
                    bool holds = true;
                    for (double t = hi; t <= Math.Min(hi + hold, to) && holds; t += 0.25) holds = Touching(t) == onset;
                    if (holds)
                    {
                        found = hi;
                        if (first) return found;
                    }
                }
                a = b;
            }
            return found;
        }

        // Mid swing as Perry & Burnfield delimit it (75–87 % of the cycle), searched finely.
        private (double Clearance, double Percent) MinToeClearanceInMidSwing()
        {
            double best = double.PositiveInfinity, at = double.NaN;
            for (double p = GaitNorms.MidSwingStart; p <= GaitNorms.MidSwingEnd; p += 0.05)
            {
                double d = Distance(PoseAt(p), FootPart.Toe);
                if (d < best) { best = d; at = p; }
            }
            return (best, at);
        }
    }
}
