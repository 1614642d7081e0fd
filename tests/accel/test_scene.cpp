// Scene's methods: primitive counts, bounds, and surfaceAt, which recomputes
// triangle hits in double so every accelerator hands identical data to shading.

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "accel/accel_test_helpers.h"
#include "renderer/scene.h"

using namespace raylab;
using namespace raylab::accel_test;

namespace {

bool identical(const SurfaceInteraction& a, const SurfaceInteraction& b) {
    return a.t == b.t && a.p == b.p && a.ng == b.ng && a.ns == b.ns && a.frontFace == b.frontFace &&
           a.object == b.object && a.material == b.material;
}

bool allFinite(const SurfaceInteraction& s) {
    return std::isfinite(s.t) && isFinite(s.p) && isFinite(s.ng) && isFinite(s.ns);
}

/// One object: the square [0,2]² at z = 0, triangles (0,1,2) and (0,2,3).
Scene quadScene() {
    Scene scene;
    scene.materials.resize(4);
    scene.objects.push_back(meshObject("quad", quadMesh(0, 0, 2, 2, 0), 1));
    return scene;
}

}  // namespace

TEST_CASE("scene: primitiveCount counts analytic shapes once and every triangle") {
    Scene scene;
    scene.objects.push_back(shapeObject("a", makeSphere({0, 0, 0}, 1)));
    scene.objects.push_back(shapeObject("b", makeSphere({3, 0, 0}, 1)));
    scene.objects.push_back(meshObject("quad", quadMesh(0, 0, 1, 1, 0)));
    // uvSphereMesh(rings = 4, segments = 6): 6 cap triangles at each pole plus
    // 2 per quad of the (4 - 2) middle bands: 6 + 6 + 2·2·6 = 36.
    scene.objects.push_back(meshObject("ball", uvSphereMesh({0, 0, 0}, 1, 4, 6, false)));
    CHECK(scene.primitiveCount() == 2 + 2 + 36);
    CHECK(Scene{}.primitiveCount() == 0);
}

TEST_CASE("scene: bounds enclose every object") {
    Scene scene;
    CHECK(scene.bounds().empty());
    scene.objects.push_back(shapeObject("a", makeSphere({5, 0, 0}, 1)));
    scene.objects.push_back(meshObject("quad", quadMesh(-3, -2, 1, 1, 7)));
    const Bounds3 b = scene.bounds();
    // Sphere box [4,6]×[-1,1]² (padded by its own rule), quad [-3,1]×[-2,1]×{7}.
    CHECK(b.lo.x == -3);
    CHECK(b.lo.y == -2);
    CHECK(b.lo.z <= -1);
    CHECK(b.lo.z > -1.001);
    CHECK(b.hi.x >= 6);
    CHECK(b.hi.x < 6.001);
    CHECK(b.hi.y >= 1);
    CHECK(b.hi.z == 7);
}

TEST_CASE("scene: surfaceAt on a triangle, hand-computed") {
    const Scene scene = quadScene();
    // o = (1.5, 0.5, 1), d = (0,0,-1) reaches z = 0 at t = 1, point (1.5, 0.5, 0),
    // inside triangle 0 = (0,0,0), (2,0,0), (2,2,0). (1-u-v)p0 + u p1 + v p2 =
    // (2u + 2v, 2v, 0) gives v = 0.25, u = 0.5. Normal (2,0,0)×(2,2,0) = (0,0,4) -> +z.
    const Ray ray{{1.5, 0.5, 1}, {0, 0, -1}};
    const SurfaceInteraction si = scene.surfaceAt(ray, Hit{1.0, 0, 0, 0, 0});
    CHECK(si.t == 1.0);
    CHECK(si.p == Vec3{1.5, 0.5, 0});
    CHECK(si.ng == Vec3{0, 0, 1});
    CHECK(si.ns == Vec3{0, 0, 1});  // no vertex normals: ns = ng
    CHECK(si.frontFace);
    CHECK(si.object == 0);
    CHECK(si.material == 1);

    // From below: same normal (outward = CCW side), back face.
    const SurfaceInteraction below =
        scene.surfaceAt(Ray{{1.5, 0.5, -2}, {0, 0, 1}}, Hit{2.0, 0, 0});
    CHECK(below.t == 2.0);
    CHECK(below.ng == Vec3{0, 0, 1});
    CHECK_FALSE(below.frontFace);
}

TEST_CASE("scene: triangle surface data ignores the accelerator's t, u, v") {
    // Embree reports float t, u, v; the naive loop double ones. surfaceAt
    // recomputes from the ray and the triangle, so any of them give identical data.
    const Scene scene = quadScene();
    const Ray ray{{0.3, 0.2, 3}, {0.1, 0.05, -1}};
    const SurfaceInteraction a = scene.surfaceAt(ray, Hit{3.0, 0, 0, 0.1, 0.1});
    const SurfaceInteraction b = scene.surfaceAt(ray, Hit{2.99999, 0, 0, 0.7, 0.2});
    CHECK(identical(a, b));
    // Hit point: (0.3 + 0.1·3, 0.2 + 0.05·3, 0) = (0.6, 0.35, 0) at t = 3.
    CHECK(a.t == doctest::Approx(3.0).epsilon(1e-15));
    CHECK(a.p.x == doctest::Approx(0.6).epsilon(1e-15));
    CHECK(a.p.y == doctest::Approx(0.35).epsilon(1e-15));
    CHECK(a.p.z == 0);
}

TEST_CASE("scene: interpolated vertex normals, and ng when they cancel") {
    Scene scene = quadScene();
    auto mesh = quadMesh(0, 0, 2, 2, 0);
    // Triangle 0 uses vertices 0, 1, 2 with weights (1-u-v, u, v) = (0.25, 0.5, 0.25)
    // at (1.5, 0.5): ns ∝ 0.25·(0,0,1) + 0.5·(1,0,0) + 0.25·(0,1,0) = (0.5, 0.25, 0.25).
    mesh->normals = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    scene.objects[0].shape = mesh;
    const Ray ray{{1.5, 0.5, 1}, {0, 0, -1}};
    const SurfaceInteraction si = scene.surfaceAt(ray, Hit{1.0, 0, 0});
    const double len = std::sqrt(0.375);
    CHECK(si.ns.x == doctest::Approx(0.5 / len).epsilon(1e-15));
    CHECK(si.ns.y == doctest::Approx(0.25 / len).epsilon(1e-15));
    CHECK(si.ns.z == doctest::Approx(0.25 / len).epsilon(1e-15));
    CHECK(si.ng == Vec3{0, 0, 1});

    // Normals that cancel at the hit point: (1,0,0), (-1,0,0) with equal weights
    // at the midpoint of edge 0-1 (u = 0.5, v = 0) -> zero vector -> falls back to ng.
    auto cancel = quadMesh(0, 0, 2, 2, 0);
    cancel->normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    scene.objects[0].shape = cancel;
    const SurfaceInteraction c = scene.surfaceAt(Ray{{1, 0, 1}, {0, 0, -1}}, Hit{1.0, 0, 0});
    CHECK(c.ns == Vec3{0, 0, 1});
    CHECK(allFinite(c));
}

TEST_CASE("scene: per-face materials") {
    Scene scene = quadScene();
    scene.objects[0].faceMaterials = {2, 3};
    // (0.5, 1.5) is in triangle 1 = (0,0,0), (2,2,0), (0,2,0).
    const SurfaceInteraction si = scene.surfaceAt(Ray{{0.5, 1.5, 1}, {0, 0, -1}}, Hit{1.0, 0, 1});
    CHECK(si.material == 3);
}

TEST_CASE("scene: a triangle hit a hair outside its edge is clamped onto it") {
    // Float traversal can report triangle 0 for a ray that, in double, passes
    // just outside it: (1.5, -0.001) is below the edge y = 0. The plane gives
    // t = 1; barycentrics (2u+2v, 2v) = (1.5, -0.001) -> v = -0.0005 -> clamped
    // to v = 0, u = 0.7505: p = (1.501, 0, 0).
    const Scene scene = quadScene();
    const SurfaceInteraction si =
        scene.surfaceAt(Ray{{1.5, -0.001, 1}, {0, 0, -1}}, Hit{1.0, 0, 0});
    CHECK(si.t == 1.0);
    CHECK(si.p.x == doctest::Approx(1.501).epsilon(1e-12));
    CHECK(si.p.y == 0);
    CHECK(si.p.z == 0);
    CHECK(si.ng == Vec3{0, 0, 1});
}

TEST_CASE("scene: degenerate triangle or parallel ray never yields NaN") {
    Scene scene;
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}, {0, 1, 3}};
    scene.objects.push_back(meshObject("degenerate", mesh));
    const SurfaceInteraction a = scene.surfaceAt(Ray{{1, 0, 1}, {0, 0, -1}}, Hit{1.0, 0, 0});
    CHECK(allFinite(a));
    CHECK(length(a.ng) == doctest::Approx(1.0));
    // Ray parallel to triangle 1's plane: the plane t is not finite, hit.t is used.
    const Vec3 n = normalize(cross(Vec3{1, 1, 1}, Vec3{0, 1, 0}));
    const Vec3 along = cross(n, Vec3{0, 1, 0});
    const SurfaceInteraction b = scene.surfaceAt(Ray{Vec3{0, 0, 0} + n, along}, Hit{0.5, 0, 1});
    CHECK(allFinite(b));
    CHECK(b.t == 0.5);
}

TEST_CASE("scene: analytic hits are forwarded to the shape") {
    Scene scene;
    scene.materials.resize(3);
    scene.objects.push_back(shapeObject("s", makeSphere({0, 0, 0}, 1), 2));
    // Unit sphere, ray from z = -5 along +z: entry at t = 4, p = (0,0,-1), n = -z.
    const Ray ray{{0, 0, -5}, {0, 0, 1}};
    const auto h = intersect1(*scene.objects[0].shape, ray, 0, kInf);
    REQUIRE(h);
    const SurfaceInteraction si = scene.surfaceAt(ray, Hit{h->t, 0, 0, h->u, h->v});
    CHECK(si.t == 4.0);
    CHECK(si.p == Vec3{0, 0, -1});
    CHECK(si.ng == Vec3{0, 0, -1});
    CHECK(si.frontFace);
    CHECK(si.material == 2);
}
