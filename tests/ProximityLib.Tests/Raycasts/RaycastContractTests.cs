using System;
using System.Collections.Generic;
using NUnit.Framework;
using ProximityLib.Double;
using ProximityReference;
using static ProximityTests.Raycasts.Hits;

namespace ProximityTests.Raycasts
{
    /// <summary>
    /// Every target: 2^k scaling gives the 2^k-scaled hit bit for bit (across the fast and slow paths, 2^±900
    /// included) with every field finite; extreme magnitudes stay finite; and exact rational references for spheres,
    /// boxes, triangles, half-spaces and 2D segments.
    /// </summary>
    public class RaycastContractTests
    {
        private const double U = 1.0 / (1L << 53);

        private static double MaxAbs(Vector3D v) => Math.Max(Math.Abs(v.X), Math.Max(Math.Abs(v.Y), Math.Abs(v.Z)));

        private static Vector3D P(Random r, double s = 4) => V(Math.Round((r.NextDouble() * 2 - 1) * s * 64) / 64, Math.Round((r.NextDouble() * 2 - 1) * s * 64) / 64, Math.Round((r.NextDouble() * 2 - 1) * s * 64) / 64);
        private static Vector2D P2(Random r) => Vector2D.From3(P(r));
        private static double Size(Random r) => r.Next(6) == 0 ? 0 : Math.Round(r.NextDouble() * 3 * 64) / 64;

        /// <summary>Random cases per target, as the cast of the configuration scaled by k (a power of two).</summary>
        private static IEnumerable<(string Name, Func<double, RayHit3>? Cast3, Func<double, RayHit2>? Cast2)> Cases(int seed)
        {
            var r = new Random(seed);
            for (int i = 0; i < 60; i++)
            {
                var o = P(r); var d = P(r) - o; if (d == default) d = V(1, 0, 0);
                var a = P(r); var b = r.Next(4) == 0 ? a : P(r); var c = P(r); double s = Size(r);
                var o2 = Vector2D.From3(o); var d2 = Vector2D.From3(d); if (d2 == default) d2 = V(0, 1);
                var a2 = Vector2D.From3(a); var b2 = Vector2D.From3(b); var c2 = Vector2D.From3(c);
                var along = Vector2D.From3(c - a); if (along == default) along = V(1, 0);
                Ray3 R(double k) => new Ray3(o * k, d);
                Ray2 R2(double k) => new Ray2(o2 * k, d2);
                yield return ("point", k => Raycast.Cast(R(k), a * k), k => Raycast.Cast(R2(k), a2 * k));
                yield return ("segment", k => Raycast.Cast(R(k), new Segment3(a * k, b * k)), k => Raycast.Cast(R2(k), new Segment2(a2 * k, b2 * k)));
                yield return ("line/ray", null, k => Raycast.Cast(R2(k), new Line2(a2 * k, along)));
                yield return ("ray", null, k => Raycast.Cast(R2(k), new Ray2(a2 * k, along)));
                yield return ("sphere", k => Raycast.Cast(R(k), new Sphere(a * k, s * k)), k => Raycast.Cast(R2(k), new Circle(a2 * k, s * k)));
                yield return ("capsule", k => Raycast.Cast(R(k), new Capsule3(a * k, b * k, s * k)), k => Raycast.Cast(R2(k), new Capsule2(a2 * k, b2 * k, s * k)));
                yield return ("triangle", k => Raycast.Cast(R(k), new Triangle3(a * k, b * k, c * k)), k => Raycast.Cast(R2(k), new Triangle2(a2 * k, b2 * k, c2 * k)));
                yield return ("half-space", k => Raycast.Cast(R(k), HalfSpace.FromPointNormal(a * k, c - b == default ? V(0, 0, 1) : c - b)),
                    k => Raycast.Cast(R2(k), HalfPlane.FromPointNormal(a2 * k, along)));
                var lo = V(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z));
                var hi = V(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z));
                yield return ("aabb", k => Raycast.Cast(R(k), new Aabb3(lo * k, hi * k)), k => Raycast.Cast(R2(k), new Aabb2(Vector2D.From3(lo) * k, Vector2D.From3(hi) * k)));
                var half = V(Size(r), Size(r), Size(r));
                var box = new Obb3(a, new System.Numerics.Quaternion(0.1f * i, 0.2f, -0.3f, 1), half);
                var box2 = new Obb2(a2, 0.3 * i, Vector2D.From3(half));
                yield return ("obb", k => Raycast.Cast(R(k), new Obb3(a * k, box.AxisX, box.AxisY, box.AxisZ, half * k)),
                    k => Raycast.Cast(R2(k), new Obb2(a2 * k, box2.AxisX, Vector2D.From3(half) * k)));
            }
        }

        [TestCase(-900), TestCase(-300), TestCase(-7), TestCase(5), TestCase(300), TestCase(900)]
        public void ScalingByAPowerOfTwoScalesTheHitBitForBit(int e)
        {
            double k = Math.Pow(2, e);
            int hits = 0;
            foreach (var (name, cast3, cast2) in Cases(e + 1000))
            {
                if (cast3 != null)
                {
                    var h = cast3(1); var s = cast3(k);
                    Sane(h); Sane(s);
                    Assert.DoesNotThrow(() => Scales(h, s, k), name);
                    if (h.Hit) hits++;
                }
                if (cast2 != null)
                {
                    var h = cast2(1); var s = cast2(k);
                    Sane(h); Sane(s);
                    Assert.DoesNotThrow(() => Scales(h, s, k), name + " 2D");
                }
            }
            Assert.That(hits, Is.GreaterThan(60));
        }

        [Test]
        public void ExtremeMagnitudesStayFinite()
        {
            double big = 1.5e308;
            Sane(Raycast.Cast(new Ray3(V(big, 0, 0), V(-1, 0, 0)), new Sphere(V(-big, 0, 0), 1e307)));
            Miss(Raycast.Cast(new Ray3(V(big, 0, 0), V(-1, 0, 0)), new Sphere(V(-big, 0, 0), 1e307))); // 2.9e308 away
            var h = Raycast.Cast(new Ray3(V(big, 0, 0), V(-1, 0, 0)), new Sphere(V(0, 0, 0), 1));
            IsHit(h, big - 1, V(1, 0, 0), V(1, 0, 0), 0);
            IsHit(Raycast.Cast(new Ray3(V(big, big, 0), V(0, -1, 0)), new Aabb3(V(big - 1e300, -big, -1), V(big + 1e300, big, 1))), 0, V(big, big, 0), V(0, 1, 0));
            IsHit(Raycast.Cast(new Ray3(V(1e-310, 0, 1e-320), V(-1, 0, 0)), new Triangle3(V(0, -1e-310, -1e-310), V(0, 1e-310, -1e-310), V(0, 0, 1e-310))),
                1e-310, V(0, 0, 1e-320), V(1, 0, 0), 1e-323);
            Sane(Raycast.Cast(new Ray3(V(-big, 0, 0), V(1, 1e-300, 0)), new Capsule3(V(big, 0, 0), V(big, big, 0), 1e300)));
            Sane(Raycast.Cast(new Ray2(V(-big, big), V(1, -1)), new Segment2(V(big, -big), V(-big, -big))));
            Sane(Raycast.Cast(new Ray2(V(-big, big), V(1, -1)), new Triangle2(V(big, -big), V(-big, -big), V(0, big))));
        }

        [Test]
        public void FloatHitsPastFloatRangeAreMisses()
        {
            // T past float's range, the point inside it: origin −3e38, box at 3e38 (T = 6e38).
            var o = new System.Numerics.Vector3(-3e38f, 0, 0);
            var dir = new System.Numerics.Vector3(1, 0, 0);
            var lo = new System.Numerics.Vector3(3e38f, -1, -1);
            var hi = new System.Numerics.Vector3(3.2e38f, 1, 1);
            var d = Raycast.Cast(new Ray3(V(o.X, 0, 0), V(1, 0, 0)), new Aabb3(V(lo.X, -1, -1), V(hi.X, 1, 1)));
            Assert.That(d.Hit && d.T > float.MaxValue, Is.True, $"the double API hits at T = {d.T:R}");
            var f = ProximityLib.Raycast.Cast(new ProximityLib.Ray3(o, dir), new ProximityLib.Aabb3(lo, hi));
            Assert.That(f.Hit, Is.False, f.ToString());
            Assert.That(f.T, Is.EqualTo(float.PositiveInfinity));
            Assert.That(f.Point, Is.EqualTo(System.Numerics.Vector3.Zero));
            // The point past float's range (ray-cast fuzz 2:43913): two nearly parallel 2D rays meet at about 1e40.
            var ro = new System.Numerics.Vector2(1.557653E+37f, -1.8201409E+37f);
            var rd = new System.Numerics.Vector2(0.87450975f, -0.48500797f);
            var to = new System.Numerics.Vector2(-4.3067526E+36f, 7.3409025E+36f);
            var td = new System.Numerics.Vector2(0.014745111f, -0.008405173f);
            var d2 = Raycast.Cast(new Ray2(V(ro.X, ro.Y), V(rd.X, rd.Y)), new Ray2(V(to.X, to.Y), V(td.X, td.Y)));
            Assert.That(d2.Hit && Math.Max(Math.Abs(d2.Point.X), Math.Abs(d2.Point.Y)) > float.MaxValue, Is.True, $"the double API hits at {d2.Point}");
            var f2 = ProximityLib.Raycast.Cast(new ProximityLib.Ray2(ro, rd), new ProximityLib.Ray2(to, td));
            Assert.That(f2.Hit, Is.False, f2.ToString());
            Assert.That(f2.Point, Is.EqualTo(System.Numerics.Vector2.Zero));
            // Just inside the range: still a hit, T rounded.
            var f3 = ProximityLib.Raycast.Cast(new ProximityLib.Ray3(new System.Numerics.Vector3(-1e38f, 0, 0), dir), new ProximityLib.Aabb3(new System.Numerics.Vector3(2e38f, -1, -1), hi));
            Assert.That(f3.Hit, Is.True, f3.ToString());
            Assert.That(f3.T, Is.EqualTo((float)(2e38f - (double)-1e38f)));
        }

        // ---- exact rational references on dyadic inputs: hit flags outside a band, T within 32·u·S ----

        private static Rational Dot(RVec a, RVec b) => RVec.Dot(a, b);

        private static void Compare(string name, bool hit, double t, bool exactHit, Rational exactT, double scale, ref int checkedHits)
        {
            Assert.That(hit, Is.EqualTo(exactHit), $"{name}: exact T {exactT}");
            if (!hit) return;
            checkedHits++;
            Assert.That(Math.Abs(t - exactT.ToDouble()), Is.LessThanOrEqualTo(32 * U * scale), $"{name}: T {t:R}, exact {exactT}");
        }

        [Test]
        public void SpheresMatchTheExactRoot()
        {
            var r = new Random(3);
            int hits = 0;
            for (int i = 0; i < 400; i++)
            {
                var ray = new Ray3(P(r), P(r));
                if (ray.Direction == default) continue;
                var s = new Sphere(P(r), Size(r) + 0.25);
                var h = Raycast.Cast(ray, s);
                var w = RVec.From(ray.Origin) - RVec.From(s.Center);
                var d = RVec.From(ray.Direction);
                Rational dd = Dot(d, d), b = Dot(w, d), c = Dot(w, w) - (Rational)s.Radius * s.Radius;
                Rational disc = b * b - dd * c;
                double scale = Math.Max(MaxAbs(ray.Origin - s.Center), s.Radius);
                if (c.Sign <= 0)
                {
                    if (Math.Abs(c.ToDouble()) < 1e-9) continue;
                    Assert.That(h.StartsInside, Is.True);
                    continue;
                }
                bool exact = disc.Sign >= 0 && b.Sign < 0;
                if (Math.Abs(disc.ToDouble()) < 1e-9 * scale * scale) continue; // grazing band
                Rational t = exact ? (-b - Rational.Sqrt(disc)) / dd : Rational.Zero;
                Compare("sphere", h.Hit, h.T, exact, t, scale, ref hits);
            }
            Assert.That(hits, Is.GreaterThan(15));
        }

        [Test]
        public void BoxesMatchTheExactSlabs()
        {
            var r = new Random(4);
            int hits = 0;
            for (int i = 0; i < 400; i++)
            {
                var o = P(r);
                var d = i % 5 == 0 ? V(r.Next(3) - 1, r.Next(3) - 1, 1) : P(r);
                if (d == default) continue;
                var ray = new Ray3(o, d);
                var a = P(r); var b = P(r);
                var box = new Aabb3(V(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y), Math.Min(a.Z, b.Z)), V(Math.Max(a.X, b.X), Math.Max(a.Y, b.Y), Math.Max(a.Z, b.Z)));
                var h = Raycast.Cast(ray, box);
                RVec ro = RVec.From(ray.Origin), rd = RVec.From(ray.Direction), lo = RVec.From(box.Min), hi = RVec.From(box.Max);
                Rational enter = Rational.Zero, exit = Rational.Zero;
                bool bounded = false, ok = true;
                for (int k = 0; k < 3; k++)
                {
                    Rational ok_ = k == 0 ? ro.X : k == 1 ? ro.Y : ro.Z, dk = k == 0 ? rd.X : k == 1 ? rd.Y : rd.Z;
                    Rational l = k == 0 ? lo.X : k == 1 ? lo.Y : lo.Z, u = k == 0 ? hi.X : k == 1 ? hi.Y : hi.Z;
                    if (dk.IsZero) { ok &= l <= ok_ && ok_ <= u; continue; }
                    Rational t1 = (l - ok_) / dk, t2 = (u - ok_) / dk;
                    Rational n = Rational.Min(t1, t2), f = Rational.Max(t1, t2);
                    if (!bounded) { enter = n; exit = f; bounded = true; }
                    else { enter = Rational.Max(enter, n); exit = Rational.Min(exit, f); }
                }
                bool exactHit = ok && enter <= exit && exit.Sign >= 0;
                double scale = Math.Max(MaxAbs(o - box.Min), MaxAbs(box.Max - box.Min));
                if (exactHit && (exit - enter).ToDouble() < 1e-9 * scale) continue; // grazing band
                Compare("aabb", h.Hit, h.T, exactHit, Rational.Max(enter, Rational.Zero), scale, ref hits);
            }
            Assert.That(hits, Is.GreaterThan(30));
        }

        [Test]
        public void TrianglesMatchTheExactPlaneCrossing()
        {
            var r = new Random(5);
            int hits = 0;
            for (int i = 0; i < 500; i++)
            {
                var t = new Triangle3(P(r), P(r), P(r));
                var target = t.A * 0.25 + t.B * 0.25 + t.C * 0.5 + P(r, 1);
                var o = P(r, 8);
                if (o == target) continue;
                var ray = new Ray3(o, target - o);
                var h = Raycast.Cast(ray, t);
                RVec ro = RVec.From(ray.Origin), rd = RVec.From(ray.Direction), A = RVec.From(t.A), B = RVec.From(t.B), C = RVec.From(t.C);
                var n = RVec.Cross(B - A, C - A);
                Rational den = Dot(n, rd);
                if (den.IsZero) continue;
                Rational tt = Dot(n, A - ro) / den;
                var p = ro + rd * tt;
                Rational l0 = Dot(RVec.Cross(B - A, p - A), n), l1 = Dot(RVec.Cross(C - B, p - B), n), l2 = Dot(RVec.Cross(A - C, p - C), n);
                double nn = n.LengthSquared.ToDouble(), band = 1e-9 * nn;
                double scale = Math.Max(MaxAbs(t.A - o), Math.Max(MaxAbs(t.B - o), MaxAbs(t.C - o)));
                if (Math.Abs(l0.ToDouble()) < band || Math.Abs(l1.ToDouble()) < band || Math.Abs(l2.ToDouble()) < band || Math.Abs(tt.ToDouble()) < 1e-9 * scale) continue;
                if (Math.Abs(den.ToDouble()) < 1e-6 * Math.Sqrt(nn)) continue; // nearly edge-on: ill-conditioned
                bool exactHit = tt.Sign >= 0 && l0.Sign == l1.Sign && l1.Sign == l2.Sign;
                Compare("triangle", h.Hit, h.T, exactHit, tt, scale / Math.Abs(den.ToDouble() / Math.Sqrt(nn)), ref hits);
            }
            Assert.That(hits, Is.GreaterThan(100));
        }

        [Test]
        public void HalfSpacesAndSegments2DMatchTheExactCrossing()
        {
            var r = new Random(6);
            int hits = 0;
            for (int i = 0; i < 400; i++)
            {
                var ray = new Ray3(P(r), P(r));
                var hs = HalfSpace.FromPointNormal(P(r), P(r) == default ? V(1, 0, 0) : P(r));
                var h = Raycast.Cast(ray, hs);
                RVec ro = RVec.From(ray.Origin), rd = RVec.From(ray.Direction), n = RVec.From(hs.Normal), p = RVec.From(hs.Point);
                Rational s = Dot(n, ro - p), rate = -Dot(n, rd);
                double scale = MaxAbs(ray.Origin - hs.Point);
                if (Math.Abs(s.ToDouble()) < 1e-9 * scale || Math.Abs(rate.ToDouble()) < 1e-6) continue;
                if (s.Sign < 0) { Assert.That(h.StartsInside); continue; }
                Compare("half-space", h.Hit, h.T, rate.Sign > 0, rate.Sign > 0 ? s / rate : Rational.Zero, scale / Math.Abs(rate.ToDouble()), ref hits);

                var ray2 = new Ray2(P2(r), P2(r) == default ? V(1, 0) : P2(r));
                var seg = new Segment2(P2(r), P2(r));
                var g = Raycast.Cast(ray2, seg);
                RVec o2 = RVec.From(ray2.Origin), d2 = RVec.From(ray2.Direction), a2 = RVec.From(seg.Start), b2 = RVec.From(seg.End);
                Rational den = RVec.Cross(d2, b2 - a2).Z;
                if (den.IsZero || Math.Abs(den.ToDouble()) < 1e-6) continue;
                Rational tt = RVec.Cross(a2 - o2, b2 - a2).Z / den, ss = RVec.Cross(a2 - o2, d2).Z / den;
                double sc = Math.Max(MaxAbs((seg.Start - ray2.Origin).To3()), MaxAbs((seg.End - ray2.Origin).To3()));
                if (Math.Abs(ss.ToDouble()) < 1e-9 || Math.Abs(ss.ToDouble() - 1) < 1e-9 || Math.Abs(tt.ToDouble()) < 1e-9 * sc) continue;
                bool exact = tt.Sign >= 0 && ss.Sign >= 0 && ss <= Rational.One;
                Compare("segment2", g.Hit, g.T, exact, tt, sc / Math.Abs(den.ToDouble()) * 2, ref hits);
            }
            Assert.That(hits, Is.GreaterThan(100));
        }
    }
}
