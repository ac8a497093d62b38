using System;
using System.Globalization;
using System.Numerics;
using ProximityLib;

// A first look at the library: a few closest-distance and proximity queries, printed.
// (The foot–ground gait simulation will become this project's main job.)
CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;

var heel = new Sphere(new Vector3(0, 0.05f, 0), 0.04f);
var ground = new Aabb3(new Vector3(-1, -0.1f, -1), new Vector3(1, 0, 1));
var sole = new Obb3(new Vector3(0.1f, 0.03f, 0), Quaternion.CreateFromAxisAngle(Vector3.UnitZ, 0.2f), new Vector3(0.12f, 0.01f, 0.04f));
var shin = new Segment3(new Vector3(0, 0.1f, 0), new Vector3(0.05f, 0.5f, 0));
var ball = new Sphere(new Vector3(0.3f, 0.3f, 0), 0.1f);

Print("sphere (heel) – AABB (ground)", ClosestDistance.Between(heel, ground), ProximityQuery.Overlaps(heel, ground));
Print("OBB (sole)    – AABB (ground)", ClosestDistance.Between(sole, ground), ProximityQuery.Overlaps(sole, ground));
Print("segment       – sphere", ClosestDistance.Between(shin, ball), ProximityQuery.Overlaps(shin, ball));
Print("segment       – OBB (sole)", ClosestDistance.Between(shin, sole), ProximityQuery.Overlaps(shin, sole));

var a = new Segment2(new Vector2(0, 0), new Vector2(4, 0));
var b = new Segment2(new Vector2(1, 1), new Vector2(3, 2));
var r2 = ClosestDistance.Between(a, b);
Console.WriteLine($"2D segment – segment: distance {r2.Distance:0.######} between {r2.PointA} (t={r2.ParameterA:0.###}) and {r2.PointB} (t={r2.ParameterB:0.###}), overlaps: {ProximityQuery.Overlaps(a, b)}");

var box2 = new Obb2(new Vector2(5, 0.5f), MathF.PI / 4, new Vector2(1, 0.5f));
var disc = new Circle(new Vector2(3.5f, 0.5f), 0.5f);
var r3 = ClosestDistance.Between(disc, box2);
Console.WriteLine($"2D circle – OBB: distance {r3.Distance:0.######} between {r3.PointA} and {r3.PointB}, overlaps: {ProximityQuery.Overlaps(disc, box2)}");

static void Print(string name, DistanceResult3 r, bool overlaps) =>
    Console.WriteLine($"{name}: distance {r.Distance,10:0.######}  A {r.PointA}  B {r.PointB}  overlaps: {overlaps}");
