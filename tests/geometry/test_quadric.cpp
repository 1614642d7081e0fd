// General quadrics: the paraboloid of NUMERICS.md §4 (17) (a = 0, linear
// root), a sphere written as a quadric against makeSphere, ellipsoids (derived
// bounds), hyperboloids with clip-box rejection of either root, degenerate
// cases and validation.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/geometry_test_helpers.h"
#include "geometry/primitives.h"
#include "geometry/quadric.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

QuadricParams coefficients(double A, double B, double C, double D, double E, double F, double G,
                           double H, double I, double J) {
    return QuadricParams{A, B, C, D, E, F, G, H, I, J, Bounds3{}, false};
}

QuadricParams clipped(QuadricParams p, Vec3 lo, Vec3 hi) {
    p.clip = Bounds3(lo, hi);
    p.hasClip = true;
    return p;
}
}  // namespace

TEST_CASE("quadric: paraboloid z = x² + y² hit along its axis (a = 0)") {
    // Q = x² + y² - z. From (0.3, 0.4, 10) along -z: a = dᵀMd = 0, h = d·(M o + g/2) = 0.5,
    // c = Q(o) = 0.25 - 10 = -9.75: the linear root t = -c / (2h) = 9.75, at z = 0.25.
    // The ray starts inside the bowl (Q < 0) and leaves it: a back-face hit.
    auto p =
        makeQuadric(clipped(coefficients(1, 1, 0, 0, 0, 0, 0, 0, -1, 0), {-2, -2, -1}, {2, 2, 4}));
    const Ray ray{{0.3, 0.4, 10}, {0, 0, -1}};
    CHECK_FALSE(intersect1(*p, ray, 0, kInf));  // one-sided: back face
    p->setSidedness(Sidedness::Both);
    for (Precision prec : {Precision::Double, Precision::Float}) {
        const IntersectOptions opt = withPrecision(prec);
        const auto hit = intersect1(*p, ray, 0, kInf, opt);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(9.75).epsilon(prec == Precision::Double ? 1e-15 : 1e-6));
        const SurfaceGeometry g = surface1(*p, ray, *hit, opt);
        // Gradient (2x, 2y, -1) = (0.6, 0.8, -1): outward points down and out of the bowl.
        const Vec3 n = normalize(Vec3{0.6, 0.8, -1});
        CHECK(g.ng.x == doctest::Approx(n.x).epsilon(1e-6));
        CHECK(g.ng.z == doctest::Approx(n.z).epsilon(1e-6));
        CHECK_FALSE(g.frontFace);
    }
    // Negated coefficients turn it inside out: the same ray is a front-face hit.
    auto inv =
        makeQuadric(clipped(coefficients(-1, -1, 0, 0, 0, 0, 0, 0, 1, 0), {-2, -2, -1}, {2, 2, 4}));
    const auto hit = intersect1(*inv, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(9.75).epsilon(1e-15));
    CHECK(surface1(*inv, ray, *hit).frontFace);
}

TEST_CASE("quadric: sphere as a quadric equals makeSphere") {
    // (x-1)² + (y-2)² + (z-3)² - 4 = x² + y² + z² - 2x - 4y - 6z + 10. No clip box: the
    // ellipsoid box is derived.
    auto q = makeQuadric(coefficients(1, 1, 1, 0, 0, 0, -2, -4, -6, 10));
    auto s = makeSphere({1, 2, 3}, 2);
    const Bounds3 qb = q->bounds(), sb = s->bounds();
    CHECK(qb.lo.x == doctest::Approx(sb.lo.x).epsilon(1e-12));
    CHECK(qb.hi.z == doctest::Approx(sb.hi.z).epsilon(1e-12));
    test::Rng rng(21);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 o = Vec3{1, 2, 3} + rng.direction() * rng.uniform(0.1, 8);
        const Vec3 target = Vec3{1, 2, 3} + rng.direction() * 2.5;
        const Ray ray{o, (target - o) * rng.uniform(0.5, 2)};
        for (Sidedness side : {Sidedness::Outside, Sidedness::Inside, Sidedness::Both}) {
            q->setSidedness(side);
            s->setSidedness(side);
            const auto hq = intersect1(*q, ray, 0, kInf);
            const auto hs = intersect1(*s, ray, 0, kInf);
            REQUIRE(hq.has_value() == hs.has_value());
            if (!hq) continue;
            ++hits;
            CHECK(hq->t == doctest::Approx(hs->t).epsilon(1e-9));
            const SurfaceGeometry gq = surface1(*q, ray, *hq), gs = surface1(*s, ray, *hs);
            CHECK(gq.frontFace == gs.frontFace);
            CHECK(dot(gq.ng, gs.ng) > 1 - 1e-9);
        }
    }
    CHECK(hits > 2000);
}

TEST_CASE("quadric: ellipsoid hits, derived bounds, clip ∩ derived") {
    // x²/4 + y² + z²/9 = 1: semi-axes 2, 1, 3. From (-5,0,0) along +x: x = -2 at t = 3,
    // normal -x. From (0,0,-5) along +z: z = -3 at t = 2.
    const QuadricParams e = coefficients(0.25, 1, 1.0 / 9, 0, 0, 0, 0, 0, 0, -1);
    auto q = makeQuadric(e);
    const Ray rx{{-5, 0, 0}, {1, 0, 0}};
    const auto hx = intersect1(*q, rx, 0, kInf);
    REQUIRE(hx);
    CHECK(hx->t == doctest::Approx(3.0).epsilon(1e-15));
    CHECK(surface1(*q, rx, *hx).ng == Vec3{-1, 0, 0});
    CHECK(intersect1(*q, Ray{{0, 0, -5}, {0, 0, 1}}, 0, kInf)->t == doctest::Approx(2.0));
    const Bounds3 b = q->bounds();
    CHECK(b.hi.x == doctest::Approx(2.0).epsilon(1e-6));
    CHECK(b.hi.x >= 2.0);
    CHECK(b.lo.y <= -1.0);
    CHECK(b.hi.z == doctest::Approx(3.0).epsilon(1e-6));
    // With a clip box x ∈ [-1, 5]: bounds become x ∈ [-1, 2]; the -x hit is clipped away
    // and the ray from -x now finds nothing front-facing (the far root is a back face).
    auto c = makeQuadric(clipped(e, {-1, -5, -5}, {5, 5, 5}));
    CHECK(c->bounds().lo.x == doctest::Approx(-1.0).epsilon(1e-6));
    CHECK(c->bounds().hi.x == doctest::Approx(2.0).epsilon(1e-6));
    CHECK_FALSE(intersect1(*c, rx, 0, kInf));
    c->setSidedness(Sidedness::Both);
    CHECK(intersect1(*c, rx, 0, kInf)->t == doctest::Approx(7.0).epsilon(1e-15));
}

TEST_CASE("quadric: rotated ellipsoid box is tight (cross terms)") {
    // x² + y² + z² + xy + 0.5 yz - 1 = 0 is positive definite. Sample its surface along
    // rays from the centre; the derived box contains all samples and is tight.
    auto q = makeQuadric(coefficients(1, 1, 1, 1, 0, 0.5, 0, 0, 0, -1));
    q->setSidedness(Sidedness::Both);
    const Bounds3 b = q->bounds();
    test::Rng rng(8);
    Bounds3 samples;
    for (int i = 0; i < 20000; ++i) {
        const Ray ray{{0, 0, 0}, rng.direction()};
        const auto hit = intersect1(*q, ray, 0, kInf);
        REQUIRE(hit);
        samples.expand(ray.at(hit->t));
    }
    CHECK(b.contains(samples.lo));
    CHECK(b.contains(samples.hi));
    CHECK(maxComponent(abs(b.hi - samples.hi)) < 0.01);
    CHECK(maxComponent(abs(b.lo - samples.lo)) < 0.01);
}

TEST_CASE("quadric: hyperboloid of one sheet") {
    // x² + y² - z² = 1 in [-2,2]³. From (-5,0,0) along +x: x = -1 at t = 4 (front),
    // x = 1 at t = 6 (back). At z = 1.5, ρ = sqrt(3.25): t = 5 - 1.80277...
    auto q =
        makeQuadric(clipped(coefficients(1, 1, -1, 0, 0, 0, 0, 0, 0, -1), {-2, -2, -2}, {2, 2, 2}));
    const Ray r0{{-5, 0, 0}, {1, 0, 0}};
    const auto h0 = intersect1(*q, r0, 0, kInf);
    REQUIRE(h0);
    CHECK(h0->t == doctest::Approx(4.0).epsilon(1e-15));
    CHECK(surface1(*q, r0, *h0).ng == Vec3{-1, 0, 0});
    const auto h1 = intersect1(*q, Ray{{-5, 0, 1.5}, {1, 0, 0}}, 0, kInf);
    REQUIRE(h1);
    CHECK(h1->t == doctest::Approx(5 - std::sqrt(3.25)).epsilon(1e-15));
    // At z = 1.9 both roots (x = ±2.147) lie outside the box: miss.
    q->setSidedness(Sidedness::Both);
    CHECK_FALSE(intersect1(*q, Ray{{-5, 0, 1.9}, {1, 0, 0}}, 0, kInf));
    q->setSidedness(Sidedness::Inside);
    CHECK(intersect1(*q, r0, 0, kInf)->t == doctest::Approx(6.0).epsilon(1e-15));
}

TEST_CASE("quadric: hyperboloid of two sheets, near root clipped, far root kept") {
    // z² - x² - y² = 1, clip z ∈ [0, 3] (upper sheet only). From (0,0,-5) along +z the roots
    // are z = -1 (t = 4, outside the box) and z = 1 (t = 6, inside): the far root is the hit.
    auto q =
        makeQuadric(clipped(coefficients(-1, -1, 1, 0, 0, 0, 0, 0, 0, -1), {-3, -3, 0}, {3, 3, 3}));
    q->setSidedness(Sidedness::Both);
    const auto hit = intersect1(*q, Ray{{0, 0, -5}, {0, 0, 1}}, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == doctest::Approx(6.0).epsilon(1e-15));
    // From above: z = 1 first (t = 4), front facing (gradient (0,0,2z) against d).
    q->setSidedness(Sidedness::Outside);
    const Ray down{{0, 0, 5}, {0, 0, -1}};
    const auto top = intersect1(*q, down, 0, kInf);
    REQUIRE(top);
    CHECK(top->t == doctest::Approx(4.0).epsilon(1e-15));
    CHECK(surface1(*q, down, *top).frontFace);
}

TEST_CASE("quadric: degenerate linear quadric (a plane) and the cone's apex") {
    // I z + J = z - 2 (a plane) in [-1,1]² × [1,3]: from (0,0,5) along -z: a = 0, h = -0.5,
    // c = 3, t = -c / (2h) = 3; front (gradient +z). Parallel ray: a = h = 0, miss.
    auto plane =
        makeQuadric(clipped(coefficients(0, 0, 0, 0, 0, 0, 0, 0, 1, -2), {-1, -1, 1}, {1, 1, 3}));
    const Ray ray{{0.5, 0.5, 5}, {0, 0, -1}};
    const auto hit = intersect1(*plane, ray, 0, kInf);
    REQUIRE(hit);
    CHECK(hit->t == 3.0);
    CHECK(surface1(*plane, ray, *hit).ng == Vec3{0, 0, 1});
    plane->setSidedness(Sidedness::Both);
    CHECK_FALSE(intersect1(*plane, Ray{{0, 0, 2}, {1, 0, 0}}, -kInf, kInf));
    // Cone x² + y² - z² = 0: every line through the apex is a double root there; the
    // gradient vanishes and the normal falls back to facing the ray (finite, unit).
    auto cone =
        makeQuadric(clipped(coefficients(1, 1, -1, 0, 0, 0, 0, 0, 0, 0), {-1, -1, -1}, {1, 1, 1}));
    cone->setSidedness(Sidedness::Both);
    const Ray apex{{0, 0, 3}, {0, 0, -1}};
    const auto ha = intersect1(*cone, apex, 0, kInf);
    REQUIRE(ha);
    CHECK(ha->t == 3.0);
    const SurfaceGeometry g = surface1(*cone, apex, *ha);
    CHECK(g.ng == Vec3{0, 0, 1});
}

TEST_CASE("quadric: factory validation") {
    CHECK_THROWS_WITH_AS(makeQuadric(coefficients(1, 1, 0, 0, 0, 0, 0, 0, -1, 0)),
                         "quadric: unbounded surface needs a clip box", std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeQuadric(coefficients(1, 1, -1, 0, 0, 0, 0, 0, 0, -1)),
                         "quadric: unbounded surface needs a clip box", std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeQuadric(coefficients(1, 1, 1, 0, 0, 0, 0, 0, 0, 1)),
                         "quadric: ellipsoid has no real points (empty)", std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeQuadric(coefficients(0, 0, 0, 0, 0, 0, 0, 0, 0, 1)),
                         "quadric: coefficients A..I are all 0 (no surface)",
                         std::invalid_argument);
    CHECK_THROWS_WITH_AS(makeQuadric(coefficients(1, std::nan(""), 1, 0, 0, 0, 0, 0, 0, -1)),
                         "quadric: B must be finite (got nan)", std::invalid_argument);
    QuadricParams bad = coefficients(1, 1, 0, 0, 0, 0, 0, 0, -1, 0);
    bad.hasClip = true;  // default Bounds3 is empty (lo = +inf)
    CHECK_THROWS_AS(makeQuadric(bad), std::invalid_argument);
    bad.clip = Bounds3({0, 0, 0}, {1, 1, kInf});
    CHECK_THROWS_AS(makeQuadric(bad), std::invalid_argument);
    auto ok =
        makeQuadric(clipped(coefficients(1, 1, 0, 0, 0, 0, 0, 0, -1, 0), {-1, -1, 0}, {1, 1, 2}));
    CHECK(ok->bounds().finite());
    CHECK(std::string(ok->kind()) == "quadric");
}
