// Every path a render writes is checked before the render against every file
// it reads and against the other outputs, by file identity: through hard
// links, symbolic links and "..", and for each numbered name of --frames.
// A clash is a usage error (exit 2) that writes nothing and leaves the inputs
// byte for byte as they were.
#include <doctest/doctest.h>

#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/io/errors.h"
#include "renderer/io/input_files.h"
#include "renderer/io/output_names.h"
#include "renderer/io/text_file.h"
#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

const std::string kObj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
const std::string kMtl = "newmtl red\nKd 0.8 0.1 0.1\n";

/// A JSON scene naming mesh `obj` (relative to the scene), with a camera path for --frames.
std::string meshScene(const std::string& obj) {
    return "{\"camera\": {\"eye\": [0.3, 0.3, 3], \"look_at\": [0.3, 0.3, 0]},\n"
           " \"lights\": [{\"type\": \"point\", \"position\": [2, 3, 4]}],\n"
           " \"camera_path\": {\"keyframes\": [{\"frame\": 1, \"eye\": [0.3, 0.3, 3], "
           "\"look_at\": [0.3, 0.3, 0]}]},\n"
           " \"objects\": [{\"type\": \"mesh\", \"file\": \"" + obj + "\"}]}\n";
}

/// Writes scene.json + meshes/m.obj + meshes/m.mtl into `dir`.
void writeMeshScene(const TempDir& dir) {
    dir.write("scene.json", meshScene("meshes/m.obj"));
    dir.write("meshes/m.obj", kObj);
    dir.write("meshes/m.mtl", kMtl);
}

std::vector<std::string> render(const std::string& scene, const std::vector<std::string>& extra) {
    std::vector<std::string> args{"render", scene, "--width", "8", "--height", "8", "--quiet"};
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
}

/// The inputs are byte for byte as written by writeMeshScene.
void checkInputsIntact(const TempDir& dir) {
    CHECK(readFile(dir.file("scene.json")) == meshScene("meshes/m.obj"));
    CHECK(readFile(dir.file("meshes/m.obj")) == kObj);
    CHECK(readFile(dir.file("meshes/m.mtl")) == kMtl);
}

const std::vector<std::string> kInputs = {"meshes/m.mtl", "meshes/m.obj", "scene.json"};

}  // namespace

TEST_CASE("output names: --stats naming a mesh or an MTL library is refused, the file intact") {
    // Issue 22: `--stats meshes/torus.obj` replaced the mesh with JSON.
    TempDir dir;
    writeMeshScene(dir);
    for (const char* input : {"meshes/m.obj", "meshes/m.mtl"}) {
        CAPTURE(input);
        const RunResult r = runRaylab(render(dir.file("scene.json"),
                                             {"-o", dir.file("out.exr"), "--stats", dir.file(input)}));
        checkRefused(r, dir, kInputs, 2, "--stats", "which this render reads");
        CHECK(contains(r.err, "same file"));
        checkInputsIntact(dir);
    }
    // The shipped torus, as in the report: the mesh of a bare-OBJ scene.
    const std::string torus = std::string(RAYLAB_SOURCE_DIR) + "/scenes/meshes/torus.obj";
    const std::string before = readFile(torus);
    const RunResult r = runRaylab(render(std::string(RAYLAB_SOURCE_DIR) + "/scenes/demo.json",
                                         {"-o", dir.file("out.exr"), "--stats", torus}));
    checkRefused(r, dir, kInputs, 2, "--stats", "which this render reads");
    CHECK(readFile(torus) == before);
}

TEST_CASE("output names: an input reached through a hard link, a symbolic link or '..' is refused") {
    TempDir dir;
    writeMeshScene(dir);
    std::filesystem::create_directories(dir.file("sub"));
    REQUIRE(::link(dir.file("meshes/m.obj").c_str(), dir.file("hard.json").c_str()) == 0);
    std::filesystem::create_symlink(dir.file("meshes/m.mtl"), dir.file("soft.json"));
    std::filesystem::create_symlink("meshes", dir.file("linkdir"));
    const std::vector<std::vector<std::string>> cases = {
        {"--stats", dir.file("hard.json")},
        {"--stats", dir.file("soft.json")},
        {"--stats", dir.file("sub/../meshes/./m.obj")},
        {"--stats", dir.file("linkdir/m.mtl")},
    };
    for (const std::vector<std::string>& flags : cases) {
        CAPTURE(flags[1]);
        std::vector<std::string> extra{"-o", dir.file("out.exr")};
        extra.insert(extra.end(), flags.begin(), flags.end());
        const RunResult r = runRaylab(render(dir.file("scene.json"), extra));
        CHECK(r.exitCode == 2);
        CHECK(lines(r.err).size() == 1);
        CHECK(contains(r.err, "which this render reads"));
        checkInputsIntact(dir);
        CHECK(readFile(dir.file("hard.json")) == kObj);
        CHECK(std::filesystem::is_symlink(dir.file("soft.json")));
        CHECK_FALSE(std::filesystem::exists(dir.file("out.exr")));
    }
}

TEST_CASE("output names: --frames numbered names are checked against the scene and each other") {
    // Issue 22: `--frames 1 --stats s.json` on a scene named s_0001.json replaced the scene.
    TempDir dir;
    dir.write("meshes/m.obj", kObj);
    dir.write("meshes/m.mtl", kMtl);
    const std::string scene = dir.write("s_0001.json", meshScene("meshes/m.obj"));
    RunResult r = runRaylab(render(scene, {"-o", dir.file("out.exr"), "--frames", "1:1",
                                                "--stats", dir.file("s.json")}));
    checkRefused(r, dir, {"meshes/m.mtl", "meshes/m.obj", "s_0001.json"}, 2, "--stats",
                 "s_0001.json");
    CHECK(readFile(scene) == meshScene("meshes/m.obj"));

    // A frame's output that is a link to another flag's frame, or to a mesh,
    // with a sequence long enough (100 frames) that the directory is scanned.
    std::filesystem::create_symlink("meshes/m.obj", dir.file("out_0042.exr"));
    r = runRaylab(render(scene, {"-o", dir.file("out.exr"), "--frames", "1:100"}));
    CHECK(r.exitCode == 2);
    CHECK(contains(r.err, "out_0042.exr"));
    CHECK(contains(r.err, "which this render reads"));
    CHECK(readFile(dir.file("meshes/m.obj")) == kObj);
    std::filesystem::remove(dir.file("out_0042.exr"));

    std::filesystem::create_symlink("img_0007.exr", dir.file("img_0007.png"));  // dangling
    r = runRaylab(render(scene, {"-o", dir.file("img.exr"), "--png", dir.file("img.png"),
                                      "--frames", "1:100"}));
    CHECK(r.exitCode == 2);
    CHECK(contains(r.err, "img_0007.png"));
    CHECK(contains(r.err, "both would write one file"));
    // The same with 3 frames (names looked up one by one).
    r = runRaylab(render(scene, {"-o", dir.file("img.exr"), "--png", dir.file("img.png"),
                                      "--frames", "5:7"}));
    CHECK(r.exitCode == 2);
    CHECK(contains(r.err, "both would write one file"));
    CHECK(dir.files() == std::vector<std::string>{"meshes/m.mtl", "meshes/m.obj", "s_0001.json"});
}

TEST_CASE("output names: two outputs that are one existing file through links are refused") {
    TempDir dir;
    writeMeshScene(dir);
    dir.write("a.exr", "old exr");
    REQUIRE(::link(dir.file("a.exr").c_str(), dir.file("a.png").c_str()) == 0);
    RunResult r = runRaylab(render(dir.file("scene.json"),
                                   {"-o", dir.file("a.exr"), "--png", dir.file("a.png")}));
    CHECK(r.exitCode == 2);
    CHECK(contains(r.err, "are one file"));
    std::filesystem::remove(dir.file("a.png"));
    std::filesystem::create_symlink("a.exr", dir.file("b.png"));
    r = runRaylab(render(dir.file("scene.json"),
                         {"-o", dir.file("a.exr"), "--png", dir.file("b.png")}));
    CHECK(r.exitCode == 2);
    CHECK(contains(r.err, "are one file"));
    CHECK(readFile(dir.file("a.exr")) == "old exr");
    // Distinct files are fine, and the inputs stay as they were.
    std::filesystem::remove(dir.file("b.png"));
    r = runRaylab(render(dir.file("scene.json"),
                         {"-o", dir.file("a.exr"), "--png", dir.file("b.png"), "--stats",
                          dir.file("s.json")}));
    CHECK(r.exitCode == 0);
    checkInputsIntact(dir);
}

TEST_CASE("output names: checkOutputNames on its own") {
    TempDir dir;
    const std::string mesh = dir.write("m.obj", kObj);
    std::vector<raylab::InputFile> inputs;
    {
        raylab::InputFileLog log;
        CHECK(raylab::readTextFile(mesh) == kObj);
        CHECK(raylab::readTextFile(mesh) == kObj);  // recorded once
        inputs = log.files();
    }
    REQUIRE(inputs.size() == 1);
    CHECK(inputs[0].path == mesh);
    using Flags = std::vector<raylab::OutputFlag>;
    CHECK_NOTHROW(raylab::checkOutputNames(Flags{{"-o", dir.file("a.exr")}}, nullptr, inputs));
    CHECK_THROWS_AS(raylab::checkOutputNames(Flags{{"--stats", mesh}}, nullptr, inputs),
                    raylab::UsageError);
    CHECK_THROWS_AS(raylab::checkOutputNames(Flags{{"-o", dir.file("x")}, {"--stats", dir.file("./x")}},
                                             nullptr, {}),
                    raylab::UsageError);
    // Frames: the numbered names of two flags never meet unless their names do.
    const raylab::OutputFrames frames{1, 1000, [](const std::string& p, int f) {
                                          const size_t dot = p.rfind('.');
                                          char digits[16];
                                          std::snprintf(digits, sizeof digits, "_%04d", f);
                                          return p.substr(0, dot) + digits + p.substr(dot);
                                      }};
    CHECK_NOTHROW(raylab::checkOutputNames(
        Flags{{"-o", dir.file("a.exr")}, {"--stats", dir.file("a.json")}}, &frames, inputs));
    CHECK_THROWS_AS(raylab::checkOutputNames(
                        Flags{{"-o", dir.file("a.exr")}, {"--stats", dir.file("sub/../a.exr")}},
                        &frames, inputs),
                    raylab::UsageError);
    // A file outside the range is not an output: m_1001.obj may stay a link to the mesh.
    std::filesystem::create_symlink(mesh, dir.file("m_1001.obj"));
    CHECK_NOTHROW(raylab::checkOutputNames(Flags{{"--stats", dir.file("m.obj")}}, &frames, {}));
    CHECK_NOTHROW(raylab::checkOutputNames(Flags{{"--stats", dir.file("m.obj")}}, &frames, inputs));
    std::filesystem::create_symlink(mesh, dir.file("m_0999.obj"));
    CHECK_THROWS_AS(raylab::checkOutputNames(Flags{{"--stats", dir.file("m.obj")}}, &frames, inputs),
                    raylab::UsageError);
}
