using System;
using System.Collections.Concurrent;
using System.Linq;
using System.Reflection;

namespace ProximityReference
{
    /// <summary>
    /// The public queries called on boxed shapes: the overload of ClosestDistance.Between / Distance or
    /// ProximityQuery.Overlaps whose shape types match the arguments, double (ProximityLib.Double) or float (ProximityLib),
    /// found by reflection. The double API takes its shapes as <c>in</c> parameters, which the runtime binder behind
    /// <c>dynamic</c> does not bind; reflection sees either form.
    /// </summary>
    public static class Api
    {
        private static readonly ConcurrentDictionary<(Type, string, Type, Type), MethodInfo?> _methods =
            new ConcurrentDictionary<(Type, string, Type, Type), MethodInfo?>();

        public static dynamic Between(object a, object b) => Call(Owner(a, typeof(ProximityLib.ClosestDistance), typeof(ProximityLib.Double.ClosestDistance)), "Between", a, b);
        /// <summary>The Distance of <see cref="Between"/> (float results widened exactly).</summary>
        public static double BetweenDistance(object a, object b) => Convert.ToDouble(((dynamic)Between(a, b)).Distance);
        public static double Distance(object a, object b) => Convert.ToDouble(Call(Owner(a, typeof(ProximityLib.ClosestDistance), typeof(ProximityLib.Double.ClosestDistance)), "Distance", a, b));
        public static bool Overlaps(object a, object b) => (bool)Call(Owner(a, typeof(ProximityLib.ProximityQuery), typeof(ProximityLib.Double.ProximityQuery)), "Overlaps", a, b);

        /// <summary>The overload of <paramref name="owner"/>.<paramref name="method"/> for (a's type, b's type), or null.</summary>
        public static MethodInfo? Find(Type owner, string method, Type a, Type b) =>
            _methods.GetOrAdd((owner, method, a, b), k => k.Item1.GetMethods(BindingFlags.Public | BindingFlags.Static)
                .SingleOrDefault(m => m.Name == k.Item2 && m.GetParameters() is { Length: 2 } ps && Shape(ps[0]) == k.Item3 && Shape(ps[1]) == k.Item4));

        private static object Call(Type owner, string method, object a, object b)
        {
            var m = Find(owner, method, a.GetType(), b.GetType())
                ?? throw new MissingMethodException(owner.FullName, method + "(" + a.GetType().Name + ", " + b.GetType().Name + ")");
            try { return m.Invoke(null, new[] { a, b })!; }
            catch (TargetInvocationException e) when (e.InnerException != null)
            {
                System.Runtime.ExceptionServices.ExceptionDispatchInfo.Capture(e.InnerException).Throw();
                throw;
            }
        }

        private static Type Owner(object a, Type single, Type dbl) => a.GetType().Namespace == "ProximityLib.Double" ? dbl : single;

        private static Type Shape(ParameterInfo p) => p.ParameterType.IsByRef ? p.ParameterType.GetElementType()! : p.ParameterType;
    }
}
