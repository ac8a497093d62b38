// Signatures follow the Unity 2021.3 scripting reference; bodies only make the stub compile. Add a member here only
// when a script in unity-demo/ needs it, with Unity's exact signature.
using System;

namespace UnityEngine
{
    public class Object
    {
        public string name { get => ""; set { } }
        public static void Destroy(Object obj) { }
        public static T FindObjectOfType<T>() where T : Object => throw new NotSupportedException();
        public static bool operator ==(Object? x, Object? y) => ReferenceEquals(x, y);
        public static bool operator !=(Object? x, Object? y) => !ReferenceEquals(x, y);
        public static implicit operator bool(Object? exists) => exists is object;
        public override bool Equals(object? other) => ReferenceEquals(this, other);
        public override int GetHashCode() => 0;
    }

    public class Component : Object
    {
        public Transform transform => throw new NotSupportedException();
        public GameObject gameObject => throw new NotSupportedException();
        public T GetComponent<T>() => throw new NotSupportedException();
    }

    public class Behaviour : Component { public bool enabled { get; set; } }
    public class MonoBehaviour : Behaviour { }

    public sealed class GameObject : Object
    {
        public GameObject(string name) { }
        public string tag { get => ""; set { } }
        public Transform transform => throw new NotSupportedException();
        public T AddComponent<T>() where T : Component => throw new NotSupportedException();
        public T GetComponent<T>() => throw new NotSupportedException();
        public static GameObject CreatePrimitive(PrimitiveType type) => throw new NotSupportedException();
    }

    public class Transform : Component
    {
        public Vector3 position { get; set; }
        public Quaternion rotation { get; set; }
        public Vector3 localScale { get; set; }
        public Vector3 lossyScale => default;
        public Vector3 TransformVector(Vector3 vector) => vector;
        public Vector3 TransformPoint(Vector3 position) => position;
    }

    public class Collider : Component { }

    public class CapsuleCollider : Collider
    {
        public Vector3 center { get; set; }
        public float radius { get; set; }
        public float height { get; set; }
        public int direction { get; set; }
    }

    public sealed class Mesh : Object
    {
        public Vector3[] vertices { get => Array.Empty<Vector3>(); set { } }
        public int[] triangles { get => Array.Empty<int>(); set { } }
    }

    public struct Ray
    {
        public Ray(Vector3 origin, Vector3 direction) { this.origin = origin; this.direction = direction; }
        public Vector3 origin { get; set; }
        public Vector3 direction { get; set; }
    }

    public struct Plane
    {
        public Plane(Vector3 inNormal, float d) { normal = inNormal; distance = d; }
        public Vector3 normal { get; set; }
        public float distance { get; set; }
    }

    public enum PrimitiveType { Sphere = 0, Capsule = 1, Cylinder = 2, Cube = 3, Plane = 4, Quad = 5 }
    public enum LightType { Spot = 0, Directional = 1, Point = 2, Area = 3, Rectangle = 3, Disc = 4 }
    public enum TextAnchor { UpperLeft = 0, UpperCenter = 1, UpperRight = 2, MiddleLeft = 3, MiddleCenter = 4, MiddleRight = 5, LowerLeft = 6, LowerCenter = 7, LowerRight = 8 }

    public enum KeyCode
    {
        Tab = 9, Minus = 45, Equals = 61, L = 108, R = 114,
        KeypadMinus = 269, KeypadPlus = 270,
        UpArrow = 273, DownArrow = 274, RightArrow = 275, LeftArrow = 276, PageUp = 280, PageDown = 281,
    }

    public sealed class Camera : Behaviour { public static Camera main => throw new NotSupportedException(); }
    public sealed class Light : Behaviour { public LightType type { get; set; } }

    public class Renderer : Component
    {
        public bool enabled { get; set; }
        public Material material { get; set; } = null!;
    }

    public sealed class LineRenderer : Renderer
    {
        public Color startColor { get; set; }
        public Color endColor { get; set; }
        public float startWidth { get; set; }
        public float endWidth { get; set; }
        public int positionCount { get; set; }
        public bool loop { get; set; }
        public void SetPosition(int index, Vector3 position) { }
    }

    public class Material : Object
    {
        public Material(Shader shader) { }
        public Color color { get; set; }
    }

    public sealed class Shader : Object { public static Shader Find(string name) => throw new NotSupportedException(); }

    public static class Input { public static bool GetKeyDown(KeyCode key) => false; }
    public static class Time { public static float deltaTime => 0; }
    public static class Screen { public static int width => 0; public static int height => 0; }

    public static class Mathf
    {
        public static float Abs(float f) => Math.Abs(f);
        public static float Max(float a, float b) => Math.Max(a, b);
    }

    [AttributeUsage(AttributeTargets.Class, Inherited = false)]
    public sealed class DisallowMultipleComponent : Attribute { }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public abstract class PropertyAttribute : Attribute
    {
        protected PropertyAttribute() { }
        public int order { get; set; }
    }

    [AttributeUsage(AttributeTargets.Field, Inherited = true, AllowMultiple = false)]
    public sealed class MinAttribute : PropertyAttribute
    {
        public readonly float min;
        public MinAttribute(float min) { this.min = min; }
    }

    public struct Vector2
    {
        public float x, y;
        public Vector2(float x, float y) { this.x = x; this.y = y; }
    }

    public struct Vector3 : IEquatable<Vector3>
    {
        public float x, y, z;
        public Vector3(float x, float y, float z) { this.x = x; this.y = y; this.z = z; }
        public static Vector3 zero => default;
        public static Vector3 one => new Vector3(1, 1, 1);
        public static Vector3 operator +(Vector3 a, Vector3 b) => new Vector3(a.x + b.x, a.y + b.y, a.z + b.z);
        public static Vector3 operator -(Vector3 a, Vector3 b) => new Vector3(a.x - b.x, a.y - b.y, a.z - b.z);
        public static Vector3 operator *(Vector3 a, float d) => new Vector3(a.x * d, a.y * d, a.z * d);
        public static bool operator ==(Vector3 a, Vector3 b) => a.Equals(b);
        public static bool operator !=(Vector3 a, Vector3 b) => !a.Equals(b);
        public bool Equals(Vector3 other) => x == other.x && y == other.y && z == other.z;
        public override bool Equals(object? other) => other is Vector3 v && Equals(v);
        public override int GetHashCode() => HashCode.Combine(x, y, z);
    }

    public struct Quaternion
    {
        public float x, y, z, w;
        public Quaternion(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
        public static Quaternion identity => new Quaternion(0, 0, 0, 1);
        public static Quaternion Euler(float x, float y, float z) => identity;
        public static Quaternion LookRotation(Vector3 forward, Vector3 upwards) => identity;
        public static Vector3 operator *(Quaternion rotation, Vector3 point) => point;
        public static Quaternion operator *(Quaternion lhs, Quaternion rhs) => lhs;
    }

    public struct Color
    {
        public float r, g, b, a;
        public Color(float r, float g, float b) { this.r = r; this.g = g; this.b = b; a = 1; }
        public static Color white => new Color(1, 1, 1);
        public static Color yellow => new Color(1, 0.92f, 0.016f);
    }

    public struct Rect { public Rect(float x, float y, float width, float height) { } }

    public sealed class GUIStyleState { public Color textColor { get; set; } }

    public sealed class GUIStyle
    {
        public GUIStyle(GUIStyle other) { }
        public int fontSize { get; set; }
        public TextAnchor alignment { get; set; }
        public GUIStyleState normal { get; set; } = new GUIStyleState();
    }

    public sealed class GUISkin : Object { public GUIStyle label { get; set; } = null!; }
    public sealed class GUILayoutOption { }

    public static class GUI
    {
        public static GUISkin skin { get; set; } = null!;
        public static void Label(Rect position, string text, GUIStyle style) { }
    }

    public static class GUILayout
    {
        public static void BeginArea(Rect screenRect) { }
        public static void EndArea() { }
        public static void BeginHorizontal(params GUILayoutOption[] options) { }
        public static void EndHorizontal() { }
        public static bool Button(string text, params GUILayoutOption[] options) => false;
        public static void Label(string text, params GUILayoutOption[] options) { }
        public static GUILayoutOption Width(float width) => new GUILayoutOption();
        public static Vector2 BeginScrollView(Vector2 scrollPosition, params GUILayoutOption[] options) => scrollPosition;
        public static void EndScrollView() { }
    }
}
