// Copied from src/ProximityLib.Scenes/ColliderShapes.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;

namespace ProximityLib.Scenes
{
    /// <summary>
    /// Unity's capsule colliders, planes and meshes as ProximityLib shapes, from plain numbers (the Unity layer passes
    /// the component's and transform's values), so the rules are tested outside Unity.
    /// </summary>
    public static class ColliderShapes
    {
        /// <summary>
        /// A CapsuleCollider as Unity sizes it: <paramref name="radius"/> scaled by the larger |scale| of the two axes
        /// across <paramref name="direction"/> (0 = X, 1 = Y, 2 = Z), <paramref name="height"/> (which includes both caps)
        /// by |scale| along it; the axis runs along the rotated local direction through <paramref name="center"/> (world),
        /// half-length max(height/2 − radius, 0). Bad sizes count as 0 (<see cref="ShapeSizes"/>); a direction outside
        /// 0…2 throws <see cref="ArgumentException"/>.
        /// </summary>
        public static Capsule3 Capsule(Vector3 center, Quaternion rotation, Vector3 lossyScale, float radius, float height, int direction)
        {
            if (direction < 0 || direction > 2)
                throw new ArgumentException($"direction must be 0 (X), 1 (Y) or 2 (Z) (got {direction}).", nameof(direction));
            static float Axis(Vector3 v, int i) => i == 0 ? v.X : i == 1 ? v.Y : v.Z;
            float across = Math.Max(Math.Abs(Axis(lossyScale, (direction + 1) % 3)), Math.Abs(Axis(lossyScale, (direction + 2) % 3)));
            float r = ShapeSizes.Scaled(radius, across);
            float half = Math.Max(ShapeSizes.Scaled(height, Axis(lossyScale, direction)) / 2 - r, 0);
            var local = direction == 0 ? Vector3.UnitX : direction == 1 ? Vector3.UnitY : Vector3.UnitZ;
            var axis = Vector3.Transform(local, rotation) * half;
            return new Capsule3(center - axis, center + axis, r);
        }

        /// <summary>
        /// A UnityEngine.Plane (the points with normal·x + distance = 0) as the solid half-space behind it: the side its
        /// normal points away from, where Plane.GetSide is false. The normal need not be unit length.
        /// </summary>
        public static HalfSpace BehindPlane(Vector3 normal, float distance) => new HalfSpace(normal, -distance);

        /// <summary>
        /// A mesh's triangles from its vertices (already in world space) and Mesh.triangles indices (three per
        /// triangle; arrays, as Unity gives them: Mono's span indexer is not usable from Unity's compiler). Throws <see cref="ArgumentException"/> when the index count is not a multiple of 3 or an index is out
        /// of range.
        /// </summary>
        public static Triangle3[] Triangles(Vector3[] vertices, int[] indices)
        {
            if (indices.Length % 3 != 0)
                throw new ArgumentException($"indices must come in threes (got {indices.Length}).", nameof(indices));
            var result = new Triangle3[indices.Length / 3];
            for (int i = 0; i < indices.Length; i++)
                if ((uint)indices[i] >= (uint)vertices.Length)
                    throw new ArgumentException($"indices[{i}] = {indices[i]} is outside the {vertices.Length} vertices.", nameof(indices));
            for (int t = 0; t < result.Length; t++)
                result[t] = new Triangle3(vertices[indices[3 * t]], vertices[indices[3 * t + 1]], vertices[indices[3 * t + 2]]);
            return result;
        }
    }
}
