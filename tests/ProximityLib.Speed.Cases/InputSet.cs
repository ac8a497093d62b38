using System;
using System.Collections.Generic;
using System.Globalization;
using System.IO;

namespace ProximitySpeed
{
    /// <summary>
    /// The inputs every case reads, as the driver wrote them (tests/ProximityLib.Speed, Inputs.cs): per query
    /// ("3D sphere–OBB"), pairs of shapes given by their defining numbers in double. Every runtime and every library
    /// version builds its own shapes from the same numbers.
    /// </summary>
    public sealed class InputSet
    {
        private readonly Dictionary<string, double[][][]> _pairs = new Dictionary<string, double[][][]>(StringComparer.Ordinal);

        /// <summary>
        /// Reads the file: a line "query &lt;name&gt;" starts a query, then one line per pair, "a0 a1 … | b0 b1 …" (round-trip
        /// numbers). Point: coordinates; segment: start, end; sphere/circle: center, radius; AABB: min, max; OBB 3D:
        /// center, axis X, Y, Z, half-extents; OBB 2D: center, axis X, half-extents.
        /// </summary>
        public static InputSet Read(string path)
        {
            var set = new InputSet();
            string? query = null;
            var pairs = new List<double[][]>();
            foreach (var line in File.ReadLines(path))
            {
                if (line.Length == 0 || line[0] == '#') continue;
                if (line.StartsWith("query ", StringComparison.Ordinal))
                {
                    if (query != null) set._pairs[query] = pairs.ToArray();
                    query = line.Substring(6);
                    pairs.Clear();
                    continue;
                }
                var halves = line.Split('|');
                pairs.Add(new[] { Numbers(halves[0]), Numbers(halves[1]) });
            }
            if (query != null) set._pairs[query] = pairs.ToArray();
            return set;
        }

        private static double[] Numbers(string text)
        {
            var parts = text.Split(new[] { ' ' }, StringSplitOptions.RemoveEmptyEntries);
            var v = new double[parts.Length];
            for (int i = 0; i < parts.Length; i++) v[i] = double.Parse(parts[i], NumberStyles.Float, CultureInfo.InvariantCulture);
            return v;
        }

        /// <summary>The numbers of shape A (side 0) or B (side 1) of every pair of the query.</summary>
        public double[][] Side(string query, int side)
        {
            if (!_pairs.TryGetValue(query, out var pairs)) throw new ArgumentException("the inputs have no query '" + query + "'", nameof(query));
            var result = new double[pairs.Length][];
            for (int i = 0; i < pairs.Length; i++) result[i] = pairs[i][side];
            return result;
        }
    }
}
