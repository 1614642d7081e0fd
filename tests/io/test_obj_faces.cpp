// OBJ faces are triangulated as their authors drew them: a concave L (with a
// collinear corner), a ten-corner star and a comb, each written as one OBJ
// face in a tilted plane, render with the same depth on every pixel as the
// same polygon given to the analytic JSON polygon, through both accelerators.
// A fan (what tinyobjloader did) fills the notches and fails the same check.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "geometry/polygon.h"
#include "geometry/primitives.h"
#include "io/io_test_helpers.h"
#include "renderer/io/obj_loader.h"
#include "renderer/io/scene_loader.h"

using namespace raylab;
using raylab::test::TempDir;

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Outline {
    const char* name;
    std::vector<std::pair<double, double>> xy;  ///< counter-clockwise
};

std::vector<Outline> outlines() {
    Outline star{"star", {}};
    for (int k = 0; k < 10; ++k) {
        const double a = kPi / 2 + k * kPi / 5, r = k % 2 == 0 ? 1.5 : 0.6;
        star.xy.push_back({r * std::cos(a), r * std::sin(a)});
    }
    return {
        // An L with a collinear corner at (1.5, 0) on its bottom edge, starting
        // at a corner from which a fan crosses the notch.
        {"L", {{3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}, {0, 0}, {1.5, 0}}},
        star,
        // A comb of four teeth, open at the top.
        {"comb", {{0, 0}, {7, 0}, {7, 3}, {6, 3}, {6, 1}, {5, 1}, {5, 3}, {4, 3}, {4, 1},
                  {3, 1}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}},
    };
}

/// The outline in a tilted plane, each coordinate rounded to float as the
/// OBJ reader reads it, so both scenes hold the very same vertices.
std::vector<Vec3> placed(const Outline& o) {
    const Vec3 e1 = normalize(Vec3(1, 0.2, 0.1));
    const Vec3 e2 = normalize(cross(Vec3(0.1, -0.3, 1), e1));
    std::vector<Vec3> out;
    for (const auto& [x, y] : o.xy) {
        const Vec3 p = Vec3(0.25, -0.5, 0.125) + e1 * x + e2 * y;
        out.push_back(Vec3(double(float(p.x)), double(float(p.y)), double(float(p.z))));
    }
    return out;
}

std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

std::string vec(const Vec3& v) { return "[" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + "]"; }

/// A scene around `object` (JSON), looking at the outline from its front, a little off-axis.
std::string scene(const std::vector<Vec3>& v, const std::string& object) {
    Bounds3 box;
    for (const Vec3& p : v) box.expand(p);
    const Vec3 centre = box.centre();
    const Vec3 n = normalize(newellNormal(v));
    const Vec3 eye = centre + n * (2.2 * maxComponent(box.extent())) + Vec3(0.13, 0.07, -0.05);
    return "{\"camera\": {\"eye\": " + vec(eye) + ", \"look_at\": " + vec(centre) +
           ", \"fov\": 40}, \"objects\": [" + object + "]}";
}

/// Compares eye distance pixel by pixel; returns the pixels where coverage or depth differ.
int depthDifferences(const Film& a, const Film& b) {
    int differ = 0;
    for (size_t i = 0; i < a.distance.size(); ++i) {
        const float x = a.distance[i], y = b.distance[i];
        const bool hitA = x < kNoHitDepth, hitB = y < kNoHitDepth;
        if (hitA != hitB || (hitA && std::abs(x - y) > 1e-6f * x)) ++differ;
    }
    return differ;
}

int covered(const Film& f) {
    int n = 0;
    for (float d : f.distance) n += d < kNoHitDepth;
    return n;
}

}  // namespace

TEST_CASE("obj faces: concave L, star and comb match the analytic polygon's depth on every pixel") {
    TempDir dir;
    for (const Outline& o : outlines()) {
        const std::string name = o.name;
        CAPTURE(name);
        const std::vector<Vec3> v = placed(o);
        std::string obj, face = "f", vertices;
        for (size_t i = 0; i < v.size(); ++i) {
            char line[128];
            std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", v[i].x, v[i].y, v[i].z);
            obj += line;
            face += " " + std::to_string(i + 1);
            vertices += (i ? ", " : "") + vec(v[i]);
        }
        dir.write(std::string(o.name) + ".obj", obj + face + "\n");
        const Scene meshScene = loadScene(dir.write(
            "mesh.json", scene(v, "{\"type\": \"mesh\", \"file\": \"" + std::string(o.name) +
                                      ".obj\"}")));
        const Scene polygonScene = loadScene(dir.write(
            "polygon.json",
            scene(v, "{\"type\": \"polygon\", \"sides\": \"both\", \"vertices\": [" + vertices +
                         "]}")));
        // One face, one mesh of at most n - 2 triangles (the L's collinear
        // corner, no longer exactly collinear in float, may add a sliver).
        REQUIRE(meshScene.objects.size() == 1);
        const TriangleMesh* mesh = test::meshOf(meshScene.objects[0]);
        REQUIRE(mesh != nullptr);
        CHECK(mesh->triangleCount() <= v.size() - 2);
        // Every triangle wound like the face.
        const Vec3 n = newellNormal(v);
        for (const auto& t : mesh->triangles)
            CHECK(dot(cross(mesh->positions[t[1]] - mesh->positions[t[0]],
                            mesh->positions[t[2]] - mesh->positions[t[0]]),
                      n) > 0);

        const Film reference = test::renderFilm(polygonScene, "naive", 64, 64);
        CHECK(covered(reference) > 64 * 64 / 10);  // the outline fills a good part of the image
        for (const char* accel : {"embree", "naive"}) {
            CAPTURE(accel);
            CHECK(depthDifferences(test::renderFilm(meshScene, accel, 64, 64), reference) == 0);
        }

        // The check can fail: a fan from the first corner (tinyobjloader's
        // triangulation) covers the notches, which the polygon leaves empty.
        Scene fan = meshScene;
        auto fanMesh = std::make_shared<TriangleMesh>(*mesh);
        fanMesh->positions = v;
        fanMesh->triangles.clear();
        for (uint32_t k = 1; k + 1 < v.size(); ++k) fanMesh->triangles.push_back({0, k, k + 1});
        fan.objects[0].shape = fanMesh;
        CHECK(depthDifferences(test::renderFilm(fan, "naive", 64, 64), reference) > 0);
    }
}

TEST_CASE("obj faces: warped, collinear and crossing faces") {
    TempDir dir;
    // A warped quad (one corner lifted off the plane of the others) and a
    // warped concave pentagon triangulate on their Newell plane: all area kept.
    const ObjModel warped = loadObj(
        dir.write("warped.obj", "v 0 0 0\nv 2 0 0\nv 2 2 0.3\nv 1 0.5 0\nv 0 2 0\n"
                                "f 1 2 3 4 5\nf 1 2 3 5\n"),
        [] {
            ObjLoadOptions o;
            o.printWarnings = false;
            return o;
        }());
    CHECK(warped.triangleCount() == 3 + 2);
    // Collinear corners only: a zero-area face, dropped with a warning at its line.
    ObjLoadOptions quiet;
    quiet.printWarnings = false;
    const ObjModel flat = loadObj(
        dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nv 0 1 0\nv 0 0 1\n"
                              "f 1 2 3 4\nf 1 5 6\n"),
        quiet);
    CHECK(flat.triangleCount() == 1);
    REQUIRE(flat.warnings.size() == 1);
    CHECK(flat.warnings[0] == dir.file("flat.obj") +
                                  ":7: face encloses no area (collinear or repeated corners, or a "
                                  "crossing outline whose parts cancel); dropped");
    // A figure-eight quad with unequal lobes crosses itself: its triangles
    // cover more than its signed area, which the loader says at the face's line.
    const ObjModel bow = loadObj(
        dir.write("bow.obj", "v 0 0 0\nv 4 4 0\nv 4 0 0\nv 0 2 0\n# crossing\nf 1 2 3 4\n"),
        quiet);
    bool crossing = false;
    for (const std::string& w : bow.warnings)
        crossing = crossing || w == dir.file("bow.obj") +
                                        ":6: face crosses itself: its triangles cover more than "
                                        "its area";
    CHECK(crossing);
}
