using System;
using System.Linq;
using NUnit.Framework;
using ProximityLib.Scenes.Gait;

namespace ProximityTests.Scenes.Gait
{
    public class GaitOptionsTests
    {
        [Test]
        public void NoArgumentsGiveTheScenesDefaults()
        {
            var o = GaitOptions.Parse(Array.Empty<string>());
            Assert.That(o.Help, Is.False);
            Assert.That(o.Cadence, Is.Null);
            Assert.That(o.Speed, Is.Null);
            Assert.That(o.FootLength, Is.Null);
            Assert.That(o.Frames, Is.EqualTo(200));
            Assert.That(o.ToleranceMm, Is.EqualTo(2));
            Assert.That(o.OutputFolder, Is.EqualTo("gait-output"));
        }

        [Test]
        public void EveryOptionIsRead()
        {
            var o = GaitOptions.Parse(new[] { "--cadence", "110", "--foot-length", "0.26", "--frames", "400", "--tolerance", "1.5", "--out", "out dir" });
            Assert.That(o.Cadence, Is.EqualTo(110));
            Assert.That(o.FootLength, Is.EqualTo(0.26));
            Assert.That(o.Frames, Is.EqualTo(400));
            Assert.That(o.ToleranceMm, Is.EqualTo(1.5));
            Assert.That(o.OutputFolder, Is.EqualTo("out dir"));
            Assert.That(GaitOptions.Parse(new[] { "--speed", "1.2" }).Speed, Is.EqualTo(1.2));
            Assert.That(GaitOptions.Parse(new[] { "--frames", "50", "-h" }).Help, Is.True);
            Assert.That(GaitOptions.Parse(new[] { "--help" }).Help, Is.True);
        }

        [TestCase("--bogus", "unknown option '--bogus'")]
        [TestCase("--bogus 3", "unknown option '--bogus'")]
        [TestCase("--frames", "'--frames' needs a value")]
        [TestCase("--cadence fast", "'fast' is not a number")]
        [TestCase("--tolerance NaN", "'NaN' is not a number")]
        [TestCase("--frames 2.5", "'2.5' is not a whole number")]
        [TestCase("extra", "unexpected argument 'extra'")]
        public void BadArgumentsGetOneLineNamingTheProblem(string args, string message)
        {
            Assert.That(() => GaitOptions.Parse(args.Split(' ')),
                Throws.InstanceOf<FormatException>().With.Message.Contains(message).And.Message.Not.Contains("\n"));
        }

        [Test]
        public void OutOfRangeValuesAreLeftToTheScene()
        {
            var o = GaitOptions.Parse(new[] { "--cadence", "-3" });
            Assert.That(() => o.CreateSimulation(), Throws.ArgumentException.With.Message.Contains("cadence"));
        }

        // The help once said 5 mm while the scene used 2 mm: each default the help states must be the one a run uses.
        [Test]
        public void TheHelpStatesTheDefaultsARunUses()
        {
            var help = GaitOptions.HelpLines();
            string Line(string option) => help.Single(l => l.StartsWith(option + " ", StringComparison.Ordinal));
            var sim = GaitOptions.Parse(Array.Empty<string>()).CreateSimulation();
            Assert.That(sim.ContactTolerance, Is.EqualTo(0.002));
            Assert.That(Line("--tolerance"), Does.EndWith("(default 2)"));
            Assert.That(sim.FrameCount, Is.EqualTo(200));
            Assert.That(Line("--frames"), Does.EndWith("(default 200)"));
            Assert.That(Line("--foot-length"), Does.EndWith($"(default: the recorded {Math.Round(sim.Foot.FootLength, 3):0.###})"));
            Assert.That(Line("--out"), Does.EndWith("(default gait-output)"));
        }
    }
}
