// The output group (EXR, PNG, statistics) is committed as close to atomically
// as POSIX allows: failures are injected into the real binary's rename(2) and
// link(2) by an LD_PRELOAD shim (tests/robustness/shim/fault_shim.cpp), and
// the previous outputs must survive byte for byte.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <string>
#include <vector>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

const std::string& kScene = kSphereScene;

/// The environment that preloads the shim with `settings` ("RAYLAB_SHIM_...=...").
std::vector<std::string> shim(std::vector<std::string> settings) {
    settings.push_back(std::string("LD_PRELOAD=") + RAYLAB_FAULT_SHIM);
    // An ASan build insists on being first in the library list; the shim is plain C++.
    settings.push_back("ASAN_OPTIONS=verify_asan_link_order=0:detect_leaks=0");
    return settings;
}

/// Scene plus an earlier render's three outputs, with recognisable bytes.
struct Previous {
    TempDir dir;
    std::string scene = dir.write("scene.json", kScene);
    std::string exr = dir.write("out.exr", "old exr bytes");
    std::string png = dir.write("out.png", "old png bytes");
    std::string stats = dir.write("out.json", "old stats bytes");

    std::vector<std::string> args() const {
        return {"render", scene, "-o", exr, "--png", png, "--stats", stats,
                "--width", "8", "--height", "8", "--quiet"};
    }
    void checkIntact() const {
        CHECK(readFile(exr) == "old exr bytes");
        CHECK(readFile(png) == "old png bytes");
        CHECK(readFile(stats) == "old stats bytes");
        CHECK(dir.files() == std::vector<std::string>{"out.exr", "out.json", "out.png", "scene.json"});
    }
};

}  // namespace

TEST_CASE("commit: the second rename fails: the first output is put back, exit 1, one line") {
    // Issue 22: with EIO injected into the second rename, out.exr had already
    // been replaced. Renames: 1 = EXR, 2 = PNG (fails), 3 = EXR's old file back.
    Previous p;
    const RunResult r = runRaylab(p.args(), 60, 0, shim({"RAYLAB_SHIM_FAIL_RENAME=2"}));
    checkRefused(r, p.dir, {"out.exr", "out.json", "out.png", "scene.json"}, 1, p.png + ":",
                 "rename failed");
    CHECK(contains(r.err, "no output was changed"));
    p.checkIntact();
}

TEST_CASE("commit: the last rename fails: both earlier outputs are put back") {
    Previous p;
    const RunResult r = runRaylab(p.args(), 60, 0, shim({"RAYLAB_SHIM_FAIL_RENAME=3"}));
    CHECK(r.exitCode == 1);
    CHECK(lines(r.err).size() == 1);
    CHECK(contains(r.err, p.stats + ": cannot write file: rename failed"));
    p.checkIntact();
}

TEST_CASE("commit: without earlier outputs, a failed rename leaves no output at all") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const RunResult r = runRaylab(tinyRender(dir, scene), 60, 0, shim({"RAYLAB_SHIM_FAIL_RENAME=2"}));
    checkRefused(r, dir, {"scene.json"}, 1, dir.file("out.png") + ":", "rename failed");
}

TEST_CASE("commit: where hard links are refused, copies keep the old outputs instead") {
    Previous p;
    const RunResult r = runRaylab(
        p.args(), 60, 0, shim({"RAYLAB_SHIM_FAIL_LINK=1", "RAYLAB_SHIM_FAIL_RENAME=2"}));
    CHECK(r.exitCode == 1);
    CHECK(contains(r.err, "no output was changed"));
    p.checkIntact();
    // And with no failure, the copies are gone after the commit.
    const RunResult ok = runRaylab(p.args(), 60, 0, shim({"RAYLAB_SHIM_FAIL_LINK=1"}));
    CHECK(ok.exitCode == 0);
    CHECK(readFile(p.exr).substr(0, 4) == "\x76\x2f\x31\x01");  // OpenEXR magic
    CHECK(p.dir.files() == std::vector<std::string>{"out.exr", "out.json", "out.png", "scene.json"});
}

TEST_CASE("commit: when putting an output back fails too, the message names the kept file") {
    // Renames: 1 = EXR in place, 2 = PNG fails, 3 = restoring the EXR fails.
    Previous p;
    const RunResult r = runRaylab(p.args(), 60, 0, shim({"RAYLAB_SHIM_FAIL_RENAME=2,3"}));
    CHECK(r.exitCode == 1);
    CHECK(lines(r.err).size() == 1);
    CHECK(contains(r.err, p.exr + " could not be restored"));
    CHECK(contains(r.err, "its old content is in "));
    // The old EXR survives under the name the message gives.
    const std::string kept = r.err.substr(r.err.find("its old content is in ") + 22);
    CHECK(readFile(kept.substr(0, kept.find('\n'))) == "old exr bytes");
    CHECK(readFile(p.png) == "old png bytes");
    CHECK(readFile(p.stats) == "old stats bytes");
}

TEST_CASE("commit: a signal during the renames undoes them: exit 143, old outputs intact") {
    Previous p;
    const RunResult r = runRaylab(p.args(), 60, 0, shim({"RAYLAB_SHIM_SIGNAL_RENAME=2:15"}));
    CHECK(r.exitCode == 143);
    CHECK(lines(r.err) == std::vector<std::string>{"raylab: interrupted by SIGTERM: no output written"});
    p.checkIntact();
}

TEST_CASE("commit: an existing output keeps its mode, a new one gets the umask's") {
    Previous p;
    REQUIRE(::chmod(p.exr.c_str(), 0600) == 0);
    REQUIRE(::chmod(p.png.c_str(), 0640) == 0);
    const RunResult r = runRaylab(p.args());
    REQUIRE(r.exitCode == 0);
    struct stat st {};
    REQUIRE(::stat(p.exr.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0600);
    REQUIRE(::stat(p.png.c_str(), &st) == 0);
    CHECK((st.st_mode & 07777) == 0640);
    CHECK(readFile(p.exr) != "old exr bytes");
    CHECK(p.dir.files() == std::vector<std::string>{"out.exr", "out.json", "out.png", "scene.json"});
}

TEST_CASE("commit: legal 255-byte output names are written and replaced") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const std::string exr = std::string(251, 'e') + ".exr", png = std::string(251, 'p') + ".png",
                      stats = std::string(250, 's') + ".json";
    for (int run = 0; run < 2; ++run) {  // created, then replaced
        const RunResult r = runRaylab({"render", scene, "-o", dir.file(exr), "--png", dir.file(png),
                                       "--stats", dir.file(stats), "--width", "8", "--height", "8",
                                       "--quiet"});
        CAPTURE(r.err);
        CHECK(r.exitCode == 0);
        CHECK(dir.files() == std::vector<std::string>{exr, png, "scene.json", stats});
    }
}
