// Self-intersection ("acne") and light leaks through the whole stack
// (NUMERICS.md §3.2 / §4 (4)-(6), (22)): rendered ground planes, a huge
// ground sphere and a ground mesh near and far (1e5) from the world origin,
// with the robust offset (asserted clean) and the lecture's fixed epsilon
// (measured, reported); contact shadows at a 1e-4 thin wall; and rays spawned
// from every analytic shape kind in double and float.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "geometry/spawn.h"
#include "geometry/triangle.h"
#include "numerics/numerics_helpers.h"
#include "shape_queries.h"

using namespace raylab;
using namespace raylab::numerics_test;

namespace {

enum class Ground { Plane, Sphere, Mesh };

const char* groundName(Ground g) {
    return g == Ground::Plane ? "plane" : g == Ground::Sphere ? "sphere r=1e4" : "mesh";
}

/// A matte ground (kd = 0.8, no ambient) seen from about 2 units above at
/// 64x48, lit by one directional light, everything shifted by `s`. The ground
/// is tilted (normal ~(0.02, 1, 0.03)) and its coordinates are not round
/// numbers, so neither its float copy in Embree nor a float intersector
/// reproduces the double surface exactly. Nothing but the ground itself can
/// shadow it, so every ground pixel must be lit: a black one is acne.
Scene groundScene(Ground g, const Vec3& s, const Vec3& lightDir) {
    Scene scene;
    scene.camera =
        Camera::perspective(s + Vec3{0.1, 2.3, 8.7}, s + Vec3{0.05, 0, -6}, {0, 1, 0}, 50);
    scene.image.width = 64;
    scene.image.height = 48;
    scene.background = Color(0.3, 0.5, 0.8);
    Light light;
    light.type = Light::Type::Directional;
    light.direction = normalize(lightDir);
    scene.lights.push_back(light);
    scene.materials.push_back(material(Color(0.8)));
    const Vec3 n = normalize(Vec3{0.02, 1, 0.03});
    const Vec3 p = s + Vec3{0.0123, -0.0456, 0.0789};
    if (g == Ground::Plane) {
        scene.objects.push_back(shapeObject("ground", makePlane(p, n, 1e3)));
    } else if (g == Ground::Sphere) {
        scene.objects.push_back(shapeObject("ground", makeSphere(p - n * 1e4, 1e4)));
    } else {
        // A square of half-size 1e3 in the plane: two huge triangles, so
        // their float vertices (ulp(1e3) = 6e-5) tilt the float plane most.
        const Vec3 u = normalize(cross(n, Vec3{0, 0, 1})), v = cross(u, n);
        const double e = 1e3 + 0.377;
        auto m = std::make_shared<TriangleMesh>();
        m->positions = {p - u * e - v * e, p + u * e - v * e, p + u * e + v * e, p - u * e + v * e};
        m->triangles = {{0, 1, 2}, {0, 2, 3}};
        if (dot(triangleNormal(m->positions[0], m->positions[1], m->positions[2]), n) < 0)
            m->triangles = {{0, 2, 1}, {0, 3, 2}};
        scene.objects.push_back(meshObject("ground", m));
    }
    // Two-sided, the harder case: a one-sided ground hides self-hits from
    // below (a shadow ray that starts under the surface meets its back face).
    if (scene.objects[0].shape) scene.objects[0].shape->setSidedness(Sidedness::Both);
    return scene;
}

struct AcneCount {
    int ground = 0;  ///< pixels whose (centre) camera ray hits the ground
    int black = 0;   ///< of those, pixels with no direct light: acne
    uint64_t nonFinite = 0;
};

AcneCount renderAcne(Scene& scene, const RenderOverrides& o, bool departures = true,
                     FilmPlane* rgba = nullptr) {
    const RenderResult r = renderWith(scene, o, departures);
    if (rgba) *rgba = r.film.rgba;
    AcneCount c;
    c.nonFinite = r.nonFiniteSamples + nonFiniteValues(r.film);
    for (size_t i = 0; i < r.film.objectId.size(); ++i) {
        if (r.film.objectId[i] != 0) continue;
        ++c.ground;
        if (r.film.rgba[4 * i] < 1e-6f) ++c.black;
    }
    return c;
}

}  // namespace

TEST_CASE("acne: grounds near and 1e5 from the origin, robust offset vs fixed epsilon") {
    // Robust offset (default): 0 acne pixels for every ground, scale and
    // light. Fixed epsilon 1e-2, 1e-4, 1e-6 and float intersectors: counted
    // and reported (docs/accuracy.md), not asserted.
    for (const Vec3 s : {Vec3{0, 0, 0}, Vec3{1e4, 1e4, -1e4}, Vec3{1e5, 1e5, -1e5}}) {
        for (Ground g : {Ground::Plane, Ground::Sphere, Ground::Mesh}) {
            for (const Vec3 light : {Vec3{0, -1, 0}, Vec3{1, -0.5, 0.3}}) {
                Scene scene = groundScene(g, s, light);
                std::string line = std::string(groundName(g)) + ", offset " +
                                   std::to_string(int(s.x)) + ", light " +
                                   (light.x == 0 ? "overhead" : "at 27 deg") + ": acne pixels";
                // Without departures: every shadow feeler is also tested
                // against the ground it leaves, which is what acne is about.
                FilmPlane tested, skipped;
                const AcneCount robust = renderAcne(scene, {}, false, &tested);
                CAPTURE(line);
                CHECK(robust.ground > 1000);
                CHECK(robust.black == 0);
                CHECK(robust.nonFinite == 0);
                // With them (the default), the same picture.
                renderAcne(scene, {}, true, &skipped);
                CHECK(tested == skipped);
                line +=
                    " robust " + std::to_string(robust.black) + "/" + std::to_string(robust.ground);
                for (double eps : {1e-2, 1e-4, 1e-6}) {
                    RenderOverrides o;
                    o.epsilon = eps;
                    const AcneCount c = renderAcne(scene, o);
                    CHECK(c.nonFinite == 0);
                    char buf[64];
                    std::snprintf(buf, sizeof buf, ", eps %g %d", eps, c.black);
                    line += buf;
                }
                RenderOverrides f;
                f.precision = Precision::Float;
                const AcneCount fl = renderAcne(scene, f);
                CHECK(fl.nonFinite == 0);
                line += ", float+robust " + std::to_string(fl.black);
                MESSAGE(line);
            }
        }
    }
}

namespace {

/// Floor (plane y = 0) and a wall 1e-4 thick standing on it (a closed box
/// mesh x in [0, 1e-4], y in [0, 2], z in [-2, 2]), shifted by `s`.
Scene thinWall(const Vec3& s) {
    Scene scene;
    scene.materials.resize(1);
    scene.objects.push_back(shapeObject("floor", makePlane(s, {0, 1, 0}, 100)));
    const double w = 1e-4;
    auto m = std::make_shared<TriangleMesh>();
    for (int i = 0; i < 8; ++i)
        m->positions.push_back(s +
                               Vec3{(i & 1) ? w : 0.0, (i & 2) ? 2.0 : 0.0, (i & 4) ? 2.0 : -2.0});
    // Two triangles per face, outward winding.
    m->triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},   // x = 0, x = w
                    {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},   // y = 0, y = 2
                    {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};  // z = -2, z = 2
    scene.objects.push_back(meshObject("wall", m));
    return scene;
}

}  // namespace

TEST_CASE("acne: contact shadows at a 1e-4 thin wall, and a light 1e-4 behind it") {
    // Point light at (-3, 1.5, 0), left of the wall. Floor points right of
    // the wall at distance δ from it must be in shadow (their shadow ray
    // crosses the wall: a lit one is a light leak); floor points left of it
    // at distance δ must be lit (a shadowed one is a false contact shadow).
    // Then the light moves to 1e-4 left of the wall (x = -1e-4, y = 1): points
    // right of the wall must still be in shadow (§4 (22)). The floor points
    // come from real hits (a ray straight down, Scene::surfaceAt), the shadow
    // rays from spawnRay with the render's settings, as in the integrator.
    // Robust offset: 0 leaks, 0 false shadows for δ down to 1e-6, near the
    // origin and 1e5 away. Fixed epsilon: reported.
    for (const Vec3 s : {Vec3{0, 0, 0}, Vec3{1e5, 1e5, -1e5}}) {
        const Scene scene = thinWall(s);
        const Vec3 eye = s + Vec3{2, 3, 6};
        for (const Backend& b : allBackends()) {
            const auto accel = build(b, scene, eye);
            for (const char* mode : {"robust", "eps 1e-2", "eps 1e-4", "eps 1e-6"}) {
                SpawnSettings spawn;
                spawn.reference = eye;
                if (std::string(mode) != "robust") {
                    spawn.mode = OffsetMode::FixedEpsilon;
                    spawn.epsilon = std::atof(mode + 4);
                }
                int leaks = 0, falseShadows = 0, nearLeaks = 0, points = 0;
                for (double delta : {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1}) {
                    for (double z : {-1.0, 0.0, 1.3}) {
                        for (bool right : {true, false}) {
                            const double x = right ? 1e-4 + delta : -delta;
                            const Ray down{s + Vec3{x, 1, z}, {0, -1, 0}};
                            const auto hit = accel->intersect(down, 0, kInf);
                            REQUIRE(hit);
                            REQUIRE(hit->object == 0);
                            const SurfaceInteraction si = scene.surfaceAt(down, *hit);
                            ++points;
                            for (const Vec3 light : {s + Vec3{-3, 1.5, 0}, s + Vec3{-1e-4, 1, 0}}) {
                                const bool nearLight = light.x == s.x - 1e-4;
                                if (nearLight && !right)
                                    continue;  // that light sits on the floor side
                                const SpawnedRay r = spawnRay(si.p, si.ng, si.span, light - si.p, spawn);
                                const bool occ = accel->occluded(r.ray, r.tMin, 1.0);
                                if (right && !occ) ++(nearLight ? nearLeaks : leaks);
                                if (!right && occ) ++falseShadows;
                            }
                        }
                    }
                }
                MESSAGE(b.label << ", offset " << s.x << ", " << mode << ": " << leaks << " leaks, "
                                << nearLeaks << " leaks from the light 1e-4 behind "
                                << "the wall, " << falseShadows << " false shadows (" << points
                                << " floor points)");
                if (std::string(mode) == "robust") {
                    CHECK(leaks == 0);
                    CHECK(nearLeaks == 0);
                    CHECK(falseShadows == 0);
                }
            }
        }
    }
}

namespace {

/// One object of each analytic kind (and a mesh), convex or flat, about
/// unit size around `c`: outward rays spawned from any of its surface points
/// must not hit it again.
std::vector<std::pair<std::string, Scene>> shapeKinds(const Vec3& c) {
    std::vector<std::pair<std::string, Scene>> v;
    const auto add = [&](const std::string& name, std::unique_ptr<Shape> shape) {
        Scene s;
        s.materials.resize(1);
        shape->setSidedness(Sidedness::Both);
        s.objects.push_back(shapeObject(name, std::move(shape)));
        v.emplace_back(name, std::move(s));
    };
    add("sphere", makeSphere(c, 1));
    add("plane", makePlane(c, normalize(Vec3{0.2, 0.1, 1}), 10));
    add("disk", makeDisk(c, normalize(Vec3{-0.1, 0.3, 1}), 1.5));
    PolygonParams quad;
    quad.vertices = {c + Vec3{-1, -1, 0}, c + Vec3{1, -1, 0.2}, c + Vec3{1, 1, 0.4},
                     c + Vec3{-1, 1, 0.2}};
    add("polygon", makePolygon(quad));
    ConeParams cyl;
    cyl.base = c + Vec3{0, -1, 0};
    cyl.apex = c + Vec3{0, 1, 0};
    cyl.capped = true;
    add("cylinder", makeCone(cyl));
    ConeParams cone = cyl;
    cone.apexRadius = 0;
    add("cone", makeCone(cone));
    QuadricParams ell;  // (x/1)² + (y/0.7)² + (z/1.2)² = 1 around c, expanded
    ell.A = 1;
    ell.B = 1 / 0.49;
    ell.C = 1 / 1.44;
    ell.G = -2 * c.x * ell.A;
    ell.H = -2 * c.y * ell.B;
    ell.I = -2 * c.z * ell.C;
    ell.J = ell.A * c.x * c.x + ell.B * c.y * c.y + ell.C * c.z * c.z - 1;
    add("ellipsoid quadric", makeQuadric(ell));
    Scene mesh;
    mesh.materials.resize(1);
    mesh.objects.push_back(meshObject("mesh", accel_test::uvSphereMesh(c, 1, 16, 32, false)));
    v.emplace_back("mesh sphere", std::move(mesh));
    return v;
}

struct Rehits {
    int hits = 0, rehits = 0;
};

/// Camera rays from an eye 4 units away; from each hit a mirror ray leaves
/// on the side it arrived from (spawnRay, robust offset relative to the eye).
Rehits mirrorRehits(const Scene& scene, const Backend& b, const Vec3& c,
                    Precision precision = Precision::Double) {
    const Vec3 eye = c + Vec3{0.3, 0.2, 4};
    SpawnSettings spawn;
    spawn.reference = eye;
    const auto accel = build(b, scene, eye, precision);
    Rng rng(1212);
    Rehits r;
    for (int i = 0; i < 600; ++i) {
        const Ray camera{eye, c + rng.point(-1, 1) - eye};
        const auto hit = accel->intersect(camera, 0, kInf);
        if (!hit) continue;
        ++r.hits;
        const SurfaceInteraction si = scene.surfaceAt(camera, *hit, withPrecision(precision));
        const Vec3 ng = si.frontFace ? si.ng : -si.ng;
        const Vec3 d = normalize(camera.d);
        const SpawnedRay m = spawnRay(si.p, ng, si.span, d - ng * (2 * dot(d, ng)), spawn);
        if (accel->intersect(m.ray, m.tMin, kInf)) ++r.rehits;
    }
    return r;
}

}  // namespace

TEST_CASE("acne: mirror rays from every shape kind, double precision, near and far") {
    // Every kind is convex or flat, so a mirror ray leaving it can only hit
    // it again by self-intersection. Double precision, robust offset: 0 at
    // every scale.
    for (double scale : {0.0, 1e4, 1e5}) {
        const Vec3 c{scale, -0.5 * scale, 0.25 * scale};
        for (const auto& kind : shapeKinds(c)) {
            // Plain variables: C++17 lambdas (CAPTURE) cannot capture structured bindings.
            const std::string name = kind.first;
            const Scene& scene = kind.second;
            for (const Backend& b : allBackends()) {
                CAPTURE(name);
                CAPTURE(b.label);
                CAPTURE(scale);
                const Rehits r = mirrorRehits(scene, b, c);
                CHECK(r.hits > 100);
                CHECK(r.rehits == 0);
            }
        }
    }
}

TEST_CASE("acne: mirror rays from every shape kind in float precision") {
    // The same with Precision::Float. Expected 0 everywhere: a float solver
    // that works relative to its shape keeps errors ~1e-7 of the shape's
    // size, below the robust offset. Before the fix every kind rounded world
    // coordinates to float first and re-hit itself far from the origin
    // (e.g. sphere 214 / 251 of 600 mirror rays at 1e4 / 1e5); all shapes now
    // subtract their reference point in double before rounding.
    for (double scale : {0.0, 1e4, 1e5}) {
        const Vec3 c{scale, -0.5 * scale, 0.25 * scale};
        for (auto& kind : shapeKinds(c)) {
            const std::string name = kind.first;
            const Scene& scene = kind.second;
            for (const Backend& b : allBackends()) {
                if (b.robust) continue;
                CAPTURE(name);
                CAPTURE(b.label);
                CAPTURE(scale);
                const Rehits r = mirrorRehits(scene, b, c, Precision::Float);
                MESSAGE("float " << name << ", " << b.label << ", scale " << scale << ": "
                                 << r.rehits << "/" << r.hits << " mirror rays re-hit");
                CHECK(r.rehits == 0);
            }
        }
    }
}
