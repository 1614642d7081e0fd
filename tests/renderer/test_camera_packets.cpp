// Camera rays in packets (FrameRenderer: renderRowInPackets for tiles, 16
// corners at a time for SPD), and the feelers of their hits in packets
// (WhittedIntegrator::prepareCameraHits), against the same accelerator asked
// one ray at a time (renderPixel, the corner loop): every film plane bit for
// bit, the same ray counts and surface-filter counts, for square and n-rooks
// sample counts, more samples than a packet holds, a crop window that cuts
// tiles, the SPD procedure, the general kernel, filtered and opaque feelers.
#include <doctest/doctest.h>

#include <atomic>
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
#include "support/temp_dir.h"

using namespace raylab;

namespace {

template <class Plane>
bool sameBytes(const Plane& a, const Plane& b) {
    return a.size() == b.size() &&
           std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

/// Forwards packets too, counting the packets of feelers.
class PacketCounter final : public test::ForwardingAccelerator {
public:
    explicit PacketCounter(const Accelerator& inner)
        : ForwardingAccelerator(inner), m_inner(inner) {}
    bool tracesPackets() const override { return true; }
    void intersectPacket(const Ray* rays, const double* tMin, const double* tMax, int count,
                         std::optional<Hit>* out) const override {
        m_inner.intersectPacket(rays, tMin, tMax, count, out);
    }
    void shadowPacket(const Ray* rays, const double* tMin, const double* tMax, const Departure* from,
                      int count, bool filtered, Color* out, OcclusionHint* hints) const override {
        ++shadowPackets;
        m_inner.shadowPacket(rays, tMin, tMax, from, count, filtered, out, hints);
    }
    mutable std::atomic<long> shadowPackets{0};

private:
    const Accelerator& m_inner;
};

/// Renders `scene` with its Embree accelerator asked in packets and one ray at
/// a time, and checks that every film plane and count agrees; returns how
/// many packets of feelers the first render asked.
long checkPacketsAgree(const Scene& scene, const RenderOptions& options) {
    const auto embree = makeAccelerator("embree", scene, options.accelOptions);
    REQUIRE(embree->tracesPackets());
    const PacketCounter packets(*embree);
    const auto embreeSingle = makeAccelerator("embree", scene, options.accelOptions);
    const test::ForwardingAccelerator single(*embreeSingle);  // asked one ray at a time
    REQUIRE_FALSE(single.tracesPackets());
    const EffectSet effects = analyseEffects(scene, options);
    const RenderResult a = render(scene, packets, options, effects);
    const RenderResult b = render(scene, single, options, effects);
    CHECK(sameBytes(a.film.rgba, b.film.rgba));
    CHECK(sameBytes(a.film.z, b.film.z));
    CHECK(sameBytes(a.film.distance, b.film.distance));
    CHECK(sameBytes(a.film.normal, b.film.normal));
    CHECK(sameBytes(a.film.albedo, b.film.albedo));
    CHECK(sameBytes(a.film.objectId, b.film.objectId));
    CHECK(sameBytes(a.film.mattes, b.film.mattes));
    CHECK(a.rays.byDepth == b.rays.byDepth);  // every ray type at every depth
    CHECK(a.rays.cameraHits == b.rays.cameraHits);
    CHECK(a.rays.total(RayType::Camera) > 0);
    // Crossings of lit feelers are counted once each, whoever asked.
    CHECK(embree->filterCounts().attenuated == embreeSingle->filterCounts().attenuated);
    return packets.shadowPackets.load();
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
        // Feelers of camera hits in packets: filtered through the glass, or
        // opaque (SPD) with the shadow cache's guesses first.
        CHECK(checkPacketsAgree(scene, options) > 0);
    }
}

TEST_CASE("camera packets: the feelers of camera hits, filtered, opaque, general kernel") {
    RenderOverrides small;
    small.width = 45;
    small.height = 29;
    small.spp = 2;
    SUBCASE("glass shadows (spheres, a polygon pane)") {
        const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/glass_shadows.json");
        CHECK(checkPacketsAgree(scene, resolveRenderOptions(scene, small)) > 0);
    }
    SUBCASE("the demo's general kernel: feelers from faces turned away too") {
        const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json");
        RenderOverrides o = small;
        o.effects = EffectsMode::All;
        CHECK(checkPacketsAgree(scene, resolveRenderOptions(scene, o)) > 0);
    }
    SUBCASE("opaque feelers among meshes alone (no shadow cache: it names analytic shapes)") {
        // The demo's meshes (the gem's glass stops an opaque feeler) over a
        // floor mesh; point lights and a directional one (feelers to infinity).
        test::TempDir dir;
        dir.write("floor.obj", "v -6 0 -6\nv 6 0 -6\nv 6 0 6\nv -6 0 6\nf 1 3 2\nf 1 4 3\n");
        const std::string meshes = std::string(RAYLAB_SOURCE_DIR) + "/scenes/meshes/";
        const Scene scene = loadScene(dir.write("s.json", R"({
            "image": {"width": 40, "height": 30, "spp": 1, "depth": 4},
            "camera": {"type": "perspective", "eye": [0, 2.4, 8], "look_at": [0, 0.9, 0],
                       "up": [0, 1, 0], "fov": 40},
            "lights": [{"type": "point", "position": [-5, 8, 6], "intensity": 0.8},
                       {"type": "point", "position": [6, 5, 4], "intensity": 0.4},
                       {"type": "directional", "direction": [0.3, -1, -0.5], "intensity": 0.3}],
            "materials": {"matte": {"kd": 0.7, "ks": 0.2, "shininess": 30, "km": 0.1}},
            "objects": [
                {"type": "mesh", "file": "floor.obj", "material": "matte"},
                {"type": "mesh", "file": ")" + meshes + R"(torus.obj",
                 "transform": {"scale": 0.75, "translate": [1.5, 1.1, -1]}},
                {"type": "mesh", "file": ")" + meshes + R"(gem.obj",
                 "transform": {"scale": 0.5, "translate": [-0.6, 0.5, 1.4]}}]
        })"));
        RenderOverrides o = small;
        o.shadows = ShadowMode::Opaque;
        CHECK(checkPacketsAgree(scene, resolveRenderOptions(scene, o)) > 0);
    }
    SUBCASE("opaque feelers where analytic shapes are the bulk: the shadow cache, one at a time") {
        // 49 balls over a polygon floor (SPD balls' kind of scene).
        std::string balls;
        for (int i = 0; i < 49; ++i)
            balls += R"(, {"type": "sphere", "center": [)" + std::to_string(i % 7 - 3) + ", 0.4, " +
                     std::to_string(i / 7 - 3) + R"(], "radius": 0.4, "material": "matte"})";
        test::TempDir dir;
        const Scene scene = loadScene(dir.write("s.json", R"({
            "image": {"width": 40, "height": 30, "spp": 1, "depth": 3},
            "camera": {"type": "perspective", "eye": [0, 5, 7], "look_at": [0, 0, 0],
                       "up": [0, 1, 0], "fov": 50},
            "lights": [{"type": "point", "position": [-5, 8, 6], "intensity": 0.8}],
            "materials": {"matte": {"kd": 0.7, "ks": 0.2, "shininess": 30, "km": 0.2}},
            "objects": [{"type": "polygon", "material": "matte",
                         "vertices": [[-6, 0, 6], [6, 0, 6], [6, 0, -6], [-6, 0, -6]]})" +
                                                  balls + "]}"));
        RenderOverrides o = small;
        o.shadows = ShadowMode::Opaque;
        CHECK(checkPacketsAgree(scene, resolveRenderOptions(scene, o)) == 0);
    }
    SUBCASE("opaque feelers with the shadow cache: its guesses first, the rest in packets") {
        const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json");
        RenderOverrides o = small;
        o.shadows = ShadowMode::Opaque;
        CHECK(checkPacketsAgree(scene, resolveRenderOptions(scene, o)) > 0);
    }
}
