// SPD testing procedure on tiny NFF scenes whose ray statistics are counted
// by hand: eye rays through pixel corners ((W+1)(H+1) of them, each pixel the
// mean of its four corners), zero-weight reflection rays traced, no shadow ray
// when N.L <= 0. Plus the SPD tetrahedron from ../shared when it is present,
// and the --stats JSON of the app.
#include <doctest/doctest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "renderer/accel/accelerator.h"
#include "renderer/accelerator_kind.h"
#include "renderer/effects.h"
#include "renderer/io/json.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render.h"
#include "renderer/render_setup.h"
#include "support/temp_dir.h"

using namespace raylab;

namespace {

// Eye at the origin looking down -z with a 90° field of view: tan(45°) = 1,
// so the ray through image position (px, py) of a W x H = 4 x 4 image has
// direction (a, b, -1) with a = 2·px/4 - 1 and b = 1 - 2·py/4.
// Sphere: centre c = (0, 0, -3), radius r = 1.7 (r² = 2.89). One light at
// (20, 0, -3) without colour: intensity sqrt(1)/2 = 0.5, ambient 0.5 too.
//
// Hits: the ray (a, b, -1) passes the centre at distance² 9·s/(1+s) with
// s = a² + b², so it hits iff 9s < 2.89(1+s), i.e. s < 2.89/6.11 = 0.4730.
// Shadow rays: at a hit p with N = (p-c)/r, N.L > 0 iff (p-c)·(ℓ-p) > 0, and
// (p-c)·(ℓ-p) = (p-c)·(ℓ-c) - r² = 20·p.x - 2.89, so iff p.x > 0.1445.
std::string sphereScene(const std::string& material, bool light = true) {
    return "v\nfrom 0 0 0\nat 0 0 -1\nup 0 1 0\nangle 90\nhither 0\nresolution 4 4\n" +
           std::string(light ? "l 20 0 -3\n" : "") + material + "\ns 0 0 -3 1.7\n";
}

const char* const kMatte = "f 1 1 1 1 0 1 0 0";
const char* const kMirror = "f 1 1 1 0.5 0.5 10 0 0";
const char* const kGlass = "f 1 1 1 0.1 0 1 0.9 1.5";

struct Rendered {
    RenderResult result;
    RenderOptions options;
};

Rendered renderNff(const std::string& text, AcceleratorKind accel, bool spd,
                   std::optional<int> width = {}, std::optional<int> height = {}) {
    const Scene scene = loadNffScene(text, "tiny.nff");
    RenderOverrides o;
    o.spd = spd;
    o.accel = accel;
    o.width = width;
    o.height = height;
    o.threads = 2;
    Rendered r;
    r.options = resolveRenderOptions(scene, o);
    const auto a = makeAccelerator(accel, scene, r.options.accelOptions);
    r.result = render(scene, *a, r.options, analyseEffects(scene, r.options));
    CHECK(r.result.nonFiniteSamples == 0);
    return r;
}

uint64_t count(const Rendered& r, RayType t) { return r.result.rays.total(t); }

}  // namespace

TEST_CASE("spd render: 4x4 pixel centres, one sphere, one light: hits and shadow rays") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        // Pixel centres a, b ∈ {±0.25, ±0.75}: only the four middle pixels
        // have s = 0.125 < 0.473 (the next, s = 0.625, misses): 4 hits. On the
        // middle rays t = 3/√1.125 - √(2.89 - 1) = 1.45366, so
        // p.x = ±0.25·t/√1.125 = ±0.34272: the two right ones (> 0.1445) cast
        // shadow rays, the two left ones face away from the light.
        const Rendered r = renderNff(sphereScene(kMatte), accel, false);
        CHECK(r.options.width == 4);  // the NFF resolution is the default
        CHECK(count(r, RayType::Camera) == 16);
        CHECK(r.result.rays.cameraHits == 4);
        CHECK(count(r, RayType::Shadow) == 2);
        CHECK(count(r, RayType::Reflection) == 0);
        CHECK(count(r, RayType::Refraction) == 0);
    }
}

TEST_CASE("spd render: the same scene in SPD mode: 25 corner rays, 5 hits, 1 shadow ray") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        // Corners a, b ∈ {-1, -0.5, 0, 0.5, 1}: s = 0 (centre) and s = 0.25
        // (the four corners next to it) hit; s = 0.5 already misses
        // (distance² 3 > 2.89): 5 hits of 25. The centre hit and the hits at
        // a = 0 have p.x = 0, the one at a = -0.5 has p.x < 0: only the
        // corner (0.5, 0) casts a shadow ray, with
        // t = 3/√1.25 - √(2.89 - 1.8) = 1.63928 and p.x = 0.5·t/√1.25 = 0.73310.
        const Rendered r = renderNff(sphereScene(kMatte), accel, true, 4, 4);
        CHECK(r.options.spd);
        CHECK(count(r, RayType::Camera) == 25);
        CHECK(r.result.rays.cameraHits == 5);
        CHECK(count(r, RayType::Shadow) == 1);
        CHECK(count(r, RayType::Reflection) == 0);  // matte: Ks = 0, T = 0
        CHECK(count(r, RayType::Refraction) == 0);

        // Each pixel is the mean of its corners. Coverage: pixel (0, 0) has
        // no hit corner, pixel (1, 0) one (the corner (0, 0.5)), the four
        // middle pixels three each.
        const Film& f = r.result.film;
        CHECK(f.rgba[4 * f.index(0, 0) + 3] == 0.0f);
        CHECK(f.rgba[4 * f.index(1, 0) + 3] == 0.25f);
        for (int y = 1; y <= 2; ++y)
            for (int x = 1; x <= 2; ++x) CHECK(f.rgba[4 * f.index(x, y) + 3] == 0.75f);

        // Radiance of pixel (2, 1): corners (0, 0.5), (0.5, 0.5), (0, 0), (0.5, 0).
        // Unlit hits give ka·Ia = 1·0.5; (0.5, 0.5) misses (black background);
        // (0.5, 0) adds kd·I·N.L with p = t·(0.5, 0, -1)/√1.25, N = (p - c)/r,
        // L = normalize(ℓ - p).
        const double t = 3 / std::sqrt(1.25) - std::sqrt(2.89 - 1.8);
        const Vec3 p = Vec3(0.5, 0, -1) * (t / std::sqrt(1.25));
        const Vec3 n = (p - Vec3(0, 0, -3)) / 1.7;
        const double nl = dot(n, normalize(Vec3(20, 0, -3) - p));
        CHECK(nl == doctest::Approx(0.35828).epsilon(1e-4));
        const double expected = (0.5 + 0.0 + 0.5 + (0.5 + 0.5 * nl)) / 4;
        CHECK(f.rgba[4 * f.index(2, 1) + 0] == doctest::Approx(expected).epsilon(1e-6));
    }
}

TEST_CASE("spd render: SPD eye rays = (W+1)(H+1), --spd means 512x512, depth 5") {
    const Scene scene = loadNffScene(sphereScene(kMatte), "tiny.nff");
    RenderOverrides o;
    o.spd = true;
    const RenderOptions spd = resolveRenderOptions(scene, o);
    CHECK(spd.width == 512);  // the SPD size, over the NFF resolution 4x4
    CHECK(spd.height == 512);
    CHECK(spd.maxDepth == 5);
    CHECK(spd.spp == 1);
    // Flags still override the SPD size; a non-square image has 8 x 6 corners.
    const Rendered r = renderNff(sphereScene(kMatte), AcceleratorKind::Embree, true, 7, 5);
    CHECK(r.result.film.width == 7);
    CHECK(count(r, RayType::Camera) == 8 * 6);
}

TEST_CASE("spd render: reflective surfaces spawn one mirror ray per hit") {
    for (const bool spd : {false, true}) {
        CAPTURE(spd);
        // Ks = 0.5 > 0: every camera hit spawns a reflection ray (depth 2),
        // which leaves the convex sphere and hits nothing.
        const Rendered r = renderNff(sphereScene(kMirror), AcceleratorKind::Embree, spd, 4, 4);
        const uint64_t hits = spd ? 5 : 4;
        CHECK(r.result.rays.cameraHits == hits);
        CHECK(count(r, RayType::Reflection) == hits);
        CHECK(r.result.rays.byDepth[size_t(RayType::Reflection)][2] == hits);
        CHECK(count(r, RayType::Refraction) == 0);
    }
}

TEST_CASE("spd render: a glass sphere: zero-weight reflections are traced only in SPD mode") {
    for (const AcceleratorKind accel : {AcceleratorKind::Embree, AcceleratorKind::Naive}) {
        CAPTURE(acceleratorName(accel));
        // T = 0.9, Ks = 0, no lights (no shadow rays). In a sphere every
        // inner hit sees the same angle as the refracted entry ray, so total
        // internal reflection never happens.
        // Default mode: the camera hit refracts in (depth 2), the inner hit
        // refracts out (depth 3, misses): 2 refraction rays per hit, and no
        // reflection ray (its weight Ks is 0).
        const Rendered plain = renderNff(sphereScene(kGlass, false), accel, false);
        CHECK(plain.result.rays.cameraHits == 4);
        CHECK(count(plain, RayType::Refraction) == 2 * 4);
        CHECK(count(plain, RayType::Reflection) == 0);
        CHECK(count(plain, RayType::Shadow) == 0);
        // SPD: every hit on a transmitter also spawns a (zero-weight)
        // reflection ray. Camera hit (depth 1): refraction + reflection at
        // depth 2; the reflection leaves, the refraction hits the inside (d 2)
        // and spawns refraction (out) + reflection (stays inside) at depth 3;
        // likewise at depths 3 and 4; the hit at depth 5 spawns nothing. Per
        // camera hit: 4 refraction and 4 reflection rays, one at each depth 2..5.
        const Rendered spd = renderNff(sphereScene(kGlass, false), accel, true, 4, 4);
        CHECK(spd.result.rays.cameraHits == 5);
        CHECK(count(spd, RayType::Refraction) == 4 * 5);
        CHECK(count(spd, RayType::Reflection) == 4 * 5);
        for (int d = 2; d <= 5; ++d) {
            CAPTURE(d);
            CHECK(spd.result.rays.byDepth[size_t(RayType::Reflection)][size_t(d)] == 5);
            CHECK(spd.result.rays.byDepth[size_t(RayType::Refraction)][size_t(d)] == 5);
        }
    }
}

TEST_CASE("spd render: a matte scene (like tetra) spawns no reflection rays") {
    // Matte triangles, a matte quad and a matte sphere in front of the eye.
    const std::string text =
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 16 16\n"
        "l 2 2 6\nf 1 0.2 0.2 1 0 100000 0 0\n"
        "p 3 -1 -1 0 1 -1 0 0 1 0\n"
        "p 4 -2 -2 -1 2 -2 -1 2 2 -1 -2 2 -1\n"
        "s 0.5 0.5 0.5 0.3\n";
    const Scene scene = loadNffScene(text, "matte.nff");
    RenderOverrides o;
    o.spd = true;
    o.width = o.height = 16;
    const RenderOptions opt = resolveRenderOptions(scene, o);
    const EffectSet effects = analyseEffects(scene, opt);
    CHECK_FALSE(effects.has(kReflection));
    CHECK_FALSE(effects.has(kRefraction));
    const Rendered r = renderNff(text, AcceleratorKind::Embree, true, 16, 16);
    CHECK(count(r, RayType::Camera) == 17 * 17);
    CHECK(r.result.rays.cameraHits > 0);
    CHECK(count(r, RayType::Shadow) > 0);
    CHECK(count(r, RayType::Reflection) == 0);
    CHECK(count(r, RayType::Refraction) == 0);
}

TEST_CASE("spd render: SPD tetra.nff at low resolution has no NaN (needs ../shared)") {
    const std::string path = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/tetra.nff";
    if (!std::filesystem::exists(path)) {
        MESSAGE("skipped: " << path << " not present");
        return;
    }
    const Scene scene = loadScene(path);
    // 4096 triangles (p 3), one light: 1 + 4096 -> one mesh object.
    CHECK(scene.primitiveCount() == 4096);
    CHECK(scene.lights.size() == 1);
    RenderOverrides o;
    o.spd = true;
    o.width = o.height = 48;
    const RenderOptions opt = resolveRenderOptions(scene, o);
    const auto accel = makeAccelerator(opt.accel, scene, opt.accelOptions);
    const RenderResult r = render(scene, *accel, opt, analyseEffects(scene, opt));
    CHECK(r.nonFiniteSamples == 0);
    for (float v : r.film.rgba) REQUIRE(std::isfinite(v));
    CHECK(r.rays.total(RayType::Camera) == 49 * 49);
    CHECK(r.rays.cameraHits > 0);
    CHECK(r.rays.cameraHits < 49 * 49);  // background around the tetrahedron
    CHECK(r.rays.total(RayType::Reflection) == 0);  // Ks = 0: matte
    CHECK(r.rays.total(RayType::Refraction) == 0);
}

TEST_CASE("spd render: raylab render --spd --stats writes the SPD statistics") {
    const test::TempDir dir;
    const std::string nff = dir.write("tiny.nff", sphereScene(kMatte));
    const std::string stats = dir.file("stats.json");
    const std::string cmd = std::string(RAYLAB_BINARY) + " render '" + nff + "' -o '" +
                            dir.file("out.exr") + "' --spd --width 4 --height 4 --stats '" + stats +
                            "' --quiet >/dev/null 2>&1";
    const int status = std::system(cmd.c_str());
    REQUIRE(WIFEXITED(status));
    REQUIRE(WEXITSTATUS(status) == 0);
    const JsonValue json = parseJson(test::readFile(stats), stats);
    const JsonValue* rays = json.find("rays");
    REQUIRE(rays);
    // The counts derived in "the same scene in SPD mode" above.
    CHECK(rays->find("camera")->asNumber() == 25);
    CHECK(json.find("camera_hits")->asNumber() == 5);
    CHECK(rays->find("shadow")->asNumber() == 1);
    CHECK(rays->find("reflection")->asNumber() == 0);
    CHECK(rays->find("refraction")->asNumber() == 0);
    const JsonValue* time = json.find("time_s");
    REQUIRE(time);
    for (const char* key : {"parse", "build", "render"}) {
        CAPTURE(key);
        REQUIRE(time->find(key));
        CHECK(time->find(key)->asNumber() >= 0);
    }
}
