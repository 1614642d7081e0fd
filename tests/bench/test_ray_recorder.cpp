// The recording decorator and the bare Embree replay: the recorder sees
// exactly the rays the integrator counts (by type and depth), in an order
// that does not depend on the thread count, and bare rtcIntersect1 /
// rtcOccluded1 agree with the accelerator on every recorded ray.

#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "renderer/accel/accelerator.h"
#include "renderer/accel/ray_recorder.h"
#include "renderer/accel/embree_replay.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "tools/bench/scene_generators.h"

using namespace raylab;

namespace {

struct Recording {
    RenderResult result;
    std::vector<RecordedRay> rays;
    uint64_t unmatched = 0;
};

RenderOptions optionsFor(const Scene& scene, int width, int height, int spp, int threads,
                         bool spd = false) {
    RenderOverrides o;
    o.spd = spd;
    o.width = width;
    o.height = height;
    o.spp = spp;
    o.threads = threads;
    o.shadows = ShadowMode::Opaque;  // what bare Embree can replay (bench limit does the same)
    return resolveRenderOptions(scene, o);
}

Recording record(const Scene& scene, const Accelerator& accel, const RenderOptions& options) {
    RayRecorder recorder(accel, scene, options);
    Recording r;
    r.result = render(scene, recorder, options, analyseEffects(scene, options));
    r.rays = recorder.takeRays();
    r.unmatched = recorder.unmatchedRays();
    return r;
}

void checkCountsMatch(const Recording& r) {
    const RayCounters c = RayRecorder::countRays(r.rays);
    CHECK(r.unmatched == 0);
    CHECK(r.rays.size() == r.result.rays.total());
    CHECK(c.cameraHits == r.result.rays.cameraHits);
    for (size_t t = 0; t < size_t(RayType::Count); ++t) {
        CAPTURE(rayTypeName(RayType(t)));
        CHECK(c.total(RayType(t)) == r.result.rays.total(RayType(t)));
        for (size_t d = 0; d <= size_t(RayCounters::kMaxTrackedDepth); ++d) {
            CAPTURE(d);
            CHECK(c.byDepth[t][d] == r.result.rays.byDepth[t][d]);
        }
    }
}

bool sameRays(const std::vector<RecordedRay>& a, const std::vector<RecordedRay>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const RecordedRay& x = a[i];
        const RecordedRay& y = b[i];
        if (std::memcmp(&x.ray, &y.ray, sizeof x.ray) != 0 || x.tMin != y.tMin ||
            !(x.tMax == y.tMax) || x.type != y.type || x.depth != y.depth ||
            x.occlusion != y.occlusion || x.hit != y.hit)
            return false;
    }
    return true;
}

std::string demoPath() { return std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json"; }

}  // namespace

TEST_CASE("recorder: per-type and per-depth counts equal the render's RayCounters (demo)") {
    // demo.json has mirrors, glass and two lights: all four ray types occur.
    Scene scene = loadScene(demoPath());
    for (int spp : {1, 4}) {
        CAPTURE(spp);
        const RenderOptions options = optionsFor(scene, 48, 36, spp, 2);
        const auto accel = makeAccelerator("embree", scene, options.accelOptions);
        const Recording r = record(scene, *accel, options);
        checkCountsMatch(r);
        CHECK(r.result.rays.total(RayType::Camera) == uint64_t(48 * 36 * spp));
        CHECK(r.result.rays.total(RayType::Shadow) > 0);
        CHECK(r.result.rays.total(RayType::Reflection) > 0);
        CHECK(r.result.rays.total(RayType::Refraction) > 0);
        // Every occlusion query is a shadow ray and vice versa.
        for (const RecordedRay& ray : r.rays) CHECK(ray.occlusion == (ray.type == RayType::Shadow));
    }
}

TEST_CASE("recorder: SPD corner rays on the sphereflake, and the naive back end") {
    Scene scene = makeSphereflakeScene(2);
    const RenderOptions options = optionsFor(scene, 24, 24, 1, 2, /*spd=*/true);
    for (const char* name : {"embree", "naive"}) {
        CAPTURE(name);
        const auto accel = makeAccelerator(name, scene, options.accelOptions);
        const Recording r = record(scene, *accel, options);
        checkCountsMatch(r);
        // SPD: one eye ray through every pixel corner, (24+1)² of them.
        CHECK(r.result.rays.total(RayType::Camera) == 25u * 25u);
        CHECK(r.result.rays.total(RayType::Reflection) > 0);
    }
}

TEST_CASE("recorder: orthographic camera rays are recognised") {
    Scene scene = makeSphereflakeScene(1);
    scene.camera = Camera::orthographic({2.1, 1.3, 1.7}, {-2.1, -1.3, -1.7}, {0, 0, 1}, 3.0);
    const RenderOptions options = optionsFor(scene, 20, 16, 1, 2);
    const auto accel = makeAccelerator("embree", scene, options.accelOptions);
    const Recording r = record(scene, *accel, options);
    checkCountsMatch(r);
    CHECK(r.result.rays.total(RayType::Camera) == 20u * 16u);
}

TEST_CASE("recorder: same image as without it, rays in a thread-independent pixel order") {
    Scene scene = loadScene(demoPath());
    const RenderOptions one = optionsFor(scene, 40, 30, 1, 1);
    const RenderOptions two = optionsFor(scene, 40, 30, 1, 2);
    const auto accel = makeAccelerator("embree", scene, one.accelOptions);
    const Recording a = record(scene, *accel, one);
    const Recording b = record(scene, *accel, two);
    CHECK(sameRays(a.rays, b.rays));

    const RenderResult plain = render(scene, *accel, one, analyseEffects(scene, one));
    CHECK(plain.film.rgba == a.result.film.rgba);
    CHECK(plain.rays.byDepth == a.result.rays.byDepth);

    // Trees come in row-major pixel order: camera ray k belongs to pixel k.
    size_t camera = 0;
    for (const RecordedRay& r : a.rays) {
        if (r.type != RayType::Camera) continue;
        const Ray expected = scene.camera.generateRay(double(camera % 40) + 0.5,
                                                      double(camera / 40) + 0.5, 40, 30);
        CHECK(r.ray.o == expected.o);
        CHECK(r.ray.d == expected.d);
        ++camera;
    }
    CHECK(camera == 40u * 30u);
}

TEST_CASE("bare Embree replay agrees with the accelerator on every recorded ray") {
    std::vector<std::string> files = {demoPath()};
    const std::string balls = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/balls_s2.nff";
    if (std::filesystem::exists(balls)) files.push_back(balls);
    for (const std::string& file : files) {
        CAPTURE(file);
        Scene scene = loadScene(file);
        const RenderOptions options = optionsFor(scene, 40, 30, 1, 2);
        const auto accel = makeAccelerator("embree", scene, options.accelOptions);
        const Recording r = record(scene, *accel, options);
        REQUIRE(!r.rays.empty());
        EmbreeReplay replay(*accel, r.rays);
        CHECK(replay.tracedCount() == r.rays.size());  // all rays here are traceable
        for (int threads : {1, 2}) {
            CAPTURE(threads);
            replay.run(threads);
            size_t disagreements = 0, hits = 0;
            for (size_t i = 0; i < r.rays.size(); ++i) {
                disagreements += replay.results()[i] != uint8_t(r.rays[i].hit);
                hits += replay.results()[i];
            }
            CHECK(disagreements == 0);
            CHECK(hits > 0);
            CHECK(hits < r.rays.size());
        }
        // The recorded answers are the accelerator's own.
        for (size_t i = 0; i < r.rays.size(); i += 7) {
            const RecordedRay& x = r.rays[i];
            const bool direct = x.occlusion ? accel->occluded(x.ray, x.tMin, x.tMax)
                                            : accel->intersect(x.ray, x.tMin, x.tMax).has_value();
            CHECK(direct == x.hit);
        }
    }
}

TEST_CASE("bare replay needs the Embree back end") {
    Scene scene = makeSphereflakeScene(0);
    const auto naive = makeAccelerator("naive", scene);
    const std::vector<RecordedRay> none;
    CHECK_THROWS_AS(EmbreeReplay(*naive, none), std::invalid_argument);
}
