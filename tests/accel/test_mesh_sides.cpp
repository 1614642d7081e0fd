// One-sided triangle meshes (NFF's opaque triangles): the back of a triangle
// is invisible to both accelerators, for closest hits and shadow rays alike.
#include <doctest/doctest.h>

#include <limits>
#include <memory>
#include <string>

#include "renderer/accel/accelerator.h"

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
    Object o;
    o.mesh = mesh;
    o.meshSides = sides;
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
