using System;
using ProximityLib.Scenes.Gait;

namespace ProximitySpeed
{
    public static partial class Catalog
    {
        private const int GaitFrames = 200;

        /// <summary>One frame of the gait scene: placing the foot and its 6 queries (3 distances, 3 overlaps), over a whole cycle.</summary>
        static partial void AddScenes(Action<string, string, int, Func<int, double>> add)
        {
            var sim = new GaitSimulation(frames: GaitFrames);
            add("scene gait", "gait frame", GaitFrames, reps =>
            {
                double sum = 0;
                for (int r = 0; r < reps; r++)
                    for (int k = 0; k < GaitFrames; k++)
                    {
                        var f = sim.Frame(k);
                        sum += f.Distances.X + f.Distances.Y + f.Distances.Z + (f.ToeContact ? 1 : 0);
                    }
                return sum;
            });
        }
    }
}
