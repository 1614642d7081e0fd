// Planar polygons: hand-computed hits and normals in the three coordinate
// planes, collinear leading vertices, fill rules on a pentagram, per-vertex
// normals, validation, and the watertightness measurement (NUMERICS.md §3.4,
// §4 (8)-(13)): a fan of quads tiling a square, rays exactly through the
// shared edges and the shared centre vertex.

#include <doctest/doctest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/geometry_test_helpers.h"
#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "shape_queries.h"

using namespace raylab;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

std::unique_ptr<Shape> polygon(std::vector<Vec3> v, PolygonTest test,
                               FillRule rule = FillRule::EvenOdd) {
    PolygonParams p;
    p.vertices = std::move(v);
    p.test = test;
    p.rule = rule;
    return makePolygon(p);
}

const std::array<PolygonTest, 2> kTests{PolygonTest::Projected, PolygonTest::Watertight};
const std::array<Precision, 2> kPrecisions{Precision::Double, Precision::Float};
}  // namespace

TEST_CASE("polygon: unit square in the XY plane") {
    // CCW seen from +z: Newell normal +z. From (0.25, 0.5, 1) along -z: t = 1.
    for (PolygonTest test : kTests) {
        for (Precision prec : kPrecisions) {
            auto sq = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, test);
            const IntersectOptions opt = withPrecision(prec);
            const Ray ray{{0.25, 0.5, 1}, {0, 0, -1}};
            const auto hit = intersect1(*sq, ray, 0, kInf, opt);
            REQUIRE(hit);
            CHECK(hit->t == 1.0);
            const SurfaceGeometry g = surface1(*sq, ray, *hit, opt);
            CHECK(g.ng == Vec3{0, 0, 1});
            CHECK(g.ns == Vec3{0, 0, 1});
            CHECK(g.p == Vec3{0.25, 0.5, 0});
            CHECK(g.frontFace);
            CHECK_FALSE(intersect1(*sq, Ray{{1.5, 0.5, 1}, {0, 0, -1}}, 0, kInf, opt));
            CHECK_FALSE(intersect1(*sq, Ray{{0.5, -0.01, 1}, {0, 0, -1}}, 0, kInf, opt));
            // Back face (from below): rejected by the default one-sided rule.
            CHECK_FALSE(intersect1(*sq, Ray{{0.5, 0.5, -1}, {0, 0, 1}}, 0, kInf, opt));
            sq->setSidedness(Sidedness::Both);
            const Ray below{{0.5, 0.5, -1}, {0, 0, 1}};
            const auto back = intersect1(*sq, below, 0, kInf, opt);
            REQUIRE(back);
            CHECK_FALSE(surface1(*sq, below, *back, opt).frontFace);
            CHECK(surface1(*sq, below, *back, opt).ng == Vec3{0, 0, 1});
        }
    }
}

TEST_CASE("polygon: squares in the YZ and XZ planes") {
    for (PolygonTest test : kTests) {
        // x = 2, CCW seen from +x: (v1 - v0) × (v2 - v0) = (0,1,0) × (0,1,1) = (1,0,0).
        // From (5, 0.3, 0.6) along -x: t = 3.
        auto yz = polygon({{2, 0, 0}, {2, 1, 0}, {2, 1, 1}, {2, 0, 1}}, test);
        const Ray r1{{5, 0.3, 0.6}, {-1, 0, 0}};
        const auto h1 = intersect1(*yz, r1, 0, kInf);
        REQUIRE(h1);
        CHECK(h1->t == 3.0);
        CHECK(surface1(*yz, r1, *h1).ng == Vec3{1, 0, 0});
        CHECK_FALSE(intersect1(*yz, Ray{{5, 1.3, 0.6}, {-1, 0, 0}}, 0, kInf));
        // y = -1, CCW seen from +y: (0,0,1) × (1,0,1) = (0,1,0). From (0.5, 3, 0.5) along
        // (0,-2,0): distance 4, t = 2.
        auto xz = polygon({{0, -1, 0}, {0, -1, 1}, {1, -1, 1}, {1, -1, 0}}, test);
        const Ray r2{{0.5, 3, 0.5}, {0, -2, 0}};
        const auto h2 = intersect1(*xz, r2, 0, kInf);
        REQUIRE(h2);
        CHECK(h2->t == 2.0);
        CHECK(surface1(*xz, r2, *h2).ng == Vec3{0, 1, 0});
        CHECK_FALSE(intersect1(*xz, Ray{{0.5, 3, 1.5}, {0, -2, 0}}, 0, kInf));
    }
}

TEST_CASE("polygon: oblique ray and tilted polygon") {
    // Triangle in the plane x + y + z = 1 (normal (1,1,1)/√3, CCW from outside).
    // Ray from the origin-side point (0.2, 0.2, -1) along (0, 0, 1): hits z = 0.6 at t = 1.6,
    // (0.2, 0.2, 0.6) is inside (all barycentrics positive). The ray arrives from the
    // back (d·n > 0); from (0.2, 0.2, 2) along -z it is front-facing at t = 1.4.
    for (PolygonTest test : kTests) {
        auto tri = polygon({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, test);
        const auto hit = intersect1(*tri, Ray{{0.2, 0.2, 2}, {0, 0, -1}}, 0, kInf);
        REQUIRE(hit);
        CHECK(hit->t == doctest::Approx(1.4).epsilon(1e-15));
        CHECK_FALSE(intersect1(*tri, Ray{{0.2, 0.2, -1}, {0, 0, 1}}, 0, kInf));
        CHECK_FALSE(intersect1(*tri, Ray{{0.6, 0.6, 2}, {0, 0, -1}}, 0, kInf));  // x + y > 1
        CHECK(tri->bounds().contains({0.2, 0.2, 0.6}));
    }
}

TEST_CASE("polygon: collinear leading vertices give the right Newell normal") {
    // (0,0),(1,0),(2,0) are collinear: a normal from the first three vertices would be zero.
    const std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    const Vec3 n = newellNormal(v);
    CHECK(n.x == 0);
    CHECK(n.y == 0);
    CHECK(n.z == doctest::Approx(8.0));  // twice the area 4
    for (PolygonTest test : kTests) {
        auto p = polygon(v, test);
        const Ray ray{{1.5, 0.5, 3}, {0, 0, -1}};
        const auto hit = intersect1(*p, ray, 0, kInf);
        REQUIRE(hit);
        CHECK(surface1(*p, ray, *hit).ng == Vec3{0, 0, 1});
    }
}

TEST_CASE("polygon: rays parallel to the plane or in it miss without NaN") {
    for (PolygonTest test : kTests) {
        auto sq = polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, test);
        sq->setSidedness(Sidedness::Both);
        CHECK_FALSE(intersect1(*sq, Ray{{-1, 0.5, 0}, {1, 0, 0}}, -kInf, kInf));  // in the plane
        CHECK_FALSE(intersect1(*sq, Ray{{-1, 0.5, 1}, {1, 0, 0}}, 0, kInf));      // above
        CHECK_FALSE(intersect1(*sq, Ray{{0.5, 0.5, 1}, {0, 0, 0}}, 0, kInf));     // no direction
    }
}

TEST_CASE("polygon: concave L shape") {
    // L: the square [0,2]² minus [1,2]². (1.5, 1.5) is in the notch, (0.5, 1.5) inside.
    for (PolygonTest test : kTests) {
        for (FillRule rule : {FillRule::EvenOdd, FillRule::NonZero}) {
            auto l = polygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
                             test, rule);
            CHECK(intersect1(*l, Ray{{0.5, 1.5, 1}, {0, 0, -1}}, 0, kInf));
            CHECK(intersect1(*l, Ray{{1.5, 0.5, 1}, {0, 0, -1}}, 0, kInf));
            CHECK_FALSE(intersect1(*l, Ray{{1.5, 1.5, 1}, {0, 0, -1}}, 0, kInf));
        }
    }
}

TEST_CASE("polygon: pentagram centre is inside under NonZero, outside under EvenOdd") {
    // Star through the pentagon vertices P_k = (cos(90° + 72°k), sin(90° + 72°k)) in the
    // order 0, 2, 4, 1, 3: it winds twice around the centre (winding 2, two crossings).
    std::vector<Vec3> star;
    for (int k : {0, 2, 4, 1, 3}) {
        const double a = kPi / 2 + 2 * kPi * k / 5;
        star.push_back({std::cos(a), std::sin(a), 0});
    }
    // Tip of P_0: on the axis (0, 0.8), winding 1. Notch between tips: the inner pentagon's
    // vertices are at radius cos 72° / cos 36° ≈ 0.382, so (0.5·cos 54°, 0.5·sin 54°)...
    // is between the tips of P_0 and P_4 (directions 90° and 18°): outside.
    const Ray centre{{0, 0, 1}, {0, 0, -1}};
    const Ray tip{{0, 0.8, 1}, {0, 0, -1}};
    const Ray notch{{0.5 * std::cos(54 * kPi / 180), 0.5 * std::sin(54 * kPi / 180), 1},
                    {0, 0, -1}};
    for (PolygonTest test : kTests) {
        auto nonzero = polygon(star, test, FillRule::NonZero);
        auto evenodd = polygon(star, test, FillRule::EvenOdd);
        CHECK(intersect1(*nonzero, centre, 0, kInf));
        CHECK_FALSE(intersect1(*evenodd, centre, 0, kInf));
        CHECK(intersect1(*nonzero, tip, 0, kInf));
        CHECK(intersect1(*evenodd, tip, 0, kInf));
        CHECK_FALSE(intersect1(*nonzero, notch, 0, kInf));
        CHECK_FALSE(intersect1(*evenodd, notch, 0, kInf));
    }
}

TEST_CASE("polygon: per-vertex normals are interpolated (mean-value = barycentric on a triangle)") {
    // On a triangle mean-value coordinates are the barycentric coordinates. Vertices
    // (0,0,0), (1,0,0), (0,1,0); the point (0.3, 0.5) has barycentrics (0.2, 0.3, 0.5).
    PolygonParams p;
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    p.normals = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}};  // normalised by the factory
    auto tri = makePolygon(p);
    const Vec3 n0{0, 0, 1}, n1 = normalize(Vec3{1, 0, 1}), n2 = normalize(Vec3{0, 1, 1});

    const Ray ray{{0.3, 0.5, 1}, {0, 0, -1}};
    const auto hit = intersect1(*tri, ray, 0, kInf);
    REQUIRE(hit);
    const SurfaceGeometry g = surface1(*tri, ray, *hit);
    const Vec3 expected = normalize(n0 * 0.2 + n1 * 0.3 + n2 * 0.5);
    CHECK(g.ns.x == doctest::Approx(expected.x).epsilon(1e-12));
    CHECK(g.ns.y == doctest::Approx(expected.y).epsilon(1e-12));
    CHECK(g.ns.z == doctest::Approx(expected.z).epsilon(1e-12));
    CHECK(g.ng == Vec3{0, 0, 1});

    // Edge midpoint (0.5, 0): halfway between n0 and n1. At vertex 2: n2.
    const Ray edge{{0.5, 0, 1}, {0, 0, -1}};
    const Vec3 mid = normalize(n0 + n1);
    const Vec3 ge = surface1(*tri, edge, ShapeHit{1.0, 0, 0}).ns;
    CHECK(ge.x == doctest::Approx(mid.x).epsilon(1e-12));
    CHECK(ge.z == doctest::Approx(mid.z).epsilon(1e-12));
    const Ray vertex{{0, 1, 1}, {0, 0, -1}};
    const Vec3 gv = surface1(*tri, vertex, ShapeHit{1.0, 0, 0}).ns;
    CHECK(gv.y == doctest::Approx(n2.y).epsilon(1e-12));
    CHECK(gv.z == doctest::Approx(n2.z).epsilon(1e-12));

    // Square: by symmetry its centre gets the normalised mean of the four normals.
    PolygonParams q;
    q.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    q.normals = {{-1, -1, 2}, {1, -1, 2}, {1, 1, 2}, {-1, 1, 4}};
    auto sq = makePolygon(q);
    const Vec3 sum = normalize(Vec3{-1, -1, 2}) + normalize(Vec3{1, -1, 2}) +
                     normalize(Vec3{1, 1, 2}) + normalize(Vec3{-1, 1, 4});
    const Vec3 c = surface1(*sq, Ray{{1, 1, 1}, {0, 0, -1}}, ShapeHit{1.0, 0, 0}).ns;
    CHECK(c.x == doctest::Approx(normalize(sum).x).epsilon(1e-12));
    CHECK(c.y == doctest::Approx(normalize(sum).y).epsilon(1e-12));
}

TEST_CASE("polygon: validation") {
    PolygonParams p;
    p.vertices = {{0, 0, 0}, {1, 0, 0}};
    CHECK_THROWS_WITH_AS(makePolygon(p), "polygon: needs at least 3 vertices (got 2)",
                         std::invalid_argument);
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 0, 0}};
    CHECK_THROWS_WITH_AS(makePolygon(p), "polygon: fewer than 3 distinct vertices (got 2)",
                         std::invalid_argument);
    p.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
    CHECK_THROWS_WITH_AS(makePolygon(p), "polygon: vertices are collinear (zero area)",
                         std::invalid_argument);
    // A square with one corner lifted by 0.1 (diagonal √2·... tolerance ~3e-5): not planar.
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.1}, {0, 1, 0}};
    try {
        makePolygon(p);
        FAIL("non-planar polygon accepted");
    } catch (const std::invalid_argument& e) {
        CHECK(std::string(e.what()).find("polygon: vertices are not coplanar") == 0);
    }
    // ... lifted by 1e-7: within tolerance, accepted.
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 1e-7}, {0, 1, 0}};
    CHECK_NOTHROW(makePolygon(p));
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, std::nan(""), 0}};
    CHECK_THROWS_AS(makePolygon(p), std::invalid_argument);
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
    p.normals = {{0, 0, 1}, {0, 0, 1}};
    CHECK_THROWS_WITH_AS(makePolygon(p), "polygon: 2 vertex normals for 3 vertices",
                         std::invalid_argument);
    p.normals = {{0, 0, 1}, {0, 0, 0}, {0, 0, 1}};
    CHECK_THROWS_AS(makePolygon(p), std::invalid_argument);
    // A closing vertex equal to the first is dropped, not an error.
    p.normals.clear();
    p.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}};
    auto ok = makePolygon(p);
    CHECK(static_cast<const Polygon&>(*ok).vertices().size() == 3);
    CHECK(ok->bounds().finite());
    CHECK(std::string(ok->kind()) == "polygon");
}

namespace {
/// Four quads (centre, edge midpoint, corner, next edge midpoint) tiling a square of
/// half-size 1, rotated and moved off the origin so that the shared edges have general
/// orientations and the coordinates round. All share the exact same vertex values.
struct Fan {
    std::vector<std::unique_ptr<Shape>> quads;
    IntersectOptions opt;  ///< the arithmetic the quads are intersected in
    Vec3 centre;
    std::array<Vec3, 4> mids;
    Vec3 normal;
};

Fan makeFan(PolygonTest test, Precision precision) {
    const Vec3 origin{3.7, -12.1, 5.3};
    const Vec3 n = normalize(Vec3{0.3, -0.5, 0.8});
    const Vec3 t = test::perpendicular(n);
    const Vec3 b = cross(n, t);
    const auto at = [&](double x, double y) { return origin + t * x + b * y; };
    Fan fan;
    fan.centre = at(0.013, -0.021);  // not exactly the middle
    fan.normal = n;
    const std::array<Vec3, 4> corners{at(1, 1), at(-1, 1), at(-1, -1), at(1, -1)};
    fan.mids = {at(0.07, 1), at(-1, 0.11), at(-0.05, -1), at(1, -0.13)};
    for (int k = 0; k < 4; ++k) {
        PolygonParams p;
        // CCW seen from +n: centre, mid k (top edge side ...), corner, next mid.
        p.vertices = {fan.centre, fan.mids[(k + 3) % 4], corners[k], fan.mids[k]};
        p.test = test;
        fan.quads.push_back(makePolygon(p));
    }
    fan.opt = withPrecision(precision);
    return fan;
}

struct FanResult {
    int rays = 0, zero = 0, one = 0, many = 0;
};

/// Rays from random points above the fan through `target` (a point on a shared edge
/// or the centre vertex); counts how many quads each ray hits.
FanResult shootFan(const Fan& fan, test::Rng& rng, int count, bool centreOnly) {
    FanResult r;
    for (int i = 0; i < count; ++i) {
        Vec3 target = fan.centre;
        if (!centreOnly) {
            const double s = rng.uniform(0.001, 0.999);
            target = fan.centre + (fan.mids[i % 4] - fan.centre) * s;
        }
        Vec3 dir = rng.direction();
        // Keep the origin on the front side, at least ~3° above the plane.
        const double up = dot(dir, fan.normal);
        if (up < 0.05) dir = dir + fan.normal * (0.05 + 2 * std::abs(up));
        const Vec3 o = target + dir * rng.uniform(0.5, 20);
        const Ray ray{o, target - o};
        int hits = 0;
        for (const auto& q : fan.quads) hits += intersect1(*q, ray, 0, kInf, fan.opt).has_value();
        ++r.rays;
        if (hits == 0)
            ++r.zero;
        else if (hits == 1)
            ++r.one;
        else
            ++r.many;
    }
    return r;
}
}  // namespace

TEST_CASE("polygon: watertight test hits exactly one quad of a fan on shared edges/vertex") {
    // The ray-space test decides each edge from the exact sign of a function of the two
    // shared vertices' sheared coordinates (bit-identical in both neighbours), with a
    // symbolic tie-break: every ray through a shared edge or the shared centre hits
    // exactly one quad. The projected test is measured and reported, not required.
    const int kRays = 20000;
    for (Precision prec : kPrecisions) {
        for (PolygonTest t : kTests) {
            const Fan fan = makeFan(t, prec);
            test::Rng rng(99);
            const FanResult edge = shootFan(fan, rng, kRays, false);
            const FanResult vertex = shootFan(fan, rng, kRays, true);
            const std::string name = t == PolygonTest::Watertight ? "watertight" : "projected";
            const std::string pname = prec == Precision::Double ? "double" : "float";
            MESSAGE(name << " (" << pname << "): edge rays missing all quads "
                         << 100.0 * edge.zero / edge.rays << "%, hitting two "
                         << 100.0 * edge.many / edge.rays << "%; centre-vertex rays missing "
                         << 100.0 * vertex.zero / vertex.rays << "%, hitting 2+ "
                         << 100.0 * vertex.many / vertex.rays << "%");
            if (t == PolygonTest::Watertight) {
                CHECK(edge.one == edge.rays);
                CHECK(vertex.one == vertex.rays);
            }
        }
    }
}

TEST_CASE("polygon: watertight test with exact zeros (ray exactly through a vertex)") {
    // Dyadic coordinates and directions make the sheared 2D coordinates exact, so the ray
    // passes *exactly* through the shared vertex or edge: edge functions are exactly 0 and
    // only the tie-break decides. Six triangles and two quads around the vertex (0, 0, 0)
    // of the plane z = 0 (irregular angles, vertices on the axes included). The symbolic
    // perturbation makes it a point in general position: exactly one polygon, every time.
    const std::vector<Vec3> ring{{1, 0, 0},  {1, 0.75, 0}, {0, 1, 0},  {-0.5, 1, 0},
                                 {-1, 0, 0}, {-1, -1, 0},  {0, -1, 0}, {0.5, -0.25, 0}};
    const Vec3 centre{0, 0, 0};
    for (Precision prec : kPrecisions) {
        const IntersectOptions opt = withPrecision(prec);
        std::vector<std::unique_ptr<Shape>> fan;
        for (size_t k = 0; k < ring.size(); ++k) {
            std::vector<Vec3> v{centre, ring[k], ring[(k + 1) % ring.size()]};
            if (k % 4 == 1) v.insert(v.begin() + 2, (ring[k] + ring[(k + 1) % ring.size()]) * 0.5);
            fan.push_back(polygon(v, PolygonTest::Watertight));
        }
        // Targets: the centre vertex, points on the spokes, and spoke midpoints.
        std::vector<Vec3> targets{centre};
        for (const Vec3& r : ring) {
            targets.push_back(r * 0.5);
            targets.push_back(r * 0.25);
        }
        int rays = 0, exactlyOne = 0;
        for (const Vec3& target : targets) {
            for (double dx : {0.0, 1.0, -0.5, 0.25, -2.0}) {
                for (double dy : {0.0, 0.5, -1.0, 2.0}) {
                    const Vec3 d{dx, dy, -4};  // dominant axis z; shear factors are dyadic
                    const Ray ray{target - d * 2.0, d};
                    int hits = 0;
                    for (const auto& p : fan) hits += intersect1(*p, ray, 0, kInf, opt).has_value();
                    ++rays;
                    exactlyOne += hits == 1;
                }
            }
        }
        CHECK(rays == 340);
        CHECK(exactlyOne == rays);
    }
}

TEST_CASE("polygon: closed cube of quads, rays from inside through edges and corners") {
    // NUMERICS §4 (8): six quads (outward normals, seen from inside: back faces, so
    // Sidedness::Inside) around a cube moved off the origin. Rays from random interior
    // points exactly through points on the 12 edges and the 8 corners: the watertight test
    // hits exactly one face every time; the projected test's misses are reported.
    const Vec3 lo{-1.3, 2.1, 0.7}, hi{0.9, 3.6, 2.2};
    const auto corner = [&](int i) {
        return Vec3{i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
    };
    // Faces as corner indices, counter-clockwise seen from outside.
    const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const int edges[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                              {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (Precision prec : kPrecisions) {
        const IntersectOptions opt = withPrecision(prec);
        for (PolygonTest t : kTests) {
            std::vector<std::unique_ptr<Shape>> quads;
            for (const auto& f : faces) {
                auto q = polygon({corner(f[0]), corner(f[1]), corner(f[2]), corner(f[3])}, t);
                q->setSidedness(Sidedness::Inside);
                quads.push_back(std::move(q));
            }
            test::Rng rng(31);
            int rays[2] = {0, 0}, zero[2] = {0, 0}, many[2] = {0, 0};  // [0] edges, [1] corners
            for (int i = 0; i < 20000; ++i) {
                const Vec3 o{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y),
                             rng.uniform(lo.z, hi.z)};
                const int kind = i % 2;
                Vec3 target = corner((i / 2) % 8);
                if (kind == 0) {
                    const auto& e = edges[(i / 2) % 12];
                    const Vec3 a = corner(e[0]), b = corner(e[1]);
                    target = a + (b - a) * rng.uniform(0.01, 0.99);
                }
                int hits = 0;
                for (const auto& q : quads) {
                    hits += intersect1(*q, Ray{o, target - o}, 0, kInf, opt).has_value();
                }
                ++rays[kind];
                zero[kind] += hits == 0;
                many[kind] += hits > 1;
            }
            MESSAGE(std::string(t == PolygonTest::Watertight ? "watertight" : "projected")
                    << std::string(prec == Precision::Double ? " (double)" : " (float)")
                    << ": cube rays missing every face: edges " << 100.0 * zero[0] / rays[0]
                    << "%, corners " << 100.0 * zero[1] / rays[1] << "%; hitting 2+ faces: "
                    << "edges " << 100.0 * many[0] / rays[0] << "%, corners "
                    << 100.0 * many[1] / rays[1] << "%");
            if (t == PolygonTest::Watertight) {
                CHECK(zero[0] + zero[1] == 0);
                CHECK(many[0] + many[1] == 0);
            }
        }
    }
}

TEST_CASE("polygon: timing of the two inside tests (reported)") {
    // ns per intersect() on a 4-vertex quad and a 144-vertex concave gear-like face
    // (18 teeth, like SPD gears); the same 1000 rays for both tests. Indicative only:
    // tools/bench/primitive_bench.cpp (raylab bench primitives) is the real measurement.
    std::vector<Vec3> gear;
    for (int i = 0; i < 144; ++i) {
        const double a = 2 * kPi * i / 144;
        const double r = (i / 4) % 2 == 0 ? 1.0 : 0.8;
        gear.push_back({r * std::cos(a), r * std::sin(a), 0.5});
    }
    const std::vector<Vec3> quad{{-1, -1, 0.5}, {1, -1, 0.5}, {1, 1, 0.5}, {-1, 1, 0.5}};
    test::Rng rng(5);
    std::vector<Ray> rays;
    for (int i = 0; i < 1000; ++i) {
        rays.push_back({{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), 3},
                        {rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1), -1}});
    }
    for (int shape = 0; shape < 2; ++shape) {
        int hitsPerTest[2] = {0, 0};
        for (int k = 0; k < 2; ++k) {
            auto p = polygon(shape == 0 ? quad : gear, kTests[k]);
            int hits = 0;
            const auto start = std::chrono::steady_clock::now();
            for (int rep = 0; rep < 20; ++rep) {
                for (const Ray& r : rays) hits += intersect1(*p, r, 0, kInf).has_value();
            }
            const auto elapsed = std::chrono::steady_clock::now() - start;
            const double ns = std::chrono::duration<double, std::nano>(elapsed).count() / 20000;
            hitsPerTest[k] = hits / 20;
            MESSAGE(std::string(shape == 0 ? "quad " : "144-gon ")
                    << std::string(k == 0 ? "projected" : "watertight") << ": " << ns
                    << " ns/intersect (" << hits / 20 << "/1000 hit)");
        }
        // Random rays almost never graze an edge: both tests agree on them.
        CHECK(hitsPerTest[0] == hitsPerTest[1]);
        CHECK(hitsPerTest[0] > 300);
    }
}
