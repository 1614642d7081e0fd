// Issue 22 item 7: a light of colour 1.7e308 x intensity 10 rendered black,
// and two lights of 1.7e308 a black crescent where both reach. Now a product
// of inputs that overflows is refused at its line (JSON light colour x
// intensity, NFF colour x Kd, MTL values beyond float range), and every
// other overflow of radiance saturates at the largest value (never Inf, never
// NaN, never black): in every scene format, checked on the real binary's EXR
// (float pixels) and statistics.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include "renderer/film.h"
#include "renderer/io/exr_reader.h"
#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

/// Renders `scene` at 16x16 with float pixels and statistics; the film.
raylab::Film renderFloat(const TempDir& dir, const std::string& scene, std::string& stats,
                         const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"render", scene, "-o", dir.file("out.exr"), "--float",
                                  "--width", "16", "--height", "16", "--stats",
                                  dir.file("stats.json"), "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runRaylab(args);
    CAPTURE(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(r.err.empty());
    stats = readFile(dir.file("stats.json"));
    return raylab::readExr(dir.file("out.exr"));
}

struct PixelCounts {
    int lit = 0;         ///< some channel > 0
    int nonFinite = 0;   ///< NaN or Inf in a channel
    int saturated = 0;   ///< some channel at the largest float
};

PixelCounts countPixels(const raylab::Film& film) {
    PixelCounts c;
    for (int i = 0; i < film.width * film.height; ++i) {
        bool lit = false, bad = false, top = false;
        for (int k = 0; k < 3; ++k) {
            const float v = film.rgba[size_t(4 * i + k)];
            lit = lit || v > 0;
            bad = bad || !std::isfinite(v);
            top = top || v == FLT_MAX;
        }
        c.lit += lit;
        c.nonFinite += bad;
        c.saturated += top;
    }
    return c;
}

/// A white diffuse sphere seen from +z, lit by `lights` (JSON array text).
std::string jsonSphere(const std::string& lights, const std::string& extra = "") {
    return "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 30},\n" + extra +
           " \"lights\": " + lights + ",\n"
           " \"materials\": {\"white\": {\"kd\": 1, \"ka\": 0}},\n"
           " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1,"
           " \"material\": \"white\"}]}\n";
}

const std::string kLeft = "{\"type\": \"point\", \"position\": [-4, 0, 3], \"color\": 1.7e308}";
const std::string kRight = "{\"type\": \"point\", \"position\": [4, 0, 3], \"color\": 1.7e308}";

}  // namespace

TEST_CASE("overflow, JSON: colour x intensity beyond a double is refused at its line") {
    TempDir dir;
    const std::string scene = dir.write(
        "s.json", jsonSphere("[{\"type\": \"point\", \"position\": [0, 0, 5],\n"
                             "   \"color\": 1.7e308, \"intensity\": 10}]"));
    const RunResult r = runRaylab(tinyRender(dir, scene));
    checkRefused(r, dir, {"s.json"}, 1, scene + ":3:",
                 "lights[0].intensity: color x intensity overflows a double (1.7e+308 x 10)");
}

TEST_CASE("overflow, JSON: two lights of 1.7e308 light every pixel either lights, none black") {
    TempDir dir;
    std::string stats;
    const PixelCounts left = countPixels(renderFloat(dir, dir.write("l.json", jsonSphere("[" + kLeft + "]")), stats));
    const PixelCounts right = countPixels(renderFloat(dir, dir.write("r.json", jsonSphere("[" + kRight + "]")), stats));
    const raylab::Film both = renderFloat(dir, dir.write("b.json", jsonSphere("[" + kLeft + ", " + kRight + "]")), stats);
    const raylab::Film leftFilm = renderFloat(dir, dir.file("l.json"), stats);
    const raylab::Film rightFilm = renderFloat(dir, dir.file("r.json"), stats);
    const PixelCounts b = countPixels(both);
    CHECK(left.lit > 0);
    CHECK(right.lit > 0);
    CHECK(b.nonFinite == 0);
    // Every pixel one light reaches is lit with both (the sum overflowed
    // where both reach: before the fix, a black crescent).
    int lostPixels = 0, overlap = 0;
    for (int i = 0; i < 16 * 16; ++i) {
        const bool l = leftFilm.rgba[size_t(4 * i)] > 0, r = rightFilm.rgba[size_t(4 * i)] > 0;
        overlap += l && r;
        if ((l || r) && !(both.rgba[size_t(4 * i)] > 0)) ++lostPixels;
    }
    CHECK(overlap > 0);
    CHECK(lostPixels == 0);
    CHECK(b.saturated >= overlap);
    // The integrator saturated the sum itself: no sample had to be replaced.
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
}

TEST_CASE("overflow, JSON: ambient, mirror and filtered-shadow products saturate, not black") {
    TempDir dir;
    std::string stats;
    // ka x ambient = 1e200 x 1e200, no light at all.
    const std::string ambient =
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 30},\n"
        " \"ambient\": 1e200, \"lights\": [],\n"
        " \"materials\": {\"m\": {\"kd\": 0, \"ka\": 1e200}},\n"
        " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]}\n";
    PixelCounts c = countPixels(renderFloat(dir, dir.write("a.json", ambient), stats));
    CHECK(c.lit > 0);
    CHECK(c.saturated == c.lit);
    CHECK(c.nonFinite == 0);
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
    // km x background = 1e300 x 1e300: every reflection ray misses.
    const std::string mirror =
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 30},\n"
        " \"background\": 1e300, \"lights\": [],\n"
        " \"materials\": {\"m\": {\"kd\": 0, \"ka\": 0, \"km\": 1e300}},\n"
        " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, \"material\": \"m\"}]}\n";
    c = countPixels(renderFloat(dir, dir.write("m.json", mirror), stats));
    CHECK(c.saturated == 16 * 16);  // the background is 1e300 too: beyond float everywhere
    CHECK(c.nonFinite == 0);
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
    // A shadow feeler through two glass surfaces of kt 1e200 (product 1e400),
    // light 1: the light arrives saturated at a surface of kd 1e-300.
    const std::string filtered =
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 30},\n"
        " \"lights\": [{\"type\": \"directional\", \"direction\": [0, 0, -1]}],\n"
        " \"materials\": {\"glass\": {\"kd\": 0, \"kt\": 1e200, \"ior\": 1},\n"
        "               \"floor\": {\"kd\": 1e-300, \"ka\": 0}},\n"
        " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 2, \"material\": \"glass\"},\n"
        "              {\"type\": \"sphere\", \"center\": [0, 0, -3], \"radius\": 0.5, \"material\": \"floor\"}]}\n";
    c = countPixels(renderFloat(dir, dir.write("f.json", filtered), stats));
    CHECK(c.lit > 0);
    CHECK(c.nonFinite == 0);
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
}

TEST_CASE("overflow, NFF: colour x Kd refused at its line, lights of 1.7e308 never black") {
    TempDir dir;
    const std::string view =
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 30\nhither 0.01\nresolution 16 16\n";
    const std::string bad = dir.write("bad.nff", view + "b 0 0 0\nl 0 0 5\nf 1e300 1 1 1e10 0 0 0 0\ns 0 0 0 1\n");
    const RunResult r = runRaylab(tinyRender(dir, bad));
    checkRefused(r, dir, {"bad.nff"}, 1, bad + ":10:", "colour x Kd overflows a double");

    std::string stats;
    const std::string two = dir.write(
        "two.nff", view + "b 0 0 0\nl -4 0 3 1.7e308 1.7e308 1.7e308\nl 4 0 3 1.7e308 1.7e308 1.7e308\n"
                          "f 1 1 1 1 0 0 0 0\ns 0 0 0 1\n");
    const std::string one = dir.write(
        "one.nff", view + "b 0 0 0\nl -4 0 3 1.7e308 1.7e308 1.7e308\nf 1 1 1 1 0 0 0 0\ns 0 0 0 1\n");
    const raylab::Film oneFilm = renderFloat(dir, one, stats);
    const raylab::Film twoFilm = renderFloat(dir, two, stats);
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
    CHECK(countPixels(twoFilm).nonFinite == 0);
    int lost = 0;
    for (int i = 0; i < 16 * 16; ++i)
        if (oneFilm.rgba[size_t(4 * i)] > 0 && !(twoFilm.rgba[size_t(4 * i)] > 0)) ++lost;
    CHECK(countPixels(oneFilm).lit > 0);
    CHECK(lost == 0);
}

TEST_CASE("overflow, OBJ/MTL: values beyond float range refused at their line, kd x light saturates") {
    TempDir dir;
    const std::string quad = "mtllib m.mtl\nusemtl hot\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    dir.write("q.obj", quad);
    dir.write("m.mtl", "newmtl hot\nKd 1e39 1 1\n");
    const std::string scene = dir.write(
        "s.json", "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 30},\n"
                  " \"lights\": [{\"type\": \"point\", \"position\": [0, 0, 5], \"color\": 1e300}],\n"
                  " \"objects\": [{\"type\": \"mesh\", \"file\": \"q.obj\"}]}\n");
    const RunResult r = runRaylab(tinyRender(dir, scene));
    checkRefused(r, dir, {"m.mtl", "q.obj", "s.json"}, 1, dir.file("m.mtl") + ":2:",
                 "'Kd': '1e39' is beyond float range (about 3.4e38)");

    // Kd 3e38 (a float) x light 1e300 overflows a double: saturated, lit.
    dir.write("m.mtl", "newmtl hot\nKd 3e38 3e38 3e38\nKa 0 0 0\n");
    std::string stats;
    const PixelCounts c = countPixels(renderFloat(dir, scene, stats));
    CHECK(c.lit > 0);
    CHECK(c.saturated == c.lit);
    CHECK(c.nonFinite == 0);
    CHECK(contains(stats, "\"non_finite_samples\": 0"));
}
