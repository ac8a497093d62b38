// Copied from src/ProximityLib/Batch/ShapeSets.cs by tests/ProximityLib.UnityCheck (sync): edit the original, not this copy.
#nullable enable
using System;
using System.Numerics;

namespace ProximityLib.Batch
{
    /// <summary>
    /// Structure-of-arrays storage for the batch queries: one float array per coordinate, padded to a whole number of
    /// SIMD vectors (the padding lanes are computed and never reported). Build once, update in place, query without
    /// allocating.
    /// </summary>
    public abstract class ShapeSet
    {
        /// <summary>The number of shapes in the set.</summary>
        public int Count { get; }

        /// <summary>Allocates the arrays for <paramref name="count"/> shapes.</summary>
        private protected ShapeSet(int count)
        {
            if (count < 0) throw new ArgumentException("count must be non-negative.", nameof(count));
            Count = count;
        }

        private protected static float[] Lanes(int count) => new float[(count + Vector<float>.Count - 1) / Vector<float>.Count * Vector<float>.Count];
    }

    /// <summary>Points as SoA float arrays.</summary>
    public sealed class PointSet : ShapeSet
    {
        internal readonly float[] X, Y, Z;

        /// <summary>A set holding the given points.</summary>
        public PointSet(ReadOnlySpan<Vector3> points) : base(points.Length)
        {
            X = Lanes(Count); Y = Lanes(Count); Z = Lanes(Count);
            for (int i = 0; i < points.Length; i++) Set(i, Spans.At(points, i));
        }

        /// <summary>Replaces point i; throws <see cref="ArgumentException"/> on non-finite coordinates.</summary>
        public void Set(int i, Vector3 p)
        {
            if (!float.IsFinite(p.X) || !float.IsFinite(p.Y) || !float.IsFinite(p.Z))
                throw new ArgumentException($"point {i} must have finite coordinates (got {p}).", nameof(p));
            X[i] = p.X; Y[i] = p.Y; Z[i] = p.Z;
        }
    }

    /// <summary>Segments as SoA float arrays of their endpoints.</summary>
    public sealed class SegmentSet : ShapeSet
    {
        internal readonly float[] AX, AY, AZ, BX, BY, BZ;

        /// <summary>A set holding the given segments.</summary>
        public SegmentSet(ReadOnlySpan<Segment3> segments) : base(segments.Length)
        {
            AX = Lanes(Count); AY = Lanes(Count); AZ = Lanes(Count); BX = Lanes(Count); BY = Lanes(Count); BZ = Lanes(Count);
            for (int i = 0; i < segments.Length; i++) Set(i, Spans.At(segments, i));
        }

        /// <summary>Replaces segment i (already validated by its constructor).</summary>
        public void Set(int i, Segment3 s)
        {
            var a = s.Start;
            var b = s.End;
            AX[i] = a.X; AY[i] = a.Y; AZ[i] = a.Z; BX[i] = b.X; BY[i] = b.Y; BZ[i] = b.Z;
        }
    }

    /// <summary>Spheres as SoA float arrays.</summary>
    public sealed class SphereSet : ShapeSet
    {
        internal readonly float[] X, Y, Z, R;

        /// <summary>A set holding the given spheres.</summary>
        public SphereSet(ReadOnlySpan<Sphere> spheres) : base(spheres.Length)
        {
            X = Lanes(Count); Y = Lanes(Count); Z = Lanes(Count); R = Lanes(Count);
            for (int i = 0; i < spheres.Length; i++) Set(i, Spans.At(spheres, i));
        }

        /// <summary>Replaces sphere i (already validated by its constructor).</summary>
        public void Set(int i, Sphere s)
        {
            var c = s.Center;
            X[i] = c.X; Y[i] = c.Y; Z[i] = c.Z; R[i] = s.Radius;
        }
    }

    /// <summary>Axis-aligned boxes as SoA float arrays.</summary>
    public sealed class AabbSet : ShapeSet
    {
        internal readonly float[] MinX, MinY, MinZ, MaxX, MaxY, MaxZ;

        /// <summary>A set holding the given boxes.</summary>
        public AabbSet(ReadOnlySpan<Aabb3> boxes) : base(boxes.Length)
        {
            MinX = Lanes(Count); MinY = Lanes(Count); MinZ = Lanes(Count);
            MaxX = Lanes(Count); MaxY = Lanes(Count); MaxZ = Lanes(Count);
            for (int i = 0; i < boxes.Length; i++) Set(i, Spans.At(boxes, i));
        }

        /// <summary>Replaces box i (already validated by its constructor).</summary>
        public void Set(int i, Aabb3 b)
        {
            var min = b.Min;
            var max = b.Max;
            MinX[i] = min.X; MinY[i] = min.Y; MinZ[i] = min.Z; MaxX[i] = max.X; MaxY[i] = max.Y; MaxZ[i] = max.Z;
        }
    }

    /// <summary>Oriented boxes as SoA float arrays: center, three axes, half-extents.</summary>
    public sealed class ObbSet : ShapeSet
    {
        internal readonly float[] CX, CY, CZ, XX, XY, XZ, YX, YY, YZ, ZX, ZY, ZZ, HX, HY, HZ;

        /// <summary>A set holding the given boxes.</summary>
        public ObbSet(ReadOnlySpan<Obb3> boxes) : base(boxes.Length)
        {
            CX = Lanes(Count); CY = Lanes(Count); CZ = Lanes(Count);
            XX = Lanes(Count); XY = Lanes(Count); XZ = Lanes(Count);
            YX = Lanes(Count); YY = Lanes(Count); YZ = Lanes(Count);
            ZX = Lanes(Count); ZY = Lanes(Count); ZZ = Lanes(Count);
            HX = Lanes(Count); HY = Lanes(Count); HZ = Lanes(Count);
            for (int i = 0; i < boxes.Length; i++) Set(i, Spans.At(boxes, i));
        }

        /// <summary>Replaces box i (already validated by its constructor).</summary>
        public void Set(int i, Obb3 b)
        {
            var c = b.Center; var x = b.AxisX; var y = b.AxisY; var z = b.AxisZ; var h = b.HalfExtents;
            CX[i] = c.X; CY[i] = c.Y; CZ[i] = c.Z;
            XX[i] = x.X; XY[i] = x.Y; XZ[i] = x.Z;
            YX[i] = y.X; YY[i] = y.Y; YZ[i] = y.Z;
            ZX[i] = z.X; ZY[i] = z.Y; ZZ[i] = z.Z;
            HX[i] = h.X; HY[i] = h.Y; HZ[i] = h.Z;
        }
    }

    /// <summary>Triangles as SoA float arrays of their vertices.</summary>
    public sealed class TriangleSet : ShapeSet
    {
        internal readonly float[] AX, AY, AZ, BX, BY, BZ, CX, CY, CZ;

        /// <summary>A set holding the given triangles.</summary>
        public TriangleSet(ReadOnlySpan<Triangle3> triangles) : base(triangles.Length)
        {
            AX = Lanes(Count); AY = Lanes(Count); AZ = Lanes(Count);
            BX = Lanes(Count); BY = Lanes(Count); BZ = Lanes(Count);
            CX = Lanes(Count); CY = Lanes(Count); CZ = Lanes(Count);
            for (int i = 0; i < triangles.Length; i++) Set(i, Spans.At(triangles, i));
        }

        /// <summary>Replaces triangle i (already validated by its constructor).</summary>
        public void Set(int i, Triangle3 t)
        {
            var a = t.A; var b = t.B; var c = t.C;
            AX[i] = a.X; AY[i] = a.Y; AZ[i] = a.Z; BX[i] = b.X; BY[i] = b.Y; BZ[i] = b.Z; CX[i] = c.X; CY[i] = c.Y; CZ[i] = c.Z;
        }

        /// <summary>The coordinate arrays of vertex A, B or C (0, 1, 2) along axis k.</summary>
        internal float[] Coordinate(int vertex, int k) => vertex switch
        {
            0 => k == 0 ? AX : k == 1 ? AY : AZ,
            1 => k == 0 ? BX : k == 1 ? BY : BZ,
            _ => k == 0 ? CX : k == 1 ? CY : CZ,
        };
    }
}
