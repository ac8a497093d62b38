#nullable enable
using System;
using ProximityLib.Scenes.Gait;
using UnityEngine;

namespace ProximityLib.Unity
{
    /// <summary>
    /// The paper's foot–ground scene on top of <see cref="GaitSimulation"/>: animates the heel sphere, sole box and toe
    /// sphere over an AABB ground, colours each part while it is in contact, and shows the distances and the gait
    /// events (ours against the norms) with IMGUI. All geometry and timing come from the scene model; this component
    /// only draws. Put it on any GameObject in an empty scene and press Play.
    /// </summary>
    public sealed class GaitController : MonoBehaviour
    {
        private static readonly Color Touching = new Color(0.9f, 0.2f, 0.2f);
        private static readonly Color Free = new Color(0.8f, 0.82f, 0.86f);

        /// <summary>Steps per minute; 0 keeps the recording's.</summary>
        public float cadence;
        /// <summary>Heel–toe length in metres; 0 keeps the recorded foot.</summary>
        public float footLength;
        /// <summary>Contact tolerance in millimetres.</summary>
        public float contactToleranceMm = 2;
        /// <summary>1 plays in real time; smaller values play in slow motion.</summary>
        public float playbackRate = 0.5f;

        private GaitSimulation? _sim;
        private string _message = "";
        private double _time;
        private Transform? _heel, _sole, _toe, _camera;
        private Renderer? _heelLook, _soleLook, _toeLook;
        private GaitFrame _frame;

        private void Start()
        {
            try
            {
                _sim = new GaitSimulation(cadence > 0 ? cadence : (double?)null, null, footLength > 0 ? footLength : (double?)null,
                    200, contactToleranceMm / 1000);
            }
            catch (Exception e) when (e is ArgumentException || e is InvalidOperationException)
            {
                _message = e.Message;
                return;
            }
            var cam = Camera.main;
            if (cam == null)
            {
                var go = new GameObject("Main Camera") { tag = "MainCamera" };
                cam = go.AddComponent<Camera>();
            }
            _camera = cam.transform;
            if (FindObjectOfType<Light>() == null)
            {
                var light = new GameObject("Light").AddComponent<Light>();
                light.type = LightType.Directional;
                light.transform.rotation = Quaternion.Euler(50, -30, 0);
            }
            var ground = GameObject.CreatePrimitive(PrimitiveType.Cube);
            ground.name = "Ground (AABB)";
            var g = _sim.Ground;
            ground.transform.position = ((g.Min + g.Max) / 2).ToUnity();
            ground.transform.localScale = (g.Max - g.Min).ToUnity();
            (_heel, _heelLook) = Part(PrimitiveType.Sphere, "Heel (sphere)");
            (_sole, _soleLook) = Part(PrimitiveType.Cube, "Sole (OBB)");
            (_toe, _toeLook) = Part(PrimitiveType.Sphere, "Toe (sphere)");
        }

        private static (Transform, Renderer) Part(PrimitiveType type, string name)
        {
            var go = GameObject.CreatePrimitive(type);
            go.name = name;
            return (go.transform, go.GetComponent<Renderer>());
        }

        private void Update()
        {
            if (_sim == null || _heel == null || _sole == null || _toe == null || _camera == null
                || _heelLook == null || _soleLook == null || _toeLook == null) return;
            _time += Time.deltaTime * playbackRate;
            double cycles = _time / _sim.StrideDuration;
            _frame = _sim.Evaluate(100 * (cycles - Math.Floor(cycles)));
            // Whole strides already walked move the foot on, so it keeps walking forward instead of jumping back.
            var walked = new Vector3((float)(Math.Floor(cycles) * _sim.StrideLength), 0, 0);
            var pose = _frame.Pose;
            Place(_heel, _heelLook, pose.Heel, walked, _frame.HeelContact);
            Place(_toe, _toeLook, pose.Toe, walked, _frame.ToeContact);
            var sole = pose.Sole;
            _sole.position = sole.Center.ToUnity() + walked;
            _sole.rotation = Quaternion.LookRotation(sole.AxisZ.ToUnity(), sole.AxisY.ToUnity());
            _sole.localScale = (sole.HalfExtents * 2).ToUnity();
            _soleLook.material.color = _frame.SoleContact ? Touching : Free;
            _camera.position = new Vector3(_heel.position.x + 0.15f, 0.2f, -1.2f);
        }

        private static void Place(Transform part, Renderer look, Sphere sphere, Vector3 walked, bool contact)
        {
            part.position = sphere.Center.ToUnity() + walked;
            part.localScale = Vector3.one * (2 * sphere.Radius);
            look.material.color = contact ? Touching : Free;
        }

        private void OnGUI()
        {
            GUILayout.BeginArea(new Rect(8, 8, 460, 260));
            if (_sim == null)
            {
                GUILayout.Label(_message);
                GUILayout.EndArea();
                return;
            }
            var e = _sim.Events;
            GUILayout.Label($"{_frame.Percent:0.0} % of the gait cycle   ({_sim.Cadence:0} steps/min, {_sim.Speed:0.00} m/s)");
            GUILayout.Label($"distance to ground: heel {_frame.Distances.X * 1000:0.0} mm   sole {_frame.Distances.Y * 1000:0.0} mm   toe {_frame.Distances.Z * 1000:0.0} mm");
            GUILayout.Label($"events (ours / Perry & Burnfield 2010): foot flat {e.FootFlat:0.0} / ≤ {GaitNorms.FootFlatLatest} %,  " +
                            $"heel off {e.HeelOff:0.0} / {GaitNorms.HeelOff} %,  toe off {e.ToeOff:0.0} / {GaitNorms.ToeOff} %");
            GUILayout.Label($"minimum toe clearance in mid swing: {e.MinToeClearance * 1000:0.0} mm   (red: in contact)");
            GUILayout.EndArea();
        }
    }
}
