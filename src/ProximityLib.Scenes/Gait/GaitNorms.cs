namespace ProximityLib.Scenes.Gait
{
    /// <summary>
    /// Normative timing of the gait cycle the scene's events are compared with, in percent of the cycle, from the
    /// phase boundaries of Perry J. and Burnfield J. M., <i>Gait Analysis: Normal and Pathological Function</i>, 2nd ed.,
    /// SLACK, 2010 (loading response 0–12 %, mid stance 12–31 %, terminal stance 31–50 % beginning with heel rise,
    /// pre-swing 50–62 % ending with toe off, initial swing 62–75 %, mid swing 75–87 %, terminal swing 87–100 %).
    /// </summary>
    public static class GaitNorms
    {
        /// <summary>The forefoot is down by the end of loading response: foot flat falls in [0, 12] %.</summary>
        public const double FootFlatLatest = 12;
        /// <summary>Heel rise starts terminal stance.</summary>
        public const double HeelOff = 31;
        /// <summary>Toe off ends pre-swing.</summary>
        public const double ToeOff = 62;
        /// <summary>Start of mid swing.</summary>
        public const double MidSwingStart = 75;
        /// <summary>End of mid swing.</summary>
        public const double MidSwingEnd = 87;

        /// <summary>
        /// How far (percentage points) one subject's event may be from the norm and still count as normal. Our choice,
        /// not the source's: a single trial at its own speed (stance lengthens as walking slows) against a mean.
        /// </summary>
        public const double Tolerance = 5;

        /// <summary>Whether an event time agrees with the norm range [low, high] within <see cref="Tolerance"/>.</summary>
        public static bool Agrees(double percent, double low, double high) => percent >= low - Tolerance && percent <= high + Tolerance;
    }
}
