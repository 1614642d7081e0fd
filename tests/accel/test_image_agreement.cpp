// --accel naive and --accel embree render the same images: the textbook loop
// and the BVH answer from the same geometry/ math, Scene::surfaceAt
// recomputes every hit in double, and a triangle hit on a shared edge goes to
// the triangle the naive loop picks (renderer/accel/embree_edge_hits.h), so
// pixels agree bit for bit. The scenes that ship with raylab are required to
// agree exactly; the SPD scenes too.
#include <doctest/doctest.h>

#include <cstring>
#include <fstream>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"

using namespace raylab;

namespace {

/// Fraction of pixels whose RGBA floats are bit-identical.
double identicalFraction(const Film& a, const Film& b) {
    size_t same = 0;
    const size_t n = size_t(a.width) * a.height;
    for (size_t i = 0; i < n; ++i)
        same += std::memcmp(&a.rgba[4 * i], &b.rgba[4 * i], 4 * sizeof(float)) == 0;
    return double(same) / double(n);
}

void checkAgreement(const std::string& path, int width, int height) {
    CAPTURE(path);
    Scene scene = loadScene(path);
    RenderOverrides o;
    o.width = width;
    o.height = height;
    o.spp = 1;
    const RenderOptions options = resolveRenderOptions(scene, o);
    const EffectSet effects = analyseEffects(scene, options);
    auto embree = makeAccelerator("embree", scene, options.accelOptions);
    auto naive = makeAccelerator("naive", scene, options.accelOptions);
    const RenderResult a = render(scene, *embree, options, effects);
    const RenderResult b = render(scene, *naive, options, effects);
    const double fraction = identicalFraction(a.film, b.film);
    CAPTURE(fraction);
    CHECK(fraction == 1.0);
    CHECK(a.nonFiniteSamples == 0);
    CHECK(b.nonFiniteSamples == 0);
    // Same hits for the camera rays (a disagreement would show up here first).
    CHECK(a.rays.cameraHits == b.rays.cameraHits);
}

}  // namespace

TEST_CASE("naive vs embree: the demo scene (spheres, OBJ meshes, checker floor, mirror, glass)") {
    checkAgreement(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json", 96, 72);
}

TEST_CASE("naive vs embree: the primitives scene (cone, cylinder, star polygon, quadric, disk)") {
    checkAgreement(std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json", 96, 72);
}

TEST_CASE("naive vs embree: the cut-outs, glass-shadows and textures scenes") {
    // Masks, transmitters and textures: both accelerators ask the same
    // surface filter about the same candidates.
    for (const char* name : {"cutouts.json", "glass_shadows.json", "textures.json"})
        checkAgreement(std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name, 96, 60);
}

TEST_CASE("naive vs embree: SPD scenes when ../shared is present") {
    for (const char* name : {"balls_s2.nff", "tetra.nff", "teapot.nff"}) {
        const std::string path = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/" + name;
        if (!std::ifstream(path)) {
            MESSAGE("skipped: " << path << " not present");
            continue;
        }
        checkAgreement(path, 64, 64);
    }
}
