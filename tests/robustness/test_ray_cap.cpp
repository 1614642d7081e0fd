// Bounded work per camera sample (issue 22 item 6): a glass sphere inside a
// mirror sphere doubles its ray tree at every level, so at --depth 64 a
// single pixel would never finish. Once a sample has traced
// RenderOptions::maxRaysPerSample rays (every type) it traces no further
// reflection or refraction ray; such samples are counted in --stats and the
// summary, and the run warns once. Counts and bytes, never timings.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "renderer/render_options.h"
#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

/// One pixel inside a mirror sphere without lights: every hit spawns exactly
/// one reflection ray and no shadow ray, so a sample traces a chain of
/// min(depth, cap) rays: the camera ray and depth - 1 reflections.
std::string mirrorChain(const std::string& renderBlock) {
    return "{\"image\": {\"width\": 1, \"height\": 1, \"depth\": 64},\n" + renderBlock +
           " \"camera\": {\"eye\": [0, 0, 0.5], \"look_at\": [0, 0, -1]},\n"
           " \"lights\": [],\n"
           " \"materials\": {\"mirror\": {\"kd\": 0, \"km\": 1}},\n"
           " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 3,\n"
           "               \"material\": \"mirror\", \"sides\": \"inside\"}]}\n";
}

/// The number after `"key": ` in a --stats document (-1 when absent).
long long statNumber(const std::string& json, const std::string& key) {
    const size_t at = json.find("\"" + key + "\": ");
    if (at == std::string::npos) return -1;
    return std::stoll(json.substr(at + key.size() + 4));
}

/// The statistics without the lines that depend on time or thread count.
std::string countsOnly(const std::string& json) {
    std::string out;
    for (const std::string& line : lines(json))
        if (!contains(line, "\"parse\"") && !contains(line, "\"build\"") &&
            !contains(line, "\"render\"") && !contains(line, "\"write\"") &&
            !contains(line, "mrays_per_s") && !contains(line, "\"threads\""))
            out += line + "\n";
    return out;
}

}  // namespace

TEST_CASE("ray cap: glass inside a mirror at depth 64 ends capped, counted, warned once, "
          "identical for any thread count") {
    TempDir dir;
    const std::string scene = dir.write("deep.json", kGlassInMirrorScene);
    std::vector<std::string> exr, stats;
    for (const char* threads : {"1", "2"}) {
        const std::string n = threads;
        const RunResult r = runRaylab({"render", scene, "-o", dir.file("t" + n + ".exr"), "--stats",
                                       dir.file("t" + n + ".json"), "--threads", threads});
        CAPTURE(r.err);
        REQUIRE_FALSE(r.timedOut);
        CHECK(r.exitCode == 0);
        // Every one of the 16 samples reaches the cap: one warning says so.
        CHECK(lines(r.err) ==
              std::vector<std::string>{
                  "raylab: warning: 16 of 16 camera samples reached the cap of 65536 rays per "
                  "sample; their deeper reflections and refractions were not traced (--max-rays, "
                  "--depth)"});
        CHECK(contains(r.out, "  samples:  at most "));
        CHECK(contains(r.out, " rays in one sample, 16 capped at 65536\n"));
        exr.push_back(readFile(dir.file("t" + n + ".exr")));
        stats.push_back(readFile(dir.file("t" + n + ".json")));
    }
    CHECK(raylab::kDefaultMaxRaysPerSample == 65536);
    CHECK(statNumber(stats[0], "rays_per_sample") == 65536);
    CHECK(statNumber(stats[0], "capped_samples") == 16);
    // A sample stops branching at the cap; the hit of its last ray still
    // sends its one shadow feeler: at most cap + 1 rays.
    const long long most = statNumber(stats[0], "most_rays_in_a_sample");
    CHECK(most >= 65536);
    CHECK(most <= 65536 + 1);
    // 16 samples of at most cap + 1 rays each.
    CHECK(statNumber(stats[0], "total") <= 16 * (65536 + 1));
    CHECK(statNumber(stats[0], "camera") == 16);
    CHECK(exr[0] == exr[1]);
    CHECK(countsOnly(stats[0]) == countsOnly(stats[1]));
}

TEST_CASE("ray cap: the cut falls at exactly the cap (a chain of mirror reflections)") {
    TempDir dir;
    struct Case {
        std::vector<std::string> flags;
        std::string renderBlock;
        long long rays, capped;
    };
    const std::vector<Case> cases = {
        // Depth 64 ends the chain first: 64 rays, nothing capped.
        {{}, "", 64, 0},
        {{"--max-rays", "64"}, "", 64, 0},
        // 63 rays traced (camera + 62 reflections), then the 64th is refused.
        {{"--max-rays", "63"}, "", 63, 1},
        {{"--max-rays", "10"}, "", 10, 1},
        {{"--max-rays", "1"}, "", 1, 1},
        // The scene file's render block sets it too; the flag wins.
        {{}, " \"render\": {\"max_rays\": 5},\n", 5, 1},
        {{"--max-rays", "7"}, " \"render\": {\"max_rays\": 5},\n", 7, 1},
    };
    for (const Case& c : cases) {
        const std::string scene = dir.write("chain.json", mirrorChain(c.renderBlock));
        std::vector<std::string> args{"render", scene, "-o", dir.file("out.exr"), "--stats",
                                      dir.file("s.json"), "--quiet"};
        args.insert(args.end(), c.flags.begin(), c.flags.end());
        const RunResult r = runRaylab(args);
        CAPTURE(r.err);
        CAPTURE(c.rays);
        REQUIRE(r.exitCode == 0);
        const std::string s = readFile(dir.file("s.json"));
        CHECK(statNumber(s, "total") == c.rays);
        CHECK(statNumber(s, "reflection") == c.rays - 1);
        CHECK(statNumber(s, "shadow") == 0);
        CHECK(statNumber(s, "most_rays_in_a_sample") == c.rays);
        CHECK(statNumber(s, "capped_samples") == c.capped);
        CHECK(lines(r.err).size() == size_t(c.capped));
        if (c.capped) CHECK(contains(r.err, "1 of 1 camera samples reached the cap"));
    }
}

TEST_CASE("ray cap: out-of-range caps are refused (flag: usage, file: its line)") {
    TempDir dir;
    const std::string scene = dir.write("chain.json", mirrorChain(""));
    for (const char* bad : {"0", "-1", "1099511627777", "1e3", "many"}) {
        CAPTURE(bad);
        const RunResult r = runRaylab(
            {"render", scene, "-o", dir.file("out.exr"), "--max-rays", bad, "--quiet"});
        checkRefused(r, dir, {"chain.json"}, 2, "", "--max-rays");
    }
    const std::string zero = dir.write("zero.json", mirrorChain(" \"render\": {\"max_rays\": 0},\n"));
    const RunResult r = runRaylab({"render", zero, "-o", dir.file("out.exr"), "--quiet"});
    checkRefused(r, dir, {"chain.json", "zero.json"}, 1, zero + ":2:", "render.max_rays");
}
