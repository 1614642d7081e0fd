// Ray–triangle math: hand-computed hits of the watertight (Woop et al. 2013)
// and Möller–Trumbore tests, Embree's barycentric convention, interval rules,
// edge/vertex rays, watertightness on shared edges and vertices, degenerate
// triangles and parallel rays.

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/random.h"
#include "geometry/triangle.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using TriRng = SplitMix64;

using Intersector = std::optional<TriangleHit> (*)(const Ray&, const Vec3&, const Vec3&,
                                                   const Vec3&, double, double);

// The unit right triangle in the z = 0 plane, counter-clockwise seen from +z.
const Vec3 kP0{0, 0, 0}, kP1{1, 0, 0}, kP2{0, 1, 0};

}  // namespace

TEST_CASE("triangle: straight-down ray, hand-computed t, u, v (both tests)") {
    // o = (0.25, 0.5, 1), d = (0, 0, -1) meets z = 0 at t = 1, point (0.25, 0.5, 0).
    // (1-u-v)·p0 + u·p1 + v·p2 = (u, v, 0), so u = 0.25 (x) and v = 0.5 (y).
    // All quantities are dyadic, so both tests are exact.
    for (Intersector f :
         {Intersector(&intersectTriangle), Intersector(&intersectTriangleMollerTrumbore)}) {
        const auto h = f(Ray{{0.25, 0.5, 1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf);
        REQUIRE(h);
        CHECK(h->t == 1.0);
        CHECK(h->u == 0.25);
        CHECK(h->v == 0.5);
    }
}

TEST_CASE("triangle: t is in units of |d|") {
    // Same ray with d = (0, 0, -2): the plane is reached at t = 0.5.
    const auto h = intersectTriangle(Ray{{0.25, 0.5, 1}, {0, 0, -2}}, kP0, kP1, kP2, 0, kInf);
    REQUIRE(h);
    CHECK(h->t == 0.5);
    CHECK(h->u == 0.25);
    CHECK(h->v == 0.5);
}

TEST_CASE("triangle: two-sided, the back side gives the same hit") {
    // From below (z = -1) going up: t = 1, same point, same barycentrics.
    for (Intersector f :
         {Intersector(&intersectTriangle), Intersector(&intersectTriangleMollerTrumbore)}) {
        const auto h = f(Ray{{0.25, 0.5, -1}, {0, 0, 1}}, kP0, kP1, kP2, 0, kInf);
        REQUIRE(h);
        CHECK(h->t == 1.0);
        CHECK(h->u == 0.25);
        CHECK(h->v == 0.5);
    }
}

TEST_CASE("triangle: oblique ray on a tilted triangle") {
    // Triangle (1,0,0), (0,1,0), (0,0,1) lies in x + y + z = 1. The ray o = 0, d = (1,2,3)
    // reaches it when 6t = 1: t = 1/6, point (1/6, 1/3, 1/2). With p0 = (1,0,0):
    // (1-u-v)·p0 + u·p1 + v·p2 = (1-u-v, u, v), hence u = 1/3 and v = 1/2.
    const Vec3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1};
    for (Intersector f :
         {Intersector(&intersectTriangle), Intersector(&intersectTriangleMollerTrumbore)}) {
        const auto h = f(Ray{{0, 0, 0}, {1, 2, 3}}, a, b, c, 0, kInf);
        REQUIRE(h);
        CHECK(h->t == doctest::Approx(1.0 / 6).epsilon(1e-15));
        CHECK(h->u == doctest::Approx(1.0 / 3).epsilon(1e-15));
        CHECK(h->v == doctest::Approx(0.5).epsilon(1e-15));
    }
    // Reversed winding (a, c, b): same t, the roles of u and v swap.
    const auto h = intersectTriangle(Ray{{0, 0, 0}, {1, 2, 3}}, a, c, b, 0, kInf);
    REQUIRE(h);
    CHECK(h->t == doctest::Approx(1.0 / 6).epsilon(1e-15));
    CHECK(h->u == doctest::Approx(0.5).epsilon(1e-15));
    CHECK(h->v == doctest::Approx(1.0 / 3).epsilon(1e-15));
}

TEST_CASE("triangle: the interval is open, tMin < t < tMax") {
    const Ray ray{{0.25, 0.5, 1}, {0, 0, -1}};  // hits at t = 1 exactly
    for (Intersector f :
         {Intersector(&intersectTriangle), Intersector(&intersectTriangleMollerTrumbore)}) {
        CHECK_FALSE(f(ray, kP0, kP1, kP2, 0, 1.0));
        CHECK_FALSE(f(ray, kP0, kP1, kP2, 1.0, kInf));
        CHECK(f(ray, kP0, kP1, kP2, 0, std::nextafter(1.0, 2.0)));
        CHECK(f(ray, kP0, kP1, kP2, std::nextafter(1.0, 0.0), kInf));
        // Behind the origin: the plane is at t = -1.
        CHECK_FALSE(f(Ray{{0.25, 0.5, -1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf));
        // NaN bounds never accept.
        const double nan = std::numeric_limits<double>::quiet_NaN();
        CHECK_FALSE(f(ray, kP0, kP1, kP2, nan, kInf));
        CHECK_FALSE(f(ray, kP0, kP1, kP2, 0, nan));
    }
}

TEST_CASE("triangle: a ray outside misses") {
    // (0.6, 0.6) has x + y = 1.2 > 1: outside the hypotenuse.
    CHECK_FALSE(intersectTriangle(Ray{{0.6, 0.6, 1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf));
    CHECK_FALSE(
        intersectTriangleMollerTrumbore(Ray{{0.6, 0.6, 1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf));
    // x < 0.
    CHECK_FALSE(intersectTriangle(Ray{{-0.01, 0.5, 1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf));
}

TEST_CASE("triangle: rays through edges and vertices hit (boundary is inside)") {
    struct Case {
        Vec3 target;
        double u, v;
    };
    // Points on the boundary and their barycentrics (u = x, v = y here).
    const Case cases[] = {
        {{0.5, 0, 0}, 0.5, 0},      // edge p0-p1
        {{0, 0.5, 0}, 0, 0.5},      // edge p0-p2
        {{0.5, 0.5, 0}, 0.5, 0.5},  // hypotenuse p1-p2
        {{0, 0, 0}, 0, 0},          // vertex p0
        {{1, 0, 0}, 1, 0},          // vertex p1
        {{0, 1, 0}, 0, 1},          // vertex p2
    };
    for (const Case& c : cases) {
        CAPTURE(c.target.x);
        CAPTURE(c.target.y);
        const auto h =
            intersectTriangle(Ray{c.target + Vec3{0, 0, 2}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf);
        REQUIRE(h);
        CHECK(h->t == 2.0);
        CHECK(h->u == c.u);
        CHECK(h->v == c.v);
    }
}

TEST_CASE("triangle: degenerate triangles never hit and never produce NaN") {
    const Ray ray{{0.5, 0.5, 1}, {0, 0, -1}};
    // A repeated vertex, all three equal, and exactly collinear vertices.
    const std::array<std::array<Vec3, 3>, 4> degenerate{{
        {{{0, 0, 0}, {1, 1, 0}, {1, 1, 0}}},
        {{{0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0}}},
        {{{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}}},
        {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}},
    }};
    for (const auto& t : degenerate) {
        CHECK_FALSE(intersectTriangle(ray, t[0], t[1], t[2], 0, kInf));
        CHECK_FALSE(intersectTriangleMollerTrumbore(ray, t[0], t[1], t[2], 0, kInf));
        // A ray along the degenerate segment itself.
        const Ray along{t[0] - (t[2] - t[0]), t[2] - t[0]};
        CHECK_FALSE(intersectTriangle(along, t[0], t[1], t[2], -kInf, kInf));
        CHECK_FALSE(intersectTriangleMollerTrumbore(along, t[0], t[1], t[2], -kInf, kInf));
    }
    CHECK(triangleNormal({0, 0, 0}, {1, 1, 1}, {2, 2, 2}) == Vec3{0, 0, 0});
}

TEST_CASE("triangle: rays parallel to the plane miss, without NaN") {
    for (Intersector f :
         {Intersector(&intersectTriangle), Intersector(&intersectTriangleMollerTrumbore)}) {
        // In the plane z = 0, crossing the triangle: every edge function is 0 -> det = 0.
        CHECK_FALSE(f(Ray{{-1, 0.25, 0}, {1, 0, 0}}, kP0, kP1, kP2, -kInf, kInf));
        // Above the plane, parallel to it.
        CHECK_FALSE(f(Ray{{-1, 0.25, 1}, {1, 0, 0}}, kP0, kP1, kP2, -kInf, kInf));
        CHECK_FALSE(f(Ray{{-1, -1, 1}, {1, 1, 0}}, kP0, kP1, kP2, -kInf, kInf));
    }
}

TEST_CASE("triangle: invalid rays miss") {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(intersectTriangle(Ray{{0.25, 0.25, 1}, {0, 0, 0}}, kP0, kP1, kP2, 0, kInf));
    CHECK_FALSE(intersectTriangle(Ray{{nan, 0.25, 1}, {0, 0, -1}}, kP0, kP1, kP2, 0, kInf));
    CHECK_FALSE(intersectTriangle(Ray{{0.25, 0.25, 1}, {0, kInf, -1}}, kP0, kP1, kP2, 0, kInf));
}

TEST_CASE("triangle: per-ray constants of the watertight test") {
    // d = (0.5, 0.25, -1): |d_z| dominates -> kz = 2; kx = 0, ky = 1, swapped
    // because d_z < 0 (keeps the winding) -> kx = 1, ky = 0. Shear
    // sx = d_y / d_z = -0.25, sy = d_x / d_z = -0.5, sz = 1 / d_z = -1.
    const WatertightRay w(Ray{{1, 2, 3}, {0.5, 0.25, -1}});
    REQUIRE(w.valid);
    CHECK(w.kz == 2);
    CHECK(w.kx == 1);
    CHECK(w.ky == 0);
    CHECK(w.sx == -0.25);
    CHECK(w.sy == -0.5);
    CHECK(w.sz == -1.0);
    CHECK_FALSE(WatertightRay(Ray{{1, 2, 3}, {0, 0, 0}}).valid);
    CHECK_FALSE(WatertightRay(Ray{{1, 2, kInf}, {0, 0, 1}}).valid);
    // The precomputed form gives the Ray overload's hit.
    const auto h =
        intersectTriangle(WatertightRay(Ray{{0.25, 0.5, 1}, {0, 0, -1}}), kP0, kP1, kP2, 0, kInf);
    REQUIRE(h);
    CHECK(h->t == 1.0);
    CHECK(h->u == 0.25);
    CHECK(h->v == 0.5);
}

TEST_CASE("triangle: normal is the CCW cross product, length twice the area") {
    // (2,0,0) × (0,3,0) = (0, 0, 6); area 3.
    CHECK(triangleNormal({0, 0, 0}, {2, 0, 0}, {0, 3, 0}) == Vec3{0, 0, 6});
    CHECK(triangleNormal({0, 0, 0}, {0, 3, 0}, {2, 0, 0}) == Vec3{0, 0, -6});
    CHECK(triangleNormal(kP0, kP1, kP2) == Vec3{0, 0, 1});
}

TEST_CASE("triangle: random hits satisfy o + t·d = (1-u-v)·p0 + u·p1 + v·p2") {
    TriRng rng(7);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 p0 = rng.point(-1, 1), p1 = rng.point(-1, 1), p2 = rng.point(-1, 1);
        // Aim at a point of the plane around the triangle (about half inside).
        const Vec3 target =
            p0 + (p1 - p0) * rng.uniform(-0.2, 1.2) + (p2 - p0) * rng.uniform(-0.2, 1.2);
        const Vec3 o = rng.point(-3, 3);
        const Ray ray{o, (target - o) * rng.uniform(0.5, 2)};
        const auto w = intersectTriangle(ray, p0, p1, p2, 0, kInf);
        const auto m = intersectTriangleMollerTrumbore(ray, p0, p1, p2, 0, kInf);
        if (!w) continue;
        ++hits;
        CHECK(w->u >= 0);
        CHECK(w->v >= 0);
        CHECK(w->u + w->v <= 1 + 1e-15);
        const Vec3 a = ray.at(w->t);
        const Vec3 b = p0 * (1 - w->u - w->v) + p1 * w->u + p2 * w->v;
        const double scale = 1 + length(ray.o) + length(ray.d) * w->t;
        CHECK(length(a - b) < 1e-12 * scale);
        // Möller–Trumbore agrees except for rays within rounding of an edge.
        const double margin = std::min({w->u, w->v, 1 - w->u - w->v});
        if (margin > 1e-9) {
            REQUIRE(m);
            CHECK(m->t == doctest::Approx(w->t).epsilon(1e-9));
            CHECK(m->u == doctest::Approx(w->u).epsilon(1e-9));
            CHECK(m->v == doctest::Approx(w->v).epsilon(1e-9));
        }
    }
    CHECK(hits > 5000);  // the property was exercised
}

TEST_CASE("triangle: the overload given the triangle's normal answers bit for bit as the others") {
    // Scene::surfaceAt passes the normal it already holds; the answers, hits,
    // misses and rejected zero-area triangles alike, must not change.
    TriRng rng(11);
    int hits = 0, misses = 0;
    const auto same = [](const std::optional<TriangleHit>& a, const std::optional<TriangleHit>& b) {
        return a.has_value() == b.has_value() &&
               (!a || (a->t == b->t && a->u == b->u && a->v == b->v));
    };
    for (int i = 0; i < 20000; ++i) {
        Vec3 p0 = rng.point(-1, 1), p1 = rng.point(-1, 1), p2 = rng.point(-1, 1);
        if (i % 10 == 0) p2 = p1;                                  // a repeated vertex
        if (i % 10 == 1) p2 = p0 + (p1 - p0) * 2.0;                // collinear
        const Vec3 target =
            p0 + (p1 - p0) * rng.uniform(-0.2, 1.2) + (p2 - p0) * rng.uniform(-0.2, 1.2);
        const Vec3 o = rng.point(-3, 3);
        const Ray ray{o, (target - o) * rng.uniform(0.5, 2)};
        const double tMin = i % 3 == 0 ? -kInf : 0, tMax = i % 5 == 0 ? 1.0 : kInf;
        const auto plain = intersectTriangle(ray, p0, p1, p2, tMin, tMax);
        const auto given = intersectTriangle(ray, p0, p1, p2, triangleNormal(p0, p1, p2), tMin, tMax);
        const auto pre = intersectTriangle(WatertightRay(ray), p0, p1, p2, tMin, tMax);
        CHECK(same(plain, given));
        CHECK(same(plain, pre));
        (plain ? hits : misses)++;
    }
    CHECK(hits > 3000);  // both outcomes were exercised
    CHECK(misses > 3000);
    // A zero-area triangle the edge functions would pass: rejected either way.
    const Ray down{{0.5, 0.5, 1}, {0, 0, -1}};
    const Vec3 a{0, 0, 0}, b{1, 1, 0}, c{1, 1, 0};
    CHECK_FALSE(intersectTriangle(down, a, b, c, triangleNormal(a, b, c), -kInf, kInf));
}

TEST_CASE("triangle: watertight on a shared edge (never misses both triangles)") {
    // Random pairs of triangles sharing the edge (a, b); rays from random
    // origins aimed at random points of that edge (rounded to double, so
    // generally a hair off the exact line). The ray crosses the union of the
    // two triangles whenever both lie on opposite sides of the ray's plane
    // through the edge: then at least one must report a hit.
    TriRng rng(11);
    int tested = 0, missedBoth = 0, mtMissedBoth = 0;
    for (int i = 0; i < 20000; ++i) {
        const Vec3 a = rng.point(-1, 1), b = rng.point(-1, 1);
        const Vec3 c = rng.point(-1, 1), e = rng.point(-1, 1);
        const Vec3 target = a + (b - a) * rng.uniform();
        const Vec3 o = rng.point(-4, 4);
        const Ray ray{o, target - o};
        // Only count rays that cross the edge (c and e on opposite sides of the
        // plane through the ray and the edge), so the union is really crossed.
        const Vec3 n = cross(b - a, ray.d);
        if (!(dot(n, c - a) * dot(n, e - a) < 0)) continue;
        ++tested;
        const bool w =
            intersectTriangle(ray, a, b, c, 0, kInf) || intersectTriangle(ray, b, a, e, 0, kInf);
        const bool m = intersectTriangleMollerTrumbore(ray, a, b, c, 0, kInf) ||
                       intersectTriangleMollerTrumbore(ray, b, a, e, 0, kInf);
        missedBoth += !w;
        mtMissedBoth += !m;
    }
    MESSAGE("shared-edge rays: ", tested, ", watertight misses: ", missedBoth,
            ", Moller-Trumbore misses: ", mtMissedBoth);
    CHECK(tested > 5000);
    CHECK(missedBoth == 0);
}

TEST_CASE("triangle: watertight at vertices of a closed octahedron") {
    // Octahedron with vertices ±x, ±y, ±z (scaled by irrational-ish factors so
    // the arithmetic is inexact); rays from interior points aimed at every
    // vertex and edge midpoint must hit at least one face.
    const double s = 1.0 / 3.0;
    const std::array<Vec3, 6> v{{{1.1 + s, 0, 0},
                                 {-0.9 - s, 0, 0},
                                 {0, 1.3 + s, 0},
                                 {0, -0.7 - s, 0},
                                 {0, 0, 1.7 + s},
                                 {0, 0, -1.2 - s}}};
    // Faces: one per octant, (x, y, z) vertex choices.
    std::vector<std::array<int, 3>> faces;
    for (int ix : {0, 1})
        for (int iy : {2, 3})
            for (int iz : {4, 5}) faces.push_back({ix, iy, iz});
    std::vector<Vec3> targets(v.begin(), v.end());
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) targets.push_back((v[f[k]] + v[f[(k + 1) % 3]]) * 0.5);

    TriRng rng(5);
    int misses = 0, total = 0;
    for (int i = 0; i < 300; ++i) {
        const Vec3 o = rng.point(-0.2, 0.2);
        for (const Vec3& target : targets) {
            const Ray ray{o, target - o};
            bool hit = false;
            for (const auto& f : faces)
                hit = hit || intersectTriangle(ray, v[f[0]], v[f[1]], v[f[2]], 0, kInf);
            misses += !hit;
            ++total;
        }
    }
    CHECK(total == 300 * 30);
    CHECK(misses == 0);
}
