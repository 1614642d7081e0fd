// One-sided triangle meshes (NFF's opaque triangles, JSON meshes with
// "sides"): the back of a triangle is invisible to both accelerators, for
// closest hits and shadow rays alike, and a triangulated polygon keeps the
// facing of the analytic one.
#include <doctest/doctest.h>

#include <limits>
#include <memory>
#include <string>

#include "geometry/triangle_mesh.h"
#include "renderer/accel/accelerator.h"
#include "renderer/io/scene_loader.h"

using namespace raylab;

namespace {

/// One triangle in the z = 0 plane, counter-clockwise seen from +z: its
/// front faces +z.
Scene triangleScene(Sidedness sides) {
    Scene s;
    s.materials.push_back(Material{});
    auto mesh = std::make_shared<TriangleMesh>();
    mesh->positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    mesh->setSidedness(sides);
    Object o;
    o.shape = mesh;
    s.objects.push_back(std::move(o));
    return s;
}

}  // namespace

TEST_CASE("one-sided meshes: back faces are culled by Embree and the naive loop") {
    const Ray fromFront{{0, 0, 5}, {0, 0, -1}};
    const Ray fromBack{{0, 0, -5}, {0, 0, 1}};
    const double inf = std::numeric_limits<double>::infinity();
    struct Expect {
        Sidedness sides;
        bool front, back;
    };
    for (const Expect& e : {Expect{Sidedness::Both, true, true}, Expect{Sidedness::Outside, true, false},
                            Expect{Sidedness::Inside, false, true}}) {
        const Scene scene = triangleScene(e.sides);
        for (const std::string name : {"embree", "naive"}) {
            CAPTURE(name);
            CAPTURE(int(e.sides));
            const auto accel = makeAccelerator(name, scene);
            const auto hf = accel->intersect(fromFront, 0, inf);
            const auto hb = accel->intersect(fromBack, 0, inf);
            CHECK(hf.has_value() == e.front);
            CHECK(hb.has_value() == e.back);
            if (hf) CHECK(hf->t == doctest::Approx(5.0));
            CHECK(accel->occluded(fromFront, 0, inf) == e.front);
            CHECK(accel->occluded(fromBack, 0, inf) == e.back);
        }
    }
}

TEST_CASE("json \"sides\": a triangulated polygon faces the way the analytic one does") {
    // A concave L-shape in z = 0, counter-clockwise seen from +z: its outward
    // (Newell) normal is +z, and the ear-clipped triangles must keep that winding.
    const std::string lShape = "[[0,0,0], [2,0,0], [2,1,0], [1,1,0], [1,2,0], [0,2,0]]";
    const double inf = std::numeric_limits<double>::infinity();
    for (const std::string sides : {"outside", "inside", "both"}) {
        const std::string text = R"({"camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0]},
            "objects": [
              {"type": "polygon", "vertices": )" + lShape + R"(, "sides": ")" + sides + R"("},
              {"type": "polygon", "vertices": )" + lShape + R"(, "sides": ")" + sides +
                                 R"(", "triangulate": true}]})";
        Scene scene = loadJsonScene(text, "sides.json");
        REQUIRE(scene.objects.size() == 2);
        REQUIRE(scene.objects[1].shape->nativeTriangles() != nullptr);
        // Each polygon alone in a scene, so every hit is its own.
        Scene analytic, triangles;
        analytic.materials = triangles.materials = scene.materials;
        analytic.objects.push_back(std::move(scene.objects[0]));
        triangles.objects.push_back(std::move(scene.objects[1]));
        const bool front = sides != "inside", back = sides != "outside";
        // Points inside the L (including the concave corner's neighbourhood).
        for (const Vec3 at : {Vec3{0.5, 0.5, 0}, Vec3{1.5, 0.5, 0}, Vec3{0.5, 1.5, 0},
                              Vec3{0.9, 0.9, 0}}) {
            const Ray fromFront{at + Vec3{0.1, 0.2, 4}, normalize(Vec3{-0.1, -0.2, -4})};
            const Ray fromBack{at + Vec3{0.2, -0.1, -4}, normalize(Vec3{-0.2, 0.1, 4})};
            for (const std::string name : {"embree", "naive"}) {
                CAPTURE(sides);
                CAPTURE(name);
                CAPTURE(at.x);
                CAPTURE(at.y);
                for (const Scene* s : {&analytic, &triangles}) {
                    const auto accel = makeAccelerator(name, *s);
                    CHECK(accel->intersect(fromFront, 0, inf).has_value() == front);
                    CHECK(accel->intersect(fromBack, 0, inf).has_value() == back);
                    CHECK(accel->occluded(fromFront, 0, inf) == front);
                    CHECK(accel->occluded(fromBack, 0, inf) == back);
                }
            }
        }
        // Outside the L (the notch) neither is hit from anywhere.
        const Ray notch{{1.5, 1.5, 4}, {0, 0, -1}};
        for (const Scene* s : {&analytic, &triangles})
            CHECK_FALSE(makeAccelerator("naive", *s)->intersect(notch, 0, inf).has_value());
    }
}
