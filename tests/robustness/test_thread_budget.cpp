// `render --threads N` bounds the whole command, not only the render loop:
// loading, the accelerator build and the output step use at most N threads
// too (before, `--threads 1` built polygons, the BVH and the EXR on two).
// The process is watched from outside (/proc/PID/status while it runs): TBB
// keeps a worker thread alive until the process ends once it has started
// one, so a worker is seen if it ever existed.

#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

int threadsOf(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8));
    return 0;
}

/// The most threads `raylab ARGS...` had at once, and its exit code.
struct Watched {
    int maxThreads = 0;
    int exitCode = -1;
};

Watched watch(const std::vector<std::string>& args, const TempDir& dir) {
    Process p(args, dir.file("stdout"), dir.file("stderr"));
    REQUIRE(p.started());
    Watched w;
    while (!p.wait(0)) {
        w.maxThreads = std::max(w.maxThreads, threadsOf(p.pid()));
        usleep(200);
    }
    w.exitCode = p.exitCode();
    return w;
}

}  // namespace

TEST_CASE("render --threads N: the whole command runs on at most N threads of work") {
    const TempDir dir;
    const std::string scene = std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json";
    const auto render = [&](const char* threads) {
        return watch({"render", scene, "--width", "200", "--height", "150", "--threads", threads,
                      "-o", dir.file("out.exr"), "--png", dir.file("out.png"), "-q"},
                     dir);
    };
    const Watched one = render("1");
    const Watched two = render("2");
    REQUIRE(one.exitCode == 0);
    REQUIRE(two.exitCode == 0);
    // One thread of work: the main thread and the signal watchdog (which
    // only waits), no TBB worker, from the first line read to the last byte
    // written. Two: exactly one worker more.
    CHECK(one.maxThreads <= 2);
    CHECK(two.maxThreads == one.maxThreads + 1);
}
