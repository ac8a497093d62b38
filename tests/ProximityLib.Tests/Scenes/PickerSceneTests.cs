using System;
using System.Collections.Generic;
using System.Numerics;
using NUnit.Framework;
using ProximityLib.Scenes.Picker;
using F = ProximityLib;
using Api = ProximityReference.Api;

namespace ProximityTests.Scenes
{
    public class PickerSceneTests
    {
        private static readonly PrimitiveKind[] Kinds = (PrimitiveKind[])Enum.GetValues(typeof(PrimitiveKind));

        public static IEnumerable<TestCaseData> Pairs()
        {
            foreach (int dim in new[] { 2, 3 })
                foreach (var a in Kinds)
                    foreach (var b in Kinds)
                        yield return new TestCaseData(dim, a, b).SetArgDisplayNames($"{dim}D", a.ToString(), b.ToString());
        }

        [Test]
        public void TheNewKindsHaveTheirDocumentedBaseShapes()
        {
            // A capsule at height 2 (axis along x, radius 0.5) above the ground half-space through the origin: 1.5 apart.
            var capsule = new Primitive(PrimitiveKind.Capsule, 3, new Vector3(0, 2, 0));
            var ground = new Primitive(PrimitiveKind.HalfSpace, 3, Vector3.Zero);
            var view = new PickerScene(PickerMode.ClosestDistance, capsule, ground).Evaluate();
            Assert.That(view.Distance, Is.EqualTo(1.5f).Within(1e-6f));
            Assert.That(view.PointB.Y, Is.EqualTo(0f).Within(1e-6f));
            // A 2D triangle scaled 2: corners (−2, −1), (2, −1), (0, 1.5); a ray from (0, −3) up along y (yaw 90°) enters at y = −1.
            var tri = new Primitive(PrimitiveKind.Triangle, 2, Vector3.Zero, 0, 0, 2);
            Assert.That(((F.Triangle2)tri.Shape).C, Is.EqualTo(new Vector2(0, 1.5f)));
            var ray = new Primitive(PrimitiveKind.Ray, 2, new Vector3(0, -3, 0), MathF.PI / 2);
            Assert.That(new PickerScene(PickerMode.ProximityQuery, ray, tri).Evaluate().Colliding, Is.True);
            // A line along x at y = 3 misses it by 1.5; a 2D half-plane's name says so.
            var line = new Primitive(PrimitiveKind.Line, 2, new Vector3(0, 3, 0));
            Assert.That(new PickerScene(PickerMode.ClosestDistance, line, tri).Evaluate().Distance, Is.EqualTo(1.5f).Within(1e-6f));
            Assert.That(new Primitive(PrimitiveKind.HalfSpace, 2, Vector3.Zero).Name, Is.EqualTo("2D half-plane"));
        }

        [TestCaseSource(nameof(Pairs))]
        public void BothModesShowWhatTheLibraryComputes(int dim, PrimitiveKind ka, PrimitiveKind kb)
        {
            var rng = new Random(dim * 100 + (int)ka * 10 + (int)kb);
            for (int i = 0; i < 10; i++)
            {
                var a = new Primitive(ka, dim, new Vector3(R(rng), R(rng), R(rng)), R(rng), R(rng), 0.5f + (float)rng.NextDouble());
                var b = new Primitive(kb, dim, new Vector3(R(rng), R(rng), R(rng)), R(rng), R(rng), 0.5f + (float)rng.NextDouble());
                var distance = new PickerScene(PickerMode.ClosestDistance, a, b).Evaluate();
                var proximity = new PickerScene(PickerMode.ProximityQuery, a, b).Evaluate();
                dynamic expected = Api.Between(a.Shape, b.Shape);
                bool overlaps = Api.Overlaps(a.Shape, b.Shape);
                Assert.That(distance.Distance, Is.EqualTo((float)expected.Distance), $"{a.Name} vs {b.Name}");
                Assert.That(proximity.Colliding, Is.EqualTo(overlaps), $"{a.Name} vs {b.Name}");
                Assert.That(distance.Text, Does.StartWith("Minimum distance: "));
                Assert.That(proximity.Text, Is.EqualTo(overlaps ? "Colliding" : "Not colliding"));
                // The yellow line joins the two closest points, whose length is the distance when apart.
                if (distance.Distance > 0)
                    Assert.That(Vector3.Distance(distance.PointA, distance.PointB), Is.EqualTo(distance.Distance).Within(1e-5f));
            }
        }

        private static float R(Random rng) => (float)(rng.NextDouble() * 4 - 2);

        [Test]
        public void MixingDimensionsIsRefused()
        {
            var circle = new Primitive(PrimitiveKind.Round, 2, Vector3.Zero);
            var sphere = new Primitive(PrimitiveKind.Round, 3, Vector3.Zero);
            Assert.That(() => new PickerScene(PickerMode.ClosestDistance, circle, sphere),
                Throws.ArgumentException.With.Message.Contains("same dimension").And.Message.Contains("2D circle").And.Message.Contains("3D sphere"));
        }

        [Test]
        public void MovesRotationsAndScalingApply()
        {
            var scene = new PickerScene(PickerMode.ClosestDistance,
                new Primitive(PrimitiveKind.Round, 3, Vector3.Zero), new Primitive(PrimitiveKind.Point, 3, new Vector3(3, 0, 0)));
            Assert.That(scene.Evaluate().Distance, Is.EqualTo(2));
            Assert.That(scene.Scale(0, 2).Evaluate().Distance, Is.EqualTo(1));
            Assert.That(scene.Move(1, new Vector3(1, 0, 0)).Evaluate().Distance, Is.EqualTo(3));
            Assert.That(scene.Move(1, new Vector3(-3, 0, 0)).Evaluate().Colliding, Is.True);
            Assert.That(scene.Move(1, new Vector3(-3, 0, 0)).WithMode(PickerMode.ProximityQuery).Evaluate().Text, Is.EqualTo("Colliding"));

            // Eighteen presses of L turn a 2D OBB by 90°: its long axis (half-extent 1) then lies along y.
            var box = new PickerScene(PickerMode.ClosestDistance,
                new Primitive(PrimitiveKind.Obb, 2, Vector3.Zero), new Primitive(PrimitiveKind.Point, 2, new Vector3(0, 3, 0)));
            Assert.That(box.Evaluate().Distance, Is.EqualTo(2.5f).Within(1e-5f));
            for (int i = 0; i < 18; i++) box = box.RotateLeft(0);
            Assert.That(box.Evaluate().Distance, Is.EqualTo(2f).Within(1e-5f));
            Assert.That(box.RotateRight(0).First.Yaw, Is.EqualTo(17 * PickerScene.RotationStep).Within(1e-5f));
            Assert.That(() => box.Move(2, Vector3.One), Throws.InstanceOf<ArgumentOutOfRangeException>());
        }

        [Test]
        public void HalfExtentsAreTheBoxesTheQueriesUse()
        {
            // The Unity picker draws boxes from HalfExtents; they must be the boxes the queries see.
            var obb = new Primitive(PrimitiveKind.Obb, 3, new Vector3(1, 2, 3), 0.3f, 0.2f, 2);
            Assert.That(obb.HalfExtents, Is.EqualTo(new Vector3(2, 1, 1.5f)));
            Assert.That(((ProximityLib.Obb3)obb.Shape).HalfExtents, Is.EqualTo(obb.HalfExtents));
            var aabb = new Primitive(PrimitiveKind.Aabb, 2, new Vector3(1, 2, 0), 0.3f, 0, 0.5f);
            Assert.That(aabb.HalfExtents, Is.EqualTo(new Vector3(0.5f, 0.25f, 0)));
            var box2 = (ProximityLib.Aabb2)aabb.Shape;
            Assert.That((box2.Max - box2.Min) / 2, Is.EqualTo(new Vector2(aabb.HalfExtents.X, aabb.HalfExtents.Y)));
        }

        [Test]
        public void AFrameAllocatesNothing()
        {
            var scene = new PickerScene(PickerMode.ClosestDistance,
                new Primitive(PrimitiveKind.Obb, 3, Vector3.Zero, 0.3f, 0.2f), new Primitive(PrimitiveKind.Segment, 3, new Vector3(2, 1, 0), 1f));
            scene.Evaluate();
            scene.WithMode(PickerMode.ProximityQuery).Evaluate();
            long before = GC.GetAllocatedBytesForCurrentThread();
            float sum = 0;
            for (int i = 0; i < 1000; i++) sum += scene.Evaluate().Distance;
            Assert.That(GC.GetAllocatedBytesForCurrentThread() - before, Is.EqualTo(0), $"sum {sum}");
        }

        [Test]
        public void PrimitivesValidate()
        {
            Assert.That(() => new Primitive(PrimitiveKind.Point, 4, Vector3.Zero), Throws.ArgumentException.With.Property("ParamName").EqualTo("dimension"));
            Assert.That(() => new Primitive(PrimitiveKind.Point, 3, Vector3.Zero, scale: 0), Throws.ArgumentException.With.Property("ParamName").EqualTo("scale"));
            Assert.That(() => new Primitive(PrimitiveKind.Point, 3, new Vector3(float.NaN)), Throws.ArgumentException.With.Property("ParamName").EqualTo("position"));
        }
    }
}
