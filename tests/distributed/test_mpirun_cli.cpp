// `mpirun -np 2 raylab render` against `raylab render`: the files rank 0
// writes, sequences, and how failed ranks are reported. These cases start
// mpirun themselves; they run only when RAYLAB_MPIRUN names it (set by the
// ctest entry in tests/distributed/mpi_tests.cmake), never under mpirun.

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "distributed_test_helpers.h"
#include "renderer/io/exr_reader.h"
#include "support/run_command.h"
#include "support/temp_dir.h"

using namespace raylab;

namespace {

const auto kWithMpirun = doctest::skip(std::getenv("RAYLAB_MPIRUN") == nullptr);

using Run = test::CommandResult;
using test::readFile;
using test::errorLines;
using test::runCommand;

std::string raylabBinary() { return RAYLAB_BINARY; }

/// "mpirun -np N <flags> raylab".
std::string mpirunRaylab(int ranks) {
    const char* flags = std::getenv("RAYLAB_MPIRUN_FLAGS");
    return std::string(std::getenv("RAYLAB_MPIRUN")) + " -np " + std::to_string(ranks) + " " +
           (flags ? flags : "") + " " + raylabBinary();
}

std::string demo() { return std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json"; }

/// Every item goes to the other ranks: a fault on rank 1 cannot be outrun.
const std::string kRootServesOnly = "RAYLAB_MPI_ROOT_RENDERS=0 ";

/// The "rays" object and camera_hits of a --stats file (everything but times).
std::string rayStats(const std::string& json) {
    const size_t a = json.find("\"rays\""), b = json.find("\"time_s\"");
    REQUIRE(a != std::string::npos);
    REQUIRE(b != std::string::npos);
    return json.substr(a, b - a);
}

void checkSameExr(const std::string& a, const std::string& b) {
    INFO(a << " vs " << b);
    REQUIRE(std::filesystem::exists(a));
    REQUIRE(std::filesystem::exists(b));
    CHECK(test::filmDifference(readExr(a), readExr(b)) == "");
}

/// A small JSON scene with a camera path (no meshes, so it can live anywhere).
const char* const kPathScene = R"({
    "image": {"width": 48, "height": 32, "spp": 1, "depth": 4},
    "camera": {"eye": [0, 2, 8], "look_at": [0, 0.8, 0], "fov": 40},
    "camera_path": {
        "interpolation": "catmull_rom",
        "keyframes": [
            {"frame": 1, "eye": [0, 2, 8], "look_at": [0, 0.8, 0]},
            {"frame": 3, "eye": [5, 3, 6], "look_at": [0, 0.8, 0], "fov": 35}
        ]
    },
    "background": [0.5, 0.6, 0.8],
    "ambient": 0.1,
    "lights": [{"type": "point", "position": [-4, 7, 5]}],
    "materials": {
        "mirror": {"kd": 0.1, "ks": 0.5, "shininess": 200, "km": 0.8},
        "glass": {"kd": 0, "ks": 0.5, "shininess": 300, "km": 0.1, "kt": 0.9, "ior": 1.5},
        "floor": {"kd": [0.8, 0.8, 0.7]}
    },
    "objects": [
        {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"},
        {"type": "sphere", "center": [-1, 1, 0], "radius": 1, "material": "mirror"},
        {"type": "sphere", "center": [1.2, 0.7, 1], "radius": 0.7, "material": "glass"}
    ]
})";

}  // namespace

TEST_CASE("mpirun cli: the demo image, PNG and ray counts equal one process" * kWithMpirun) {
    const test::TempDir dir;
    const std::string flags = " --width 96 --height 72 --spp 2 --float ";
    const Run one = runCommand(raylabBinary() + " render " + demo() + flags + "--threads 2 -o " +
                               dir.file("one.exr") + " --png " + dir.file("one.png") + " --stats " +
                               dir.file("one.json") + " --quiet");
    REQUIRE_MESSAGE(one.exitCode == 0, one.err);
    const Run two = runCommand(mpirunRaylab(2) + " render " + demo() + flags + "--threads 1 -o " +
                               dir.file("two.exr") + " --png " + dir.file("two.png") + " --stats " +
                               dir.file("two.json"));
    REQUIRE_MESSAGE(two.exitCode == 0, two.err);
    checkSameExr(dir.file("one.exr"), dir.file("two.exr"));
    CHECK(readFile(dir.file("one.png")) == readFile(dir.file("two.png")));
    CHECK(rayStats(readFile(dir.file("one.json"))) == rayStats(readFile(dir.file("two.json"))));
    // One summary (rank 0's) with the per-rank table; 96x72 pixels = 6x5 tiles.
    CHECK(two.out.find("ranks:    2 ranks, 30 tiles") != std::string::npos);
    CHECK(two.out.find("rank 1 (") != std::string::npos);
    CHECK(two.out.find("raylab: 96x72") == two.out.rfind("raylab: 96x72"));
}

namespace {

/// shared/'s balls_s2.nff, or (without shared/) a small NFF scene with a
/// mirror and a glass ball written into `dir`.
std::string spdScene(const test::TempDir& dir) {
    const std::string shared = std::string(RAYLAB_SHARED_DIR) + "/scenes/spd/balls_s2.nff";
    if (std::filesystem::exists(shared)) return shared;
    const std::string scene = dir.file("spd.nff");
    std::ofstream(scene) << "v\nfrom 0 1 -6\nat 0 0.5 0\nup 0 1 0\nangle 40\nhither 0.01\n"
                            "resolution 64 64\nb 0.1 0.2 0.3\nl 3 5 -4\n"
                            "f 0.9 0.2 0.2 0.6 0.4 20 0 1\ns -1 0.5 0 0.5\n"
                            "f 0.8 0.8 0.9 0.1 0.6 100 0.8 1.5\ns 0.8 0.6 0.2 0.6\n";
    return scene;
}

}  // namespace

TEST_CASE("mpirun cli: an SPD render equals one process" * kWithMpirun) {
    const test::TempDir dir;
    const std::string scene = spdScene(dir);
    const std::string flags = " --spd --width 64 --height 64 --float --quiet ";
    const Run one = runCommand(raylabBinary() + " render " + scene + flags + "-o " +
                               dir.file("one.exr") + " --stats " + dir.file("one.json"));
    REQUIRE_MESSAGE(one.exitCode == 0, one.err);
    const Run two = runCommand(mpirunRaylab(2) + " render " + scene + flags + "--threads 1 -o " +
                               dir.file("two.exr") + " --stats " + dir.file("two.json"));
    REQUIRE_MESSAGE(two.exitCode == 0, two.err);
    checkSameExr(dir.file("one.exr"), dir.file("two.exr"));
    CHECK(rayStats(readFile(dir.file("one.json"))) == rayStats(readFile(dir.file("two.json"))));
}

TEST_CASE("mpirun cli: an SPD --crop equals one process and the full frame's pixels" *
          kWithMpirun) {
    const test::TempDir dir;
    const std::string scene = spdScene(dir);
    // x: ceil(0.3·64) = 20 .. ceil(0.77·64) = 50 (exclusive); y: ceil(0.2·64) = 13 ..
    // ceil(0.9·64) = 58: 30x45 pixels whose edges cut through 16-pixel tiles.
    const std::string flags = " --spd --width 64 --height 64 --float --quiet ";
    const std::string crop = " --crop 0.3,0.77,0.2,0.9 ";
    const Run full = runCommand(raylabBinary() + " render " + scene + flags + "-o " +
                                dir.file("full.exr"));
    REQUIRE_MESSAGE(full.exitCode == 0, full.err);
    const Run one = runCommand(raylabBinary() + " render " + scene + flags + crop + "-o " +
                               dir.file("one.exr") + " --png " + dir.file("one.png") +
                               " --stats " + dir.file("one.json"));
    REQUIRE_MESSAGE(one.exitCode == 0, one.err);
    const Run two = runCommand(mpirunRaylab(2) + " render " + scene + flags + crop +
                               "--threads 1 -o " + dir.file("two.exr") + " --png " +
                               dir.file("two.png") + " --stats " + dir.file("two.json"));
    REQUIRE_MESSAGE(two.exitCode == 0, two.err);
    checkSameExr(dir.file("one.exr"), dir.file("two.exr"));
    CHECK(readFile(dir.file("one.png")) == readFile(dir.file("two.png")));
    CHECK(rayStats(readFile(dir.file("one.json"))) == rayStats(readFile(dir.file("two.json"))));

    // The distributed crop is the window of the full frame: data window
    // (20, 13) 30x45 in a 64x64 display window, every layer bit for bit.
    const Film f = readExr(dir.file("full.exr"));
    const Film c = readExr(dir.file("two.exr"));
    CHECK(c.originX == 20);
    CHECK(c.originY == 13);
    CHECK(c.width == 30);
    CHECK(c.height == 45);
    CHECK(c.fullWidth == 64);
    CHECK(c.fullHeight == 64);
    Film window(c.width, c.height, c.originX, c.originY, f.width, f.height);
    window.mattes.clear();  // readExr keeps no mattes (the Cryptomatte channels: tests/cli/test_crop.cpp)
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x) {
            const size_t from = f.index(c.originX + x, c.originY + y);
            const size_t to = window.index(c.originX + x, c.originY + y);
            for (int k = 0; k < 4; ++k) window.rgba[to * 4 + k] = f.rgba[from * 4 + k];
            window.z[to] = f.z[from];
            window.distance[to] = f.distance[from];
            for (int k = 0; k < 3; ++k) {
                window.normal[to * 3 + k] = f.normal[from * 3 + k];
                window.albedo[to * 3 + k] = f.albedo[from * 3 + k];
            }
            window.objectId[to] = f.objectId[from];
        }
    CHECK(test::filmDifference(window, c) == "");
}

TEST_CASE("mpirun cli: --frames writes a numbered sequence equal to one process" * kWithMpirun) {
    const test::TempDir dir;
    std::ofstream(dir.file("path.json")) << kPathScene;
    const std::string args = " render " + dir.file("path.json") + " --frames 1:3 --float --quiet ";
    const Run one = runCommand(raylabBinary() + args + "-o " + dir.file("one.exr"));
    REQUIRE_MESSAGE(one.exitCode == 0, one.err);
    const Run two = runCommand(mpirunRaylab(2) + args + "--threads 1 -o " + dir.file("two.exr") +
                               " --png " + dir.file("two.png"));
    REQUIRE_MESSAGE(two.exitCode == 0, two.err);
    for (const char* n : {"_0001", "_0002", "_0003"}) {
        checkSameExr(dir.file(std::string("one") + n + ".exr"),
                     dir.file(std::string("two") + n + ".exr"));
        CHECK(std::filesystem::exists(dir.file(std::string("two") + n + ".png")));
    }
    CHECK_FALSE(std::filesystem::exists(dir.file("two.exr")));
    CHECK_FALSE(std::filesystem::exists(dir.file("two_0004.exr")));
    // The camera moves: the first and last frames differ.
    CHECK(test::filmDifference(readExr(dir.file("two_0001.exr")),
                               readExr(dir.file("two_0003.exr"))) == "rgba");
    // A single frame of the sequence renders the same picture on its own.
    const Run single = runCommand(raylabBinary() + " render " + dir.file("path.json") +
                                  " --frames 2 --float --quiet -o " + dir.file("single.exr"));
    REQUIRE_MESSAGE(single.exitCode == 0, single.err);
    checkSameExr(dir.file("single_0002.exr"), dir.file("two_0002.exr"));
}

TEST_CASE("mpirun cli: --frames needs a camera_path" * kWithMpirun) {
    const test::TempDir dir;
    const Run r = runCommand(raylabBinary() + " render " + std::string(RAYLAB_SOURCE_DIR) +
                             "/scenes/primitives.json --frames 1:2 -o " + dir.file("x.exr"));
    CHECK(r.exitCode == 1);
    CHECK(r.err.find("--frames needs a \"camera_path\" in the scene") != std::string::npos);
    const Run usage =
        runCommand(raylabBinary() + " render " + demo() + " --frames 5:2 -o " + dir.file("x.exr"));
    CHECK(usage.exitCode == 2);
    CHECK(usage.err.find("--frames: expected FIRST:LAST") != std::string::npos);
}

TEST_CASE("mpirun cli: a rank that stops answering is reported, nothing is written" * kWithMpirun) {
    const test::TempDir dir;
    // Rank 0 only serves (kRootServesOnly), so rank 1 gets the first chunk
    // however late it starts: on a loaded machine rank 0 could otherwise render
    // all 12 tiles before rank 1 asks, and nothing would fail.
    const Run r = runCommand("RAYLAB_MPI_FAULT=stall:1 RAYLAB_MPI_TIMEOUT=2 " + kRootServesOnly +
                             mpirunRaylab(2) + " render " + demo() +
                             " --width 64 --height 48 --threads 1 --quiet -o " + dir.file("x.exr"));
    CHECK(r.exitCode != 0);
    CHECK_MESSAGE(r.err.find("raylab: error: rank 1 sent nothing for 2 s while holding ") !=
                      std::string::npos,
                  r.err);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

TEST_CASE("mpirun cli: a killed rank ends the job, nothing is written" * kWithMpirun) {
    const test::TempDir dir;
    const Run r =
        runCommand("RAYLAB_MPI_FAULT=kill:1 " + kRootServesOnly + mpirunRaylab(2) + " render " +
                   demo() + " --width 64 --height 48 --threads 1 --quiet -o " + dir.file("x.exr"));
    CHECK(r.exitCode != 0);
    // Open MPI: "... exited on signal 9 (Killed)"; MPICH: "KILLED BY SIGNAL: 9".
    CHECK_MESSAGE((r.err.find("signal 9") != std::string::npos ||
                   r.err.find("SIGNAL: 9") != std::string::npos),
                  r.err);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

namespace {

/// An MPMD launch of two ranks: rank 0 runs `raylab <rank0>`, rank 1 `raylab <rank1>`.
std::string mpirunTwoCommands(const std::string& rank0, const std::string& rank1) {
    return mpirunRaylab(1) + " " + rank0 + " : -np 1 " + raylabBinary() + " " + rank1;
}

const std::string kAgreementAdvice =
    "; every rank must render the same scene with the same options";

}  // namespace

TEST_CASE("mpirun cli: ranks launched with different scenes stop before rendering" * kWithMpirun) {
    const test::TempDir dir;
    const std::string primitives = std::string(RAYLAB_SOURCE_DIR) + "/scenes/primitives.json";
    const std::string out = " --width 48 --height 32 --threads 1 --quiet -o " + dir.file("x.exr");
    const Run r =
        runCommand(mpirunTwoCommands("render " + demo() + out, "render " + primitives + out));
    CHECK(r.exitCode == 1);
    CHECK_MESSAGE(r.err.find("raylab: error: ranks disagree: rank 1 (") != std::string::npos,
                  r.err);
    CHECK_MESSAGE(r.err.find(") read other scene bytes than rank 0: " + primitives +
                             " (1 file, ") != std::string::npos,
                  r.err);
    CHECK_MESSAGE(r.err.find(" against " + demo() + " (5 files, ") != std::string::npos, r.err);
    CHECK(errorLines(r.err) == 1);  // rank 0 says it; rank 1 ends without a second line
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

TEST_CASE("mpirun cli: a mesh that differs between ranks is caught" * kWithMpirun) {
    // Two folders with byte-identical scene files naming mesh.obj; the meshes
    // differ in one digit (what two machines with unsynchronised copies see).
    const test::TempDir dir;
    const std::string scene = R"({"camera": {"eye": [0, 0, 4], "look_at": [0, 0, 0]},
        "lights": [{"type": "point", "position": [2, 3, 4]}],
        "objects": [{"type": "mesh", "file": "mesh.obj"}]})";
    dir.write("a/scene.json", scene);
    dir.write("b/scene.json", scene);
    const std::string mesh = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    dir.write("a/mesh.obj", mesh);
    dir.write("b/mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 2 0\nf 1 2 3\n");
    const std::string files =
        " (2 files, " + std::to_string(scene.size() + mesh.size()) + " bytes)";
    const std::string out = " --width 32 --height 24 --threads 1 --quiet -o " + dir.file("x.exr");
    const Run r = runCommand(mpirunTwoCommands("render " + dir.file("a/scene.json") + out,
                                               "render " + dir.file("b/scene.json") + out));
    CHECK(r.exitCode == 1);
    CHECK_MESSAGE(r.err.find("read other scene bytes than rank 0: " + dir.file("b/scene.json") +
                             files + " against " + dir.file("a/scene.json") + files +
                             kAgreementAdvice) != std::string::npos,
                  r.err);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}

TEST_CASE("mpirun cli: ranks with other image settings stop, other thread counts agree" *
          kWithMpirun) {
    const test::TempDir dir;
    const std::string render = "render " + demo() + " --height 32 --quiet -o " + dir.file("x.exr");
    const Run wider = runCommand(mpirunTwoCommands(render + " --width 48", render + " --width 64"));
    CHECK(wider.exitCode == 1);
    CHECK_MESSAGE(wider.err.find("raylab: error: ranks disagree: rank 1 (") != std::string::npos,
                  wider.err);
    CHECK_MESSAGE(wider.err.find(") renders with width=64, rank 0 with width=48" +
                                 kAgreementAdvice) != std::string::npos,
                  wider.err);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
    // --threads does not change a pixel: the same render with 1 and 2 threads is one picture.
    const Run threads = runCommand(
        mpirunTwoCommands(render + " --width 48 --threads 1", render + " --width 48 --threads 2"));
    CHECK_MESSAGE(threads.exitCode == 0, threads.err);
    CHECK(std::filesystem::exists(dir.file("x.exr")));
}

TEST_CASE("mpirun cli: an MPI module that cannot be loaded is one error line per rank" *
          kWithMpirun) {
    // A copy of raylab with a broken raylab-mpi.so beside it: the loader takes
    // the module beside the executable first, and reports it rather than
    // falling back to the build tree's.
    const test::TempDir dir;
    const std::string copy = dir.file("raylab");
    std::filesystem::copy_file(raylabBinary(), copy);
    dir.write("raylab-mpi.so", "not a shared object\n");
    const char* flags = std::getenv("RAYLAB_MPIRUN_FLAGS");
    const Run r = runCommand(std::string(std::getenv("RAYLAB_MPIRUN")) + " -np 2 " +
                             (flags ? flags : "") + " " + copy + " render " + demo() +
                             " --width 32 --height 24 --quiet -o " + dir.file("x.exr"));
    CHECK(r.exitCode == 1);
    const std::string line = "raylab: error: MPI is not available (" + dir.file("raylab-mpi.so") + ": ";
    CHECK_MESSAGE(r.err.rfind(line, 0) == 0, r.err);
    // Each rank says it once (mpirun may end rank 1 before it does, once rank 0 has exited 1).
    CHECK_MESSAGE((errorLines(r.err) == 1 || errorLines(r.err) == 2), r.err);
    CHECK(r.err.find("Segmentation") == std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.file("x.exr")));
}
