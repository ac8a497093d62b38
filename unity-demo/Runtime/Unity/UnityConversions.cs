#nullable enable
using UnityEngine;
using N = System.Numerics;

namespace ProximityLib.Unity
{
    /// <summary>
    /// Conversions between UnityEngine and System.Numerics values. Components are copied as they are: a quaternion
    /// builds the same rotation matrix from the same four numbers in both libraries, so no axis is flipped.
    /// </summary>
    public static class UnityConversions
    {
        /// <summary>The same vector as System.Numerics.</summary>
        public static N.Vector3 ToNumerics(this Vector3 v) => new N.Vector3(v.x, v.y, v.z);
        /// <summary>The same vector as UnityEngine.</summary>
        public static Vector3 ToUnity(this N.Vector3 v) => new Vector3(v.X, v.Y, v.Z);
        /// <summary>The same vector as System.Numerics.</summary>
        public static N.Vector2 ToNumerics(this Vector2 v) => new N.Vector2(v.x, v.y);
        /// <summary>The same vector as UnityEngine.</summary>
        public static Vector2 ToUnity(this N.Vector2 v) => new Vector2(v.X, v.Y);
        /// <summary>The same rotation as System.Numerics.</summary>
        public static N.Quaternion ToNumerics(this Quaternion q) => new N.Quaternion(q.x, q.y, q.z, q.w);
        /// <summary>The same rotation as UnityEngine.</summary>
        public static Quaternion ToUnity(this N.Quaternion q) => new Quaternion(q.X, q.Y, q.Z, q.W);
    }
}
