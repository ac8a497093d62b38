#nullable enable
using ProximityLib.Scenes;
using UnityEngine;

namespace ProximityLib.Unity
{
    /// <summary>Which ProximityLib shape a <see cref="ProximityShape"/> stands for.</summary>
    public enum ProximityShapeKind
    {
        /// <summary>The transform's position.</summary>
        Point,
        /// <summary>A segment along the local x axis, <see cref="ProximityShape.halfLength"/> each side of the position.</summary>
        Segment,
        /// <summary>A sphere of <see cref="ProximityShape.radius"/> around the position.</summary>
        Sphere,
        /// <summary>The world-axis-aligned box enclosing the oriented box (like Unity's Renderer.bounds).</summary>
        Aabb,
        /// <summary>A box of <see cref="ProximityShape.halfExtents"/> turned with the transform.</summary>
        Obb,
    }

    /// <summary>
    /// Turns a GameObject's transform plus a radius or extents into a ProximityLib shape. Sizes are in local units
    /// and follow the transform's lossy scale (a sphere takes the largest axis, so it always encloses what it
    /// scales); a shear from non-uniformly scaled, rotated parents is not representable and is ignored. Sizes are
    /// kept non-negative in the Inspector, and one set negative (or NaN) from script counts as 0 (see <see cref="ShapeSizes"/>).
    /// </summary>
    [DisallowMultipleComponent]
    public sealed class ProximityShape : MonoBehaviour
    {
        /// <summary>The shape this component stands for.</summary>
        public ProximityShapeKind kind = ProximityShapeKind.Sphere;
        /// <summary>Sphere radius in local units.</summary>
        [Min(0)] public float radius = 0.5f;
        /// <summary>Segment half-length along local x, in local units.</summary>
        [Min(0)] public float halfLength = 0.5f;
        /// <summary>Box half-extents in local units (0.5 matches Unity's built-in cube).</summary>
        [Min(0)] public Vector3 halfExtents = new Vector3(0.5f, 0.5f, 0.5f);

        // Unity calls this after every Inspector edit: [Min(0)] clamps typed values, this also pasted, reverted and
        // debug-mode ones, so a serialized size is never negative.
        private void OnValidate()
        {
            radius = ShapeSizes.NonNegative(radius);
            halfLength = ShapeSizes.NonNegative(halfLength);
            halfExtents = new Vector3(ShapeSizes.NonNegative(halfExtents.x), ShapeSizes.NonNegative(halfExtents.y), ShapeSizes.NonNegative(halfExtents.z));
        }

        /// <summary>The position as a point.</summary>
        public System.Numerics.Vector3 Point => transform.position.ToNumerics();

        /// <summary>The segment through the position along local x.</summary>
        public Segment3 Segment
        {
            get
            {
                var c = transform.position;
                var a = transform.TransformVector(new Vector3(ShapeSizes.NonNegative(halfLength), 0, 0));
                return new Segment3((c - a).ToNumerics(), (c + a).ToNumerics());
            }
        }

        /// <summary>The sphere around the position.</summary>
        public Sphere Sphere
        {
            get
            {
                var s = transform.lossyScale;
                return new Sphere(transform.position.ToNumerics(), ShapeSizes.Scaled(radius, Mathf.Max(Mathf.Abs(s.x), Mathf.Max(Mathf.Abs(s.y), Mathf.Abs(s.z)))));
            }
        }

        /// <summary>The oriented box.</summary>
        public Obb3 Obb => new Obb3(transform.position.ToNumerics(), transform.rotation.ToNumerics(), ScaledHalfExtents.ToNumerics());

        /// <summary>The axis-aligned box enclosing the oriented box.</summary>
        public Aabb3 Aabb
        {
            get
            {
                var h = ScaledHalfExtents;
                var r = transform.rotation;
                // Each world axis gets |R| times the local half-extents: the projection of the turned box.
                var x = r * new Vector3(h.x, 0, 0);
                var y = r * new Vector3(0, h.y, 0);
                var z = r * new Vector3(0, 0, h.z);
                var half = new Vector3(
                    ShapeSizes.NonNegative(Mathf.Abs(x.x) + Mathf.Abs(y.x) + Mathf.Abs(z.x)),
                    ShapeSizes.NonNegative(Mathf.Abs(x.y) + Mathf.Abs(y.y) + Mathf.Abs(z.y)),
                    ShapeSizes.NonNegative(Mathf.Abs(x.z) + Mathf.Abs(y.z) + Mathf.Abs(z.z)));
                return Aabb3.FromCenter(transform.position.ToNumerics(), half.ToNumerics());
            }
        }

        private Vector3 ScaledHalfExtents
        {
            get
            {
                var s = transform.lossyScale;
                return new Vector3(ShapeSizes.Scaled(halfExtents.x, s.x), ShapeSizes.Scaled(halfExtents.y, s.y), ShapeSizes.Scaled(halfExtents.z, s.z));
            }
        }
    }
}
