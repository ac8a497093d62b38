// Copied from src/ProximityLib.Scenes/Gait/GaitSvg.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Globalization;
using System.Linq;
using System.Numerics;
using System.Text;

namespace ProximityLib.Scenes.Gait
{
    /// <summary>
    /// Draws the foot at a few instants of the cycle as SVG, seen from the side as the Unity sample's camera sees it:
    /// heel and toe spheres as circles, the sole as its turned rectangle, parts in contact in red, the ground below.
    /// The instants are drawn side by side, a fixed step apart, since a foot in stance does not move forward.
    /// For documentation; it allocates.
    /// </summary>
    public static class GaitSvg
    {
        /// <summary>The SVG of the foot at foot flat, heel off, toe off and mid swing after heel strike (the events of <paramref name="sim"/>).</summary>
        public static string Render(GaitSimulation sim)
        {
            if (sim == null) throw new ArgumentNullException(nameof(sim));
            var e = sim.Events;
            var snapshots = new[]
            {
                (0.0, "heel strike"), (e.FootFlat, "foot flat"), (e.HeelOff, "heel off"), (e.ToeOff, "toe off"),
                ((GaitNorms.MidSwingStart + GaitNorms.MidSwingEnd) / 2, "mid swing"),
            };
            var frames = snapshots.Select(s => (Frame: sim.Evaluate(s.Item1), Label: s.Item2)).ToArray();
            float step = (float)sim.Foot.FootLength * 1.5f;
            const float width = 960, height = 300, groundY = 230;
            float scale = width / (step * frames.Length);
            float shift = 0; // of the snapshot being drawn: its heel x moved to its slot
            string X(float x) => F((x + shift) * scale);
            string Y(float y) => F(groundY - y * scale);

            var svg = new StringBuilder();
            svg.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{F(width)}\" height=\"{F(height)}\" viewBox=\"0 0 {F(width)} {F(height)}\">\n");
            svg.Append($"<rect width=\"{F(width)}\" height=\"{F(height)}\" fill=\"#ffffff\"/>\n");
            svg.Append($"<rect x=\"0\" y=\"{F(groundY)}\" width=\"{F(width)}\" height=\"{F(height - groundY)}\" fill=\"#c8c2b4\"/>\n");
            for (int i = 0; i < frames.Length; i++)
            {
                var (frame, label) = frames[i];
                var pose = frame.Pose;
                shift = step * (i + 0.25f) - Math.Min(pose.Heel.Center.X, pose.Toe.Center.X);
                string Fill(bool contact) => contact ? "#d62728" : "#8a9bb0";
                var sole = pose.Sole;
                var u = new Vector2(sole.AxisX.X, sole.AxisX.Y) * sole.HalfExtents.X;
                var v = new Vector2(sole.AxisY.X, sole.AxisY.Y) * sole.HalfExtents.Y;
                var c = new Vector2(sole.Center.X, sole.Center.Y);
                var corners = new[] { c - u - v, c + u - v, c + u + v, c - u + v };
                svg.Append($"<polygon points=\"{string.Join(" ", corners.Select(p => X(p.X) + "," + Y(p.Y)))}\" fill=\"{Fill(frame.SoleContact)}\" fill-opacity=\"0.8\"/>\n");
                foreach (var (sphere, contact) in new[] { (pose.Heel, frame.HeelContact), (pose.Toe, frame.ToeContact) })
                    svg.Append($"<circle cx=\"{X(sphere.Center.X)}\" cy=\"{Y(sphere.Center.Y)}\" r=\"{F(sphere.Radius * scale)}\" fill=\"{Fill(contact)}\" fill-opacity=\"0.85\"/>\n");
                float labelX = (pose.Heel.Center.X + pose.Toe.Center.X) / 2;
                svg.Append($"<text x=\"{X(labelX)}\" y=\"{F(groundY + 28)}\" font-family=\"sans-serif\" font-size=\"15\" text-anchor=\"middle\">{label}</text>\n");
                svg.Append($"<text x=\"{X(labelX)}\" y=\"{F(groundY + 48)}\" font-family=\"sans-serif\" font-size=\"13\" text-anchor=\"middle\" fill=\"#555555\">{frame.Percent.ToString("0.0", CultureInfo.InvariantCulture)} %</text>\n");
            }
            svg.Append("</svg>\n");
            return svg.ToString();
        }

        private static string F(float v) => v.ToString("0.##", CultureInfo.InvariantCulture);
    }
}
