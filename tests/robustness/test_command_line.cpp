// Bad command lines and bad output paths through the real binary: usage
// errors exit 2 with one line, unwritable outputs exit 1 with one line, and
// an existing output file is never replaced by a failed or partial render.
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <string>
#include <vector>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

const std::string& kScene = kSphereScene;

}  // namespace

TEST_CASE("command line: absurd numbers and unknown flags are usage errors (exit 2)") {
    const std::vector<std::vector<std::string>> bad = {
        {"--width", "1000000000"}, {"--width", "0"},        {"--width", "-8"},
        {"--width", "8.5"},        {"--width", ""},         {"--width", "8x"},        {"--width", " 8"},       {"--spp", "4", "--spd"},
        {"--adaptive", "0.1", "--spp", "4"},
        {"--width", "99999999999999999999999"},             {"--height", "0x10"},
        {"--spp", "0"},            {"--spp", "-1"},         {"--depth", "0"},
        {"--depth", "1000000"},    {"--threads", "0"},      {"--threads", "-2"},
        {"--exposure", "nan"},     {"--exposure", "inf"},   {"--exposure", "1e400"},
        {"--epsilon", "-1"},       {"--epsilon", "inf"},    {"--min-weight", "2"},
        {"--seed", "-1"},          {"--adaptive", "nan"},   {"--accel", "bvh"},
        {"--precision", "half"},   {"--bogus"},             {"--width"},
        // Given twice: no silent "last one wins" (-o may repeat: one output per use).
        {"--width", "8", "--width", "9"}, {"--alpha", "opaque", "--alpha", "opaque"},
    };
    for (const std::vector<std::string>& flags : bad) {
        TempDir dir;
        const std::string scene = dir.write("scene.json", kScene);
        std::vector<std::string> args{"render", scene, "-o", dir.file("out.exr"), "--quiet"};
        args.insert(args.end(), flags.begin(), flags.end());
        std::string shown;
        for (const std::string& f : flags) shown += f + " ";
        CAPTURE(shown);
        checkRefused(runRaylab(args), dir, {"scene.json"}, 2, "", "");
    }
}

TEST_CASE("command line: huge or control-character arguments are not echoed raw") {
    // A 100 kB value and an escape sequence: still one short, printable line.
    for (const std::string& value : {std::string(100000, '9'), std::string("\x1b[2J\r\x07oops")}) {
        TempDir dir;
        const std::string scene = dir.write("scene.json", kScene);
        checkRefused(runRaylab({"render", scene, "-o", dir.file("out.exr"), "--width", value}),
                     dir, {"scene.json"}, 2, "", "--width");
        checkRefused(runRaylab({"render", scene, "-o", dir.file("out.exr"), "--accel", value}),
                     dir, {"scene.json"}, 2, "", "--accel");
    }
}

TEST_CASE("command line: missing or unreadable scenes are input errors (exit 1)") {
    TempDir dir;
    const std::string out = dir.file("out.exr");
    checkRefused(runRaylab({"render", dir.file("missing.json"), "-o", out}), dir, {}, 1,
                 dir.file("missing.json") + ":", "cannot open");
    std::filesystem::create_directories(dir.file("folder.json"));
    checkRefused(runRaylab({"render", dir.file("folder.json"), "-o", out}), dir, {}, 1,
                 dir.file("folder.json") + ":", "directory");
    dir.write("scene.txt", kScene);
    checkRefused(runRaylab({"render", dir.file("scene.txt"), "-o", out}), dir, {"scene.txt"}, 1,
                 dir.file("scene.txt") + ":", "unknown scene format");
    dir.write("noext", kScene);
    checkRefused(runRaylab({"render", dir.file("noext"), "-o", out}), dir,
                 {"noext", "scene.txt"}, 1, dir.file("noext") + ":", "no file extension");
}

TEST_CASE("command line: unwritable outputs fail with one line and leave no temporary file") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const std::vector<std::string> tiny{"--width", "8", "--height", "8", "--quiet"};
    auto args = [&](std::vector<std::string> a) {
        a.insert(a.begin(), {"render", scene});
        a.insert(a.end(), tiny.begin(), tiny.end());
        return a;
    };
    // The EXR's folder does not exist.
    checkRefused(runRaylab(args({"-o", dir.file("no/such/dir/out.exr")})), dir, {"scene.json"},
                 1, dir.file("no/such/dir/out.exr") + ":", "cannot write");
    // The output name is an existing directory.
    std::filesystem::create_directories(dir.file("taken.exr"));
    checkRefused(runRaylab(args({"-o", dir.file("taken.exr")})), dir, {"scene.json"}, 1,
                 dir.file("taken.exr") + ":", "");
    std::filesystem::remove(dir.file("taken.exr"));
    // The stats file cannot be written.
    const RunResult stats =
        runRaylab(args({"-o", dir.file("a.exr"), "--stats", dir.file("no/dir/s.json")}));
    const std::string err = head(stats.err);
    CAPTURE(err);
    CHECK(stats.exitCode == 1);
    CHECK(lines(stats.err).size() == 1);
    CHECK(startsWith(stats.err, "raylab: error: " + dir.file("no/dir/s.json") + ":"));
    for (const std::string& f : dir.files()) CHECK_FALSE(contains(f, ".tmp."));
}

TEST_CASE("command line: an output that is a FIFO (or any non-file node) is refused, untouched") {
    // Renaming the finished file over a device (/dev/full, /dev/null as root),
    // a FIFO or a socket would replace the node itself. A FIFO stands in for
    // them all here: the same check, and safe to try as root.
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const std::vector<std::pair<std::string, std::string>> outputs = {
        {"-o", "node.exr"}, {"--png", "node.png"}, {"--stats", "node.json"}};
    for (const auto& entry : outputs) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& flag = entry.first;
        const auto& name = entry.second;
        const std::string fifo = dir.file(name);
        REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
        std::vector<std::string> args{"render", scene, "--width", "8", "--height", "8", "--quiet"};
        if (flag != "-o") args.insert(args.end(), {"-o", dir.file("out.exr")});
        args.insert(args.end(), {flag, fifo});
        CAPTURE(flag);
        const RunResult r = runRaylab(args, 20);
        checkRefused(r, dir, {"scene.json"}, 1, fifo + ":", "not a regular file");
        CHECK(std::filesystem::is_fifo(std::filesystem::symlink_status(fifo)));
        std::filesystem::remove(fifo);
    }
}

TEST_CASE("command line: an output that is a symbolic link replaces the file it points to") {
    // The link stays a link; the file it names (relative to the link's own
    // folder) gets the render, also when it does not exist yet.
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    dir.write("real/old.png", "previous");
    std::filesystem::create_directories(dir.file("links"));
    std::filesystem::create_symlink("../real/old.png", dir.file("links/out.png"));
    std::filesystem::create_symlink("../real/new.exr", dir.file("links/out.exr"));  // dangling
    const RunResult r = runRaylab({"render", scene, "-o", dir.file("links/out.exr"), "--png",
                                   dir.file("links/out.png"), "--width", "8", "--height", "8",
                                   "--quiet"});
    const std::string err = head(r.err);
    CAPTURE(err);
    CHECK(r.exitCode == 0);
    CHECK(std::filesystem::is_symlink(dir.file("links/out.png")));
    CHECK(std::filesystem::is_symlink(dir.file("links/out.exr")));
    CHECK(startsWith(readFile(dir.file("real/old.png")), "\x89PNG"));
    CHECK(startsWith(readFile(dir.file("real/new.exr")), "\x76\x2f\x31\x01"));  // EXR magic
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir.path()))
        CHECK_FALSE(contains(e.path().string(), ".tmp."));
}

TEST_CASE("command line: a scene that is a FIFO, a device or too big is refused at once") {
    TempDir dir;
    const std::string out = dir.file("out.exr");
    // A FIFO nobody writes to: opening it for reading would wait for ever.
    const std::string fifo = dir.file("pipe.nff");
    REQUIRE(::mkfifo(fifo.c_str(), 0644) == 0);
    RunResult r = runRaylab({"render", fifo, "-o", out}, 20);
    checkRefused(r, dir, {}, 1, fifo + ":", "not a regular file");
    CHECK(r.seconds < 10);
    // A device without end: /dev/zero under a scene name.
    for (const char* name : {"zero.nff", "zero.json", "zero.obj"}) {
        std::filesystem::create_symlink("/dev/zero", dir.file(name));
        r = runRaylab({"render", dir.file(name), "-o", out}, 20);
        checkRefused(r, dir, {}, 1, dir.file(name) + ":", "not a regular file");
        CHECK(r.seconds < 10);
    }
    // A sparse file over the 1 GiB limit: refused from its size, not read.
    const std::string big = dir.write("big.nff", "");
    std::filesystem::resize_file(big, (uintmax_t(1) << 30) + 1);
    r = runRaylab({"render", big, "-o", out}, 20);
    checkRefused(r, dir, {"big.nff"}, 1, big + ":", "larger than the 1024 MiB");
    CHECK(r.seconds < 10);
}

TEST_CASE("command line: a failed render never touches an existing output file") {
    TempDir dir;
    const std::string old = "previous render, must survive";
    dir.write("out.exr", old);
    dir.write("out.png", old);
    const std::string bad = dir.write("bad.json", "{\"camera\": {\"eye\": [0, 0, 5]}}");
    const RunResult r = runRaylab(tinyRender(dir, bad));
    checkRefused(r, dir, {"bad.json", "out.exr", "out.png"}, 1, bad + ":1:", "look_at");
    CHECK(readFile(dir.file("out.exr")) == old);
    CHECK(readFile(dir.file("out.png")) == old);
}

TEST_CASE("command line: an unwritable --stats leaves the previous EXR and PNG byte-identical") {
    // Checked before the render starts, and the outputs of a frame are
    // committed together: nothing is replaced unless everything is written.
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const std::string old = "previous render, must survive";
    dir.write("out.exr", old);
    dir.write("out.png", old);
    const RunResult r = runRaylab({"render", scene, "-o", dir.file("out.exr"), "--png",
                                   dir.file("out.png"), "--stats", dir.file("no/dir/s.json"),
                                   "--width", "8", "--height", "8", "--quiet"});
    checkRefused(r, dir, {"out.exr", "out.png", "scene.json"}, 1,
                 dir.file("no/dir/s.json") + ":", "cannot write");
    CHECK(readFile(dir.file("out.exr")) == old);
    CHECK(readFile(dir.file("out.png")) == old);
}

TEST_CASE("command line: outputs naming one file, the scene, or the wrong format are refused") {
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const std::vector<std::vector<std::string>> clashes = {
        {"-o", dir.file("a.exr"), "--png", dir.file("a.exr")},
        {"-o", dir.file("a.exr"), "--stats", dir.file("sub/../a.exr")},
        {"-o", dir.file("a.exr"), "--png", dir.file("a.png"), "--stats", dir.file("./a.png")},
        {"-o", scene},
        {"-o", dir.file("a.exr"), "--stats", scene},
    };
    std::filesystem::create_directories(dir.file("sub"));
    for (const std::vector<std::string>& flags : clashes) {
        std::vector<std::string> args{"render", scene, "--quiet"};
        args.insert(args.end(), flags.begin(), flags.end());
        std::string shown;
        for (const std::string& f : flags) shown += f + " ";
        CAPTURE(shown);
        checkRefused(runRaylab(args), dir, {"scene.json"}, 2, "", "same file");
    }
    CHECK(readFile(scene) == kScene);
    // Output names without a format's extension (-o picks the format by it).
    checkRefused(runRaylab({"render", scene, "-o", dir.file("a.bmp"), "--quiet"}), dir,
                 {"scene.json"}, 2, "", ".exr, .png");
    checkRefused(runRaylab({"render", scene, "-o", dir.file("a"), "--quiet"}), dir,
                 {"scene.json"}, 2, "", ".exr, .png");
    checkRefused(runRaylab({"render", scene, "-o", dir.file("a.exr"), "--png",
                            dir.file("a.jpg"), "--quiet"}),
                 dir, {"scene.json"}, 2, "", ".png");
}

TEST_CASE("command line: --spp with the scene's own adaptive sampling is a usage error") {
    TempDir dir;
    std::string text = kScene;
    text.insert(text.rfind('}'), ",\n \"render\": {\"adaptive\": 0.1}");
    const std::string scene = dir.write("scene.json", text);
    checkRefused(runRaylab({"render", scene, "-o", dir.file("out.exr"), "--spp", "4", "--quiet"}),
                 dir, {"scene.json"}, 2, "", "--spp");
    // Without --spp it renders (adaptive, corner rays).
    const RunResult ok = runRaylab({"render", scene, "-o", dir.file("out.exr"), "--width", "8",
                                    "--height", "8", "--quiet"});
    CHECK(ok.exitCode == 0);
}

TEST_CASE("command line: --width 65536 --height 65536 is refused by the memory guard") {
    const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
    // 65536^2 pixels x 48 floats of film and encoder copies: about 824 GB.
    if (memory > 0.5e12) return;  // a machine that big would start the render
    TempDir dir;
    const std::string scene = dir.write("scene.json", kScene);
    const RunResult r = runRaylab({"render", scene, "-o", dir.file("out.exr"), "--width", "65536",
                                   "--height", "65536", "--quiet"},
                                  30);
    checkRefused(r, dir, {"scene.json"}, 1, scene + ":", "MiB");
    CHECK(r.seconds < 10);  // refused up front, not after allocating
}
