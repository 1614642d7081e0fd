// Ray-disk intersection: hits inside the radius (rim included), misses
// outside, sidedness, parallel rays, tight bounds, validation.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/disk.h"
#include "geometry/primitives.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

TEST_CASE("disk: hits within the radius, rim included, misses beyond") {
    // Centre (1,2,3), normal +z, r = 2. From (2,2,10) along -z: t = 7, local (1,0) -> u = 0.5.
    auto disk = makeDisk({1, 2, 3}, {0, 0, 1}, 2);
    for (Precision prec : {Precision::Double, Precision::Float}) {
        const IntersectOptions opt = withPrecision(prec);
        const Ray ray{{2, 2, 10}, {0, 0, -1}};
        const auto hit = intersect1(*disk, ray, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == 7.0);
        CHECK(hit->u == 0.5);
        CHECK(hit->v == 0.0);
        const SurfaceGeometry g = surface1(*disk, ray, *hit, opt);
        CHECK(g.p == Vec3{2, 2, 3});
        CHECK(g.ng == Vec3{0, 0, 1});
        CHECK(g.frontFace);
        // Local (0, -1.9): inside; (2, 0) exactly on the rim: inside; (2.1, 0): outside.
        CHECK(intersect1(*disk, Ray{{1, 0.1, 10}, {0, 0, -1}}, 0, kInf, opt));
        CHECK(intersect1(*disk, Ray{{3, 2, 10}, {0, 0, -1}}, 0, kInf, opt));
        CHECK_FALSE(intersect1(*disk, Ray{{3.1, 2, 10}, {0, 0, -1}}, 0, kInf, opt));
        // Diagonal (1.45, 1.45): distance 2.05 > 2, outside although |u|, |v| < r.
        CHECK_FALSE(intersect1(*disk, Ray{{2.45, 3.45, 10}, {0, 0, -1}}, 0, kInf, opt));
    }
}

TEST_CASE("disk: sidedness and parallel rays") {
    auto disk = makeDisk({0, 0, 0}, {0, 1, 0}, 1);  // normal +y
    const Ray below{{0.2, -1, 0.1}, {0, 2, 0}};     // t = 0.5, back face
    CHECK_FALSE(intersect1(*disk, below, 0, kInf));
    disk->setSidedness(Sidedness::Inside);
    CHECK(intersect1(*disk, below, 0, kInf)->t == 0.5);
    CHECK_FALSE(intersect1(*disk, Ray{{0, 1, 0}, {0, -1, 0}}, 0, kInf));
    disk->setSidedness(Sidedness::Both);
    const auto hit = intersect1(*disk, below, 0, kInf);
    REQUIRE(hit);
    CHECK_FALSE(surface1(*disk, below, *hit).frontFace);
    CHECK_FALSE(intersect1(*disk, Ray{{0, 0, 0}, {1, 0, 0}}, -kInf, kInf));  // in the plane
    CHECK_FALSE(intersect1(*disk, Ray{{0, 1, 0}, {1, 0, 1}}, 0, kInf));      // parallel
    CHECK_FALSE(intersect1(*disk, below, 0.5, kInf));                        // strict tMin
}

TEST_CASE("disk: tight bounds r·sqrt(1 - n_i²)") {
    // Normal (1,1,0)/√2, r = 2: half extents (2/√2, 2/√2, 2) = (1.414.., 1.414.., 2).
    const Bounds3 b = makeDisk({0, 0, 0}, {1, 1, 0}, 2)->bounds();
    CHECK(b.finite());
    CHECK(b.hi.x == doctest::Approx(std::sqrt(2.0)).epsilon(1e-6));
    CHECK(b.hi.x >= std::sqrt(2.0));
    CHECK(b.hi.z == doctest::Approx(2.0).epsilon(1e-6));
    CHECK(b.lo.y <= -std::sqrt(2.0));
    // Axis-aligned normal: flat box (only the padding) along it.
    const Bounds3 f = makeDisk({5, 0, 0}, {1, 0, 0}, 1)->bounds();
    CHECK(f.hi.x - f.lo.x < 1e-5);
    CHECK(f.hi.y >= 1);
    CHECK(f.hi.y < 1 + 1e-5);
}

TEST_CASE("disk: factory validates its parameters") {
    CHECK_THROWS_WITH_AS(makeDisk({0, 0, 0}, {0, 0, 1}, -2), "disk: radius must be > 0 (got -2)",
                         std::invalid_argument);
    CHECK_THROWS_AS(makeDisk({0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
    CHECK_THROWS_AS(makeDisk({kInf, 0, 0}, {0, 0, 1}, 1), std::invalid_argument);
    CHECK_THROWS_AS(makeDisk({0, 0, 0}, {0, 0, 1}, std::nan("")), std::invalid_argument);
    CHECK(std::string(makeDisk({0, 0, 0}, {0, 0, 1}, 1)->kind()) == "disk");
}
