#nullable enable
using System;
using System.Linq;
using ProximityLib.Scenes.Picker;
using UnityEngine;

namespace ProximityLib.Unity
{
    /// <summary>
    /// The paper's interactive app on top of <see cref="PickerScene"/>: IMGUI menu (Proximity Queries / Closest
    /// Distance, a sliding list of primitives for each slot), keyboard editing of the selected primitive, the yellow
    /// closest-point line, the orange distance text and the collision colour. All geometry is the scene model's; this
    /// component only reads input and draws. Put it on any GameObject in an empty scene and press Play.
    /// </summary>
    public sealed class PickerController : MonoBehaviour
    {
        private static readonly Color Orange = new Color(1f, 0.55f, 0f);
        private static readonly Color Idle = new Color(0.75f, 0.8f, 0.85f);
        private static readonly Color Hit = new Color(0.9f, 0.2f, 0.2f);
        // The sliding list: every kind in 3D, then in 2D, as the scene model names them.
        private static readonly Primitive[] Choices = new[] { 3, 2 }
            .SelectMany(d => ((PrimitiveKind[])Enum.GetValues(typeof(PrimitiveKind))).Select(k => new Primitive(k, d, System.Numerics.Vector3.Zero)))
            .ToArray();

        /// <summary>Distance moved per key press.</summary>
        public float moveStep = 0.1f;
        /// <summary>Scale factor per key press.</summary>
        public float scaleStep = 1.1f;

        private PickerScene _scene = new PickerScene(PickerMode.ClosestDistance,
            new Primitive(PrimitiveKind.Round, 3, new System.Numerics.Vector3(-2, 0, 0)),
            new Primitive(PrimitiveKind.Obb, 3, new System.Numerics.Vector3(2, 0, 0), 0.4f, 0.3f));
        private int _selected;
        private string _message = "";
        private Vector2 _scroll;
        private readonly GameObject?[] _visuals = new GameObject?[2];
        private readonly PrimitiveKind[] _shown = new PrimitiveKind[2];
        private readonly int[] _shownDimension = new int[2];
        private LineRenderer? _line;
        private PickerView _view;

        private void Start()
        {
            if (Camera.main == null)
            {
                var cam = new GameObject("Main Camera") { tag = "MainCamera" };
                cam.AddComponent<Camera>();
                cam.transform.position = new Vector3(0, 0, -10);
            }
            if (FindObjectOfType<Light>() == null)
            {
                var light = new GameObject("Light").AddComponent<Light>();
                light.type = LightType.Directional;
                light.transform.rotation = Quaternion.Euler(50, -30, 0);
            }
            _line = new GameObject("Closest points").AddComponent<LineRenderer>();
            _line.material = new Material(Shader.Find("Sprites/Default"));
            _line.startColor = _line.endColor = Color.yellow;
            _line.startWidth = _line.endWidth = 0.04f;
            _line.positionCount = 2;
            Refresh();
        }

        private void Update()
        {
            var before = _scene;
            bool reselected = Input.GetKeyDown(KeyCode.Tab);
            if (reselected) _selected = 1 - _selected;
            var move = Vector3.zero;
            if (Input.GetKeyDown(KeyCode.LeftArrow)) move.x -= moveStep;
            if (Input.GetKeyDown(KeyCode.RightArrow)) move.x += moveStep;
            if (Input.GetKeyDown(KeyCode.UpArrow)) move.y += moveStep;
            if (Input.GetKeyDown(KeyCode.DownArrow)) move.y -= moveStep;
            if (Input.GetKeyDown(KeyCode.PageUp)) move.z += moveStep;
            if (Input.GetKeyDown(KeyCode.PageDown)) move.z -= moveStep;
            if (move != Vector3.zero) _scene = _scene.Move(_selected, move.ToNumerics());
            if (Input.GetKeyDown(KeyCode.L)) _scene = _scene.RotateLeft(_selected);
            if (Input.GetKeyDown(KeyCode.R)) _scene = _scene.RotateRight(_selected);
            if (Input.GetKeyDown(KeyCode.Equals) || Input.GetKeyDown(KeyCode.KeypadPlus)) _scene = _scene.Scale(_selected, scaleStep);
            if (Input.GetKeyDown(KeyCode.Minus) || Input.GetKeyDown(KeyCode.KeypadMinus)) _scene = _scene.Scale(_selected, 1 / scaleStep);
            if (reselected || !ReferenceEquals(before, _scene)) Refresh();
        }

        private void OnGUI()
        {
            var big = new GUIStyle(GUI.skin.label) { fontSize = 22, alignment = TextAnchor.UpperCenter };
            big.normal.textColor = _scene.Mode == PickerMode.ClosestDistance ? Orange : (_view.Colliding ? Hit : Color.white);
            GUI.Label(new Rect(0, 8, Screen.width, 32), _view.Text, big);

            GUILayout.BeginArea(new Rect(8, 48, 260, Screen.height - 56));
            GUILayout.BeginHorizontal();
            if (GUILayout.Button("Proximity Queries")) SetScene(() => _scene.WithMode(PickerMode.ProximityQuery));
            if (GUILayout.Button("Closest Distance")) SetScene(() => _scene.WithMode(PickerMode.ClosestDistance));
            GUILayout.EndHorizontal();
            GUILayout.Label($"First: {_scene.First.Name}   Second: {_scene.Second.Name}");
            GUILayout.Label($"Editing: {(_selected == 0 ? "first" : "second")} (Tab)  ·  arrows, PgUp/PgDn move  ·  L/R rotate  ·  +/− scale");
            _scroll = GUILayout.BeginScrollView(_scroll);
            foreach (var choice in Choices)
            {
                GUILayout.BeginHorizontal();
                GUILayout.Label(choice.Name, GUILayout.Width(110));
                if (GUILayout.Button("first")) SetScene(() => new PickerScene(_scene.Mode, Replace(_scene.First, choice), _scene.Second));
                if (GUILayout.Button("second")) SetScene(() => new PickerScene(_scene.Mode, _scene.First, Replace(_scene.Second, choice)));
                GUILayout.EndHorizontal();
            }
            GUILayout.EndScrollView();
            if (_message.Length > 0) GUILayout.Label(_message);
            GUILayout.EndArea();
        }

        private static Primitive Replace(Primitive old, Primitive choice) =>
            new Primitive(choice.Kind, choice.Dimension, old.Position, old.Yaw, old.Pitch, old.Scale);

        // The scene model refuses mixed dimensions with an ArgumentException; its message is what the user sees.
        private void SetScene(Func<PickerScene> change)
        {
            try
            {
                _scene = change();
                _message = "";
                Refresh();
            }
            catch (ArgumentException e)
            {
                _message = e.Message;
            }
        }

        private void Refresh()
        {
            _view = _scene.Evaluate();
            Show(0, _scene.First);
            Show(1, _scene.Second);
            if (_line != null)
            {
                _line.enabled = _scene.Mode == PickerMode.ClosestDistance;
                _line.SetPosition(0, _view.PointA.ToUnity());
                _line.SetPosition(1, _view.PointB.ToUnity());
            }
        }

        private void Show(int which, Primitive p)
        {
            var visual = _visuals[which];
            if (visual == null || _shown[which] != p.Kind || _shownDimension[which] != p.Dimension)
            {
                if (visual != null) Destroy(visual);
                if (p.Kind == PrimitiveKind.Triangle)
                {
                    // A triangle is drawn as its closed outline: no mesh asset or lit material needed.
                    visual = new GameObject(p.Name);
                    var outline = visual.AddComponent<LineRenderer>();
                    outline.material = new Material(Shader.Find("Sprites/Default"));
                    outline.startWidth = outline.endWidth = 0.04f;
                    outline.positionCount = 3;
                    outline.loop = true;
                }
                else
                    visual = GameObject.CreatePrimitive(p.Kind == PrimitiveKind.Round ? (p.Dimension == 2 ? PrimitiveType.Cylinder : PrimitiveType.Sphere)
                        : p.Kind == PrimitiveKind.Point ? PrimitiveType.Sphere : p.Kind == PrimitiveKind.Capsule ? PrimitiveType.Capsule : PrimitiveType.Cube);
                visual.name = p.Name;
                _visuals[which] = visual;
                _shown[which] = p.Kind;
                _shownDimension[which] = p.Dimension;
            }
            var t = visual.transform;
            t.position = p.Position.ToUnity();
            var rotation = p.Rotation.ToUnity();
            float s = p.Scale;
            var half = p.HalfExtents.ToUnity();
            const float thin = 0.02f; // 2D shapes are drawn as thin slabs in z = 0
            switch (p.Kind)
            {
                case PrimitiveKind.Point:
                    t.rotation = Quaternion.identity;
                    t.localScale = Vector3.one * 0.12f;
                    break;
                case PrimitiveKind.Segment:
                    t.rotation = rotation;
                    t.localScale = new Vector3(2 * s, 0.04f, 0.04f);
                    break;
                case PrimitiveKind.Round:
                    // Unity's cylinder stands along y with height 2: turned to face the camera, it is a disc.
                    t.rotation = p.Dimension == 2 ? Quaternion.Euler(90, 0, 0) : Quaternion.identity;
                    t.localScale = p.Dimension == 2 ? new Vector3(2 * s, thin, 2 * s) : Vector3.one * (2 * s);
                    break;
                case PrimitiveKind.Line:
                case PrimitiveKind.Ray:
                    // Unbounded: drawn 8 units out (a line both ways), as a thin bar along the turned x axis.
                    t.rotation = rotation;
                    t.localScale = new Vector3(p.Kind == PrimitiveKind.Line ? 16 : 8, 0.04f, 0.04f);
                    if (p.Kind == PrimitiveKind.Ray) t.position = (p.Position + System.Numerics.Vector3.Transform(System.Numerics.Vector3.UnitX, p.Rotation) * 4).ToUnity();
                    break;
                case PrimitiveKind.Capsule:
                    // Unity's capsule stands along y, radius 0.5 and height 2 (caps included) at scale 1: turned onto the
                    // x axis, its axis half-length s and radius s/2 give a height of 3s.
                    t.rotation = rotation * Quaternion.Euler(0, 0, 90);
                    t.localScale = new Vector3(s, 1.5f * s, p.Dimension == 2 ? thin : s);
                    break;
                case PrimitiveKind.Triangle:
                    var corners = visual.GetComponent<LineRenderer>();
                    for (int i = 0; i < 3; i++)
                        corners.SetPosition(i, (p.Position + System.Numerics.Vector3.Transform(Primitive.TriangleCorners[i], p.Rotation) * s).ToUnity());
                    break;
                case PrimitiveKind.HalfSpace:
                    // A slab 16 wide and 2 deep below the boundary (its normal is the turned y axis).
                    t.rotation = rotation;
                    t.position = (p.Position - System.Numerics.Vector3.Transform(System.Numerics.Vector3.UnitY, p.Rotation)).ToUnity();
                    t.localScale = new Vector3(16, 2, p.Dimension == 2 ? thin : 16);
                    break;
                default:
                    t.rotation = p.Kind == PrimitiveKind.Aabb ? Quaternion.identity : rotation;
                    t.localScale = new Vector3(2 * half.x, 2 * half.y, p.Dimension == 2 ? thin : 2 * half.z);
                    break;
            }
            visual.GetComponent<Renderer>().material.color = _view.Colliding ? Hit : (which == _selected ? Color.white : Idle);
        }
    }
}
