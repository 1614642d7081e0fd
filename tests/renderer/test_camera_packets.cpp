// Camera rays in packets (FrameRenderer: renderRowInPackets for tiles, 8
// corners at a time for SPD) against the same accelerator asked one ray at a
// time (renderPixel, the corner loop): every film plane bit for bit, and the
// same ray counts, for square and n-rooks sample counts, more samples than a
// packet holds, a crop window that cuts tiles, and the SPD procedure.
#include <doctest/doctest.h>

#include <cstring>
#include <memory>
#include <string>

#include "renderer/accel/accelerator.h"
#include "renderer/crop_window.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "support/forwarding_accelerator.h"

using namespace raylab;

namespace {

template <class Plane>
bool sameBytes(const Plane& a, const Plane& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

}  // namespace

TEST_CASE("camera packets: every film plane and ray count as one ray at a time") {
    const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json");
    struct Case {
        int spp;
        bool crop;
        bool spd;
    };
    for (const Case c : {Case{1, false, false}, Case{3, false, false}, Case{4, true, false},
                         Case{12, false, false}, Case{16, true, false}, Case{1, false, true},
                         Case{1, true, true}}) {
        CAPTURE(c.spp);
        CAPTURE(c.crop);
        CAPTURE(c.spd);
        RenderOverrides o;
        o.width = 61;  // tiles of 16 cut at the right and bottom
        o.height = 37;
        o.spp = c.spp;
        if (c.spd) o.spd = true;
        RenderOptions options = resolveRenderOptions(scene, o);
        if (c.crop) options.crop = CropWindow{0.13, 0.71, 0.2, 0.9};
        const auto embree = makeAccelerator("embree", scene, options.accelOptions);
        REQUIRE(embree->tracesPackets());
        const test::ForwardingAccelerator single(*embree);  // asked one ray at a time
        REQUIRE_FALSE(single.tracesPackets());
        const EffectSet effects = analyseEffects(scene, options);
        const RenderResult a = render(scene, *embree, options, effects);
        const RenderResult b = render(scene, single, options, effects);
        CHECK(sameBytes(a.film.rgba, b.film.rgba));
        CHECK(sameBytes(a.film.z, b.film.z));
        CHECK(sameBytes(a.film.distance, b.film.distance));
        CHECK(sameBytes(a.film.normal, b.film.normal));
        CHECK(sameBytes(a.film.albedo, b.film.albedo));
        CHECK(sameBytes(a.film.objectId, b.film.objectId));
        CHECK(sameBytes(a.film.mattes, b.film.mattes));
        for (int t = 0; t < int(RayType::Count); ++t)
            CHECK(a.rays.total(RayType(t)) == b.rays.total(RayType(t)));
        CHECK(a.rays.total(RayType::Camera) > 0);
    }
}
