// SIGINT, SIGTERM and SIGHUP in every phase of a render (parse, BVH build,
// render, deep ray trees, write, commit): exit 128+signal with one line, no
// temporary left, earlier outputs byte for byte intact. The phase is reached
// deterministically: RAYLAB_TEST_STOP_AT makes raylab stop itself (SIGSTOP)
// on entering it, the test sends the signal and SIGCONT. Also: a closed or
// broken stdout does not fail a finished render. No assertion on timings
// beyond a generous "it ended".
#include <doctest/doctest.h>

#include <signal.h>

#include <chrono>
#include <string>
#include <thread>

#include "renderer/io/errors.h"
#include "renderer/io/exr_reader.h"
#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

/// An NFF scene of `n` spheres in a grid in front of the camera, with two
/// lights: slow with --accel naive (every ray tests every sphere).
std::string sphereGrid(int n) {
    std::string s =
        "v\nfrom 0 0 30\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\nresolution 64 64\n"
        "l 10 10 30\nl -10 5 20\nf 0.8 0.6 0.4 0.7 0.3 20 0 1\n";
    int k = 0;
    for (int i = 0; k < n; ++i)
        for (int j = 0; j < 50 && k < n; ++j, ++k)
            s += "s " + std::to_string(j - 25) + " " + std::to_string(i % 40 - 20) + " " +
                 std::to_string(-(i / 40)) + " 0.45\n";
    return s;
}

bool hasTemp(const TempDir& dir) {
    for (const std::string& f : dir.files())
        if (contains(f, ".tmp.") || contains(f, ".old.")) return true;
    return false;
}

void sleepSeconds(double s) {
    std::this_thread::sleep_for(std::chrono::duration<double>(s));
}

}  // namespace

TEST_CASE("interrupt: SIGINT during a long render exits 130 promptly with no output") {
    TempDir dir;
    const std::string scene = dir.write("grid.nff", sphereGrid(2000));
    // 2000 spheres x 1600^2 pixels with the naive loop: minutes of work.
    Process p({"render", scene, "-o", dir.file("out.exr"), "--png", dir.file("out.png"),
               "--width", "1600", "--height", "1600", "--accel", "naive", "--threads", "2",
               "--quiet"},
              dir.file("stdout"), dir.file("stderr"));
    REQUIRE(p.started());
    sleepSeconds(0.5);
    REQUIRE_FALSE(p.wait(0));  // still rendering
    p.signal(SIGINT);
    REQUIRE(p.wait(30));  // generous: it ends in well under a second
    CHECK(p.exitCode() == 130);
    const std::string err = readFile(dir.file("stderr"));
    CAPTURE(err);
    CHECK(lines(err).size() == 1);
    CHECK(startsWith(err, "raylab: interrupted"));
    CHECK(dir.files() == std::vector<std::string>{"grid.nff", "stderr", "stdout"});
}

TEST_CASE("interrupt: a second SIGINT leaves at once, still without output") {
    TempDir dir;
    const std::string scene = dir.write("grid.nff", sphereGrid(2000));
    Process p({"render", scene, "-o", dir.file("out.exr"), "--width", "1600", "--height", "1600",
               "--accel", "naive", "--threads", "2", "--quiet"},
              dir.file("stdout"), dir.file("stderr"));
    REQUIRE(p.started());
    sleepSeconds(0.5);
    REQUIRE_FALSE(p.wait(0));
    p.signal(SIGINT);
    p.signal(SIGINT);
    REQUIRE(p.wait(10));
    CHECK(p.exitCode() == 130);
    CHECK(dir.files() == std::vector<std::string>{"grid.nff", "stderr", "stdout"});
}

TEST_CASE("interrupt: wherever SIGINT lands, the outputs are absent or complete") {
    // A short render is timed once, then interrupted at delays from 0 to
    // 1.4x its duration: before main, during the load, the render, the
    // writes, and after the end.
    TempDir dir;
    const std::string scene = dir.write("grid.nff", sphereGrid(100));
    const std::vector<std::string> args{
        "render",  scene,      "-o",     dir.file("out.exr"), "--png",     dir.file("out.png"),
        "--width", "160",      "--height", "160",             "--accel",   "naive",
        "--threads", "2",      "--quiet"};
    double full = 0;
    {
        Process p(args, dir.file("stdout"), dir.file("stderr"));
        REQUIRE(p.wait(60));
        REQUIRE(p.exitCode() == 0);
        full = p.secondsSinceStart();
    }
    int interrupted = 0, finished = 0;
    for (int i = 0; i < 12; ++i) {
        const double delay = full * 1.4 * i / 11;
        CAPTURE(delay);
        for (const char* f : {"out.exr", "out.png"}) std::filesystem::remove(dir.file(f));
        Process p(args, dir.file("stdout"), dir.file("stderr"));
        REQUIRE(p.started());
        sleepSeconds(delay);
        p.signal(SIGINT);
        REQUIRE(p.wait(60));
        CHECK_FALSE(hasTemp(dir));
        const bool exr = std::filesystem::exists(dir.file("out.exr"));
        const bool png = std::filesystem::exists(dir.file("out.png"));
        // A signal that lands after the commit still exits 130, and its line
        // says so (docs/robustness.md): then the outputs must be complete.
        const bool afterCommit =
            p.exitCode() == 130 &&
            contains(readFile(dir.file("stderr")), "interrupted by SIGINT: the output was written");
        if (p.exitCode() == 130 && !afterCommit) {
            ++interrupted;
            CHECK_FALSE(exr);
            CHECK_FALSE(png);
        } else {
            ++finished;
            if (!afterCommit) CHECK(p.exitCode() == 0);
            REQUIRE(exr);
            CHECK(png);
            // Complete: the EXR reads back at full size.
            raylab::Film film;
            CHECK_NOTHROW(film = raylab::readExr(dir.file("out.exr")));
            CHECK(film.width == 160);
            CHECK(film.height == 160);
        }
    }
    MESSAGE("render " << full << " s; interrupted " << interrupted << ", finished " << finished);
    CHECK(interrupted > 0);
    WARN(finished > 0);  // timing-dependent: the late signals usually miss the render
}

namespace {

const std::string kSmallScene =
    "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
    " \"lights\": [{\"type\": \"point\", \"position\": [2, 3, 4]}],\n"
    " \"camera_path\": {\"keyframes\": [{\"frame\": 1, \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
    "                                   {\"frame\": 3, \"eye\": [1, 0, 5], \"look_at\": [0, 0, 0]}]},\n"
    " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}]}\n";

/// A height-field OBJ of 2·n² triangles: seconds to parse and to build a BVH for.
std::string gridObj(int n) {
    std::string s;
    s.reserve(size_t(n + 1) * (n + 1) * 24 + size_t(n) * n * 40);
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            s += "v " + std::to_string(i) + " " + std::to_string(j) + " " +
                 std::to_string(((i * 7 + j * 13) % 17) * 0.01) + "\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 1, d = c + 1;
            s += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
            s += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
        }
    return s;
}

const char* signalName(int sig) {
    return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "SIGHUP";
}

/// Starts `args` with RAYLAB_TEST_STOP_AT=`phase`, waits until raylab has
/// stopped itself there, sends `sig` and SIGCONT; with `afterContinue`, the
/// signal is sent only once it runs again (it lands inside the phase's work).
/// Returns the exit code (-1: it did not end within 60 s).
int signalInPhase(const TempDir& dir, const std::vector<std::string>& args,
                  const std::string& phase, int sig, bool afterContinue = false,
                  std::vector<std::string> env = {}) {
    env.push_back("RAYLAB_TEST_STOP_AT=" + phase);
    // Sent while stopped: raylab waits, on resuming, until a thread has run
    // its handler (which thread is the kernel's choice), so the phase sees it.
    if (!afterContinue) env.push_back("RAYLAB_TEST_SIGNALED_WHILE_STOPPED=1");
    Process p(args, dir.file("stdout"), dir.file("stderr"), 0, env);
    REQUIRE(p.started());
    REQUIRE(p.waitUntilStopped());
    if (!afterContinue) p.signal(sig);
    p.signal(SIGCONT);
    if (afterContinue) p.signal(sig);
    if (!p.wait(60)) return -1;
    return p.exitCode();
}

/// One line on stderr, exactly `line`.
void checkOneLine(const TempDir& dir, const std::string& line) {
    const std::string err = readFile(dir.file("stderr"));
    CAPTURE(err);
    CHECK(lines(err) == std::vector<std::string>{line});
}

}  // namespace

TEST_CASE("signals: SIGINT, SIGTERM and SIGHUP in every phase: 128+signal, old outputs intact") {
    for (const char* phase : {"parse", "build", "render", "write", "commit"}) {
        for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
            CAPTURE(phase);
            CAPTURE(signalName(sig));
            TempDir dir;
            const std::string scene = dir.write("scene.json", kSmallScene);
            dir.write("out.exr", "old exr");
            dir.write("out.png", "old png");
            dir.write("out.json", "old stats");
            const int code = signalInPhase(
                dir, {"render", scene, "-o", dir.file("out.exr"), "--png", dir.file("out.png"),
                      "--stats", dir.file("out.json"), "--width", "32", "--height", "32", "--quiet"},
                phase, sig);
            CHECK(code == 128 + sig);
            checkOneLine(dir, std::string("raylab: interrupted by ") + signalName(sig) +
                                  ": no output written");
            CHECK(readFile(dir.file("out.exr")) == "old exr");
            CHECK(readFile(dir.file("out.png")) == "old png");
            CHECK(readFile(dir.file("out.json")) == "old stats");
            CHECK(dir.files() == std::vector<std::string>{"out.exr", "out.json", "out.png",
                                                          "scene.json", "stderr", "stdout"});
        }
    }
}

TEST_CASE("signals: stopped in the commit phase, every temporary exists, the signal removes them") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kSmallScene);
    Process p({"render", scene, "-o", dir.file("out.exr"), "--png", dir.file("out.png"), "--width",
               "16", "--height", "16", "--quiet"},
              dir.file("stdout"), dir.file("stderr"), 0,
              {"RAYLAB_TEST_STOP_AT=commit", "RAYLAB_TEST_SIGNALED_WHILE_STOPPED=1"});
    REQUIRE(p.waitUntilStopped());
    int temps = 0;
    for (const std::string& f : dir.files()) temps += contains(f, ".tmp.");
    CHECK(temps == 2);  // the write phase is over, nothing renamed yet
    p.signal(SIGINT);
    p.signal(SIGCONT);
    REQUIRE(p.wait(60));
    CHECK(p.exitCode() == 130);  // never 0 once the write phase was interrupted
    CHECK(dir.files() == std::vector<std::string>{"scene.json", "stderr", "stdout"});
}

TEST_CASE("signals: a sequence interrupted at frame 2 keeps frame 1 and says so") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kSmallScene);
    const int code = signalInPhase(
        dir, {"render", scene, "-o", dir.file("out.exr"), "--frames", "1:3", "--width", "16",
              "--height", "16", "--quiet"},
        "render:2", SIGTERM);
    CHECK(code == 143);
    checkOneLine(dir, "raylab: interrupted by SIGTERM: frames 1 to 1 written, 2 and later not");
    CHECK(dir.files() == std::vector<std::string>{"out_0001.exr", "scene.json", "stderr", "stdout"});
}

TEST_CASE("signals: a signal inside a long parse, BVH build or deep ray tree ends the run") {
    // Sent after SIGCONT, so it lands while the phase works (a 100k-triangle
    // OBJ read and parsed, its BVH built, one pixel's exponential ray tree);
    // whichever check point or the watchdog ends it, the contract is the same.
    TempDir dir;
    const std::string obj = dir.write("grid.obj", gridObj(230));
    const std::string deep = dir.write("deep.json", kGlassInMirrorScene);
    struct Case {
        const char* phase;
        std::vector<std::string> args;
    };
    const std::vector<Case> cases = {
        {"parse", {"render", obj, "-o", dir.file("out.exr"), "--width", "1024", "--height", "1024",
                   "--spp", "64", "--quiet"}},
        {"build", {"render", obj, "-o", dir.file("out.exr"), "--bvh-quality", "high", "--width",
                   "1024", "--height", "1024", "--spp", "64", "--quiet"}},
        // Depth 64 and the largest ray cap: without the check inside the ray
        // tree one sample would run for hours; without the watchdog only that
        // check can end it.
        {"render", {"render", deep, "-o", dir.file("out.exr"), "--threads", "1", "--quiet",
                    "--max-rays", "1099511627776"}},
    };
    for (const Case& c : cases) {
        for (const int sig : {SIGINT, SIGTERM}) {
            CAPTURE(c.phase);
            CAPTURE(signalName(sig));
            const std::vector<std::string> env =
                c.phase == std::string("render") ? std::vector<std::string>{"RAYLAB_TEST_NO_WATCHDOG=1"}
                                                 : std::vector<std::string>{};
            const int code = signalInPhase(dir, c.args, c.phase, sig, true, env);
            CHECK(code == 128 + sig);
            checkOneLine(dir, std::string("raylab: interrupted by ") + signalName(sig) +
                                  ": no output written");
            CHECK(dir.files() ==
                  std::vector<std::string>{"deep.json", "grid.obj", "stderr", "stdout"});
        }
    }
}

TEST_CASE("signals: a closed stdout or a broken stdout pipe does not fail a finished render") {
    // Issue 22: with stdout a pipe whose reader had gone, the summary line
    // raised SIGPIPE and the exit was 141 after every file was written.
    TempDir dir;
    const std::string scene = dir.write("scene.json", kSmallScene);
    const std::vector<std::string> args{"render", scene, "-o", dir.file("out.exr"), "--png",
                                        dir.file("out.png"), "--width", "16", "--height", "16"};
    {
        Process p(args, "|", dir.file("stderr"));
        REQUIRE(p.wait(60));
        CHECK(p.exitCode() == 0);
    }
    const std::string expected = readFile(dir.file("out.exr"));
    CHECK(expected.size() > 100);
    {
        Process p(args, "", dir.file("stderr"));  // stdout closed: nothing may land in a file
        REQUIRE(p.wait(60));
        CHECK(p.exitCode() == 0);
    }
    CHECK(readFile(dir.file("out.exr")) == expected);
    CHECK(readFile(dir.file("stderr")).empty());
    CHECK(dir.files() == std::vector<std::string>{"out.exr", "out.png", "scene.json", "stderr"});
}
