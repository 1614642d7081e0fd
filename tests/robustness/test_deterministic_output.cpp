// The EXR a render writes depends only on what defines the image: not on
// --threads, the output names, --quiet, a PNG or statistics beside it.
// Issue 22: the header recorded the whole command line, so the bytes
// differed with --threads.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "robustness_helpers.h"

using namespace raylab::robust;

TEST_CASE("deterministic output: EXR bytes do not depend on threads, names or side outputs") {
    TempDir dir;
    const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    std::filesystem::create_directories(dir.file("elsewhere"));
    const std::vector<std::vector<std::string>> runs = {
        {"-o", dir.file("a.exr"), "--threads", "1", "--quiet"},
        {"-o", dir.file("b.exr"), "--threads", "2", "--png", dir.file("b.png"), "--exposure", "1"},
        {"--quiet", "--stats", dir.file("c.json"), "--output", dir.file("elsewhere/c.exr")},
    };
    std::vector<std::string> bytes;
    for (const std::vector<std::string>& flags : runs) {
        std::vector<std::string> args{"render", scene, "--width", "48", "--height", "32"};
        args.insert(args.end(), flags.begin(), flags.end());
        const RunResult r = runRaylab(args);
        REQUIRE(r.exitCode == 0);
    }
    const std::string a = readFile(dir.file("a.exr"));
    CHECK(a.size() > 1000);
    CHECK(readFile(dir.file("b.exr")) == a);
    CHECK(readFile(dir.file("elsewhere/c.exr")) == a);
    // What defines the image is still recorded: the scene and the settings that change it.
    CHECK(contains(a, scene));
    CHECK(contains(a, "width=48 height=32 "));
    const RunResult r = runRaylab({"render", scene, "--width", "48", "--height", "32", "--alpha", "opaque",
                                   "-o", dir.file("d.exr"), "--quiet"});
    REQUIRE(r.exitCode == 0);
    CHECK(readFile(dir.file("d.exr")) != a);
}
