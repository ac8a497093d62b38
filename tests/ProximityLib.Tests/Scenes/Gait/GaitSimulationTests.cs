using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib;
using ProximityLib.Scenes.Gait;

namespace ProximityTests.Scenes.Gait
{
    public class GaitSimulationTests
    {
        private static readonly GaitSimulation Default = new GaitSimulation();

        [Test]
        public void EventsFromTheContactTimelinesAgreeWithPerryAndBurnfield()
        {
            var e = Default.Events;
            Assert.That(e.FootFlat, Is.GreaterThan(0).And.LessThan(e.HeelOff));
            Assert.That(e.HeelOff, Is.LessThan(e.ToeOff));
            Assert.That(e.ToeOff, Is.LessThan(100));
            Assert.That(GaitNorms.Agrees(e.FootFlat, 0, GaitNorms.FootFlatLatest), $"foot flat at {e.FootFlat:0.0} %");
            Assert.That(GaitNorms.Agrees(e.HeelOff, GaitNorms.HeelOff, GaitNorms.HeelOff), $"heel off at {e.HeelOff:0.0} %");
            Assert.That(GaitNorms.Agrees(e.ToeOff, GaitNorms.ToeOff, GaitNorms.ToeOff), $"toe off at {e.ToeOff:0.0} %");
        }

        [Test]
        public void ContactTimelinesFollowTheRollOver()
        {
            GaitFrame At(double percent) => Default.Frame((int)Math.Round(percent / 100 * Default.FrameCount));
            var e = Default.Events;
            Assert.That(At(0).HeelContact && !At(0).ToeContact, "heel strike: heel down, toe up");
            var flat = At((e.FootFlat + e.HeelOff) / 2);
            Assert.That(flat.HeelContact && flat.SoleContact && flat.ToeContact, "foot flat: every part down");
            var push = At((e.HeelOff + e.ToeOff) / 2);
            Assert.That(!push.HeelContact && push.ToeContact, "push-off: heel up, toe down");
            var swing = At((e.ToeOff + 100) / 2);
            Assert.That(!swing.HeelContact && !swing.SoleContact && !swing.ToeContact, "swing: nothing down");
        }

        [Test]
        public void TheCheapVerdictAgreesWithTheShownDistance()
        {
            double eps = Default.ContactTolerance;
            for (int k = 0; k < Default.FrameCount; k++)
            {
                var f = Default.Frame(k);
                foreach (FootPart part in Enum.GetValues(typeof(FootPart)))
                {
                    double d = f.Distance(part);
                    if (Math.Abs(d - eps) < 1e-5) continue; // float rounding at the threshold itself
                    Assert.That(f.Contact(part), Is.EqualTo(d <= eps), $"frame {k} {part}: distance {d * 1000:0.###} mm");
                }
            }
        }

        [Test]
        public void NoPartTouchesTheGroundInMidSwingAndTheToeClears()
        {
            var midSwing = Enumerable.Range(0, Default.FrameCount).Select(Default.Frame)
                .Where(f => f.Percent >= GaitNorms.MidSwingStart && f.Percent <= GaitNorms.MidSwingEnd).ToList();
            Assert.That(midSwing, Is.Not.Empty);
            foreach (var f in midSwing)
                Assert.That(f.HeelContact || f.SoleContact || f.ToeContact, Is.False, $"contact at {f.Percent:0.0} %");
            double clearance = Default.Events.MinToeClearance;
            Assert.That(clearance, Is.GreaterThan(Default.ContactTolerance));
            Assert.That(clearance, Is.LessThanOrEqualTo(midSwing.Min(f => f.Distances.Z) + 1e-6), "the minimum is found between frames too");
            Assert.That(Default.Events.MinToeClearancePercent, Is.InRange(GaitNorms.MidSwingStart, GaitNorms.MidSwingEnd));
        }

        [Test]
        public void AtTheReferenceInstantTheFootLiesOnTheGround()
        {
            var pose = Default.Foot.PoseAt(Default.Foot.ReferenceSample);
            Assert.That(pose.Pitch, Is.EqualTo(0));
            Assert.That(ClosestDistance.Between(pose.Heel, Default.Ground).Distance, Is.EqualTo(0).Within(1e-6));
            Assert.That(ClosestDistance.Between(pose.Sole, Default.Ground).Distance, Is.EqualTo(0).Within(1e-6));
            Assert.That(ClosestDistance.Between(pose.Toe, Default.Ground).Distance, Is.EqualTo(0).Within(1e-6));
        }

        [Test]
        public void AFrameAllocatesNothing()
        {
            float sink = 0;
            for (int k = 0; k < Default.FrameCount; k++) sink += Default.Frame(k).Distances.X;
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int k = 0; k < Default.FrameCount; k++) sink += Default.Frame(k).Distances.X;
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.EqualTo(0));
            GC.KeepAlive(sink);
        }

        [Test]
        public void CadenceAndSpeedRescaleTimeOnly()
        {
            var slow = new GaitSimulation(cadence: 80);
            var fast = new GaitSimulation(speed: 1.6);
            Assert.That(slow.StrideDuration, Is.EqualTo(120.0 / 80).Within(1e-12));
            Assert.That(fast.Speed, Is.EqualTo(1.6).Within(1e-12));
            Assert.That(slow.StrideLength, Is.EqualTo(Default.StrideLength).Within(1e-12), "the stride is the recorded one");
            foreach (var sim in new[] { slow, fast })
            {
                Assert.That(sim.Events.FootFlat, Is.EqualTo(Default.Events.FootFlat));
                Assert.That(sim.Events.HeelOff, Is.EqualTo(Default.Events.HeelOff));
                Assert.That(sim.Events.ToeOff, Is.EqualTo(Default.Events.ToeOff));
                Assert.That(sim.Frame(37).Distances, Is.EqualTo(Default.Frame(37).Distances));
            }
            Assert.That(slow.Frame(100).Time, Is.EqualTo(0.5 * slow.StrideDuration).Within(1e-12));
        }

        [Test]
        public void FootLengthScalesTheFootAndItsPath()
        {
            double ratio = 0.25 / Default.Foot.RecordedFootLength;
            var small = new GaitSimulation(footLength: 0.25);
            Assert.That(small.Foot.FootLength, Is.EqualTo(0.25).Within(1e-6));
            // The stride is measured between events, which the millimetre tolerance moves slightly on a scaled foot.
            Assert.That(small.StrideLength, Is.EqualTo(Default.StrideLength * ratio).Within(0.5).Percent);
            Assert.That(small.Frame(0).Pose.Heel.Radius, Is.EqualTo(Default.Frame(0).Pose.Heel.Radius * ratio).Within(1e-6));
            // The tolerance stays in millimetres, so events move a little with the scale, but not out of the norm band.
            Assert.That(small.Events.ToeOff, Is.EqualTo(Default.Events.ToeOff).Within(3));
        }

        [Test]
        public void ALargerToleranceLiftsTheHeelLater()
        {
            double previous = 0;
            foreach (double mm in new[] { 1.0, 2.0, 3.0 })
            {
                double heelOff = new GaitSimulation(contactTolerance: mm / 1000).Events.HeelOff;
                Assert.That(heelOff, Is.GreaterThan(previous), $"{mm} mm");
                previous = heelOff;
            }
        }

        [Test]
        public void BadOptionsAreRefusedByName()
        {
            Assert.That(() => new GaitSimulation(cadence: 100, speed: 1), Throws.ArgumentException.With.Property("ParamName").EqualTo("speed"));
            Assert.That(() => new GaitSimulation(cadence: -1), Throws.ArgumentException.With.Property("ParamName").EqualTo("cadence"));
            Assert.That(() => new GaitSimulation(cadence: double.NaN), Throws.ArgumentException.With.Property("ParamName").EqualTo("cadence"));
            Assert.That(() => new GaitSimulation(speed: 0), Throws.ArgumentException.With.Property("ParamName").EqualTo("speed"));
            Assert.That(() => new GaitSimulation(frames: 3), Throws.ArgumentException.With.Property("ParamName").EqualTo("frames"));
            Assert.That(() => new GaitSimulation(contactTolerance: -0.001), Throws.ArgumentException.With.Property("ParamName").EqualTo("contactTolerance"));
            Assert.That(() => new GaitSimulation(footLength: 2), Throws.ArgumentException.With.Property("ParamName").EqualTo("footLength"));
            Assert.That(() => Default.Frame(Default.FrameCount), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }

        [Test]
        public void TheRecordingIsConsistent()
        {
            int n = GaitTrial.HeelX.Length;
            Assert.That(new[] { GaitTrial.HeelY.Length, GaitTrial.ToeX.Length, GaitTrial.ToeY.Length }, Is.All.EqualTo(n));
            // A rigid shoe: the heel–toe marker distance stays within a few centimetres (the toes bend at push-off).
            for (int i = 0; i < n; i++)
            {
                double length = Math.Sqrt(Math.Pow(GaitTrial.ToeX[i] - GaitTrial.HeelX[i], 2) + Math.Pow(GaitTrial.ToeY[i] - GaitTrial.HeelY[i], 2));
                Assert.That(length, Is.InRange(255, 295), $"sample {i}");
            }
        }
    }
}

namespace ProximityTests.Scenes.Gait
{
    public class GaitSvgTests
    {
        [Test]
        public void DrawsTheFootAtEachEventWithThePartsInContactInRed()
        {
            var sim = new GaitSimulation();
            string svg = GaitSvg.Render(sim);
            foreach (var label in new[] { "heel strike", "foot flat", "heel off", "toe off", "mid swing" })
                Assert.That(svg, Does.Contain($">{label}<"));
            Assert.That(System.Text.RegularExpressions.Regex.Matches(svg, "<circle").Count, Is.EqualTo(10), "two spheres per instant");
            Assert.That(System.Text.RegularExpressions.Regex.Matches(svg, "<polygon").Count, Is.EqualTo(5), "one sole per instant");
            // Red exactly where the model says contact: heel strike (heel), foot flat (all three), heel off (sole, toe).
            int red = System.Text.RegularExpressions.Regex.Matches(svg, "#d62728").Count;
            int expected = new[] { 0.0, sim.Events.FootFlat, sim.Events.HeelOff, sim.Events.ToeOff, 81.0 }
                .Select(sim.Evaluate).Sum(f => (f.HeelContact ? 1 : 0) + (f.SoleContact ? 1 : 0) + (f.ToeContact ? 1 : 0));
            Assert.That(red, Is.EqualTo(expected));
            Assert.That(() => GaitSvg.Render(null!), Throws.ArgumentNullException);
        }
    }
}
