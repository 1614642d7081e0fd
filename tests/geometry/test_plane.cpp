// Ray-plane intersection: hand-computed hits, sidedness, parallel rays, the
// finite square and bounds (NUMERICS.md §3.4 and §4 (13), (14), (19)).

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/plane.h"
#include "geometry/primitives.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

TEST_CASE("plane: hit from the front, t in units of |d|, in-plane u v") {
    // z = 0, normal +z. From (1, 2, 5) along (0, 0, -2): n·(p0 - o) = -5, n·d = -2, t = 2.5.
    auto p = makePlane({0, 0, 0}, {0, 0, 1});
    const Ray ray{{1, 2, 5}, {0, 0, -2}};
    for (Precision prec : {Precision::Double, Precision::Float}) {
        const IntersectOptions opt = withPrecision(prec);
        const auto hit = intersect1(*p, ray, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == 2.5);
        // The frame of +z has tangents +x and +y, so (u, v) = (x, y) of the hit.
        CHECK(hit->u == 1.0);
        CHECK(hit->v == 2.0);
        const SurfaceGeometry g = surface1(*p, ray, *hit, opt);
        CHECK(g.p == Vec3{1, 2, 0});
        CHECK(g.ng == Vec3{0, 0, 1});
        CHECK(g.ns == Vec3{0, 0, 1});
        CHECK(g.frontFace);
    }
}

TEST_CASE("plane: tilted plane, the factory normalises the normal") {
    // Plane through (1,1,1) with normal (1,1,1)/√3. From (3,3,3) along (-1,-1,-1):
    // n·(p0 - o) = -2√3, n·d = -√3, t = 2, hit (1,1,1).
    auto p = makePlane({1, 1, 1}, {2, 2, 2});
    const Ray ray{{3, 3, 3}, {-1, -1, -1}};
    const auto hit = intersect1(*p, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(2.0).epsilon(1e-15));
    const SurfaceGeometry g = surface1(*p, ray, *hit);
    CHECK(g.ng.x == doctest::Approx(1 / std::sqrt(3.0)).epsilon(1e-15));
    CHECK(g.p.y == doctest::Approx(1.0).epsilon(1e-15));
}

TEST_CASE("plane: sidedness, back-face hits only for Inside and Both") {
    // From below (0,0,-1) along +z: t = 1, dot(d, n) > 0, a back-face hit.
    auto p = makePlane({0, 0, 0}, {0, 0, 1});
    const Ray ray{{0, 0, -1}, {0, 0, 1}};
    CHECK_FALSE(intersect1(*p, ray, 0, kInf));
    CHECK_FALSE(occluded1(*p, ray, 0, kInf));
    p->setSidedness(Sidedness::Inside);
    CHECK(intersect1(*p, ray, 0, kInf)->t == 1.0);
    CHECK_FALSE(intersect1(*p, Ray{{0, 0, 1}, {0, 0, -1}}, 0, kInf));
    p->setSidedness(Sidedness::Both);
    const auto hit = intersect1(*p, ray, 0, kInf);
    REQUIRE(hit);
    const SurfaceGeometry g = surface1(*p, ray, *hit);
    CHECK_FALSE(g.frontFace);
    CHECK(g.ng == Vec3{0, 0, 1});  // still the outward normal
}

TEST_CASE("plane: parallel rays and rays in the plane miss without NaN") {
    auto p = makePlane({0, 0, 0}, {0, 0, 1});
    p->setSidedness(Sidedness::Both);
    for (Precision prec : {Precision::Double, Precision::Float}) {
        const IntersectOptions opt = withPrecision(prec);
        CHECK_FALSE(intersect1(*p, Ray{{0, 0, 1}, {1, 0, 0}}, 0, kInf, opt));  // above, parallel
        CHECK_FALSE(intersect1(*p, Ray{{0, 0, 0}, {1, 1, 0}}, 0, kInf, opt));  // in the plane (0/0)
        CHECK_FALSE(intersect1(*p, Ray{{0, 0, 0}, {1, 1, 0}}, -kInf, kInf, opt));
        CHECK_FALSE(intersect1(*p, Ray{{0, 0, 1}, {0, 0, 0}}, 0, kInf, opt));  // zero direction
    }
}

TEST_CASE("plane: strict interval and NaN bounds") {
    auto p = makePlane({0, 0, 0}, {0, 0, 1});
    const Ray ray{{0, 0, 1}, {0, 0, -1}};  // t = 1
    CHECK_FALSE(intersect1(*p, ray, 0, 1.0));
    CHECK_FALSE(intersect1(*p, ray, 1.0, kInf));
    CHECK(intersect1(*p, ray, 0, std::nextafter(1.0, 2.0)));
    CHECK_FALSE(intersect1(*p, ray, std::nan(""), kInf));
    CHECK_FALSE(intersect1(*p, ray, 0, std::nan("")));
    CHECK_FALSE(intersect1(*p, Ray{{0, 0, 1}, {0, 0, std::nan("")}}, 0, kInf));
}

TEST_CASE("plane: grazing ray at 1e-6 rad gives a finite t and an accurate hit point") {
    // From (0,0,1) along (1, 0, -1e-6): t = 1e6, hit (1e6, 0, 0).
    auto p = makePlane({0, 0, 0}, {0, 0, 1}, 1e7);
    const Ray ray{{0, 0, 1}, {1, 0, -1e-6}};
    const auto hit = intersect1(*p, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(1e6).epsilon(1e-12));
    const SurfaceGeometry g = surface1(*p, ray, *hit);
    CHECK(std::abs(g.p.z) < 1e-12);
    CHECK(g.p.x == doctest::Approx(1e6).epsilon(1e-12));
}

TEST_CASE("plane: finite square of halfExtent, bounds finite and padded") {
    // Half extent 10 around (0,0,2) in z = 2: x = 9.5 hits, x = 10.5 misses.
    auto p = makePlane({0, 0, 2}, {0, 0, 1}, 10);
    CHECK(intersect1(*p, Ray{{9.5, -9.5, 5}, {0, 0, -1}}, 0, kInf));
    CHECK_FALSE(intersect1(*p, Ray{{10.5, 0, 5}, {0, 0, -1}}, 0, kInf));
    const Bounds3 b = p->bounds();
    CHECK(b.finite());
    CHECK(b.lo.x < -10);
    CHECK(b.lo.x > -10.001);
    CHECK(b.hi.y > 10);
    CHECK(b.lo.z < 2);
    CHECK(b.hi.z > 2);
    CHECK(b.hi.z - b.lo.z < 1e-4);  // flat along the normal
    // Default extent: still finite, and within Embree's float range.
    const Bounds3 d = makePlane({0, 0, 0}, {0.3, -0.4, 0.5})->bounds();
    CHECK(d.finite());
    CHECK(maxComponent(abs(d.hi)) < 1e6);
    // Every in-square hit lies inside the bounds (tilted plane).
    auto t = makePlane({1, 2, 3}, {0.3, -0.4, 0.5}, 4);
    t->setSidedness(Sidedness::Both);
    int inside = 0, hits = 0;
    for (int i = -10; i <= 10; ++i) {
        for (int j = -10; j <= 10; ++j) {
            const Ray ray{{1 + 0.5 * i, 2 + 0.5 * j, 20}, {0.01 * i, 0.02, -1}};
            if (auto hit = intersect1(*t, ray, 0, kInf)) {
                ++hits;
                inside += t->bounds().contains(ray.at(hit->t));
            }
        }
    }
    CHECK(hits > 100);
    CHECK(inside == hits);
}

TEST_CASE("plane: factory validates its parameters") {
    CHECK_THROWS_WITH_AS(makePlane({0, 0, 0}, {0, 0, 0}),
                         "plane: normal must be a non-zero vector (got (0, 0, 0))",
                         std::invalid_argument);
    CHECK_THROWS_AS(makePlane({0, std::nan(""), 0}, {0, 0, 1}), std::invalid_argument);
    CHECK_THROWS_AS(makePlane({0, 0, 0}, {0, 0, kInf}), std::invalid_argument);
    CHECK_THROWS_WITH_AS(makePlane({0, 0, 0}, {0, 0, 1}, 0),
                         "plane: halfExtent must be > 0 (got 0)", std::invalid_argument);
    CHECK_THROWS_AS(makePlane({0, 0, 0}, {0, 0, 1}, kInf), std::invalid_argument);
    CHECK(std::string(makePlane({0, 0, 0}, {0, 0, 1})->kind()) == "plane");
}
