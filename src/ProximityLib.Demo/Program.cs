using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using ProximityLib;
using ProximityLib.Demo;
using ProximityLib.Scenes.Picker;

// The project's sample program. With no command it runs the foot–ground gait simulation (GaitCommand.cs);
// `picker` evaluates two shapes given on the command line, as the paper's primitive picker does; `samples` prints a
// handful of queries.
CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;

if (args.Length > 0 && (args[0] == "--help" || args[0] == "-h"))
{
    Console.WriteLine("usage: ProximityLib.Demo [gait options]        the foot–ground gait simulation (the default)");
    GaitCommand.PrintOptions();
    Console.WriteLine("       ProximityLib.Demo picker [--proximity] [--svg FILE] A B  closest distance (or overlap verdict) of two shapes;");
    Console.WriteLine("                                     --svg also draws them as the picker shows them (view along +z)");
    Console.WriteLine("       ProximityLib.Demo samples         print a few sample queries");
    Console.WriteLine("shapes: point:x,y[,z]  segment:x1,y1[,z1],x2,y2[,z2]  circle:x,y,r  sphere:x,y,z,r");
    Console.WriteLine("        aabb:minX,minY[,minZ],maxX,maxY[,maxZ]  obb:cx,cy,angle,hx,hy  obb:cx,cy,cz,qx,qy,qz,qw,hx,hy,hz");
    return 0;
}
if (args.Length > 0 && args[0] == "picker") return Picker(args.Skip(1).ToArray());
if (args.Length > 0 && args[0] == "samples") return Samples();
if (args.Length > 0 && !args[0].StartsWith("--", StringComparison.Ordinal))
{
    Console.Error.WriteLine($"error: unknown command '{args[0]}' (try --help)");
    return 2;
}
return GaitCommand.Run(args);

static int Samples()
{
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
    return 0;
}

static void Print(string name, DistanceResult3 r, bool overlaps) =>
    Console.WriteLine($"{name}: distance {r.Distance,10:0.######}  A {r.PointA}  B {r.PointB}  overlaps: {overlaps}");

static int Picker(string[] args)
{
    bool proximity = args.Contains("--proximity");
    int svgAt = Array.IndexOf(args, "--svg");
    string? svg = svgAt >= 0 && svgAt + 1 < args.Length ? args[svgAt + 1] : null;
    var specs = args.Where((a, i) => a != "--proximity" && (svgAt < 0 || (i != svgAt && i != svgAt + 1))).ToArray();
    if (specs.Length != 2)
    {
        Console.Error.WriteLine("error: picker needs two shapes, e.g. picker sphere:0,0,0,1 aabb:2,0,0,3,1,1");
        return 2;
    }
    object first, second;
    try
    {
        first = ShapeSpec.Parse(specs[0]);
        second = ShapeSpec.Parse(specs[1]);
    }
    catch (FormatException e)
    {
        Console.Error.WriteLine($"error: {e.Message}");
        return 2;
    }
    if (ShapeSpec.Dimension(first) != ShapeSpec.Dimension(second))
    {
        Console.Error.WriteLine($"error: '{specs[0]}' is {ShapeSpec.Dimension(first)}D and '{specs[1]}' is {ShapeSpec.Dimension(second)}D: pick two shapes of the same dimension");
        return 2;
    }
    bool overlaps = ProximityQuery.Overlaps((dynamic)first, (dynamic)second);
    dynamic r = ClosestDistance.Between((dynamic)first, (dynamic)second);
    if (svg != null)
    {
        Vector3 To3(dynamic p) => p is Vector2 v ? new Vector3(v, 0) : (Vector3)p;
        var view = new PickerView(proximity ? PickerMode.ProximityQuery : PickerMode.ClosestDistance, (float)r.Distance, To3(r.PointA), To3(r.PointB), overlaps);
        try
        {
            File.WriteAllText(svg, PickerSvg.Render(first, second, view));
        }
        catch (Exception e) when (e is IOException || e is UnauthorizedAccessException)
        {
            Console.Error.WriteLine($"error: cannot write '{svg}': {e.Message}");
            return 2;
        }
        Console.Error.WriteLine($"wrote {svg}");
    }
    if (proximity)
    {
        Console.WriteLine(overlaps ? "Colliding" : "Not colliding");
        return 0;
    }
    Console.WriteLine($"Minimum distance: {(float)r.Distance:0.######}");
    Console.WriteLine($"closest point on A: {r.PointA}");
    Console.WriteLine($"closest point on B: {r.PointB}");
    Console.WriteLine(overlaps ? "Colliding" : "Not colliding");
    return 0;
}
