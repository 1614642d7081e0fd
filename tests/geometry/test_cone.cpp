// Cylinders, cones and truncated cones: hand-computed side and cap hits,
// the degenerate directions of NUMERICS.md §3.5 / §4 (15), (16), (18), bounds,
// validation, and a randomized surface-consistency check.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "geometry/cone.h"
#include "geometry/frame.h"
#include "geometry/geometry_test_helpers.h"
#include "geometry/primitives.h"
#include "geometry/random.h"
#include "shape_queries.h"

using namespace raylab;
using raylab::test::FlushDenormals;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

std::unique_ptr<Shape> cone(Vec3 base, double r0, Vec3 apex, double r1, bool capped = false) {
    ConeParams p;
    p.base = base;
    p.baseRadius = r0;
    p.apex = apex;
    p.apexRadius = r1;
    p.capped = capped;
    return makeCone(p);
}

void checkVec(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    CHECK(a.x == doctest::Approx(b.x).epsilon(eps).scale(1));
    CHECK(a.y == doctest::Approx(b.y).epsilon(eps).scale(1));
    CHECK(a.z == doctest::Approx(b.z).epsilon(eps).scale(1));
}
}  // namespace

TEST_CASE("cone: cylinder side hits, facing, normals, u v") {
    // Unit cylinder along z from 0 to 2. From (-5, 0, 1) along +x: enters at x = -1 (t = 4,
    // front, normal -x, v = z / h = 0.5) and leaves at x = 1 (t = 6, back).
    for (Precision prec : {Precision::Double, Precision::Float}) {
        auto cyl = cone({0, 0, 0}, 1, {0, 0, 2}, 1);
        const IntersectOptions opt = withPrecision(prec);
        CHECK(std::string(cyl->kind()) == "cylinder");
        const Ray ray{{-5, 0, 1}, {1, 0, 0}};
        auto hit = intersect1(*cyl, ray, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == 4.0);
        CHECK(hit->v == 0.5);
        const SurfaceGeometry g = surface1(*cyl, ray, *hit, opt);
        checkVec(g.ng, {-1, 0, 0});
        checkVec(g.p, {-1, 0, 1});
        CHECK(g.frontFace);
        cyl->setSidedness(Sidedness::Inside);
        hit = intersect1(*cyl, ray, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == 6.0);
        CHECK_FALSE(surface1(*cyl, ray, *hit, opt).frontFace);
        checkVec(surface1(*cyl, ray, *hit, opt).ng, {1, 0, 0});
        // |d| = 2: t halves.
        cyl->setSidedness(Sidedness::Outside);
        CHECK(intersect1(*cyl, Ray{{-5, 0, 1}, {2, 0, 0}}, 0, kInf, opt)->t == 2.0);
        // Above the top (z = 3) or below the base: the infinite cylinder's hits are clipped.
        CHECK_FALSE(intersect1(*cyl, Ray{{-5, 0, 3}, {1, 0, 0}}, 0, kInf, opt));
        CHECK_FALSE(intersect1(*cyl, Ray{{-5, 0, -0.1}, {1, 0, 0}}, 0, kInf, opt));
        // Passing 1.01 from the axis: miss.
        CHECK_FALSE(intersect1(*cyl, Ray{{-5, 1.01, 1}, {1, 0, 0}}, 0, kInf, opt));
    }
}

TEST_CASE("cone: ray along the axis hits only caps, without NaN") {
    // NUMERICS §4 (15), (16): a = b = 0 for the side. Open: nothing. Capped: the base cap
    // from outside (front, t = 1), the top cap from inside (back, t = 1) for Both/Inside.
    // The direction (1e-20, 1e-20, 1) (a = 2e-40: subnormal in float, flushed to 0 under
    // FTZ/DAZ) behaves the same, with and without FTZ/DAZ.
    for (bool daz : {false, true}) {
        const FlushDenormals mode(daz);
        for (const Vec3 d : {Vec3{0, 0, 1}, Vec3{1e-20, 1e-20, 1}}) {
            for (Precision prec : {Precision::Double, Precision::Float}) {
                auto open = cone({0, 0, 0}, 1, {0, 0, 2}, 1);
                auto capped = cone({0, 0, 0}, 1, {0, 0, 2}, 1, true);
                const IntersectOptions opt = withPrecision(prec);
                open->setSidedness(Sidedness::Both);
                const Ray fromBelow{{0.2, 0.1, -1}, d};
                CHECK_FALSE(intersect1(*open, fromBelow, 0, kInf, opt));
                auto hit = intersect1(*capped, fromBelow, 0, kInf, opt);
                REQUIRE(hit);
                CHECK(hit->t == doctest::Approx(1.0));
                SurfaceGeometry g = surface1(*capped, fromBelow, *hit, opt);
                CHECK(g.ng == Vec3{0, 0, -1});
                CHECK(g.frontFace);

                const Ray inside{{0.2, 0.1, 1}, d};
                CHECK_FALSE(intersect1(*capped, inside, 0, kInf, opt));  // back face, one-sided
                capped->setSidedness(Sidedness::Both);
                hit = intersect1(*capped, inside, 0, kInf, opt);
                REQUIRE(hit);
                CHECK(hit->t == doctest::Approx(1.0));
                g = surface1(*capped, inside, *hit, opt);
                CHECK(g.ng == Vec3{0, 0, 1});
                CHECK_FALSE(g.frontFace);
                // Outside the radius: misses the caps too.
                CHECK_FALSE(intersect1(*capped, Ray{{2, 0, -1}, d}, 0, kInf, opt));
            }
        }
    }
}

TEST_CASE("cone: ray through the rim hits at the rim (inclusive)") {
    // From (2, 0, 3) along (-1, 0, -1): reaches the top rim (1, 0, 2) at t = 1, where the
    // side (x² = 1 at t = 1, z = 2 = h) and the top cap (ρ = 1) meet.
    auto open = cone({0, 0, 0}, 1, {0, 0, 2}, 1);
    auto capped = cone({0, 0, 0}, 1, {0, 0, 2}, 1, true);
    const Ray ray{{2, 0, 3}, {-1, 0, -1}};
    CHECK(intersect1(*open, ray, 0, kInf)->t == 1.0);
    CHECK(intersect1(*capped, ray, 0, kInf)->t == 1.0);
    // Straight down exactly on the rim circle: the top cap's edge (ρ = r), t = 1.
    CHECK(intersect1(*capped, Ray{{1, 0, 3}, {0, 0, -1}}, 0, kInf)->t == 1.0);
}

TEST_CASE("cone: cone side, normal and the mirror nappe") {
    // Base r = 1 at z = 0, apex r = 0 at z = 1: k = -1, r(z) = 1 - z.
    auto c = cone({0, 0, 0}, 1, {0, 0, 1}, 0);
    CHECK(std::string(c->kind()) == "cone");
    // From (-5, 0, 0.5) along +x: r(0.5) = 0.5, enters at x = -0.5, t = 4.5; outward normal
    // ∝ (x/ρ, y/ρ, -k) = (-1, 0, 1).
    const Ray ray{{-5, 0, 0.5}, {1, 0, 0}};
    const auto hit = intersect1(*c, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 4.5);
    const SurfaceGeometry g = surface1(*c, ray, *hit);
    checkVec(g.ng, normalize(Vec3{-1, 0, 1}));
    CHECK(g.frontFace);
    // At z = 1.5 the infinite double cone has x = ±0.5 (the mirror nappe): rejected.
    c->setSidedness(Sidedness::Both);
    CHECK_FALSE(intersect1(*c, Ray{{-5, 0, 1.5}, {1, 0, 0}}, 0, kInf));
    // Below the base (z = -0.5): the lower nappe continues, r = 1.5, but z < 0: rejected.
    CHECK_FALSE(intersect1(*c, Ray{{-5, 0, -0.5}, {1, 0, 0}}, 0, kInf));
}

TEST_CASE("cone: ray parallel to a generator (a = 0) has one real root") {
    // Cone r(z) = 1 - z. d = (-1, 0, 1) is parallel to the generator (1,0,0)-(0,0,1):
    // a = dx² + dy² - k² dz² = 0. From (0.5, 0, -0.5): F(t) = (0.5 - t)² - (1.5 - t)²
    // = 2t - 2, root t = 1 at (-0.5, 0, 0.5), leaving the solid (the ray passes the base
    // centre at t = 0.5): a back-face hit. The reversed ray from (-1.5, 0, 1.5) enters at t = 1.
    auto c = cone({0, 0, 0}, 1, {0, 0, 1}, 0);
    for (Precision prec : {Precision::Double, Precision::Float}) {
        const IntersectOptions opt = withPrecision(prec);
        c->setSidedness(Sidedness::Outside);
        const Ray out{{0.5, 0, -0.5}, {-1, 0, 1}};
        CHECK_FALSE(intersect1(*c, out, 0, kInf, opt));
        c->setSidedness(Sidedness::Inside);
        auto hit = intersect1(*c, out, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(1.0).epsilon(1e-6));
        c->setSidedness(Sidedness::Outside);
        const Ray in{{-1.5, 0, 1.5}, {1, 0, -1}};
        hit = intersect1(*c, in, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(surface1(*c, in, *hit, opt).frontFace);
    }
}

TEST_CASE("cone: ray through the apex gives a finite normal") {
    // Every line through the apex is a double root there (the cone is homogeneous about
    // it): a grazing hit, seen with Both. From (0,0,3) straight down: apex at t = 2.
    auto c = cone({0, 0, 0}, 1, {0, 0, 1}, 0);
    c->setSidedness(Sidedness::Both);
    for (const Ray& ray : {Ray{{0, 0, 3}, {0, 0, -1}}, Ray{{-1, 0, 3}, {1, 0, -2}}}) {
        const auto hit = intersect1(*c, ray, 0, kInf);
        REQUIRE(hit);
        const SurfaceGeometry g = surface1(*c, ray, *hit);
        CHECK(isFinite(g.ng));
        CHECK(length(g.ng) == doctest::Approx(1.0));
        CHECK(g.p.z == doctest::Approx(1.0));
    }
    const auto axial = intersect1(*c, Ray{{0, 0, 3}, {0, 0, -1}}, 0, kInf);
    CHECK(axial->t == 2.0);
    CHECK(surface1(*c, Ray{{0, 0, 3}, {0, 0, -1}}, *axial).ng == Vec3{0, 0, 1});
}

TEST_CASE("cone: truncated cone with caps") {
    // r0 = 2 at z = 0, r1 = 1 at z = 2: k = -0.5. From (0,0,5) down: top cap, t = 3.
    // From (-5,0,1) along +x: r(1) = 1.5, t = 3.5, normal ∝ (-1, 0, 0.5).
    auto c = cone({0, 0, 0}, 2, {0, 0, 2}, 1, true);
    const Ray down{{0.5, 0, 5}, {0, 0, -1}};
    auto hit = intersect1(*c, down, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 3.0);
    CHECK(hit->u == 0.5);  // ρ / r1
    CHECK(surface1(*c, down, *hit).ng == Vec3{0, 0, 1});
    const Ray side{{-5, 0, 1}, {1, 0, 0}};
    hit = intersect1(*c, side, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 3.5);
    checkVec(surface1(*c, side, *hit).ng, normalize(Vec3{-1, 0, 0.5}));
    // Ray from below at ρ = 1.8: base cap (r0 = 2) at t = 1.
    const Ray up{{1.8, 0, -1}, {0, 0, 1}};
    hit = intersect1(*c, up, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 1.0);
    CHECK(surface1(*c, up, *hit).ng == Vec3{0, 0, -1});
}

TEST_CASE("cone: tilted cylinder") {
    // Axis (0, 0.6, 0.8) from (1, 2, 3), r = 1, height 10. A ray along -x aimed at the axis
    // point 5 along it from 5 units away hits the side at distance 4 with normal +x.
    const Vec3 axis{0, 0.6, 0.8};
    const Vec3 base{1, 2, 3};
    auto c = cone(base, 1, base + axis * 10, 1);
    const Vec3 onAxis = base + axis * 5;
    const Ray ray{onAxis + Vec3{5, 0, 0}, {-1, 0, 0}};
    const auto hit = intersect1(*c, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(4.0).epsilon(1e-14));
    checkVec(surface1(*c, ray, *hit).ng, {1, 0, 0});
    CHECK(hit->v == doctest::Approx(0.5).epsilon(1e-14));
}

TEST_CASE("cone: bounds are the box of the two end disks") {
    // z-axis cylinder: [-1,1]² × [0,2].
    const Bounds3 b = cone({0, 0, 0}, 1, {0, 0, 2}, 1)->bounds();
    CHECK(b.lo.x <= -1);
    CHECK(b.lo.x > -1 - 1e-5);
    CHECK(b.hi.z >= 2);
    CHECK(b.hi.z < 2 + 1e-5);
    CHECK(b.lo.z <= 0);
    // Tilted truncated cone: every rim point is inside, and the box is tight (within the
    // padding) around the rim points' own box.
    const Vec3 base{1, -2, 0.5}, apex{3, 1, 4};
    auto c = cone(base, 1.5, apex, 0.5);
    const Bounds3 cb = c->bounds();
    const Vec3 a = normalize(apex - base);
    const Vec3 t = test::perpendicular(a), s = cross(a, t);
    Bounds3 rims;
    for (int i = 0; i < 3600; ++i) {
        const double phi = 2 * 3.14159265358979323846 * i / 3600;
        const Vec3 dir = t * std::cos(phi) + s * std::sin(phi);
        rims.expand(base + dir * 1.5);
        rims.expand(apex + dir * 0.5);
    }
    CHECK(cb.contains(rims.lo));
    CHECK(cb.contains(rims.hi));
    CHECK(maxComponent(abs(cb.lo - rims.lo)) < 1e-4);
    CHECK(maxComponent(abs(cb.hi - rims.hi)) < 1e-4);
}

TEST_CASE("cone: random rays land on the surface with consistent facing") {
    // Hits satisfy ρ = r(z) (side) or z ∈ {0, h} (caps); intersect's facing (sidedness
    // filter) agrees with surfaceAt().frontFace away from grazing incidence.
    test::Rng rng(3);
    auto c = cone({0.5, -1, 2}, 1.2, {1.5, 0, 4}, 0.4, true);
    const Vec3 base{0.5, -1, 2}, apex{1.5, 0, 4};
    const Vec3 a = normalize(apex - base);
    const double h = length(apex - base);
    int hits = 0, bad = 0, facing = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 o = (base + apex) * 0.5 + rng.direction() * rng.uniform(0.2, 6);
        const Vec3 target = base + (apex - base) * rng.uniform(-0.2, 1.2) + rng.direction();
        const Ray ray{o, (target - o) * rng.uniform(0.3, 3)};
        for (Sidedness s : {Sidedness::Outside, Sidedness::Inside}) {
            c->setSidedness(s);
            const auto hit = intersect1(*c, ray, 0, kInf);
            if (!hit) continue;
            ++hits;
            const SurfaceGeometry g = surface1(*c, ray, *hit);
            const Vec3 rel = g.p - base;
            const double z = dot(rel, a);
            const double rho = length(rel - a * z);
            const double rz = 1.2 + (0.4 - 1.2) * z / h;
            const bool onSide = std::abs(rho - rz) < 1e-9 && z > -1e-9 && z < h + 1e-9;
            const bool onCap = (std::abs(z) < 1e-9 && rho <= 1.2 + 1e-9) ||
                               (std::abs(z - h) < 1e-9 && rho <= 0.4 + 1e-9);
            if (!onSide && !onCap) ++bad;
            const double cosine = dot(ray.d, g.ng) / length(ray.d);
            if (std::abs(cosine) > 1e-6 && g.frontFace != (s == Sidedness::Outside)) ++facing;
        }
    }
    CHECK(hits > 1000);
    CHECK(bad == 0);
    CHECK(facing == 0);
}

TEST_CASE("cone: factory validates its parameters") {
    CHECK_THROWS_WITH_AS(cone({0, 0, 0}, -1, {0, 0, 1}, -1),
                         "cylinder: baseRadius must be >= 0 (got -1)", std::invalid_argument);
    CHECK_THROWS_WITH_AS(cone({0, 0, 0}, 1, {0, 0, 1}, -0.5),
                         "cone: apexRadius must be >= 0 (got -0.5)", std::invalid_argument);
    CHECK_THROWS_WITH_AS(cone({0, 0, 0}, 0, {0, 0, 1}, 0),
                         "cylinder: radius must be > 0 (both baseRadius and apexRadius are 0)",
                         std::invalid_argument);
    CHECK_THROWS_AS(cone({1, 2, 3}, 1, {1, 2, 3}, 1), std::invalid_argument);
    CHECK_THROWS_AS(cone({0, 0, 0}, std::nan(""), {0, 0, 1}, 1), std::invalid_argument);
    CHECK_THROWS_AS(cone({0, 0, kInf}, 1, {0, 0, 1}, 1), std::invalid_argument);
    CHECK_NOTHROW(cone({0, 0, 0}, 0, {0, 0, 1}, 1));  // apex at the base end is fine
}

TEST_CASE("cone: covering boxes of a slanted cylinder, hand-computed") {
    // Axis (0,0,0) -> (4,4,0), radius 0.1: each end disk spans 0.1·sqrt(1/2)
    // in x and y and 0.1 in z. One box: extents 4.1414, 4.1414, 0.2, area
    // 37.6; four slices: 1.1414, 1.1414, 0.2, area 3.52 each, 14.1 in all
    // (37%); three slices 16.6, two 20.1: four it is.
    const auto cyl = cone({0, 0, 0}, 0.1, {4, 4, 0}, 0.1);
    std::vector<Bounds3> boxes;
    cyl->appendCoveringBoxes(0, IntersectOptions{}, boxes);
    REQUIRE(boxes.size() == 4);
    const double e = 0.1 * std::sqrt(0.5);
    Bounds3 whole({-e, -e, -0.1}, {4 + e, 4 + e, 0.1});
    const double margin = whole.padding();
    for (int i = 0; i < 4; ++i) {
        CAPTURE(i);
        checkVec(boxes[i].lo, Vec3{i - e - margin, i - e - margin, -0.1 - margin});
        checkVec(boxes[i].hi, Vec3{i + 1 + e + margin, i + 1 + e + margin, 0.1 + margin});
    }
    // In float precision the one box: a float hit may stray from the surface
    // by more than any margin fixed at build time.
    IntersectOptions inFloat;
    inFloat.precision = Precision::Float;
    std::vector<Bounds3> floatBoxes;
    cyl->appendCoveringBoxes(0, inFloat, floatBoxes);
    REQUIRE(floatBoxes.size() == 1);
    CHECK(floatBoxes[0].lo == cyl->bounds(0).lo);
    CHECK(floatBoxes[0].hi == cyl->bounds(0).hi);
    // The one box a renderer used before: the same box, padded.
    checkVec(cyl->bounds(0).lo, whole.padded().lo, 1e-15);
    checkVec(cyl->bounds(0).hi, whole.padded().hi, 1e-15);

    // Upright, or short and fat: one box, the padded bounds themselves.
    for (const auto& one : {cone({1, 2, 3}, 0.1, {1, 2, 9}, 0.1), cone({0, 0, 0}, 1, {1, 1, 0}, 1),
                            cone({0, 0, 0}, 2, {4, 4, 0}, 0.5, true)}) {
        boxes.clear();
        one->appendCoveringBoxes(0, IntersectOptions{}, boxes);
        REQUIRE(boxes.size() == 1);
        CHECK(boxes[0].lo == one->bounds(0).lo);
        CHECK(boxes[0].hi == one->bounds(0).hi);
    }
}

TEST_CASE("cone: covering boxes contain every surface point and stay inside the bounds") {
    // Random cylinders, cones and truncated cones, capped, in every
    // orientation: points of the side and of both caps each lie in some box,
    // and every box lies in bounds() (never a looser cover).
    SplitMix64 rng(2026);
    int split = 0;
    for (int shape = 0; shape < 300; ++shape) {
        const Vec3 base = rng.point(-50, 50);
        const Vec3 axis = rng.direction() * rng.uniform(0.5, 20);
        const double r0 = rng.uniform(0.01, 1.0);
        const double r1 = shape % 3 == 0 ? r0 : shape % 3 == 1 ? 0.0 : rng.uniform(0.01, 1.0);
        const auto c = cone(base, r0, base + axis, r1, true);
        const auto& solid = static_cast<const Cone&>(*c);
        std::vector<Bounds3> boxes;
        solid.appendCoveringBoxes(0, IntersectOptions{}, boxes);
        REQUIRE(!boxes.empty());
        REQUIRE(boxes.size() <= size_t(Cone::kMaxCoveringBoxes));
        split += boxes.size() > 1;
        const Bounds3 whole = solid.bounds();
        for (const Bounds3& b : boxes) {
            // Within the whole box up to rounding of the slice ends.
            const double slack = 1e-12 * (1 + maxComponent(abs(whole.hi)));
            CHECK(b.lo.x >= whole.lo.x - slack);
            CHECK(b.lo.y >= whole.lo.y - slack);
            CHECK(b.lo.z >= whole.lo.z - slack);
            CHECK(b.hi.x <= whole.hi.x + slack);
            CHECK(b.hi.y <= whole.hi.y + slack);
            CHECK(b.hi.z <= whole.hi.z + slack);
        }
        const Frame f = Frame::fromNormal(solid.axis());
        for (int k = 0; k < 200; ++k) {
            const double phi = rng.uniform(0, 2 * 3.141592653589793);
            const int part = k % 4;  // side twice as often as each cap
            const double z = part == 2 ? 0.0 : part == 3 ? solid.height()
                                                         : rng.uniform(0, solid.height());
            const double rz = r0 + (r1 - r0) * (z / solid.height());
            const double rho = part >= 2 ? rng.uniform(0, rz) : rz;
            const Vec3 p =
                base + f.n * z + f.t * (rho * std::cos(phi)) + f.b * (rho * std::sin(phi));
            bool inside = false;
            for (const Bounds3& b : boxes) inside = inside || b.contains(p);
            CAPTURE(shape);
            CAPTURE(k);
            CHECK(inside);
        }
    }
    CHECK(split > 100);  // most of these long shapes are split
}
