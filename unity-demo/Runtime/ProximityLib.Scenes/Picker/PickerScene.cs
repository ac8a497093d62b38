// Copied from src/ProximityLib.Scenes/Picker/PickerScene.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Globalization;
using System.Numerics;

namespace ProximityLib.Scenes.Picker
{
    /// <summary>The paper's two game views.</summary>
    public enum PickerMode
    {
        /// <summary>Closest distance: a yellow line between the closest points and the distance as orange text.</summary>
        ClosestDistance,
        /// <summary>Proximity query: the verdict as text, and both objects recoloured while they collide.</summary>
        ProximityQuery,
    }

    /// <summary>What the picker shows after each change.</summary>
    public readonly struct PickerView
    {
        /// <summary>A view from a query's answer: for drawing shapes that are not picker primitives (see <see cref="PickerSvg"/>).</summary>
        public PickerView(PickerMode mode, float distance, Vector3 pointA, Vector3 pointB, bool colliding)
        {
            Mode = mode; Distance = distance; PointA = pointA; PointB = pointB; Colliding = colliding;
        }

        /// <summary>The mode the view was computed in.</summary>
        public PickerMode Mode { get; }
        /// <summary>The signed closest distance (closest-distance mode; NaN-free, 0 in proximity mode).</summary>
        public float Distance { get; }
        /// <summary>The yellow line's end on the first primitive (closest-distance mode).</summary>
        public Vector3 PointA { get; }
        /// <summary>The yellow line's end on the second primitive (closest-distance mode).</summary>
        public Vector3 PointB { get; }
        /// <summary>Whether the two primitives touch or overlap (drives the colour change).</summary>
        public bool Colliding { get; }
        /// <summary>The text at the top of the screen.</summary>
        public string Text => Mode == PickerMode.ClosestDistance
            ? string.Format(CultureInfo.InvariantCulture, "Minimum distance: {0:0.000}", Distance)
            : Colliding ? "Colliding" : "Not colliding";
    }

    /// <summary>
    /// The interactive primitive picker without rendering: a mode and two primitives of the same dimension, edited by
    /// moves, L/R rotations and scaling, each edit giving the view to draw. Immutable; edits return new scenes.
    /// </summary>
    public sealed class PickerScene
    {
        /// <summary>Radians per press of the paper's L/R keys.</summary>
        public const float RotationStep = (float)(Math.PI / 36);

        /// <summary>A scene; throws <see cref="ArgumentException"/> when the primitives mix 2D and 3D.</summary>
        public PickerScene(PickerMode mode, Primitive first, Primitive second)
        {
            if (first is null) throw new ArgumentNullException(nameof(first));
            if (second is null) throw new ArgumentNullException(nameof(second));
            if (first.Dimension != second.Dimension)
                throw new ArgumentException($"pick two primitives of the same dimension: {first.Name} and {second.Name} cannot interact.", nameof(second));
            Mode = mode; First = first; Second = second;
        }

        /// <summary>Closest distance or proximity query.</summary>
        public PickerMode Mode { get; }
        /// <summary>The first selected primitive.</summary>
        public Primitive First { get; }
        /// <summary>The second selected primitive.</summary>
        public Primitive Second { get; }

        /// <summary>The same primitives in another mode.</summary>
        public PickerScene WithMode(PickerMode mode) => new PickerScene(mode, First, Second);
        /// <summary>Moves primitive 0 or 1.</summary>
        public PickerScene Move(int which, Vector3 delta) => With(which, Pick(which).Moved(delta));
        /// <summary>The L key: turns primitive 0 or 1 counter-clockwise by <see cref="RotationStep"/>.</summary>
        public PickerScene RotateLeft(int which) => With(which, Pick(which).Rotated(RotationStep));
        /// <summary>The R key: turns primitive 0 or 1 clockwise by <see cref="RotationStep"/>.</summary>
        public PickerScene RotateRight(int which) => With(which, Pick(which).Rotated(-RotationStep));
        /// <summary>Scales primitive 0 or 1 by a positive factor.</summary>
        public PickerScene Scale(int which, float factor) => With(which, Pick(which).Scaled(factor));

        /// <summary>The view after the latest change: one library query, no allocation.</summary>
        public PickerView Evaluate()
        {
            if (First.Dimension == 3)
            {
                if (Mode == PickerMode.ProximityQuery) return new PickerView(Mode, 0, default, default, Dispatch.Overlaps3(First, Second));
                var r = Dispatch.Distance3(First, Second);
                return new PickerView(Mode, r.Distance, r.PointA, r.PointB, r.Distance <= 0);
            }
            if (Mode == PickerMode.ProximityQuery) return new PickerView(Mode, 0, default, default, Dispatch.Overlaps2(First, Second));
            var r2 = Dispatch.Distance2(First, Second);
            return new PickerView(Mode, r2.Distance, new Vector3(r2.PointA, 0), new Vector3(r2.PointB, 0), r2.Distance <= 0);
        }

        private Primitive Pick(int which) => which switch
        {
            0 => First,
            1 => Second,
            _ => throw new ArgumentOutOfRangeException(nameof(which), which, "0 is the first primitive, 1 the second."),
        };

        private PickerScene With(int which, Primitive p) => which == 0 ? new PickerScene(Mode, p, Second) : new PickerScene(Mode, First, p);
    }
}
