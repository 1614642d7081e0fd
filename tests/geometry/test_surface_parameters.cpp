// Surface parameters of every primitive (docs/scene-format.md, "Surface
// parameters"): hand-computed uv and derivatives at a few points, uv ranges
// and seams, and the derivatives against finite differences of surfaceAt:
// two hits a small step apart must satisfy
//   p' - p   ≈ dpdu Δu + dpdv Δv   and   ns' - ns ≈ dndu Δu + dndv Δv
// to first order, for the hits' own (Δu, Δv).

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "geometry/geometry_test_helpers.h"
#include "geometry/primitives.h"
#include "geometry/triangle_mesh.h"
#include "shape_queries.h"

using namespace raylab;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

void checkVec(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    CHECK(a.x == doctest::Approx(b.x).epsilon(eps).scale(1));
    CHECK(a.y == doctest::Approx(b.y).epsilon(eps).scale(1));
    CHECK(a.z == doctest::Approx(b.z).epsilon(eps).scale(1));
}

/// The complete surface record where the ray from `from` towards `target`
/// first hits primitive `prim` of `s` (both sides accepted).
std::optional<SurfaceGeometry> surfaceTowards(const Shape& s, uint32_t prim, const Vec3& from,
                                              const Vec3& target) {
    const Ray ray{from, target - from};
    const auto h = s.intersect(prim, ray, 0, kInf, {});
    if (!h) return std::nullopt;
    return s.surfaceAt(prim, ray, *h, {}, SurfaceDetail::Complete);
}

/// The point of the surface at `target`, straight from above along -normal.
SurfaceGeometry surfaceAtPoint(const Shape& s, uint32_t prim, const Vec3& target,
                               const Vec3& normal) {
    const auto g = surfaceTowards(s, prim, target + normal * 3.0, target);
    REQUIRE(g);
    return *g;
}

struct FiniteDifferenceStats {
    int samples = 0;
    double worstPosition = 0;  ///< |Δp - J Δuv| / |Δp|
    double worstNormal = 0;    ///< |Δn - Jn Δuv| / |Δp| · size
};

/// Hits the shape from random directions around `centre`, then again a small
/// step `h` (relative to `size`) along a random tangent, and compares the
/// change of p and ns with the derivatives' prediction. Samples whose Δu
/// crosses the seam, or whose first hit is rejected by `usable`, are skipped.
FiniteDifferenceStats finiteDifferences(const Shape& s, uint32_t prim, const Vec3& centre,
                                        double size, uint64_t seed,
                                        const std::function<bool(const SurfaceGeometry&)>& usable) {
    test::Rng rng(seed);
    FiniteDifferenceStats st;
    const double h = 1e-6 * size;
    for (int i = 0; i < 400 && st.samples < 60; ++i) {
        const Vec3 from = centre + rng.direction() * (4 * size);
        const Vec3 target = centre + rng.point(-0.4, 0.4) * size;
        const auto a = surfaceTowards(s, prim, from, target);
        if (!a || !usable(*a)) continue;
        // A step along a random tangent direction of the surface at a.
        const Vec3 tangent =
            normalize(normalize(a->dpdu) * rng.uniform(-1, 1) + normalize(a->dpdv) * rng.uniform(-1, 1));
        const auto b = surfaceTowards(s, prim, from, a->p + tangent * h);
        if (!b || !usable(*b)) continue;
        const Vec2 duv = b->uv - a->uv;
        if (std::abs(duv.x) > 0.25 || std::abs(duv.y) > 0.25) continue;  // across a seam
        const Vec3 dp = b->p - a->p;
        if (!(length(dp) > 0.1 * h)) continue;
        const Vec3 predicted = a->dpdu * duv.x + a->dpdv * duv.y;
        const Vec3 predictedN = a->dndu * duv.x + a->dndv * duv.y;
        st.worstPosition = std::max(st.worstPosition, length(dp - predicted) / length(dp));
        st.worstNormal =
            std::max(st.worstNormal, length((b->ns - a->ns) - predictedN) / length(dp) * size);
        ++st.samples;
    }
    return st;
}

bool always(const SurfaceGeometry&) { return true; }

/// Away from the poles of a spherical parametrisation (u is ill-defined there).
bool awayFromPoles(const SurfaceGeometry& g) { return g.uv.y > 0.02 && g.uv.y < 0.98; }

void checkFiniteDifferences(const std::string& name, const Shape& s, uint32_t prim,
                            const Vec3& centre, double size,
                            const std::function<bool(const SurfaceGeometry&)>& usable = always) {
    const FiniteDifferenceStats st = finiteDifferences(s, prim, centre, size, 7, usable);
    CAPTURE(name);
    MESSAGE(name << ": " << st.samples << " pairs, worst position residual " << st.worstPosition
                 << ", worst normal residual " << st.worstNormal);
    CHECK(st.samples >= 30);
    // First order in a step of 1e-6 of the size: residuals ~1e-6 (plus
    // rounding of the hit points, ~1e-10 relative to a 1e-6 step).
    CHECK(st.worstPosition < 1e-4);
    CHECK(st.worstNormal < 1e-4);
}

std::shared_ptr<TriangleMesh> singleTriangle(bool uvs, bool normals) {
    auto m = std::make_shared<TriangleMesh>();
    m->positions = {{0, 0, 0}, {2, 0, 0}, {0, 4, 0}};
    m->triangles = {{0, 1, 2}};
    if (uvs) m->uvs = {{0, 0}, {1, 0}, {0, 1}};
    if (normals) m->normals = {normalize(Vec3{-0.3, -0.2, 1}), {0, 0, 1}, normalize(Vec3{0.1, 0.4, 1})};
    return m;
}

}  // namespace

TEST_CASE("surface parameters: sphere, hand-computed (pole +y by default)") {
    // Frame around +y: t = +x, b = -z. At (1, 0, 0): φ = 0, θ = π/2 from the
    // pole: uv = (0, 0.5); dpdu = 2π (0, 0, -1), dpdv = π (0, 1, 0).
    auto s = makeSphere({0, 0, 0}, 1);
    const SurfaceGeometry g = surfaceAtPoint(*s, 0, {1, 0, 0}, {1, 0, 0});
    CHECK(g.uv.x == 0);
    CHECK(g.uv.y == doctest::Approx(0.5).epsilon(1e-15));
    checkVec(g.dpdu, {0, 0, -2 * kPi});
    checkVec(g.dpdv, {0, kPi, 0});
    // A unit sphere's normal derivatives equal the point's.
    checkVec(g.dndu, g.dpdu);
    checkVec(g.dndv, g.dpdv);
    // dpdu × dpdv points outward.
    CHECK(dot(cross(g.dpdu, g.dpdv), g.ng) > 0);
    // Radius 2, seen from -z: local (0, 1, 0) after the frame's b = -z, so φ = π/2.
    auto big = makeSphere({0, 0, 0}, 2);
    const SurfaceGeometry back = surfaceAtPoint(*big, 0, {0, 0, -2}, {0, 0, -1});
    CHECK(back.uv.x == doctest::Approx(0.25).epsilon(1e-15));
    checkVec(back.dpdu, {-4 * kPi, 0, 0});
    // North pole: v = 1; south pole: v = 0; everything finite.
    const SurfaceGeometry north = surfaceAtPoint(*s, 0, {0, 1, 0}, {0, 1, 0});
    CHECK(north.uv.y == 1.0);
    CHECK(isFinite(north.dpdu));
    CHECK(isFinite(north.dpdv));
    CHECK(surfaceAtPoint(*s, 0, {0, -1, 0}, {0, -1, 0}).uv.y == 0.0);
    // A pole along +z (pbrt's object space): the north pole is (0, 0, 1).
    auto z = makeSphere({0, 0, 0}, 1, {0, 0, 1});
    CHECK(surfaceAtPoint(*z, 0, {0, 0, 1}, {0, 0, 1}).uv.y == 1.0);
    CHECK(surfaceAtPoint(*z, 0, {1, 0, 0}, {1, 0, 0}).uv.x == 0.0);
}

TEST_CASE("surface parameters: uv ranges and the seam of the sphere") {
    auto s = makeSphere({1, 2, 3}, 1.5);
    test::Rng rng(11);
    for (int i = 0; i < 2000; ++i) {
        const Vec3 from = Vec3{1, 2, 3} + rng.direction() * 6;
        const auto g = surfaceTowards(*s, 0, from, Vec3{1, 2, 3} + rng.point(-1, 1));
        if (!g) continue;
        CHECK(g->uv.x >= 0);
        CHECK(g->uv.x < 1);
        CHECK(g->uv.y >= 0);
        CHECK(g->uv.y <= 1);
    }
    // Either side of the seam φ = 0 (the +x side, frame t = +x): u near 0 and near 1.
    const double e = 1e-6;
    const SurfaceGeometry above =
        surfaceAtPoint(*s, 0, Vec3{1, 2, 3} + normalize(Vec3{1, 0, -e}) * 1.5, {1, 0, 0});
    const SurfaceGeometry below =
        surfaceAtPoint(*s, 0, Vec3{1, 2, 3} + normalize(Vec3{1, 0, e}) * 1.5, {1, 0, 0});
    // b = -z: local y = -z, so z = -e is φ slightly above 0, z = +e slightly below 2π.
    CHECK(above.uv.x < 1e-6);
    CHECK(below.uv.x > 1 - 1e-6);
    CHECK(below.uv.x < 1);
}

TEST_CASE("surface parameters: cylinder, cone and caps, hand-computed") {
    ConeParams c;
    c.base = {0, 0, 0};
    c.apex = {0, 0, 2};
    c.baseRadius = c.apexRadius = 1;
    c.capped = true;
    auto cyl = makeCone(c);
    // Frame around +z: t = +x, b = +y. At (-1, 0, 1): φ = π, z = 1 of 2.
    const SurfaceGeometry side = surfaceAtPoint(*cyl, 0, {-1, 0, 1}, {-1, 0, 0});
    CHECK(side.uv.x == doctest::Approx(0.5).epsilon(1e-15));
    CHECK(side.uv.y == doctest::Approx(0.5).epsilon(1e-15));
    checkVec(side.dpdu, {0, -2 * kPi, 0});
    checkVec(side.dpdv, {0, 0, 2});
    checkVec(side.dndu, {0, -2 * kPi, 0});
    checkVec(side.dndv, {0, 0, 0});
    // Base cap at (0, 0.5, 0), seen from below: polar φ = π/2, ρ / r = 0.5.
    const SurfaceGeometry cap = surfaceAtPoint(*cyl, 0, {0, 0.5, 0}, {0, 0, -1});
    CHECK(cap.ng == Vec3{0, 0, -1});
    CHECK(cap.uv.x == doctest::Approx(0.25).epsilon(1e-15));
    CHECK(cap.uv.y == doctest::Approx(0.5).epsilon(1e-15));
    checkVec(cap.dpdu, {-kPi, 0, 0});
    checkVec(cap.dpdv, {0, 1, 0});
    // A cone from r = 2 at z = 0 to r = 0 at z = 4: slope k = -0.5. At (1, 0, 2)
    // (r = 1, φ = 0): dpdv = h (k, 0, 1) = (-2, 0, 4); n = (1, 0, 0.5) / |.|.
    ConeParams k;
    k.base = {0, 0, 0};
    k.apex = {0, 0, 4};
    k.baseRadius = 2;
    k.apexRadius = 0;
    auto cone = makeCone(k);
    const SurfaceGeometry cs = surfaceAtPoint(*cone, 0, {1, 0, 2}, normalize(Vec3{1, 0, 0.5}));
    CHECK(cs.uv.x == 0);
    CHECK(cs.uv.y == doctest::Approx(0.5).epsilon(1e-15));
    checkVec(cs.dpdu, {0, 2 * kPi, 0});
    checkVec(cs.dpdv, {-2, 0, 4});
    checkVec(cs.dndu, Vec3{0, 2 * kPi, 0} / std::sqrt(1.25));
}

TEST_CASE("surface parameters: disk, plane and polygon, hand-computed") {
    auto disk = makeDisk({0, 0, 0}, {0, 0, 1}, 2);
    const SurfaceGeometry d = surfaceAtPoint(*disk, 0, {0, 1, 0}, {0, 0, 1});
    CHECK(d.uv.x == doctest::Approx(0.25).epsilon(1e-15));
    CHECK(d.uv.y == doctest::Approx(0.5).epsilon(1e-15));
    checkVec(d.dpdu, {-2 * kPi, 0, 0});
    checkVec(d.dpdv, {0, 2, 0});
    CHECK(d.dndu == Vec3{});

    // Plane: scene units along the frame tangents (t = +x, b = +y for +z).
    auto plane = makePlane({1, 1, 0}, {0, 0, 1}, 100);
    const SurfaceGeometry p = surfaceAtPoint(*plane, 0, {4, 5, 0}, {0, 0, 1});
    CHECK(p.uv == Vec2{3, 4});
    CHECK(p.dpdu == Vec3{1, 0, 0});
    CHECK(p.dpdv == Vec3{0, 1, 0});

    // A 2 x 1 rectangle listed counter-clockwise from its lower-left corner:
    // u along the first edge over [0, 2], v along n × u over [0, 1].
    PolygonParams pp;
    pp.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
    auto quad = makePolygon(pp);
    const SurfaceGeometry q = surfaceAtPoint(*quad, 0, {1.5, 0.25, 0}, {0, 0, 1});
    CHECK(q.uv.x == doctest::Approx(0.75).epsilon(1e-15));
    CHECK(q.uv.y == doctest::Approx(0.25).epsilon(1e-15));
    checkVec(q.dpdu, {2, 0, 0});
    checkVec(q.dpdv, {0, 1, 0});
    // The same rectangle standing upright (in the x-z plane, facing -y): the
    // image's up (v) is +z.
    pp.vertices = {{0, 0, 0}, {2, 0, 0}, {2, 0, 1}, {0, 0, 1}};
    auto upright = makePolygon(pp);
    const SurfaceGeometry u = surfaceAtPoint(*upright, 0, {0.5, 0, 0.9}, {0, -1, 0});
    CHECK(u.uv.x == doctest::Approx(0.25).epsilon(1e-15));
    CHECK(u.uv.y == doctest::Approx(0.9).epsilon(1e-15));
}

TEST_CASE("surface parameters: triangles, from texture coordinates or pbrt's defaults") {
    // p0 (0,0,0) uv (0,0), p1 (2,0,0) uv (1,0), p2 (0,4,0) uv (0,1):
    // dpdu = (2,0,0), dpdv = (0,4,0); (1, 1, 0) has barycentrics (1/4, 1/2, 1/4).
    auto mesh = singleTriangle(true, false);
    const SurfaceGeometry g = surfaceAtPoint(*mesh, 0, {1, 1, 0}, {0, 0, 1});
    CHECK(g.uv.x == doctest::Approx(0.5).epsilon(1e-15));
    CHECK(g.uv.y == doctest::Approx(0.25).epsilon(1e-15));
    checkVec(g.dpdu, {2, 0, 0});
    checkVec(g.dpdv, {0, 4, 0});
    CHECK(g.dndu == Vec3{});
    // Without texture coordinates: (0,0), (1,0), (1,1), i.e. uv = (b1 + b2, b2).
    auto plain = singleTriangle(false, false);
    const SurfaceGeometry d = surfaceAtPoint(*plain, 0, {1, 1, 0}, {0, 0, 1});
    CHECK(d.uv.x == doctest::Approx(0.75).epsilon(1e-15));
    CHECK(d.uv.y == doctest::Approx(0.25).epsilon(1e-15));
    // p1 - p0 = dpdu, p2 - p1 = dpdv: dpdu = (2,0,0), dpdv = (-2,4,0).
    checkVec(d.dpdu, {2, 0, 0});
    checkVec(d.dpdv, {-2, 4, 0});
    // Texture coordinates without area: a tangent frame, still finite.
    auto flat = singleTriangle(true, false);
    flat->uvs = {{0.5, 0.5}, {0.5, 0.5}, {0.5, 0.5}};
    const SurfaceGeometry f = surfaceAtPoint(*flat, 0, {1, 1, 0}, {0, 0, 1});
    CHECK(isFinite(f.dpdu));
    CHECK(length(cross(f.dpdu, f.dpdv)) > 0.5);
}

TEST_CASE("surface parameters: the unit-sphere quadric is parametrised like a sphere") {
    QuadricParams p;
    p.A = p.B = p.C = 1;
    p.J = -1;
    auto q = makeQuadric(p);
    auto s = makeSphere({0, 0, 0}, 1);
    test::Rng rng(3);
    for (int i = 0; i < 50; ++i) {
        const Vec3 n = rng.direction();
        if (std::abs(n.y) > 0.95) continue;  // the poles' u is arbitrary
        const SurfaceGeometry a = surfaceAtPoint(*q, 0, n, n);
        const SurfaceGeometry b = surfaceAtPoint(*s, 0, n, n);
        CHECK(a.uv.x == doctest::Approx(b.uv.x).epsilon(1e-9));
        CHECK(a.uv.y == doctest::Approx(b.uv.y).epsilon(1e-9));
        checkVec(a.dpdu, b.dpdu, 1e-7);
        checkVec(a.dpdv, b.dpdv, 1e-7);
        checkVec(a.dndu, b.dndu, 1e-7);
    }
}

TEST_CASE("surface parameters: derivatives agree with finite differences of surfaceAt") {
    auto sphere = makeSphere({0.5, -1, 2}, 1.5, {0.3, 1, 0.2});
    sphere->setSidedness(Sidedness::Both);
    checkFiniteDifferences("sphere", *sphere, 0, {0.5, -1, 2}, 1.5, awayFromPoles);

    ConeParams c;
    c.base = {1, 0, 0};
    c.apex = {1.5, 3, 0.5};
    c.baseRadius = 1;
    c.apexRadius = 0.4;
    c.capped = true;
    auto cone = makeCone(c);
    cone->setSidedness(Sidedness::Both);
    // Side hits only (caps are separate charts): v strictly inside (0, 1) and
    // the normal not along the axis.
    const Vec3 axis = normalize(c.apex - c.base);
    checkFiniteDifferences("cone side", *cone, 0, {1.25, 1.5, 0.25}, 1.5,
                           [&](const SurfaceGeometry& g) { return std::abs(dot(g.ng, axis)) < 0.9; });
    checkFiniteDifferences("cone caps", *cone, 0, {1.25, 1.5, 0.25}, 1.5,
                           [&](const SurfaceGeometry& g) { return std::abs(dot(g.ng, axis)) > 0.999; });

    auto disk = makeDisk({0, 0, 1}, {0.2, 0.3, 1}, 2);
    disk->setSidedness(Sidedness::Both);
    checkFiniteDifferences("disk", *disk, 0, {0, 0, 1}, 2,
                           [](const SurfaceGeometry& g) { return g.uv.y > 0.05; });

    auto plane = makePlane({0, 1, 0}, {0.1, 1, -0.2}, 50);
    plane->setSidedness(Sidedness::Both);
    checkFiniteDifferences("plane", *plane, 0, {0, 1, 0}, 3);

    PolygonParams pp;
    pp.vertices = {{0, 0, 0}, {2, 0, 0.5}, {2, 1, 0.5}, {1, 0.4, 0.25}, {0, 1, 0}};
    pp.normals = {normalize(Vec3{-0.2, 0, 1}), normalize(Vec3{0, -0.3, 1}), {0, 0, 1},
                  normalize(Vec3{0.3, 0.2, 1}), normalize(Vec3{0.1, 0.2, 1})};
    auto poly = makePolygon(pp);
    poly->setSidedness(Sidedness::Both);
    checkFiniteDifferences("concave polygon with vertex normals", *poly, 0, {1, 0.5, 0.25}, 1.5);

    QuadricParams e;  // ellipsoid x²/4 + y² + z²/0.25 = 1 around (1, 1, 1)
    e.A = 0.25;
    e.B = 1;
    e.C = 4;
    e.G = -0.5;
    e.H = -2;
    e.I = -8;
    e.J = 0.25 + 1 + 4 - 1;
    auto ellipsoid = makeQuadric(e);
    ellipsoid->setSidedness(Sidedness::Both);
    checkFiniteDifferences("ellipsoid", *ellipsoid, 0, {1, 1, 1}, 1.5, awayFromPoles);

    QuadricParams h;  // hyperboloid of one sheet x² + z² - y² = 1, clipped
    h.A = 1;
    h.B = -1;
    h.C = 1;
    h.J = -1;
    h.clip = Bounds3({-3, -1, -3}, {3, 1, 3});
    h.hasClip = true;
    auto hyperboloid = makeQuadric(h);
    hyperboloid->setSidedness(Sidedness::Both);
    checkFiniteDifferences("hyperboloid", *hyperboloid, 0, {0, 0, 0}, 1.5, awayFromPoles);

    auto tri = singleTriangle(true, true);
    checkFiniteDifferences("triangle with uv and vertex normals", *tri, 0, {0.6, 1.2, 0}, 1.5);
    auto bare = singleTriangle(false, true);
    checkFiniteDifferences("triangle, default uv", *bare, 0, {0.6, 1.2, 0}, 1.5);
}

TEST_CASE("SurfaceDetail::Derivatives: the derivatives of Complete bit for bit, a sphere's uv left zero") {
    // Textured scenes ask for Derivatives where the material has no maps (a
    // mirror or glass ball): footprints read the derivatives, and a change in
    // any bit of them would change the pictures.
    auto sphere = makeSphere({1, 2, 3}, 1.5, {0.3, 1, 0.2});
    auto disk = makeDisk({0, 0, 0}, {0, 0, 1}, 2);
    const std::vector<std::pair<const Shape*, Vec3>> cases = {
        {sphere.get(), {-4, 0.5, 1}}, {sphere.get(), {1.2, 9, 3.1}}, {sphere.get(), {1, 2, -7}},
        {sphere.get(), {2.5, 7, 4}},  // along the pole: the azimuth's origin case
        {disk.get(), {0.7, -0.4, 5}}};
    for (const auto& [shape, from] : cases) {
        const Vec3 target = shape == sphere.get() ? Vec3{1, 2, 3} : Vec3{0.3, 0.2, 0};
        const Ray ray{from, target - from};
        const auto h = shape->intersect(0, ray, 0, kInf, {});
        REQUIRE(h);
        const SurfaceGeometry c = shape->surfaceAt(0, ray, *h, {}, SurfaceDetail::Complete);
        const SurfaceGeometry d = shape->surfaceAt(0, ray, *h, {}, SurfaceDetail::Derivatives);
        for (const auto& [a, b] : {std::pair{c.dpdu, d.dpdu}, std::pair{c.dpdv, d.dpdv},
                                   std::pair{c.dndu, d.dndu}, std::pair{c.dndv, d.dndv},
                                   std::pair{c.p, d.p}, std::pair{c.ns, d.ns}}) {
            CHECK(std::memcmp(&a, &b, sizeof a) == 0);
        }
        CHECK(lengthSquared(c.dpdu) > 0);  // Complete computed them at all
        if (shape == sphere.get()) {
            CHECK(d.uv.x == 0);
            CHECK(d.uv.y == 0);
        } else {
            CHECK(std::memcmp(&c.uv, &d.uv, sizeof c.uv) == 0);  // a disk's uv costs no trigonometry beyond the azimuth it shares
        }
    }
}
