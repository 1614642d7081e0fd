// Durability of the outputs is opt-in: without --fsync the commit (temporaries,
// kept old files, renames) issues no sync call at all; with it, each output's
// temporary is fsynced before its rename and the output folder after. The real
// binary is traced with strace (skipped where strace is missing or ptrace is
// not allowed), and every sync call it made is counted by the file it named.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "robustness_helpers.h"
#include "support/run_command.h"

using namespace raylab::robust;

namespace {

/// The sync calls a traced command made, one per line: "fsync(3</dir/name>) = 0".
struct Trace {
    bool available = false;  ///< strace ran (installed, ptrace allowed)
    int exitCode = -1;       ///< the traced raylab's exit code
    std::vector<std::string> calls;
};

const char* const kSyncCalls = "fsync,fdatasync,sync,syncfs,sync_file_range";

bool straceWorks() {
    return raylab::test::runCommand(std::string("strace -f -qq -e trace=") + kSyncCalls +
                                    " -o /dev/null true")
               .exitCode == 0;
}

/// Runs raylab with `args` under strace -f -y (file descriptors shown with
/// their paths) and returns the sync calls of every thread.
Trace traceSyncs(const TempDir& dir, const std::string& args) {
    Trace t;
    if (!straceWorks()) return t;
    t.available = true;
    const std::string log = dir.file("strace.log");
    // LeakSanitizer cannot run under ptrace and fails the process at exit
    // (the sanitizer build): leak checking is off for the traced run only.
    t.exitCode = raylab::test::runCommand(
                     std::string("ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" ") +
                     "strace -f -qq -y -e signal=none -e trace=" + kSyncCalls + " -o " + log + " " +
                     RAYLAB_BINARY + " " + args)
                     .exitCode;
    for (const std::string& line : lines(readFile(log)))
        if (contains(line, "sync")) t.calls.push_back(line);
    std::filesystem::remove(log);
    return t;
}

/// How many calls named `path` exactly ("<path>)" after the descriptor).
long callsOn(const Trace& t, const std::string& path) {
    return std::count_if(t.calls.begin(), t.calls.end(),
                         [&](const std::string& c) { return contains(c, "<" + path + ">"); });
}

/// How many calls named a temporary of `target` ("<target>.tmp.PID.N").
long callsOnTemporaryOf(const Trace& t, const std::string& target) {
    return std::count_if(t.calls.begin(), t.calls.end(),
                         [&](const std::string& c) { return contains(c, "<" + target + ".tmp."); });
}

std::string renderArgs(const TempDir& dir, const std::string& scene) {
    return "render " + scene + " -o " + dir.file("out.exr") + " --png " + dir.file("out.png") +
           " --stats " + dir.file("out.json") + " --width 8 --height 8 --quiet --threads 2";
}

}  // namespace

TEST_CASE("fsync policy: without --fsync no output, folder or other file is synced") {
    if (!straceWorks()) {
        MESSAGE("raylab-test-skipped: strace is not installed or ptrace is not allowed");
        return;
    }
    TempDir dir;
    const std::string scene = dir.write("scene.json", kSphereScene);
    // Twice: new outputs, then replacing them (old files kept aside and removed).
    for (int run = 0; run < 2; ++run) {
        CAPTURE(run);
        const Trace t = traceSyncs(dir, renderArgs(dir, scene));
        REQUIRE(t.available);
        CHECK(t.exitCode == 0);
        std::string calls;
        for (const std::string& c : t.calls) calls += c + "\n";
        CAPTURE(calls);
        CHECK(t.calls.empty());
        CHECK(dir.files() ==
              std::vector<std::string>{"out.exr", "out.json", "out.png", "scene.json"});
    }
}

TEST_CASE("fsync policy: --fsync syncs each output's temporary once and the folder once") {
    if (!straceWorks()) {
        MESSAGE("raylab-test-skipped: strace is not installed or ptrace is not allowed");
        return;
    }
    TempDir dir;
    const std::string scene = dir.write("scene.json", kSphereScene);
    for (int run = 0; run < 2; ++run) {
        CAPTURE(run);
        const Trace t = traceSyncs(dir, renderArgs(dir, scene) + " --fsync");
        REQUIRE(t.available);
        std::string calls;
        for (const std::string& c : t.calls) calls += c + "\n";
        CAPTURE(calls);
        CHECK(t.exitCode == 0);
        for (const char* name : {"out.exr", "out.png", "out.json"}) {
            CAPTURE(name);
            CHECK(callsOnTemporaryOf(t, dir.file(name)) == 1);
        }
        CHECK(callsOn(t, dir.path().string()) == 1);  // the folder, after the renames
        CHECK(t.calls.size() == 4);                   // and nothing else
        CHECK(dir.files() ==
              std::vector<std::string>{"out.exr", "out.json", "out.png", "scene.json"});
    }
}
