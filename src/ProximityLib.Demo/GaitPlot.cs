using System;
using ProximityLib.Scenes.Gait;

namespace ProximityLib.Demo
{
    /// <summary>The gait plot: each part's distance to the ground over the cycle, its contact intervals shaded.</summary>
    internal static class GaitPlot
    {
        private static readonly string[] Names = { "heel", "sole", "toe" };
        private static readonly ScottPlot.Color[] Colors =
        {
            ScottPlot.Color.FromHex("#d62728"), ScottPlot.Color.FromHex("#2ca02c"), ScottPlot.Color.FromHex("#1f77b4"),
        };

        public static void Save(string file, double[] percent, double[][] distanceMm, bool[][] contact, GaitEvents events)
        {
            var plt = new ScottPlot.Plot();
            // Contact bars: one strip per part, stacked below the lowest point any curve reaches (the toe dips into the
            // ground during push-off, since the rigid foot has no toe joint), so a bar never covers a curve.
            double lowest = 0;
            foreach (var d in distanceMm) foreach (var v in d) lowest = Math.Min(lowest, v);
            const double BarHeight = 6, BarGap = 2;
            double barsTop = Math.Floor(lowest / 5) * 5 - 5;
            for (int p = 0; p < 3; p++)
            {
                double top = barsTop - p * (BarHeight + BarGap);
                for (int k = 0; k < percent.Length; k++)
                {
                    if (!contact[p][k] || (k > 0 && contact[p][k - 1])) continue;
                    int end = k;
                    while (end + 1 < percent.Length && contact[p][end + 1]) end++;
                    double right = end + 1 < percent.Length ? percent[end + 1] : 100;
                    var band = plt.Add.Rectangle(percent[k], right, top - BarHeight, top);
                    band.FillStyle.Color = Colors[p].WithAlpha(0.45);
                    band.LineStyle.Width = 0;
                }
                var line = plt.Add.ScatterLine(percent, distanceMm[p]);
                line.Color = Colors[p];
                line.LineWidth = 2;
                line.LegendText = $"{Names[p]} (bar at the bottom: in contact)";
            }
            double bottom = Math.Floor((barsTop - 3 * BarHeight - 2 * BarGap - 4) / 10) * 10, topOfPlot = 300;
            // Event labels along the top edge, each starting at its line, where no curve reaches (the heel peaks near
            // 250 mm) and clear of the tick labels below the plot; neighbours closer than a label's width take turns
            // between two rows. Heel strike opens the cycle at 0 % and closes it at 100 %.
            var marks = new[] { (0.0, "heel strike"), (events.FootFlat, "foot flat"), (events.HeelOff, "heel off"), (events.ToeOff, "toe off") };
            const double LabelWidth = 16, RowHeight = 22; // % of the cycle; mm
            double previous = double.NegativeInfinity;
            int row = 1;
            foreach (var (at, label) in marks)
            {
                if (at > 0)
                {
                    var v = plt.Add.VerticalLine(at);
                    v.LineStyle.Pattern = ScottPlot.LinePattern.Dashed;
                    v.Color = ScottPlot.Colors.Gray;
                }
                row = at - previous < LabelWidth ? 1 - row : 0;
                previous = at;
                Label(plt, at + 0.6, topOfPlot - 3 - row * RowHeight, $"{label} {at:0.0} %", ScottPlot.Alignment.UpperLeft);
            }
            row = 100 - LabelWidth - previous < LabelWidth ? 1 - row : 0;
            Label(plt, 99.4, topOfPlot - 3 - row * RowHeight, "next heel strike 100 %", ScottPlot.Alignment.UpperRight);
            plt.Add.HorizontalLine(0, 1, ScottPlot.Colors.Black);
            plt.Axes.SetLimitsX(0, 100);
            plt.Axes.SetLimitsY(bottom, topOfPlot);
            plt.XLabel("% of gait cycle (0 = heel strike)");
            plt.YLabel("distance to ground (mm)");
            plt.Title("Foot–ground distances: heel sphere, sole OBB, toe sphere against the ground AABB");
            plt.ShowLegend(ScottPlot.Edge.Bottom);
            plt.SavePng(file, 1000, 520);
        }

        private static void Label(ScottPlot.Plot plt, double x, double y, string text, ScottPlot.Alignment alignment)
        {
            var t = plt.Add.Text(text, x, y);
            t.LabelAlignment = alignment;
            t.LabelFontSize = 12;
            t.LabelFontColor = ScottPlot.Colors.Black;
            t.LabelBackgroundColor = ScottPlot.Colors.White.WithAlpha(0.85);
            t.LabelBorderColor = ScottPlot.Colors.Gray;
            t.LabelBorderWidth = 1;
            t.LabelPadding = 3;
        }
    }
}
