// Ray-sphere intersection: hand-computed hits, sidedness, interval rules and
// the numerically hard cases of NUMERICS.md §3.1 / §4 (1)-(3).

#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/geometry_test_helpers.h"
#include "geometry/primitives.h"
#include "geometry/quadratic.h"
#include "geometry/spawn.h"
#include "geometry/sphere.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

/// Reference near/far roots in long double with the same robust formulation
/// (64-bit significand, c in doubled long-double precision): its own error is
/// ~1e-19 relative, far below one double ulp.
struct RefRoots {
    bool hit = false;
    long double t0 = 0, t1 = 0;
};
RefRoots referenceRoots(const Vec3& o, const Vec3& d, const Vec3& centre, double radius) {
    using L = long double;
    const L ox = L(o.x) - L(centre.x), oy = L(o.y) - L(centre.y), oz = L(o.z) - L(centre.z);
    const L dx = d.x, dy = d.y, dz = d.z, r = radius;
    const L a = dx * dx + dy * dy + dz * dz;
    const L h = ox * dx + oy * dy + oz * dz;
    const L fx = ox - dx * (h / a), fy = oy - dy * (h / a), fz = oz - dz * (h / a);
    const L lf = std::sqrt(fx * fx + fy * fy + fz * fz);
    const L disc = a * ((r - lf) * (r + lf));
    RefRoots out;
    if (disc < 0) return out;
    const L c = sumSquaresMinusSquare<L>(ox, oy, oz, 0, 0, 0, r);
    const QuadraticRoots<L> roots = solveQuadraticHalfB<L>(a, h, c, disc);
    out.hit = roots.count > 0;
    out.t0 = roots.t0;
    out.t1 = roots.t1;
    return out;
}
}  // namespace

TEST_CASE("sphere: axis ray hits the near pole first, front face, outward normal") {
    // Unit sphere at the origin, ray from z = -5 along +z: |o + t d| = 1 at t = 4 and 6.
    auto s = makeSphere({0, 0, 0}, 1);
    const Ray ray{{0, 0, -5}, {0, 0, 1}};
    const auto hit = intersect1(*s, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 4.0);
    const SurfaceGeometry g = surface1(*s, ray, *hit);
    CHECK(g.p == Vec3{0, 0, -1});
    CHECK(g.ng == Vec3{0, 0, -1});
    CHECK(g.ns == Vec3{0, 0, -1});
    CHECK(g.frontFace);
    // u, v = x, y of the unit normal: 0 at the pole.
    CHECK(hit->u == 0.0);
    CHECK(hit->v == 0.0);
}

TEST_CASE("sphere: t is measured in units of |d| (direction not normalised)") {
    // Same geometry with |d| = 2: the hit at distance 4 is t = 2.
    auto s = makeSphere({0, 0, 0}, 1);
    const auto hit = intersect1(*s, Ray{{0, 0, -5}, {0, 0, 2}}, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 2.0);
}

TEST_CASE("sphere: off-axis hit point and normal") {
    // Sphere centre (1,2,3), r = 1; ray from (1.6, 2, -2) along +z. Local x = 0.6, so the
    // entry point has local z = -sqrt(1 - 0.36) = -0.8: p = (1.6, 2, 2.2), t = 4.2.
    auto s = makeSphere({1, 2, 3}, 1);
    const Ray ray{{1.6, 2, -2}, {0, 0, 1}};
    const auto hit = intersect1(*s, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(4.2).epsilon(1e-15));
    const SurfaceGeometry g = surface1(*s, ray, *hit);
    CHECK(g.ng.x == doctest::Approx(0.6).epsilon(1e-14));
    CHECK(g.ng.y == doctest::Approx(0.0));
    CHECK(g.ng.z == doctest::Approx(-0.8).epsilon(1e-14));
    CHECK(g.p.z == doctest::Approx(2.2).epsilon(1e-14));
    CHECK(hit->u == doctest::Approx(0.6).epsilon(1e-14));  // x, y of the unit normal
    CHECK(hit->v == doctest::Approx(0.0));
    // Ray passing 1.01 from the centre misses.
    CHECK_FALSE(intersect1(*s, Ray{{2.01, 2, -2}, {0, 0, 1}}, 0, kInf));
}

TEST_CASE("sphere: sidedness filters near (entering) and far (leaving) roots") {
    // Ray from z = -5 along +z: near root t = 4 is front-facing, far root t = 6 back-facing.
    auto s = makeSphere({0, 0, 0}, 1);
    const Ray outsideRay{{0, 0, -5}, {0, 0, 1}};
    s->setSidedness(Sidedness::Inside);
    auto hit = intersect1(*s, outsideRay, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 6.0);
    CHECK_FALSE(surface1(*s, outsideRay, *hit).frontFace);

    // Origin at the centre: the only positive root (t = 1) leaves the sphere.
    const Ray insideRay{{0, 0, 0}, {1, 0, 0}};
    s->setSidedness(Sidedness::Outside);
    CHECK_FALSE(intersect1(*s, insideRay, 0, kInf));
    CHECK_FALSE(occluded1(*s, insideRay, 0, kInf));
    s->setSidedness(Sidedness::Both);
    hit = intersect1(*s, insideRay, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 1.0);
    const SurfaceGeometry g = surface1(*s, insideRay, *hit);
    CHECK_FALSE(g.frontFace);
    CHECK(g.ng == Vec3{1, 0, 0});  // still outward
    s->setSidedness(Sidedness::Inside);
    CHECK(intersect1(*s, insideRay, 0, kInf));
}

TEST_CASE("sphere: strict interval tMin < t < tMax, NaN-safe") {
    auto s = makeSphere({0, 0, 0}, 1);
    s->setSidedness(Sidedness::Both);
    const Ray ray{{0, 0, -5}, {0, 0, 1}};  // roots 4 and 6
    CHECK_FALSE(intersect1(*s, ray, 0, 4.0));
    CHECK(intersect1(*s, ray, 0, std::nextafter(4.0, 5.0))->t == 4.0);
    CHECK(intersect1(*s, ray, 4.0, kInf)->t == 6.0);  // t = tMin excluded: next root
    CHECK_FALSE(intersect1(*s, ray, 6.0, kInf));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    CHECK_FALSE(intersect1(*s, ray, nan, kInf));
    CHECK_FALSE(intersect1(*s, ray, 0, nan));
    CHECK_FALSE(intersect1(*s, Ray{{0, 0, -5}, {0, 0, nan}}, 0, kInf));
    CHECK_FALSE(intersect1(*s, Ray{{0, 0, -5}, {0, 0, 0}}, 0, kInf));
}

TEST_CASE("sphere: tangent ray is a grazing (not front-facing) double root") {
    // Line x = 1 touches the unit sphere at (1,0,0), t = 5: discriminant exactly 0.
    // dot(d, n) = 0 there, so it is not a front-face hit: Outside misses, Both hits.
    auto s = makeSphere({0, 0, 0}, 1);
    const Ray ray{{1, 0, -5}, {0, 0, 1}};
    CHECK_FALSE(intersect1(*s, ray, 0, kInf));
    s->setSidedness(Sidedness::Both);
    const auto hit = intersect1(*s, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 5.0);
}

TEST_CASE("sphere: spawned rays do not re-hit their own surface") {
    // Reflected rays leave outward and must find nothing; refracted rays go inward and
    // must find only the far side at t = 2 r cos(theta) (|d| = 1). Several scales.
    test::Rng rng(7);
    for (double scale : {1.0, 1e4, 1e5}) {
        const Vec3 centre{scale, -scale, scale};
        const double r = 1.0 + 0.1 * scale;
        auto s = makeSphere(centre, r);
        s->setSidedness(Sidedness::Both);
        SpawnSettings spawn;
        int rehits = 0, wrongFar = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3 n = rng.direction();
            const Vec3 p = centre + n * r;
            Vec3 dir = rng.direction();
            if (dot(dir, n) < 0) dir = -dir;
            // Leaving outward.
            const SpawnedRay out = spawnRay(p, n, 0.0, dir, spawn);
            if (intersect1(*s, out.ray, out.tMin, kInf)) ++rehits;
            // Entering: the far side, about 2 r cos(theta) away (|d| = 1); exactly the far
            // root of the spawned ray (whose origin is offset inward by robustOffset()).
            const Vec3 in = -dir;
            const SpawnedRay inRay = spawnRay(p, n, 0.0, in, spawn);
            const auto hit = intersect1(*s, inRay.ray, inRay.tMin, kInf);
            const RefRoots ref = referenceRoots(inRay.ray.o, in, centre, r);
            if (!hit || !ref.hit || std::abs(hit->t - double(ref.t1)) > 1e-12 * r ||
                !(hit->t > r * dot(dir, n))) {  // past the chord's midpoint: the far side
                ++wrongFar;
            }
        }
        CHECK_MESSAGE(rehits == 0, "scale " << scale);
        CHECK_MESSAGE(wrongFar == 0, "scale " << scale);
    }
}

TEST_CASE("sphere: huge sphere seen from 1 unit above, double, within a few ulps") {
    // r = 1e4, origin at height 1 above the surface in a random direction, rays heading
    // down into the sphere: near root compared with the long-double reference. The naive
    // c = |oc|² - r² alone would carry ~1e-12 relative error (thousands of ulps).
    test::Rng rng(11);
    const double r = 1e4;
    for (const Vec3 centre : {Vec3{0, 0, 0}, Vec3{123.456, -7.89e3, 3.21e3}}) {
        auto s = makeSphere(centre, r);
        double worst = 0;
        for (int i = 0; i < 5000; ++i) {
            const Vec3 n = rng.direction();
            const Vec3 o = centre + n * (r + 1.0);
            Vec3 d = rng.direction();
            if (dot(d, n) > -0.2) d = d - n * (dot(d, n) + 0.5);  // point it downwards
            d = d * rng.uniform(0.5, 2.0);
            const RefRoots ref = referenceRoots(o, d, centre, r);
            const auto hit = intersect1(*s, Ray{o, d}, 0, kInf);
            REQUIRE(ref.hit);
            REQUIRE(hit);
            CHECK(hit->t > 0);
            worst = std::max(worst, test::ulpDistance(hit->t, double(ref.t0)));
        }
        MESSAGE("huge sphere: worst near-root error " << worst << " ulp");
        CHECK(worst <= 4);
    }
}

TEST_CASE("sphere: tiny sphere far away, double, within a few ulps") {
    // r = 1e-3 at distance 1e4 (D/r = 1e7): rays aimed at 0, 0.5 r and 0.9 r from the centre
    // hit within a few ulps of the reference; rays aimed 1.01 r away miss.
    test::Rng rng(13);
    const double r = 1e-3;
    const Vec3 centre{1e4, 0.5, -3};
    auto s = makeSphere(centre, r);
    double worst = 0;
    int wrong = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 toEye = rng.direction();
        const Vec3 o = centre + toEye * 1e4;
        const double offset = std::array<double, 4>{0.0, 0.5, 0.9, 1.01}[i % 4];
        const Vec3 target = centre + test::perpendicular(toEye) * (offset * r);
        const Vec3 d = target - o;  // |d| ≈ 1e4: t ≈ 1
        const auto hit = intersect1(*s, Ray{o, d}, 0, kInf);
        const RefRoots ref = referenceRoots(o, d, centre, r);
        if (hit.has_value() != ref.hit || hit.has_value() != (offset < 1)) ++wrong;
        if (hit && ref.hit) worst = std::max(worst, test::ulpDistance(hit->t, double(ref.t0)));
    }
    MESSAGE("tiny sphere: worst near-root error " << worst << " ulp");
    CHECK(wrong == 0);
    CHECK(worst <= 16);
}

TEST_CASE("sphere: float precision keeps hit/miss right up to D/r = 1e5") {
    // Unit sphere at the origin, eye at distance D in float, unit directions. Offsets 0.5 r
    // and 0.99 r must hit, 1.01 r must miss (naive float is ~44% wrong already at D/r = 1e4).
    // Inputs are float-representable, so the reference sees exactly what the solver sees.
    // Accuracy of t is bounded by float's own resolution at t ≈ D (ulp(1e4f) ≈ 1e-3 r):
    // checked in float ulps of t.
    test::Rng rng(17);
    for (double D : {1e2, 1e3, 1e4, 1e5}) {
        auto s = makeSphere({0, 0, 0}, 1);
        const IntersectOptions opt = withPrecision(Precision::Float);
        int wrong = 0, n = 0;
        double worstDt = 0, worstUlps = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 toEye = rng.direction();
            const Vec3 o(Vec3f(toEye * D));
            const double offset = std::array<double, 3>{0.5, 0.99, 1.01}[i % 3];
            const Vec3 d(Vec3f(normalize(test::perpendicular(toEye) * offset - o)));
            const RefRoots ref = referenceRoots(o, d, {0, 0, 0}, 1);
            const auto hit = intersect1(*s, Ray{o, d}, 0, kInf, opt);
            ++n;
            if (hit.has_value() != ref.hit || ref.hit != (offset < 1)) ++wrong;
            if (hit && ref.hit && offset == 0.5) {
                const double dt = std::abs(hit->t - double(ref.t0));
                const float tf = float(ref.t0);
                worstDt = std::max(worstDt, dt);  // |d| = 1: in units of r
                worstUlps = std::max(worstUlps, dt / double(std::nextafter(tf, 2 * tf) - tf));
            }
        }
        MESSAGE("float D/r = " << D << ": " << wrong << "/" << n << " wrong, worst |dt| = "
                               << worstDt << " r = " << worstUlps << " float ulp at offset 0.5");
        CHECK(wrong == 0);
        CHECK(worstUlps <= 4);
    }
}

TEST_CASE("sphere: huge sphere near the origin in float, stable root") {
    // NUMERICS §4 (2): origin 1 above spheres of r = 1e3, heading straight down. Float with
    // the doubled-precision c: never a negative t, error well below the NUMERICS limit.
    for (double r : {1e3, 1e4}) {
        auto s = makeSphere({0, 0, 0}, r);
        const IntersectOptions opt = withPrecision(Precision::Float);
        const auto hit = intersect1(*s, Ray{{0, 0, r + 1}, {0, 0, -1}}, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(1.0).epsilon(1e-4));
    }
}

TEST_CASE("sphere: bounds are the padded centre ± r box") {
    auto s = makeSphere({1, -2, 3}, 0.5);
    const Bounds3 b = s->bounds();
    CHECK(b.finite());
    CHECK(b.lo.x < 0.5);
    CHECK(b.lo.x > 0.5 - 1e-5);
    CHECK(b.hi.z > 3.5);
    CHECK(b.hi.z < 3.5 + 1e-5);
}

TEST_CASE("sphere: factory validates its parameters") {
    CHECK_THROWS_WITH_AS(makeSphere({0, 0, 0}, -1), "sphere: radius must be > 0 (got -1)",
                         std::invalid_argument);
    CHECK_THROWS_AS(makeSphere({0, 0, 0}, 0), std::invalid_argument);
    CHECK_THROWS_AS(makeSphere({0, 0, 0}, std::nan("")), std::invalid_argument);
    CHECK_THROWS_AS(makeSphere({0, kInf, 0}, 1), std::invalid_argument);
    CHECK(std::string(makeSphere({0, 0, 0}, 1)->kind()) == "sphere");
}
