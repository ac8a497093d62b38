#nullable enable
using ProximityLib.Scenes;
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

        /// <summary>The ray as a ProximityLib ray (its direction normalised again, in double).</summary>
        public static Ray3 ToProximity(this Ray r) => new Ray3(r.origin.ToNumerics(), r.direction.ToNumerics());
        /// <summary>The solid half-space behind the plane (the side where Plane.GetSide is false).</summary>
        public static HalfSpace ToProximity(this Plane p) => ColliderShapes.BehindPlane(p.normal.ToNumerics(), p.distance);
        /// <summary>The capsule collider in world space, sized as Unity sizes it (see <see cref="ColliderShapes.Capsule"/>).</summary>
        public static Capsule3 ToProximity(this CapsuleCollider c)
        {
            var t = c.transform;
            return ColliderShapes.Capsule(t.TransformPoint(c.center).ToNumerics(), t.rotation.ToNumerics(), t.lossyScale.ToNumerics(), c.radius, c.height, c.direction);
        }
        /// <summary>The mesh's triangles in world space, through <paramref name="transform"/> (its MeshFilter's transform).</summary>
        public static Triangle3[] ToProximityTriangles(this Mesh mesh, Transform transform)
        {
            var local = mesh.vertices;
            var world = new N.Vector3[local.Length];
            for (int i = 0; i < local.Length; i++) world[i] = transform.TransformPoint(local[i]).ToNumerics();
            return ColliderShapes.Triangles(world, mesh.triangles);
        }
    }
}
