// Procedural benchmark scenes: documented primitive counts, SPD geometry,
// determinism, and cameras that actually frame the content.

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "geometry/sphere.h"
#include "geometry/triangle_mesh.h"
#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "tools/bench/scene_generators.h"

using namespace raylab;

namespace {

const Sphere& sphereOf(const Object& o) {
    const auto* s = dynamic_cast<const Sphere*>(o.shape.get());
    REQUIRE(s != nullptr);
    return *s;
}

/// Fraction of camera rays that hit something in a small Embree render.
double cameraHitFraction(Scene& scene) {
    RenderOverrides o;
    o.width = 32;
    o.height = 24;
    o.spp = 1;
    o.maxDepth = 1;
    o.threads = 1;
    const RenderOptions options = resolveRenderOptions(scene, o);
    const auto accel = makeAccelerator("embree", scene, options.accelOptions);
    const RenderResult r = render(scene, *accel, options, analyseEffects(scene, options));
    return double(r.rays.cameraHits) / double(r.rays.total(RayType::Camera));
}

}  // namespace

TEST_CASE("sphereflake sphere counts are 1 + 9 + ... + 9^L") {
    // Sums of powers of nine: 1; 1+9; 1+9+81; 1+9+81+729; +6561; +59049.
    CHECK(sphereflakeSphereCount(0) == 1);
    CHECK(sphereflakeSphereCount(1) == 10);
    CHECK(sphereflakeSphereCount(2) == 91);
    CHECK(sphereflakeSphereCount(3) == 820);
    CHECK(sphereflakeSphereCount(4) == 7381);   // balls.nff
    CHECK(sphereflakeSphereCount(5) == 66430);  // balls_s5.nff
}

TEST_CASE("sphereflake scene: spheres plus one ground polygon, 3 lights, mirror balls") {
    for (int level = 0; level <= 3; ++level) {
        CAPTURE(level);
        const Scene s = makeSphereflakeScene(level);
        CHECK(s.primitiveCount() == sphereflakeSphereCount(level) + 1);
        REQUIRE(s.objects.size() == sphereflakeSphereCount(level) + 1);
        CHECK(std::string(s.objects[0].shape->kind()) == "polygon");
        for (size_t i = 1; i < s.objects.size(); ++i)
            CHECK(std::string(s.objects[i].shape->kind()) == "sphere");
        CHECK(s.lights.size() == 3);
        CHECK(s.materials[s.objects[1].material].reflective());
    }
    CHECK_THROWS_AS(makeSphereflakeScene(-1), std::invalid_argument);
    CHECK_THROWS_AS(makeSphereflakeScene(8), std::invalid_argument);
}

TEST_CASE("sphereflake level 1: nine children of radius 1/6 touching the root") {
    const Scene s = makeSphereflakeScene(1);
    const Sphere& root = sphereOf(s.objects[1]);
    CHECK(root.centre() == Vec3{0, 0, 0});
    CHECK(root.radius() == 0.5);
    for (size_t i = 2; i < s.objects.size(); ++i) {
        const Sphere& c = sphereOf(s.objects[i]);
        // Touching: |centre| = 0.5 + 0.5/3 = 2/3.
        CHECK(c.radius() == doctest::Approx(1.0 / 6.0).epsilon(1e-15));
        CHECK(length(c.centre()) == doctest::Approx(2.0 / 3.0).epsilon(1e-14));
        // Nothing below the root's equator: z is 0 (three trios of two) or
        // (2/3)·sqrt(2/3) = 0.5443 (three, as in balls_s1.nff's "0.544331").
        const double z = c.centre().z;
        CHECK((std::abs(z) < 1e-14 || std::abs(z - 2.0 / 3.0 * std::sqrt(2.0 / 3.0)) < 1e-14));
    }
}

TEST_CASE("sphereflake reproduces SPD's balls_s2/s3.nff and balls.nff sphere for sphere") {
    const std::string dir = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/";
    for (const auto& entry : {std::pair<std::string, int>{"balls_s2.nff", 2},
                              std::pair<std::string, int>{"balls_s3.nff", 3},
                              std::pair<std::string, int>{"balls.nff", 4}}) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& file = entry.first;
        const auto& level = entry.second;
        const std::string path = dir + file;
        if (!std::filesystem::exists(path)) {
            MESSAGE("skipped: " << path << " not present");
            continue;
        }
        CAPTURE(file);
        const Scene ref = loadScene(path);
        const Scene gen = makeSphereflakeScene(level);
        // The NFF reader keeps file order (ground polygon first, then the
        // spheres depth-first), and so does the generator.
        REQUIRE(ref.objects.size() == gen.objects.size());
        double worst = 0;
        for (size_t i = 1; i < gen.objects.size(); ++i) {
            const Sphere& a = sphereOf(ref.objects[i]);
            const Sphere& b = sphereOf(gen.objects[i]);
            worst = std::max({worst, maxComponent(abs(a.centre() - b.centre())),
                              std::abs(a.radius() - b.radius())});
        }
        // SPD prints 6 significant digits: |x| < 1 gives errors <= 5e-7.
        CHECK(worst < 1e-6);
    }
}

TEST_CASE("random spheres: N spheres + ground, deterministic per seed") {
    const Scene a = makeRandomSpheresScene(100, 7);
    const Scene b = makeRandomSpheresScene(100, 7);
    const Scene c = makeRandomSpheresScene(100, 8);
    CHECK(a.primitiveCount() == 101);
    REQUIRE(a.objects.size() == 101);
    bool differs = false;
    for (size_t i = 1; i < a.objects.size(); ++i) {
        CHECK(sphereOf(a.objects[i]).centre() == sphereOf(b.objects[i]).centre());
        CHECK(sphereOf(a.objects[i]).radius() == sphereOf(b.objects[i]).radius());
        CHECK(a.objects[i].material == b.objects[i].material);
        differs = differs || sphereOf(a.objects[i]).centre() != sphereOf(c.objects[i]).centre();
        // Centres in [-1, 1]³; radius in [0.5, 1]·0.6/cbrt(100).
        CHECK(maxComponent(abs(sphereOf(a.objects[i]).centre())) <= 1.0);
        const double r = 0.6 / std::cbrt(100.0);
        CHECK(sphereOf(a.objects[i]).radius() >= 0.5 * r);
        CHECK(sphereOf(a.objects[i]).radius() <= r);
    }
    CHECK(differs);
    CHECK(makeRandomSpheresScene(1).primitiveCount() == 2);
    CHECK_THROWS_AS(makeRandomSpheresScene(0), std::invalid_argument);
}

TEST_CASE("height field: one mesh of 2·g² triangles, g = round(sqrt(N/2))") {
    // N = 1000: sqrt(500) = 22.36 -> g = 22 -> 968 triangles on 23² = 529 vertices.
    CHECK(heightFieldGridSize(1000) == 22);
    // N = 100: sqrt(50) = 7.07 -> 7 -> 98 triangles.
    CHECK(heightFieldGridSize(100) == 7);
    // N = 2: g = 1 (2 triangles); N = 0 still gives one cell.
    CHECK(heightFieldGridSize(2) == 1);
    CHECK(heightFieldGridSize(0) == 1);
    const Scene s = makeHeightFieldScene(1000);
    CHECK(s.primitiveCount() == 968);
    REQUIRE(s.objects.size() == 1);
    const TriangleMesh* mesh = s.objects[0].shape->nativeTriangles();
    REQUIRE(mesh);
    CHECK(mesh->positions.size() == 529);
    CHECK(mesh->normals.size() == 529);
    // Corner vertices at (±1, ±1): the grid spans [-1, 1]².
    CHECK(mesh->positions.front().x == -1.0);
    CHECK(mesh->positions.back().y == 1.0);
}

TEST_CASE("polygon field: exactly N polygons") {
    const Scene s = makePolygonFieldScene(10);
    CHECK(s.primitiveCount() == 10);
    REQUIRE(s.objects.size() == 10);
    for (const Object& o : s.objects) CHECK(std::string(o.shape->kind()) == "polygon");
    CHECK(makePolygonFieldScene(1).primitiveCount() == 1);
    CHECK(makePolygonFieldScene(1000).primitiveCount() == 1000);
    CHECK_THROWS_AS(makePolygonFieldScene(0), std::invalid_argument);
}

TEST_CASE("every generator's camera frames its content") {
    // At least a quarter of the camera rays must hit something: the camera
    // looks at the scene rather than past it.
    for (const SceneGenerator& g : benchSceneGenerators()) {
        for (size_t p : g.quickSizes) {
            CAPTURE(g.name);
            CAPTURE(p);
            Scene s = g.make(p);
            CHECK(cameraHitFraction(s) > 0.25);
        }
    }
}
