// Triangle meshes through the accelerators: a closed tessellated sphere shot
// from its centre (NUMERICS.md §3.3 / §4 (7)), and zero-area triangles.
// Embree 3 uses a non-watertight Möller-Trumbore variant by default and a
// Plücker test under RTC_SCENE_FLAG_ROBUST that is watertight on edges but not
// at vertices; the naive loop uses Woop-Benthin-Wald with an extended-
// precision fallback (geometry/triangle.h), watertight on both.

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "numerics/numerics_helpers.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

/// A closed UV sphere (poles shared by fans of `segments` triangles) whose
/// vertices are float-representable relative to `centre`, so Embree's float
/// copy (relative to the same point) is exactly the double mesh.
std::shared_ptr<TriangleMesh> floatExactSphere(const Vec3& centre, double radius, int rings,
                                               int segments) {
    auto m = accel_test::uvSphereMesh({0, 0, 0}, radius, rings, segments, false);
    for (Vec3& p : m->positions) p = centre + Vec3(Vec3f(p));
    return m;
}

struct MissCounts {
    int random = 0, edges = 0, vertices = 0;
    int randomRays = 0, edgeRays = 0, vertexRays = 0;
};

MissCounts shootFromCentre(const Accelerator& accel, const TriangleMesh& mesh, const Vec3& o,
                           int randomRays) {
    MissCounts m;
    Rng rng(606);
    for (int i = 0; i < randomRays; ++i) {
        m.random += !accel.intersect(Ray{o, rng.direction()}, 0, kInf);
        ++m.randomRays;
    }
    // Each undirected edge once (i < j), each vertex once.
    for (const auto& tri : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            const uint32_t i = tri[e], j = tri[(e + 1) % 3];
            if (i > j) continue;
            const Vec3 mid = (mesh.positions[i] + mesh.positions[j]) * 0.5;
            m.edges += !accel.intersect(Ray{o, mid - o}, 0, kInf);
            ++m.edgeRays;
        }
    }
    for (const Vec3& v : mesh.positions) {
        m.vertices += !accel.intersect(Ray{o, v - o}, 0, kInf);
        ++m.vertexRays;
    }
    return m;
}

}  // namespace

TEST_CASE("watertight: closed sphere mesh shot from its centre, every back end") {
    // Embree: 64 rings x 128 segments (16128 triangles, 8066 vertices, 24192
    // edges); the naive loop (O(triangles) per ray): 32 x 64 (4032, 2018,
    // 6048). Robust Embree and the naive loop: zero misses for random
    // directions and for rays aimed exactly at edge midpoints. Vertex rays:
    // the naive loop never misses; Embree's miss rates are measured and
    // reported (robust mode is not watertight at vertices, NUMERICS §3.3),
    // bounded at 10% for robust mode so a regression shows. Default Embree's
    // edge misses are reported only.
    for (const Vec3 centre : {Vec3{0, 0, 0}, Vec3{0.1, -0.2, 0.3}}) {
        for (const Backend& b : allBackends()) {
            CAPTURE(b.label);
            const bool naive = b.kind == AcceleratorKind::Naive;
            const auto mesh = floatExactSphere(centre, 2.0, naive ? 32 : 64, naive ? 64 : 128);
            Scene scene;
            scene.materials.resize(1);
            scene.objects.push_back(meshObject("ball", mesh));
            const auto accel = build(b, scene, centre);
            const MissCounts m = shootFromCentre(*accel, *mesh, centre, naive ? 2000 : 20000);
            MESSAGE(b.label << ", centre (" << centre.x << ", " << centre.y << ", " << centre.z
                            << "): misses " << m.random << "/" << m.randomRays << " random, "
                            << m.edges << "/" << m.edgeRays << " edge midpoints, " << m.vertices
                            << "/" << m.vertexRays << " vertices ("
                            << 100.0 * m.vertices / m.vertexRays << "%)");
            if (b.robust || naive) {
                CHECK(m.random == 0);
                CHECK(m.edges == 0);
            }
            if (naive) CHECK(m.vertices == 0);
            if (b.robust) CHECK(m.vertices <= m.vertexRays / 10);
        }
    }
}

TEST_CASE("watertight: hits on the closed mesh land on the surface at the right distance") {
    // Every hit from the centre is at distance <= r and >= r·cos(pi/rings)
    // (inside the circumscribed sphere, outside the inscribed polyhedron),
    // and Embree's and the naive loop's t agree to float accuracy.
    const Vec3 centre{0.1, -0.2, 0.3};
    const double r = 2.0;
    const auto mesh = floatExactSphere(centre, r, 32, 64);
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(meshObject("ball", mesh));
    const auto embree = build({"embree robust", AcceleratorKind::Embree, true}, scene, centre);
    const auto naive = build({"naive", AcceleratorKind::Naive, false}, scene, centre);
    Rng rng(707);
    int bad = 0;
    double worst = 0;
    for (int i = 0; i < 1000; ++i) {
        const Ray ray{centre, rng.direction()};
        const auto e = embree->intersect(ray, 0, kInf);
        const auto n = naive->intersect(ray, 0, kInf);
        if (!e || !n) {
            ++bad;
            continue;
        }
        const double lo = r * std::cos(kPi / 32) * 0.999, hi = r * 1.000001;
        if (!(n->t >= lo && n->t <= hi)) ++bad;
        worst = std::max(worst, std::abs(e->t - n->t) / n->t);
    }
    MESSAGE("embree vs naive: worst relative t difference " << worst);
    CHECK(bad == 0);
    CHECK(worst < 1e-5);
}

namespace {

/// A unit quad at z = 0 (triangles 0, 1) and, 0.5 above it, three zero-area
/// triangles: a repeated vertex (2: v4 v4 v5), three collinear vertices
/// (3: v4 v6 v5, v6 the midpoint of v4 v5) and a single point (4: v7 x 3).
Scene degenerateScene() {
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{-1, -1, 0},       {1, -1, 0},      {1, 1, 0},   {-1, 1, 0},  // quad
                       {-0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {0, 0, 0.5},              // collinear
                       {0.25, -0.5, 0.5}};                                           // point
    mesh->triangles = {{0, 1, 2}, {0, 2, 3}, {4, 4, 5}, {4, 6, 5}, {7, 7, 7}};
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(meshObject("mesh", mesh));
    return scene;
}

/// Shoots `ray` at degenerateScene: it must pass the zero-area triangles and
/// (when `expectQuad`) hit the quad; any hit must have a finite unit normal.
/// Returns the primitive wrongly hit (or -1 for a wrong miss), nothing if right.
std::optional<int> shootDegenerate(const Accelerator& accel, const Scene& scene, const Ray& ray,
                                   bool expectQuad, int& badNormals) {
    const auto hit = accel.intersect(ray, 0, kInf);
    if (hit) {
        const SurfaceInteraction si = scene.surfaceAt(ray, *hit);
        if (!isFinite(si.ng) || !isFinite(si.ns) || std::abs(length(si.ng) - 1) > 1e-9)
            ++badNormals;
    }
    if (hit.has_value() != expectQuad) return hit ? int(hit->prim) : -1;
    if (hit && hit->prim > 1) return int(hit->prim);
    return std::nullopt;
}

}  // namespace

TEST_CASE("watertight: zero-area triangles are never hit by rays along and across them") {
    // Rays from z = 2 straight down through points of the degenerate
    // triangles (vertices included) pass them and hit the quad at t = 2
    // (|d| = 1); rays lying in their line, above the quad, hit nothing.
    const Scene scene = degenerateScene();
    for (const Backend& b : allBackends()) {
        CAPTURE(b.label);
        const auto accel = build(b, scene, {0, 0, 2});
        int wrong = 0, badNormals = 0;
        for (int i = 0; i <= 20; ++i) {
            const double s = -0.5 + i / 20.0;  // along v4 .. v5, v6 at i = 10
            const Ray down{{s, s, 2}, {0, 0, -1}};
            wrong += shootDegenerate(*accel, scene, down, true, badNormals).has_value();
            const auto hit = accel->intersect(down, 0, kInf);
            if (hit && std::abs(hit->t - 2.0) > 1e-6) ++wrong;
        }
        wrong += shootDegenerate(*accel, scene, Ray{{0.25, -0.5, 2}, {0, 0, -1}}, true, badNormals)
                     .has_value();  // through the point triangle
        wrong += shootDegenerate(*accel, scene, Ray{{-2, -2, 0.5}, {1, 1, 0}}, false, badNormals)
                     .has_value();
        wrong += shootDegenerate(*accel, scene, Ray{{0.25, -2, 0.5}, {0, 1, 0}}, false, badNormals)
                     .has_value();
        CHECK(wrong == 0);
        CHECK(badNormals == 0);
    }
}

TEST_CASE("watertight: oblique rays exactly through a zero-area triangle's vertices") {
    // Oblique rays from z = 2 aimed exactly at v4, v5, v6 (the collinear
    // triangle's vertices) and v7 (the point triangle) must pass them and hit
    // the quad. Measured: Embree with RTC_SCENE_FLAG_ROBUST reports a hit on
    // the collinear triangle 3 for about 10% of the oblique rays through any
    // of its vertices v4, v6, v5 (41 of 434; never for the repeated-vertex or
    // the point triangle, never without the flag); Scene::surfaceAt keeps the
    // normal finite, but the hit is on an invisible primitive. Fixed in the
    // Embree adaptor: zero-area triangles are left out when building, with a
    // primID remap.
    const Scene scene = degenerateScene();
    const Vec3 targets[] = {{-0.5, -0.5, 0.5}, {0.5, 0.5, 0.5}, {0, 0, 0.5}, {0.25, -0.5, 0.5}};
    const char* targetNames[] = {"v4", "v5", "v6", "v7"};
    for (const Backend& b : allBackends()) {
        CAPTURE(b.label);
        const auto accel = build(b, scene, {0, 0, 2});
        Rng rng(808);
        int rays = 0, badNormals = 0;
        int wrongPrim[5] = {0, 0, 0, 0, 0}, wrongMiss = 0;
        std::string perTarget;
        for (int k = 0; k < 4; ++k) {
            int wrongHere = 0, raysHere = 0;
            for (int i = 0; i < 200; ++i) {
                Vec3 d = rng.direction();
                if (d.z > -0.3) d.z = -0.3 - std::abs(d.z);
                const Vec3 o = targets[k] - d * (1.5 / -d.z);  // starts at z = 2
                const Vec3 atQuad = o + d * (2 / -d.z);
                if (!(std::abs(atQuad.x) < 1 && std::abs(atQuad.y) < 1)) continue;
                ++rays;
                ++raysHere;
                const auto w = shootDegenerate(*accel, scene, Ray{o, d}, true, badNormals);
                wrongHere += w.has_value();
                if (w && *w < 0)
                    ++wrongMiss;
                else if (w)
                    ++wrongPrim[*w];
            }
            perTarget += std::string(k ? ", " : "") + targetNames[k] + " " +
                         std::to_string(wrongHere) + "/" + std::to_string(raysHere);
        }
        MESSAGE(b.label << ": " << rays << " oblique rays through degenerate vertices: hits on "
                        << "triangle 2 (repeated vertex) " << wrongPrim[2]
                        << ", triangle 3 (collinear) " << wrongPrim[3] << ", triangle 4 (point) "
                        << wrongPrim[4] << ", misses " << wrongMiss
                        << "; wrong per target: " << perTarget);
        CHECK(wrongPrim[2] + wrongPrim[3] + wrongPrim[4] + wrongMiss == 0);
        CHECK(badNormals == 0);
    }
}
