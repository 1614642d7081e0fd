// The memory guard: a render whose buffers cannot fit in this machine's
// memory is refused before anything is allocated (checkMemoryBudget), in
// every format; small files that expand into huge scenes stay bounded.
#include <doctest/doctest.h>

#include <unistd.h>

#include <string>

#include "renderer/io/errors.h"
#include "renderer/io/scene_loader.h"
#include "renderer/render_setup.h"
#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

double machineMemory() {
    return double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
}

/// Film bytes per pixel as checkMemoryBudget counts them: 12 floats
/// (RGBA, Z, N, albedo, objectId) and as much again for the encoders.
constexpr double kBytesPerPixel = 12 * 4 * 2;

}  // namespace

TEST_CASE("memory guard: NFF 'resolution 60000 60000' is refused up front") {
    // 60000^2 x 96 bytes = 3.456e11 bytes (about 322 GiB).
    if (60000.0 * 60000.0 * kBytesPerPixel <= 0.8 * machineMemory()) return;
    Scratch dir;
    const std::string scene = dir.write(
        "big.nff", "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nresolution 60000 60000\n"
                   "s 0 0 0 1\n");
    const RunResult r =
        runRaylab({"render", scene, "-o", dir.file("out.exr"), "--quiet"}, 30);
    checkRefused(r, dir, {"big.nff"}, 1, scene + ":", "60000x60000");
    CHECK(contains(r.err, "MiB"));
    CHECK(r.seconds < 10);
}

TEST_CASE("memory guard: a huge JSON image is refused up front") {
    // 32768^2 x 96 bytes = 1.03e11 bytes (96 GiB).
    if (32768.0 * 32768.0 * kBytesPerPixel <= 0.8 * machineMemory()) return;
    Scratch dir;
    const std::string scene = dir.write(
        "big.json", "{\"image\": {\"width\": 32768, \"height\": 32768},\n"
                    " \"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
                    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0],"
                    " \"radius\": 1}]}\n");
    const RunResult r =
        runRaylab({"render", scene, "-o", dir.file("out.exr"), "--quiet"}, 30);
    checkRefused(r, dir, {"big.json"}, 1, scene + ":", "32768x32768");
    CHECK(r.seconds < 10);
}

TEST_CASE("memory guard: checkMemoryBudget's arithmetic") {
    // A 1x1 image always fits; 65536 x 65536 (4.1e11 bytes) fits no
    // machine this suite runs on; the message names the size and the limit.
    raylab::Scene scene;
    scene.sourcePath = "s.json";
    raylab::RenderOptions o;
    o.width = o.height = 1;
    CHECK_NOTHROW(raylab::checkMemoryBudget(scene, o));
    o.width = o.height = 65536;
    if (65536.0 * 65536.0 * kBytesPerPixel > 0.8 * machineMemory()) {
        try {
            raylab::checkMemoryBudget(scene, o);
            FAIL("65536x65536 was not refused");
        } catch (const raylab::InputError& e) {
            CHECK(e.file() == "s.json");
            // 65536^2 x 96 B / 2^20 = 393216 MiB exactly.
            CHECK(contains(e.what(), "393216 MiB"));
        }
    }
}

TEST_CASE("memory guard: the estimate counts the film and the acceleration structure") {
    // 640x480 x 12 floats x 4 B x 2 = 29,491,200 B; 1e6 primitives x 128 B.
    const raylab::MemoryEstimate e = raylab::estimateRenderMemory(640, 480, 1000000);
    CHECK(e.filmBytes == 29491200.0);
    CHECK(e.accelBytes == 128e6);
    CHECK(e.total() == 157491200.0);
    CHECK(raylab::estimateRenderMemory(1, 1, 0).accelBytes == 0);
}

TEST_CASE("memory guard: a tiny file cannot expand into an unbounded scene") {
    // A 300-byte checkerboard with 4096 x 4096 divisions asks for 33.5 million
    // triangles: measured on the 2-core machine, 2048 divisions take 32 s and
    // 1.1 GB, 4096 take 27-60 s (over 60 s under ASan) and about 4.4 GB, all
    // before the first pixel and out of reach of the first Ctrl-C (the BVH
    // build is not interruptible). checkMemoryBudget only sees the film. A
    // small file must not cost that much: refused (or rendered) within 10 s.
    Scratch dir;
    const std::string scene = dir.write(
        "board.json",
        "{\"camera\": {\"eye\": [0, 5, 5], \"look_at\": [0, 0, 0]},\n"
        " \"materials\": {\"a\": {\"kd\": 0.8}, \"b\": {\"kd\": 0.2}},\n"
        " \"objects\": [{\"type\": \"checkerboard\", \"origin\": [-1, 0, -1],\n"
        "   \"edge_u\": [2, 0, 0], \"edge_v\": [0, 0, 2], \"divisions\": 4096,\n"
        "   \"materials\": [\"a\", \"b\"]}]}\n");
    const RunResult r = runRaylab(tinyRender(dir, scene), 20);
    const std::string err = head(r.err);
    CAPTURE(err);
    CAPTURE(r.seconds);
    CHECK_FALSE(r.timedOut);
    CHECK(r.seconds < 10);
    CHECK((r.exitCode == 0 || r.exitCode == 1));
    if (r.exitCode == 1) {
        checkRefused(r, dir, {"board.json"}, 1, scene + ":", "");
    } else {
        checkRendered(r, dir, {"board.json"});
    }
    MESSAGE("4096x4096 checkerboard: exit " << r.exitCode << " after " << r.seconds << " s");
}
