// The JSON scene format: defaults, every object type mapped to the right
// shape (checked by hand-computed ray hits), transforms on meshes, and errors
// that name the file, the line and the key path.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "geometry/polygon.h"
#include "geometry/sphere.h"
#include "io/io_test_helpers.h"
#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "support/vec_checks.h"

using namespace raylab;
using raylab::test::checkVec;
using raylab::test::contains;
using raylab::test::failureOf;
using raylab::test::TempDir;

namespace {

const char* kCamera = R"("camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]})";

/// A scene with the standard camera and the given objects (and extra top-level members).
std::string sceneWith(const std::string& objects, const std::string& extra = "") {
    return std::string("{") + kCamera + ",\n" + (extra.empty() ? "" : extra + ",\n") +
           "\"objects\": [\n" + objects + "\n]}\n";
}

Scene load(const std::string& text) { return loadJsonScene(text, "t.json"); }

test::Failure loadFailure(const std::string& text) {
    return failureOf([&] { load(text); });
}

/// Distance along the ray to the first accepted hit, or -1 for a miss.
double hitT(const Shape& s, const Vec3& o, const Vec3& d) {
    const auto h = s.intersect(0, Ray{o, d}, 1e-9, 1e30, {});
    return h ? h->t : -1;
}


}  // namespace

TEST_CASE("json scene: defaults of a minimal scene") {
    const Scene s = load(sceneWith(""));
    CHECK(s.sourcePath == "t.json");
    CHECK(s.image.width == 640);
    CHECK(s.image.height == 480);
    CHECK(s.image.spp == 1);
    CHECK(s.image.maxDepth == 5);
    CHECK(s.background == Color(0, 0, 0));
    CHECK(s.ambient == Color(0, 0, 0));
    CHECK(s.lights.empty());
    CHECK(s.materials.empty());
    CHECK(s.objects.empty());
    CHECK(s.cameraNear == 0);
    CHECK(s.camera.projection() == Camera::Projection::Perspective);
    CHECK(s.camera.vfovDegrees() == 45);
    // Eye at +5z looking at the origin with +y up: w = +z, u = +x, v = +y.
    checkVec(s.camera.frame().eye, {0, 0, 5});
    checkVec(s.camera.frame().w, {0, 0, 1});
    checkVec(s.camera.frame().u, {1, 0, 0});
    checkVec(s.camera.frame().v, {0, 1, 0});
}

TEST_CASE("json scene: image, background, ambient, lights and materials") {
    const Scene s = load(R"({
        "image": {"width": 320, "height": 200, "spp": 4, "depth": 8},
        "camera": {"type": "perspective", "eye": [0, 0, 5], "look_at": [0, 0, 0],
                   "up": [0, 2, 0], "fov": 60, "near": 0.5},
        "background": [0.1, 0.2, 0.3],
        "ambient": 0.25,
        "lights": [
            {"type": "point", "position": [1, 2, 3], "color": [1, 0.5, 0.25], "intensity": 2},
            {"type": "directional", "direction": [0, -3, 4]}
        ],
        "materials": {
            "red": {"kd": [0.8, 0.1, 0.1], "ks": 0.5, "shininess": 64, "ka": [0.1, 0, 0]},
            "glass": {"kd": 0, "kt": 0.9, "km": [0.1, 0.1, 0.1], "ior": 1.5,
                      "highlight": "phong"}
        },
        "objects": []
    })");
    CHECK(s.image.width == 320);
    CHECK(s.image.height == 200);
    CHECK(s.image.spp == 4);
    CHECK(s.image.maxDepth == 8);
    CHECK(s.camera.vfovDegrees() == 60);
    CHECK(s.cameraNear == 0.5);
    CHECK(s.background == Color(0.1, 0.2, 0.3));
    CHECK(s.ambient == Color(0.25, 0.25, 0.25));  // one number is a grey
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].type == Light::Type::Point);
    checkVec(s.lights[0].position, {1, 2, 3});
    CHECK(s.lights[0].intensity == Color(2, 1, 0.5));  // colour × intensity
    CHECK(s.lights[1].type == Light::Type::Directional);
    checkVec(s.lights[1].direction, {0, -0.6, 0.8});  // (0, -3, 4) / 5
    CHECK(s.lights[1].intensity == Color(1, 1, 1));
    REQUIRE(s.materials.size() == 2);
    const Material& red = s.materials[0];
    CHECK(red.name == "red");
    CHECK(red.kd == Color(0.8, 0.1, 0.1));
    CHECK(red.ks == Color(0.5, 0.5, 0.5));
    CHECK(red.ka == Color(0.1, 0, 0));
    CHECK(red.shininess == 64);
    CHECK(red.highlight == Highlight::BlinnPhong);  // the default
    CHECK(s.materials[1].highlight == Highlight::Phong);
    CHECK(red.km.isBlack());
    CHECK(red.kt.isBlack());
    CHECK(red.ior == 1.0);
    const Material& glass = s.materials[1];
    CHECK(glass.name == "glass");
    CHECK(glass.kd.isBlack());
    CHECK(glass.kt == Color(0.9, 0.9, 0.9));
    CHECK(glass.km == Color(0.1, 0.1, 0.1));
    CHECK(glass.ior == 1.5);
}

TEST_CASE("json scene: orthographic camera") {
    const Scene s = load(R"({"camera": {"type": "orthographic", "eye": [0, 5, 0],
        "direction": [0, -1, 0], "up": [0, 0, -1], "width": 4}, "objects": []})");
    CHECK(s.camera.projection() == Camera::Projection::Orthographic);
    CHECK(s.camera.viewWidth() == 4);
    checkVec(s.camera.frame().w, {0, 1, 0});
    // Centre ray of a 2x2 image goes straight down from the eye.
    const Ray r = s.camera.generateRay(1, 1, 2, 2);
    checkVec(r.o, {0, 5, 0});
    checkVec(normalize(r.d), {0, -1, 0});
}

TEST_CASE("json scene: sphere, plane and disk") {
    const Scene s = load(sceneWith(R"(
        {"type": "sphere", "center": [1, 2, 3], "radius": 0.5, "name": "ball"},
        {"type": "plane", "point": [0, -1, 0], "normal": [0, 2, 0]},
        {"type": "disk", "center": [0, 0, -4], "normal": [0, 0, 1], "radius": 2})"));
    REQUIRE(s.objects.size() == 3);
    const Shape& sphere = *s.objects[0].shape;
    CHECK(std::string(sphere.kind()) == "sphere");
    CHECK(s.objects[0].name == "ball");
    const auto* sp = dynamic_cast<const Sphere*>(&sphere);
    REQUIRE(sp != nullptr);
    checkVec(sp->centre(), {1, 2, 3});
    CHECK(sp->radius() == 0.5);
    // From (1, 2, 13) straight down -z: the near surface is at z = 3.5, t = 9.5.
    CHECK(hitT(sphere, {1, 2, 13}, {0, 0, -1}) == doctest::Approx(9.5));

    const Shape& plane = *s.objects[1].shape;
    CHECK(std::string(plane.kind()) == "plane");
    CHECK(s.objects[1].name == "objects[1]");  // default name: the key path
    // From y = 5 down to the plane y = -1: t = 6; from below it is a back face.
    CHECK(hitT(plane, {0, 5, 0}, {0, -1, 0}) == doctest::Approx(6));
    CHECK(hitT(plane, {0, -5, 0}, {0, 1, 0}) == -1);

    const Shape& disk = *s.objects[2].shape;
    CHECK(std::string(disk.kind()) == "disk");
    // Along -z from z = 0 to the disk at z = -4: inside radius 2 at x = 1.5, outside at 2.5.
    CHECK(hitT(disk, {1.5, 0, 0}, {0, 0, -1}) == doctest::Approx(4));
    CHECK(hitT(disk, {2.5, 0, 0}, {0, 0, -1}) == -1);
    for (const Object& o : s.objects) {
        CHECK(test::meshOf(o) == nullptr);
        CHECK(o.shape->sidedness() == Sidedness::Outside);
    }
    // No material given: one shared grey "default" material is added.
    REQUIRE(s.materials.size() == 1);
    CHECK(s.materials[0].name == "default");
    CHECK(s.objects[0].material == 0);
    CHECK(s.objects[2].material == 0);
}

TEST_CASE("json scene: cylinder and cone map to ConeParams") {
    const Scene s = load(sceneWith(R"(
        {"type": "cylinder", "base": [0, 0, 0], "apex": [0, 2, 0], "radius": 1},
        {"type": "cylinder", "base": [0, 0, 0], "apex": [0, 2, 0], "radius": 1, "caps": true},
        {"type": "cone", "base": [0, 0, 0], "apex": [0, 2, 0], "base_radius": 1},
        {"type": "cone", "base": [0, 0, 0], "apex": [0, 2, 0], "base_radius": 1,
         "apex_radius": 0.5})"));
    REQUIRE(s.objects.size() == 4);
    // Side at radius 1, hit from x = 5 at height 1: t = 4.
    CHECK(hitT(*s.objects[0].shape, {5, 1, 0}, {-1, 0, 0}) == doctest::Approx(4));
    // Straight down at r = 0.5 from y = 5: open tube -> only inside (back) faces; the
    // capped one is hit on the top cap at y = 2, t = 3.
    CHECK(hitT(*s.objects[0].shape, {0.5, 5, 0}, {0, -1, 0}) == -1);
    CHECK(hitT(*s.objects[1].shape, {0.5, 5, 0}, {0, -1, 0}) == doctest::Approx(3));
    // Cone radius 1 at y = 0 to 0 at y = 2: radius 0.5 at y = 1, so t = 5 - 0.5 = 4.5.
    CHECK(hitT(*s.objects[2].shape, {5, 1, 0}, {-1, 0, 0}) == doctest::Approx(4.5));
    // Truncated: radius 1 - 0.25 y, 0.75 at y = 1, so t = 4.25.
    CHECK(hitT(*s.objects[3].shape, {5, 1, 0}, {-1, 0, 0}) == doctest::Approx(4.25));
}

TEST_CASE("json scene: quadric coefficients and clip box") {
    // x² + y² + z² - 4 = 0: a sphere of radius 2 written as a quadric.
    const Scene s = load(sceneWith(R"(
        {"type": "quadric", "coefficients": {"A": 1, "B": 1, "C": 1, "J": -4},
         "clip": {"min": [-3, -3, -3], "max": [3, 3, 3]}},
        {"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -4],
         "clip": {"min": [-3, -3, -3], "max": [3, 3, 1]}, "sides": "both"})"));
    REQUIRE(s.objects.size() == 2);
    // From z = 10 along -z: the surface at z = 2 is at t = 8.
    CHECK(hitT(*s.objects[0].shape, {0, 0, 10}, {0, 0, -1}) == doctest::Approx(8));
    // Clipped at z <= 1 the near point is cut away; two-sided, the far one (z = -2, t = 12) counts.
    CHECK(s.objects[1].shape->sidedness() == Sidedness::Both);
    CHECK(hitT(*s.objects[1].shape, {0, 0, 10}, {0, 0, -1}) == doctest::Approx(12));
}

TEST_CASE("json scene: polygon fill rule, inside test and triangulation") {
    // A pentagram (vertices 144° apart): its centre is wound twice, so it is
    // inside under the nonzero rule and outside under even-odd.
    std::string star = "[";
    for (int k = 0; k < 5; ++k) {
        const double a = (90.0 + 144.0 * k) * 3.14159265358979323846 / 180.0;
        star += (k ? ", [" : "[") + std::to_string(std::cos(a)) + ", " +
                std::to_string(std::sin(a)) + ", 0]";
    }
    star += "]";
    const Scene s =
        load(sceneWith(R"({"type": "polygon", "vertices": )" + star + R"(, "rule": "nonzero"},
        {"type": "polygon", "vertices": )" +
                       star + R"(, "test": "projected"},
        {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
         "triangulate": true},
        {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
         "normals": [[0, 0, 1], [0, 0, 1], [0, 0, 2], [0, 0, 1]], "triangulate": true})"));
    REQUIRE(s.objects.size() == 4);
    const auto* nonzero = dynamic_cast<const Polygon*>(s.objects[0].shape.get());
    const auto* evenOdd = dynamic_cast<const Polygon*>(s.objects[1].shape.get());
    REQUIRE(nonzero != nullptr);
    REQUIRE(evenOdd != nullptr);
    CHECK(nonzero->fillRule() == FillRule::NonZero);
    CHECK(nonzero->insideTest() == PolygonTest::Watertight);  // the default
    CHECK(evenOdd->fillRule() == FillRule::EvenOdd);          // the default
    CHECK(evenOdd->insideTest() == PolygonTest::Projected);
    CHECK(hitT(*nonzero, {0, 0, 3}, {0, 0, -1}) == doctest::Approx(3));
    CHECK(hitT(*evenOdd, {0, 0, 3}, {0, 0, -1}) == -1);
    // A star tip at (0, 0.9) is inside under both rules.
    CHECK(hitT(*evenOdd, {0, 0.9, 3}, {0, 0, -1}) == doctest::Approx(3));

    // Triangulated: a mesh of n - 2 = 2 triangles over the same vertices.
    const Object& quad = s.objects[2];
    REQUIRE(test::meshOf(quad) != nullptr);
    CHECK(test::meshOf(quad)->positions.size() == 4);
    CHECK(test::meshOf(quad)->triangleCount() == 2);
    CHECK(!test::meshOf(quad)->hasNormals());
    for (size_t t = 0; t < 2; ++t) {
        const auto& tri = test::meshOf(quad)->triangles[t];
        const auto& P = test::meshOf(quad)->positions;
        // Wound like the polygon: counter-clockwise seen from +z.
        CHECK(cross(P[tri[1]] - P[tri[0]], P[tri[2]] - P[tri[0]]).z > 0);
    }
    REQUIRE(test::meshOf(s.objects[3])->hasNormals());
    checkVec(test::meshOf(s.objects[3])->normals[2], {0, 0, 1});  // normalised
}

TEST_CASE("json scene: checkerboard mesh") {
    const Scene s = load(sceneWith(R"(
        {"type": "checkerboard", "origin": [0, 0, 0], "edge_u": [2, 0, 0],
         "edge_v": [0, 0, -3], "divisions": [2, 3], "materials": ["a", "b"]})",
                                   R"("materials": {"a": {"kd": 1}, "b": {"kd": 0}})"));
    REQUIRE(s.objects.size() == 1);
    const Object& o = s.objects[0];
    REQUIRE(test::meshOf(o) != nullptr);
    // (2 + 1) x (3 + 1) grid vertices, 2 x 3 squares of 2 triangles.
    CHECK(test::meshOf(o)->positions.size() == 12);
    REQUIRE(test::meshOf(o)->triangleCount() == 12);
    REQUIRE(o.faceMaterials.size() == 12);
    // Square (i, j) uses "a" when i + j is even; triangles run i fastest.
    const uint32_t a = 0, b = 1;
    const uint32_t expected[12] = {a, a, b, b, b, b, a, a, a, a, b, b};
    for (size_t t = 0; t < 12; ++t) CHECK(o.faceMaterials[t] == expected[t]);
    // Every triangle faces edge_u × edge_v = (1, 0, 0) × (0, 0, -1) = (0, 1, 0).
    for (const auto& tri : test::meshOf(o)->triangles) {
        const auto& P = test::meshOf(o)->positions;
        checkVec(normalize(cross(P[tri[1]] - P[tri[0]], P[tri[2]] - P[tri[0]])), {0, 1, 0});
    }
    const Bounds3 box = test::meshOf(o)->bounds();
    checkVec(box.lo, {0, 0, -3});
    checkVec(box.hi, {2, 0, 0});
}

TEST_CASE("json scene: sidedness defaults and materials by name or inline") {
    const Scene s =
        load(sceneWith(R"(
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass"},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass",
         "sides": "outside"},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "sides": "inside"},
        {"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": {"kd": [0, 1, 0]}})",
                       R"("materials": {"glass": {"kt": 1, "ior": 1.5}, "default": {"kd": 0.5}})"));
    REQUIRE(s.objects.size() == 4);
    // Transmitters are two-sided unless the file says otherwise.
    CHECK(s.objects[0].shape->sidedness() == Sidedness::Both);
    CHECK(s.objects[1].shape->sidedness() == Sidedness::Outside);
    CHECK(s.objects[2].shape->sidedness() == Sidedness::Inside);
    CHECK(s.objects[0].material == 0);
    // A material the file names "default" is the default.
    CHECK(s.objects[2].material == 1);
    // Inline materials are appended, named by their key path.
    REQUIRE(s.materials.size() == 3);
    CHECK(s.objects[3].material == 2);
    CHECK(s.materials[2].name == "objects[3].material");
    CHECK(s.materials[2].kd == Color(0, 1, 0));
    // From inside the "inside" sphere the far wall is hit at t = 1.
    CHECK(hitT(*s.objects[2].shape, {0, 0, 0}, {0, 0, 1}) == doctest::Approx(1));
    CHECK(hitT(*s.objects[2].shape, {0, 0, 5}, {0, 0, -1}) == doctest::Approx(6));
}

TEST_CASE("json scene: meshes are two-sided unless \"sides\" says otherwise") {
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string board =
        R"("origin": [0, 0, 0], "edge_u": [1, 0, 0], "edge_v": [0, 1, 0], "materials": [{}, {}])";
    const std::string quad = R"("vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])";
    const std::string path = dir.write(
        "s.json", sceneWith(R"({"type": "mesh", "file": "tri.obj"},
        {"type": "mesh", "file": "tri.obj", "sides": "outside"},
        {"type": "checkerboard", )" + board + R"(},
        {"type": "checkerboard", )" + board + R"(, "sides": "inside"},
        {"type": "polygon", )" + quad + R"(, "triangulate": true},
        {"type": "polygon", )" + quad + R"(, "triangulate": true, "sides": "outside"})"));
    const Scene s = loadScene(path);
    REQUIRE(s.objects.size() == 6);
    const Sidedness expected[6] = {Sidedness::Both, Sidedness::Outside, Sidedness::Both,
                                   Sidedness::Inside, Sidedness::Both, Sidedness::Outside};
    for (size_t i = 0; i < 6; ++i) {
        CAPTURE(i);
        REQUIRE((test::meshOf(s.objects[i]) != nullptr));
        CHECK(s.objects[i].shape->sidedness() == expected[i]);
    }
}

TEST_CASE("json scene: OBJ mesh with transforms, relative to the scene file") {
    TempDir dir;
    dir.write("meshes/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    const std::string scenePath =
        dir.write("scene.json", sceneWith(R"(
        {"type": "mesh", "file": "meshes/tri.obj", "material": "m",
         "transform": {"translate": [10, 0, 0], "rotate": {"axis": [0, 0, 1], "degrees": 90},
                       "scale": 2}},
        {"type": "mesh", "file": "meshes/tri.obj", "name": "turned",
         "transform": {"rotate": [{"axis": [0, 0, 1], "degrees": 90},
                                  {"axis": [1, 0, 0], "degrees": 90}]}},
        {"type": "mesh", "file": "meshes/tri.obj", "transform": {"scale": [-1, 1, 1]}})",
                                          R"("materials": {"m": {"kd": 0.3}})"));
    const Scene s = loadScene(scenePath);
    REQUIRE(s.objects.size() == 3);

    // Scale 2, then 90° about +z ((x, y) -> (-y, x)), then +10 x:
    // (1,0,0) -> (2,0,0) -> (0,2,0) -> (10,2,0); (0,1,0) -> (0,2,0) -> (-2,0,0) -> (8,0,0).
    const Object& a = s.objects[0];
    REQUIRE(test::meshOf(a) != nullptr);
    CHECK(a.name == "meshes/tri.obj");
    CHECK(a.material == 0);  // the override
    CHECK(a.faceMaterials.empty());
    REQUIRE(test::meshOf(a)->positions.size() == 3);
    checkVec(test::meshOf(a)->positions[0], {10, 0, 0});
    checkVec(test::meshOf(a)->positions[1], {10, 2, 0});
    checkVec(test::meshOf(a)->positions[2], {8, 0, 0});
    REQUIRE(test::meshOf(a)->hasNormals());
    checkVec(test::meshOf(a)->normals[0], {0, 0, 1});

    // Rotations apply in list order: (1,0,0) -> z: (0,1,0) -> x: (0,0,1).
    const Object& b = s.objects[1];
    CHECK(b.name == "turned");
    checkVec(test::meshOf(b)->positions[1], {0, 0, 1});
    // The normal (0,0,1) -> z: (0,0,1) -> x: (0,-1,0).
    checkVec(test::meshOf(b)->normals[0], {0, -1, 0});
    // No override: the OBJ has no MTL, so its faces use a grey default added to the scene.
    CHECK(s.materials[b.material].kd == Color(0.8, 0.8, 0.8));

    // A mirror keeps the front side: the winding is swapped so the geometric
    // normal still agrees with the vertex normal (0, 0, 1).
    const Object& c = s.objects[2];
    const auto& P = test::meshOf(c)->positions;
    const auto& tri = test::meshOf(c)->triangles[0];
    CHECK(cross(P[tri[1]] - P[tri[0]], P[tri[2]] - P[tri[0]]).z > 0);
    checkVec(test::meshOf(c)->normals[0], {0, 0, 1});
}

TEST_CASE("json scene: errors name file, line and key path") {
    // The exact format of a value error.
    test::Failure f =
        loadFailure(sceneWith("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},\n"
                              "{\"type\": \"sphere\", \"center\": [0, 0, 0],\n"
                              " \"radius\": -1}"));
    CHECK(f.located == "t.json:5: objects[1].radius: must be > 0 (got -1)");

    // Unknown keys, with a hint when close to a known one.
    f = loadFailure(
        sceneWith("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1,\n\"radus\": 2}"));
    CHECK(f.line == 4);
    CHECK(
        contains(f.message, "objects[0].radus: unknown key for a sphere (did you mean 'radius'?)"));
    f = loadFailure(std::string("{") + kCamera + ",\n\"objects\": [],\n\"lihgts\": []}");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "lihgts: unknown key for a scene (did you mean 'lights'?)"));
    f = loadFailure(sceneWith(
        "{\"type\": \"plane\", \"point\": [0, 0, 0], \"normal\": [0, 1, 0], \"radius\": 1}"));
    CHECK(contains(f.message, "objects[0].radius: unknown key for a plane (expected 'type', "));

    // The closest key wins the hint: "k2a" is one edit from "ka", two from "kt".
    f = loadFailure(sceneWith("", "\"materials\": {\"m\": {\"k2a\": 1}}"));
    CHECK(contains(f.message, "materials.m.k2a: unknown key for a material (did you mean 'ka'?)"));

    // Missing keys are reported at the object.
    f = loadFailure(sceneWith("{\"type\": \"sphere\",\n \"center\": [0, 0, 0]}"));
    CHECK(f.line == 3);
    CHECK(contains(f.message, "objects[0]: missing required key 'radius' for a sphere"));
    CHECK(contains(loadFailure("{\"objects\": []}").message, "missing required key 'camera'"));

    // Wrong types and shapes of values.
    f = loadFailure(sceneWith("{\"type\": \"sphere\", \"center\": [0, 0], \"radius\": 1}"));
    CHECK(contains(f.message, "objects[0].center: expected [x, y, z] (3 numbers), got 2 elements"));
    f = loadFailure(sceneWith("{\"type\": \"sphere\", \"center\": [0, \"1\", 0], \"radius\": 1}"));
    CHECK(contains(f.message, "objects[0].center[1]: expected a number, got string"));
    f = loadFailure(sceneWith("", "\"image\": {\"width\": 2.5}"));
    CHECK(contains(f.message, "image.width: must be an integer (got 2.5)"));
    f = loadFailure(sceneWith("", "\"image\": {\"spp\": 0}"));
    CHECK(contains(f.message, "image.spp: must be in [1, 65536] (got 0)"));
    f = loadFailure(sceneWith("", "\"background\": [1, -0.5, 0]"));
    CHECK(contains(f.message, "background[1]: must be >= 0 (got -0.5)"));
    f = loadFailure(sceneWith(
        "{\"type\": \"disk\", \"center\": [0, 0, 0], \"normal\": [0, 0, 0], \"radius\": 1}"));
    CHECK(contains(f.message, "objects[0].normal: must not be the zero vector"));
    f = loadFailure(sceneWith(
        "{\"type\": \"polygon\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], \"rule\": \"odd\"}"));
    CHECK(contains(f.message, "objects[0].rule: must be one of 'even-odd', 'nonzero' (got 'odd')"));
    f = loadFailure(sceneWith("{\"type\": \"torus\"}"));
    CHECK(contains(f.message, "objects[0].type: unknown object type 'torus'"));
    f =
        loadFailure(sceneWith("{\"type\": \"cylinder\", \"base\": [0,0,0], \"apex\": [0,1,0], "
                              "\"radius\": 1, \"base_radius\": 2}"));
    CHECK(contains(f.message,
                   "objects[0].base_radius: give either 'radius' or 'base_radius'/'apex_radius'"));
    f = loadFailure(sceneWith("{\"type\": \"quadric\", \"coefficients\": {\"A\": 1, \"K\": 1}}"));
    CHECK(contains(f.message, "objects[0].coefficients.K: unknown key for quadric coefficients"));
    f =
        loadFailure(sceneWith("{\"type\": \"polygon\", \"vertices\": [[0,0,0],[1,0,0],[0,1,0]], "
                              "\"triangulate\": true, \"rule\": \"nonzero\"}"));
    CHECK(contains(f.message, "objects[0].rule: has no effect with \"triangulate\": true"));
    f = loadFailure(sceneWith(
        "{\"type\": \"checkerboard\", \"origin\": [0,0,0], \"edge_u\": [1,0,0], "
        "\"edge_v\": [0,1,0], \"materials\": [{}, {}], \"sides\": \"front\"}"));
    CHECK(contains(f.message,
                   "objects[0].sides: must be one of 'outside', 'inside', 'both' (got 'front')"));

    // Material references.
    f = loadFailure(sceneWith(
        "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1,\n\"material\": \"gold\"}",
        "\"materials\": {\"red\": {}, \"blue\": {}}"));
    CHECK(f.line == 5);
    CHECK(contains(f.message,
                   "objects[0].material: unknown material 'gold' (defined: 'blue', 'red')"));
    f = loadFailure(sceneWith("", "\"materials\": {\"red\": {\"ior\": 0}}"));
    CHECK(contains(f.message, "materials.red.ior: must be > 0 (got 0)"));

    // Camera errors from Camera's own checks keep the camera's line.
    f = loadFailure(
        "{\n\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"up\": [0, 0, "
        "1]},\n\"objects\": []}");
    CHECK(f.line == 2);
    CHECK(contains(f.message, "camera: up vector is parallel to the view direction"));
    f = loadFailure(
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 180}, \"objects\": "
        "[]}");
    CHECK(contains(f.message, "camera.fov: must be in (0, 180) degrees (got 180)"));

    // Factory errors (std::invalid_argument) gain the file, line and path.
    f = loadFailure(
        sceneWith("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},\n"
                  "{\"type\": \"polygon\",\n \"vertices\": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]}"));
    CHECK(f.file == "t.json");
    CHECK(f.line == 4);
    CHECK(contains(f.message, "objects[1]: polygon"));

    // Syntax errors come from the JSON reader with their line.
    f = loadFailure("{\n\"camera\": {},\n\"objects\": [1,]\n}");
    CHECK(f.line == 3);
    CHECK(contains(f.message, "trailing comma"));
    CHECK(contains(loadFailure("[]").message, "a scene file must be a JSON object"));
}

TEST_CASE("json scene: mesh file errors") {
    TempDir dir;
    const std::string scenePath = dir.write(
        "scene.json", sceneWith("{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},\n"
                                "{\"type\": \"mesh\",\n\"file\": \"missing.obj\"}"));
    test::Failure f = failureOf([&] { loadScene(scenePath); });
    CHECK(f.file == scenePath);
    CHECK(f.line == 5);
    CHECK(contains(f.message, "objects[1].file: '" + dir.file("missing.obj") + "': cannot open: "));
    // A bad OBJ reports its own file and line.
    dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    dir.write("scene2.json", sceneWith("{\"type\": \"mesh\", \"file\": \"bad.obj\"}"));
    f = failureOf([&] { loadScene(dir.file("scene2.json")); });
    CHECK(f.file == dir.file("bad.obj"));
    CHECK(f.line == 5);
    dir.write("scene3.json", sceneWith("{\"type\": \"mesh\", \"file\": \"x.ply\"}"));
    CHECK(contains(failureOf([&] { loadScene(dir.file("scene3.json")); }).message,
                   "only .obj meshes are supported"));
}

TEST_CASE("scene loader: dispatch by extension") {
    TempDir dir;
    const std::string text = sceneWith(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})");
    CHECK(loadScene(dir.write("a.json", text)).objects.size() == 1);
    CHECK(loadScene(dir.write("b.JSON", text)).objects.size() == 1);  // case-insensitive
    CHECK(loadScene(dir.write("c.Obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).objects.size() ==
          1);

    test::Failure f = failureOf([&] { loadScene(dir.write("d.xyz", text)); });
    CHECK(f.file == dir.file("d.xyz"));
    CHECK(f.message == "unknown scene format '.xyz' (expected .json, .obj or .nff)");
    f = failureOf([&] { loadScene(dir.write("noext", text)); });
    CHECK(contains(f.message, "no file extension"));
    f = failureOf([&] { loadScene(dir.file("absent.json")); });
    CHECK(f.file == dir.file("absent.json"));
    CHECK(f.message == "cannot open: No such file or directory");
    f = failureOf([&] { loadScene(dir.file("")); });  // a directory, not a file
    CHECK(contains(f.message, "unknown scene format"));
    std::filesystem::create_directories(dir.file("folder.json"));
    f = failureOf([&] { loadScene(dir.file("folder.json")); });
    CHECK(f.message == "cannot open: is a directory");
}

TEST_CASE("scenes/demo.json and scenes/primitives.json load") {
    for (const char* name : {"demo.json", "primitives.json"}) {
        CAPTURE(name);
        const Scene s = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name);
        CHECK(s.image.width == 640);
        CHECK(s.image.height == 480);
        CHECK(!s.lights.empty());
        CHECK(s.objects.size() >= 5);
        bool mirror = false, glass = false;
        for (const Object& o : s.objects) {
            const Material& m = s.materials.at(o.material);
            mirror = mirror || m.reflective();
            glass = glass || (m.transmissive() && m.ior > 1);
            if (o.shape && m.transmissive()) CHECK(o.shape->sidedness() == Sidedness::Both);
        }
        CHECK(mirror);
        CHECK(glass);
    }
}
