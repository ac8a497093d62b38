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
            // Contact bands: one translucent strip per part and contact interval, stacked at the bottom of the plot.
            for (int p = 0; p < 3; p++)
            {
                for (int k = 0; k < percent.Length; k++)
                {
                    if (!contact[p][k] || (k > 0 && contact[p][k - 1])) continue;
                    int end = k;
                    while (end + 1 < percent.Length && contact[p][end + 1]) end++;
                    double right = end + 1 < percent.Length ? percent[end + 1] : 100;
                    var band = plt.Add.Rectangle(percent[k], right, -12 - 6 * p, -7 - 6 * p);
                    band.FillStyle.Color = Colors[p].WithAlpha(0.45);
                    band.LineStyle.Width = 0;
                }
                var line = plt.Add.ScatterLine(percent, distanceMm[p]);
                line.Color = Colors[p];
                line.LineWidth = 2;
                line.LegendText = $"{Names[p]} (bar below: in contact)";
            }
            foreach (var (at, label) in new[] { (events.FootFlat, "foot flat"), (events.HeelOff, "heel off"), (events.ToeOff, "toe off") })
            {
                var v = plt.Add.VerticalLine(at);
                v.LineStyle.Pattern = ScottPlot.LinePattern.Dashed;
                v.Color = ScottPlot.Colors.Gray;
                v.Text = $"{label} {at:0.0} %";
                v.LabelOppositeAxis = false;
            }
            plt.Add.HorizontalLine(0, 1, ScottPlot.Colors.Black);
            plt.Axes.SetLimitsX(0, 100);
            plt.Axes.SetLimitsY(-30, 300);
            plt.XLabel("% of gait cycle (0 = heel strike)");
            plt.YLabel("distance to ground (mm)");
            plt.Title("Foot–ground distances: heel sphere, sole OBB, toe sphere against the ground AABB");
            plt.ShowLegend(ScottPlot.Alignment.UpperLeft);
            plt.SavePng(file, 1000, 520);
        }
    }
}
