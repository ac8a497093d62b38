using System;
using System.Globalization;
using System.IO;
using System.Linq;
using System.Numerics;
using ProximityLib;
using ProximityLib.Demo;
using ProximityLib.Scenes.Gait;
using ProximityLib.Scenes.Picker;

// The project's sample program. With no command it runs the foot–ground gait simulation (GaitCommand.cs);
// `picker` evaluates two shapes given on the command line, as the paper's primitive picker does; `samples` prints a
// handful of queries.
CultureInfo.DefaultThreadCurrentCulture = CultureInfo.InvariantCulture;
CultureInfo.CurrentCulture = CultureInfo.InvariantCulture;

if (args.Length > 0 && args[0] == "picker") return Picker(args.Skip(1).ToArray());
if (args.Length > 0 && args[0] == "samples") return Samples();
if (args.Length > 0 && !args[0].StartsWith("-", StringComparison.Ordinal))
{
    Console.Error.WriteLine($"error: unknown command '{args[0]}' (try --help)");
    return 2;
}
GaitOptions options;
try
{
    options = GaitOptions.Parse(args);
}
catch (FormatException e)
{
    Console.Error.WriteLine($"error: {e.Message}");
    return 2;
}
if (options.Help)
{
    Console.WriteLine("usage: ProximityLib.Demo [gait options]        the foot–ground gait simulation (the default)");
    foreach (var line in GaitOptions.HelpLines()) Console.WriteLine($"         {line}");
    Console.WriteLine("       ProximityLib.Demo picker [--proximity] [--svg FILE] A B");
    Console.WriteLine("                                         closest distance (or overlap verdict) of two shapes, e.g.");
    Console.WriteLine("                                         picker sphere:0,0,0,1 aabb:2,0,0,3,1,1; picker --help lists the shapes");
    Console.WriteLine("       ProximityLib.Demo samples         print a few sample queries");
    return 0;
}
return GaitCommand.Run(options);

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

// The overload for the two shapes' types, found by reflection: `dynamic` does not bind an overload whose shapes are
// in parameters (which most are), and a shape is an in parameter or not as its pair's kernel takes it.
static object Query(Type owner, string name, object a, object b)
{
    static Type Plain(Type t) => t.IsByRef ? t.GetElementType()! : t;
    var method = owner.GetMethods(System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.Static)
        .FirstOrDefault(m => m.Name == name && m.GetParameters() is { Length: 2 } ps && Plain(ps[0].ParameterType) == a.GetType() && Plain(ps[1].ParameterType) == b.GetType());
    return (method ?? throw new MissingMethodException(owner.Name, name)).Invoke(null, new[] { a, b })!;
}

static void Print(string name, DistanceResult3 r, bool overlaps) =>
    Console.WriteLine($"{name}: distance {r.Distance,10:0.######}  A {r.PointA}  B {r.PointB}  overlaps: {overlaps}");

static int Picker(string[] args)
{
    PickerOptions options;
    try
    {
        options = PickerOptions.Parse(args);
    }
    catch (FormatException e)
    {
        Console.Error.WriteLine($"error: {e.Message}");
        return 2;
    }
    if (options.Help)
    {
        foreach (var line in PickerOptions.HelpLines()) Console.WriteLine(line);
        return 0;
    }
    object first = options.First!, second = options.Second!;
    bool proximity = options.Proximity;
    bool overlaps;
    dynamic r;
    try
    {
        overlaps = (bool)Query(typeof(ProximityQuery), "Overlaps", first, second);
        r = Query(typeof(ClosestDistance), "Between", first, second);
    }
    catch (MissingMethodException)
    {
        // Every pair of same-dimension shapes has a query; this guards a shape added to the specs before its pairs.
        Console.Error.WriteLine($"error: the library has no query for {first.GetType().Name} and {second.GetType().Name}");
        return 2;
    }
    if (options.SvgFile is string svg)
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
