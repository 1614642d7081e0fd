// Alpha cut-outs (issue 19): where a material's alpha is below its cut-off
// the surface is a hole for every ray. Exact pixels of a masked quad over a
// lit floor, derived by hand below, through both accelerators: camera rays
// through the holes, shadow feelers through the holes, two masks in a row,
// and a uniform alpha on an analytic sphere.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "geometry/random.h"
#include "io/io_test_helpers.h"
#include "renderer/accel/embree_accelerator.h"
#include "renderer/accel/naive_accelerator.h"
#include "renderer/effects.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render_setup.h"
#include "renderer/whitted_integrator.h"
#include "renderer/shadow_cache_pixels.h"

using namespace raylab;
using raylab::test::TempDir;

namespace {

/// A unit quad in z = `z` over x, y in [0, 1], uv = (x, y), facing +z.
std::string quadObj(double z) {
    const std::string h = std::to_string(z);
    return "v 0 0 " + h + "\nv 1 0 " + h + "\nv 1 1 " + h + "\nv 0 1 " + h +
           "\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
}

/// The scene: a floor (kd 0.5) at z = 0; a white quad at z = 1 whose alpha is
/// a checker of 2 × 2 squares, black (a hole) where floor(2u) + floor(2v) is
/// even; `upperMask`: also a dark quad (kd 0.25) at z = 2 with a 4 × 4
/// checker. One directional light travelling along (-1, 0, -1)/√2, no
/// ambient; an orthographic camera looking down on x in [-1, 1], y in [0, 1].
std::string sceneJson(bool upperMask, const std::string& extra = "") {
    std::string objects =
        R"({"type": "polygon", "vertices": [[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], "material": "floor"},
           {"type": "mesh", "file": "q1.obj", "material": "mask1"})";
    if (upperMask) objects += R"(, {"type": "mesh", "file": "q2.obj", "material": "mask2"})";
    return R"({"camera": {"type": "orthographic", "eye": [0, 0.5, 5], "direction": [0, 0, -1], "width": 2},
        "lights": [{"type": "directional", "direction": [-1, 0, -1]}],
        "materials": {
          "floor": {"kd": [0.5, 0.5, 0.5]},
          "mask1": {"kd": [1, 1, 1], "alpha": {"checker": [[0, 0, 0], [1, 1, 1]], "scale": [2, 2]}},
          "mask2": {"kd": [0.25, 0.25, 0.25], "alpha": {"checker": [[0, 0, 0], [1, 1, 1]], "scale": [4, 4]}})" +
           extra + R"(},
        "objects": [)" +
           objects + "]}";
}

bool hole(double u, double v, double squares) {
    return (int(std::floor(squares * u)) + int(std::floor(squares * v))) % 2 == 0;
}

/// The pixel at (x, y) by hand. Lit surfaces facing +z see N·L = 1/√2.
double expected(double x, double y, bool upperMask) {
    const double lit = 1 / std::sqrt(2.0);
    const bool inQuad = x > 0 && x < 1;
    if (upperMask && inQuad && !hole(x, y, 4)) return 0.25 * lit;  // the z = 2 quad
    if (inQuad && !hole(x, y, 2)) return 1.0 * lit;                 // the z = 1 quad
    // The floor: its feeler towards (+1, 0, +1) meets z = 1 at x + 1 (the z = 1
    // quad when that is in [0, 1]) and z = 2 at x + 2 (beyond the upper quad).
    const double xs = x + 1;
    const bool shadowed = xs > 0 && xs < 1 && !hole(xs, y, 2);
    return shadowed ? 0.0 : 0.5 * lit;
}

}  // namespace

TEST_CASE("cut-outs: a masked quad over a lit floor, exact pixels, both accelerators") {
    for (bool upperMask : {false, true}) {
        CAPTURE(upperMask);
        TempDir dir;
        dir.write("q1.obj", quadObj(1));
        dir.write("q2.obj", quadObj(2));
        const Scene scene = loadScene(dir.write("s.json", sceneJson(upperMask)));
        const RenderOptions options = resolveRenderOptions(scene, {});
        CHECK(analyseEffects(scene, options).cutOuts);
        int holes = 0, shadows = 0;
        for (const char* accel : {"embree", "naive"}) {
            CAPTURE(accel);
            // 16 × 8 pixels of 0.125: centres at x = -0.9375 + 0.125 i, never
            // on a checker edge (multiples of 0.25).
            const Film film = test::renderFilm(scene, accel, 16, 8);
            for (int j = 0; j < 8; ++j) {
                for (int i = 0; i < 16; ++i) {
                    const double x = -1 + 0.125 * (i + 0.5), y = 1 - 0.125 * (j + 0.5);
                    CAPTURE(x);
                    CAPTURE(y);
                    const size_t p = film.index(i, j);
                    const double want = expected(x, y, upperMask);
                    CHECK(film.rgba[4 * p] == doctest::Approx(want).epsilon(1e-6));
                    CHECK(film.rgba[4 * p + 2] == doctest::Approx(want).epsilon(1e-6));
                    if (x > 0 && hole(x, y, 2)) ++holes;
                    if (want == 0) ++shadows;
                }
            }
        }
        // The scene has both kinds of pixel, so the checks above saw them.
        CHECK(holes > 0);
        CHECK(shadows > 0);
    }
}

TEST_CASE("cut-outs: a uniform alpha below the cut-off removes any primitive, shadow too") {
    TempDir dir;
    dir.write("q1.obj", quadObj(1));
    const std::string without = sceneJson(false);
    const auto render = [&](const std::string& json, const char* accel) {
        return test::renderFilm(loadScene(dir.write("s.json", json)), accel, 16, 8);
    };
    // A sphere over the floor's shadowed and lit parts, fully below its cut-off.
    std::string with = without;
    const std::string sphere =
        R"({"type": "sphere", "center": [-0.5, 0.5, 0.5], "radius": 0.4, "material": "ghost"}, )";
    with.insert(with.find("\"objects\": [") + 12, sphere);
    with.insert(with.find("\"mask2\""), R"("ghost": {"kd": [1, 0, 0], "alpha": 0.4, "alpha_cutoff": 0.5}, )");
    for (const char* accel : {"embree", "naive"}) {
        CAPTURE(accel);
        const Film a = render(without, accel), b = render(with, accel);
        CHECK(a.rgba == b.rgba);
    }
    // At alpha 0.6 it is there (and red).
    std::string visible = with;
    visible.replace(visible.find("\"alpha\": 0.4"), 12, "\"alpha\": 0.6");
    const Film c = render(visible, "embree");
    const size_t p = c.index(3, 4);  // x = -0.5625, y = 0.4375: on the sphere
    CHECK(c.rgba[4 * p] > 0);
    CHECK(c.rgba[4 * p + 1] == 0);
}

TEST_CASE("cut-outs: alpha values are checked") {
    TempDir dir;
    dir.write("q1.obj", quadObj(1));
    for (const char* bad : {R"(, "bad": {"alpha": 1.5})", R"(, "bad": {"alpha_cutoff": -0.1})"}) {
        CAPTURE(bad);
        const test::Failure f =
            test::failureOf([&] { loadScene(dir.write("s.json", sceneJson(false, bad))); });
        CHECK(f.message.find("must be in [0, 1]") != std::string::npos);
    }
}

namespace {

/// Analytic shapes (Embree user geometry, which the shadow cache names as
/// occluders) over a floor: a solid sphere, and beside it a sphere and a
/// polygon card whose checker masks cut holes; a light low enough that
/// their shadows lie side by side, seen from above through the holes.
std::string cacheSceneJson() {
    return R"({"camera": {"type": "orthographic", "eye": [0, 0, 6], "direction": [0, 0, -1], "width": 6},
        "lights": [{"type": "directional", "direction": [-0.6, 0.2, -1]}],
        "ambient": [0.1, 0.1, 0.1],
        "materials": {
          "floor": {"kd": [0.5, 0.5, 0.5]},
          "solid": {"kd": [0.2, 0.6, 0.2]},
          "holes": {"kd": [0.8, 0.2, 0.2], "alpha": {"checker": [[0, 0, 0], [1, 1, 1]], "scale": [12, 6]}},
          "card": {"kd": [0.2, 0.2, 0.8], "alpha": {"checker": [[0, 0, 0], [1, 1, 1]], "scale": [5, 5]}}},
        "objects": [
          {"type": "polygon", "vertices": [[-8, -8, 0], [8, -8, 0], [8, 8, 0], [-8, 8, 0]], "material": "floor"},
          {"type": "sphere", "center": [-1.6, 0.3, 0.9], "radius": 0.7, "material": "solid"},
          {"type": "sphere", "center": [-0.1, 0.3, 0.9], "radius": 0.7, "material": "holes"},
          {"type": "polygon", "sides": "both", "material": "card",
           "vertices": [[0.9, -1, 0.6], [2.3, -1, 0.6], [2.3, 1, 1.2], [0.9, 1, 1.2]]},
          {"type": "sphere", "center": [1.6, 1.9, 0.5], "radius": 0.4, "material": "solid"}]})";
}

}  // namespace

TEST_CASE("cut-outs: the shadow cache changes no pixel, holes in shadows next to solid ones") {
    TempDir dir;
    const Scene scene = loadScene(dir.write("s.json", cacheSceneJson()));
    RenderOverrides o;
    o.width = 96;
    o.height = 64;
    const RenderOptions options = resolveRenderOptions(scene, o);
    const EffectSet effects = analyseEffects(scene, options);
    REQUIRE(effects.cutOuts);
    REQUIRE(effects.has(kShadows));
    EmbreeAccelerator embree(scene, options.accelOptions);
    NaiveAccelerator naive(scene, options.accelOptions);
    {
        // The cache carried across pixels: a solid sphere's hint reaches
        // pixels in a hole's shadow.
        int lit = 0, dark = 0;
        for (const Color& c :
             pixelsInBothAccelerators(scene, naive, embree, options, effects, *o.width, *o.height)) {
            // The floor (grey): in shadow it keeps the ambient only.
            if (c.r == c.g && c.g == c.b) (c.r > 0.06 ? lit : dark)++;
        }
        // Floor both lit and shadowed, so the cache had occluders to name.
        CHECK(lit > 500);
        CHECK(dark > 200);
    }
    // A hint naming a masked primitive must not skip its mask: every user
    // entry as the hint of shadow feelers through the holes gives occluded()'s
    // answer (entries: floor 0, solid 1, holes 2, card 3, solid 4).
    SplitMix64 rng(11);
    int blocked = 0, passed = 0;
    for (int k = 0; k < 3000; ++k) {
        const Vec3 from{rng.uniform(-3, 3), rng.uniform(-2, 2), 0.01};
        const Vec3 to = from + Vec3{0.6, -0.2, 1} * 4.0;
        const Ray ray{from, to - from};
        const bool expected = naive.occluded(ray, 1e-9, 1.0);
        CHECK(embree.occluded(ray, 1e-9, 1.0) == expected);
        for (uint32_t entry = 0; entry < 5; ++entry) {
            OcclusionHint hint{entry};
            CHECK(embree.occluded(ray, 1e-9, 1.0, hint) == expected);
        }
        (expected ? blocked : passed)++;
    }
    CHECK(blocked > 300);
    CHECK(passed > 300);
}

TEST_CASE("cut-outs: --alpha-cutoff overrides every material's cut-off, and render.alpha_cutoff") {
    TempDir dir;
    dir.write("q1.obj", quadObj(1));
    // The ghost sphere has alpha 0.4: a hole at its own cut-off 0.5, there at 0.3.
    std::string json = sceneJson(false);
    json.insert(json.find("\"objects\": [") + 12,
                R"({"type": "sphere", "center": [-0.5, 0.5, 0.5], "radius": 0.4, "material": "ghost"}, )");
    const auto withGhost = [&](const std::string& cutoff) {
        std::string j = json;
        j.insert(j.find("\"mask1\""), R"("ghost": {"kd": [1, 0, 0], "alpha": 0.4, "alpha_cutoff": )" +
                                          cutoff + "}, ");
        return j;
    };
    const auto film = [&](const std::string& text, std::optional<double> cutoff, const char* accel) {
        const Scene scene = loadScene(dir.write("s.json", text));
        RenderOverrides o;
        o.width = 16;
        o.height = 8;
        o.spp = 1;
        o.alphaCutoff = cutoff;
        o.accel = std::string(accel) == "naive" ? AcceleratorKind::Naive : AcceleratorKind::Embree;
        const RenderOptions options = resolveRenderOptions(scene, o);
        const auto a = makeAccelerator(options.accel, scene, options.accelOptions);
        return render(scene, *a, options, analyseEffects(scene, options)).film.rgba;
    };
    for (const char* accel : {"embree", "naive"}) {
        CAPTURE(accel);
        const auto own03 = film(withGhost("0.3"), std::nullopt, accel);
        const auto own05 = film(withGhost("0.5"), std::nullopt, accel);
        CHECK(own03 != own05);
        CHECK(film(withGhost("0.5"), 0.3, accel) == own03);  // the flag wins
        CHECK(film(withGhost("0.3"), 0.5, accel) == own05);
        // The masks' checker (0 or 1) cuts the same at any cut-off in (0, 1].
        CHECK(film(withGhost("0.3"), 0.9, accel) == own05);
        // A cut-off of 0 keeps every hit: no hole anywhere, no mask shadow gap.
        std::string solid = withGhost("0");
        for (const char* m : {"\"mask1\": {", "\"mask2\": {"})
            solid.replace(solid.find(m), std::string(m).size(), std::string(m) + "\"alpha_cutoff\": 0, ");
        CHECK(film(withGhost("0.5"), 0.0, accel) == film(solid, std::nullopt, accel));
        // JSON render.alpha_cutoff, overridden by the flag in turn.
        std::string keyed = withGhost("0.5");
        keyed.insert(keyed.find("\"lights\""), R"("render": {"alpha_cutoff": 0.3}, )");
        CHECK(film(keyed, std::nullopt, accel) == own03);
        CHECK(film(keyed, 0.5, accel) == own05);
    }
    // Out of range: one error line at the key.
    std::string bad = withGhost("0.5");
    bad.insert(bad.find("\"lights\""), R"("render": {"alpha_cutoff": 1.5}, )");
    const test::Failure f = test::failureOf([&] { loadScene(dir.write("s.json", bad)); });
    CHECK(f.message.find("alpha_cutoff") != std::string::npos);
    CHECK(f.message.find("must be in [0, 1]") != std::string::npos);
}

TEST_CASE("cut-outs: packets of rays see the holes as single rays do") {
    // The mesh filter decides each lane of an Embree packet with that lane's
    // own exact ray (EmbreeQueryContext::lanes): rows of 8 rays down through
    // both masks answer as intersect() answers them one by one.
    TempDir dir;
    dir.write("q1.obj", quadObj(1));
    dir.write("q2.obj", quadObj(2));
    const Scene scene = loadScene(dir.write("s.json", sceneJson(true)));
    const RenderOptions options = resolveRenderOptions(scene, {});
    EmbreeAccelerator embree(scene, options.accelOptions);
    CHECK(embree.tracesPackets());
    SplitMix64 rng(3);
    int floorHits = 0, maskHits = 0;
    constexpr int kLanes = Accelerator::kPacketRays;  // one full packet
    for (int n = 0; n < 500; ++n) {
        Ray rays[kLanes];
        double tMin[kLanes], tMax[kLanes];
        const double y = rng.uniform(0, 1);
        for (int k = 0; k < kLanes; ++k) {
            rays[k] = Ray{Vec3{rng.uniform(-0.5, 1.5), y, 5}, Vec3{rng.uniform(-0.2, 0.2), 0, -1}};
            tMin[k] = 0;
            tMax[k] = std::numeric_limits<double>::infinity();
        }
        std::optional<Hit> packet[kLanes];
        embree.intersectPacket(rays, tMin, tMax, kLanes, packet);
        for (int k = 0; k < kLanes; ++k) {
            const std::optional<Hit> single = embree.intersect(rays[k], tMin[k], tMax[k]);
            REQUIRE(packet[k].has_value() == single.has_value());
            if (!single) continue;
            CHECK(packet[k]->object == single->object);
            CHECK(packet[k]->prim == single->prim);
            CHECK(packet[k]->t == single->t);
            (single->object == 0 ? floorHits : maskHits)++;
        }
    }
    CHECK(floorHits > 500);  // through the holes of both masks
    CHECK(maskHits > 500);
}
