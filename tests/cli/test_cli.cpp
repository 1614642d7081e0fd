// The command line as a user meets it: exit codes, one-line errors, outputs
// that appear complete or not at all.
#include <doctest/doctest.h>

#include <filesystem>

#include "cli_helpers.h"

namespace fs = std::filesystem;

namespace {
const std::string kTinyScene = R"({
  "image": {"width": 24, "height": 16},
  "camera": {"type": "perspective", "eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40},
  "ambient": [0.1, 0.1, 0.1],
  "lights": [{"type": "point", "position": [2, 4, 3], "color": [1, 1, 1], "intensity": 1}],
  "materials": {"red": {"kd": [0.8, 0.1, 0.1]}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "red"}]
})";
}  // namespace

TEST_CASE("cli: --help describes the commands and exits 0") {
    const cli::Result r = cli::run("--help");
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("render") != std::string::npos);
    const cli::Result rr = cli::run("render --help");
    CHECK(rr.exitCode == 0);
    for (const char* flag : {"--png", "--width", "--height", "--spp", "--depth", "--threads", "--accel",
                             "--stats", "--quiet", "--compression"})
        CHECK_MESSAGE(rr.out.find(flag) != std::string::npos, flag);
}

TEST_CASE("cli: usage errors exit 2 with one line") {
    for (const char* args : {"", "frobnicate", "render", "render scene.json", "render x.json -o",
                             "render x.json -o y.exr --width 0", "render x.json -o y.exr --width 1000000000",
                             "render x.json -o y.exr --spp abc", "render x.json -o y.exr --accel bvh4",
                             "render x.json -o y.exr --bogus", "render x.json -o y.exr --compression lzma",
                             "render x.json -o y.exr --compression"}) {
        CAPTURE(args);
        const cli::Result r = cli::run(args);
        CHECK(r.exitCode == 2);
        if (std::string(args).empty()) continue;  // bare 'raylab' prints the help text
        CHECK(cli::lineCount(r.err) == 1);
        CHECK(r.err.rfind("raylab: error: ", 0) == 0);
    }
}

TEST_CASE("cli: bad input exits 1 with FILE:LINE and leaves no output") {
    cli::TempDir dir;
    const std::string scene = dir.write("bad.json", "{\n  \"objects\": [\n    {\"type\": \"sphere\", \"radius\": -1}\n  ]\n}\n");
    const std::string out = dir.file("bad.exr");
    const cli::Result r = cli::run("render " + scene + " -o " + out + " --quiet");
    CHECK(r.exitCode == 1);
    CHECK(cli::lineCount(r.err) == 1);
    CHECK(r.err.rfind("raylab: error: " + scene + ":", 0) == 0);
    CHECK_FALSE(fs::exists(out));

    const cli::Result missing = cli::run("render " + dir.file("nope.json") + " -o " + out);
    CHECK(missing.exitCode == 1);
    CHECK(cli::lineCount(missing.err) == 1);

    const std::string garbage = dir.write("garbage.json", std::string("\x00\x01\xff\xfe binary", 12));
    const cli::Result g = cli::run("render " + garbage + " -o " + out);
    CHECK(g.exitCode == 1);
    CHECK(cli::lineCount(g.err) == 1);
    CHECK_FALSE(fs::exists(out));
}

TEST_CASE("cli: a render writes EXR, PNG and stats, and prints a summary") {
    cli::TempDir dir;
    const std::string scene = dir.write("tiny.json", kTinyScene);
    const cli::Result r = cli::run("render " + scene + " -o " + dir.file("a.exr") + " --png " +
                                   dir.file("a.png") + " --stats " + dir.file("a.json") +
                                   " --threads 2");
    CHECK(r.exitCode == 0);
    CHECK(fs::file_size(dir.file("a.exr")) > 0);
    CHECK(fs::file_size(dir.file("a.png")) > 0);
    const std::string stats = cli::readFile(dir.file("a.json"));
    for (const char* key : {"\"rays\"", "\"camera\"", "\"shadow\"", "\"reflection\"", "\"refraction\"",
                            "\"camera_hits\"", "\"time_s\"", "\"parse\"", "\"build\"", "\"render\"",
                            "\"primitives\"", "\"effects\"", "\"threads\"", "\"accel\""})
        CHECK_MESSAGE(stats.find(key) != std::string::npos, key);
    CHECK(stats.find("\"camera\": 384") != std::string::npos);  // 24 x 16 camera rays
    CHECK(r.out.find("Mrays/s") != std::string::npos);
    // No temporary files are left beside the outputs.
    int files = 0;
    for (const auto& e : fs::directory_iterator(dir.path())) files += e.is_regular_file();
    CHECK(files == 4);  // tiny.json, a.exr, a.png, a.json

    const cli::Result quiet = cli::run("render " + scene + " -o " + dir.file("b.exr") + " --quiet");
    CHECK(quiet.exitCode == 0);
    CHECK(quiet.out.empty());
    CHECK(quiet.err.empty());
}

TEST_CASE("cli: the same render is byte-identical for 1 and 2 threads and across runs") {
    cli::TempDir dir;
    const std::string scene = dir.write("tiny.json", kTinyScene);
    // The EXR header records the command line (which names the thread count
    // when --threads is given), so across thread counts the pixels are
    // compared through the PNG and `raylab compare`; the same command twice
    // must give the same EXR bytes.
    const auto render = [&](const std::string& name, const std::string& flags) {
        REQUIRE(cli::run("render " + scene + " -o " + dir.file(name + ".exr") + " --png " +
                         dir.file(name + ".png") + " " + flags + " --quiet").exitCode == 0);
    };
    render("1", "--threads 1");
    render("2", "--threads 2");
    CHECK(cli::readFile(dir.file("1.png")) == cli::readFile(dir.file("2.png")));
    const cli::Result c = cli::run("compare " + dir.file("1.exr") + " " + dir.file("2.exr"));
    CHECK(c.exitCode == 0);
    CHECK(c.out.find("(100.0000%)") != std::string::npos);
    const std::string first = cli::readFile(dir.file("2.exr"));
    render("2", "--threads 2");
    CHECK(cli::readFile(dir.file("2.exr")) == first);
}

TEST_CASE("cli: compare reports identical and differing renders, --polygons triangles") {
    cli::TempDir dir;
    const std::string scene = dir.write("poly.json", R"({
  "image": {"width": 24, "height": 16},
  "camera": {"eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 40},
  "ambient": 0.2,
  "lights": [{"type": "point", "position": [1, 2, 4]}],
  "objects": [{"type": "polygon", "vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [0, 0.2, 0], [-1, 1, 0]]}]
})");
    const std::string a = dir.file("a.exr"), b = dir.file("b.exr"), c = dir.file("c.exr");
    REQUIRE(cli::run("render " + scene + " -o " + a + " --quiet --float").exitCode == 0);
    REQUIRE(cli::run("render " + scene + " -o " + b + " --quiet --float --threads 1").exitCode == 0);
    REQUIRE(cli::run("render " + scene + " -o " + c + " --quiet --float --polygons triangles").exitCode == 0);
    const cli::Result same = cli::run("compare " + a + " " + b);
    CHECK(same.exitCode == 0);
    CHECK(same.out.find("bit-identical:     384 (100.0000%)") != std::string::npos);
    // The concave pentagon ear-clipped into triangles covers the same pixels;
    // only the shading of edge pixels may differ in the last bits.
    const cli::Result tri = cli::run("compare " + a + " " + c + " --threshold 0.01");
    CHECK((tri.exitCode == 0 || tri.exitCode == 3));
    CHECK(tri.out.find("over 0.01          0 pixels") != std::string::npos);
    CHECK(cli::run("compare " + a).exitCode == 2);
    CHECK(cli::run("compare " + a + " " + dir.file("missing.exr")).exitCode == 1);
}

TEST_CASE("cli: camera overrides set the camera of any scene, --up and --normals frame a bare OBJ") {
    cli::TempDir dir;
    const std::string scene = dir.write("tiny.json", kTinyScene);
    // The flags give the same picture as a scene whose camera says the same.
    std::string moved = kTinyScene;
    const std::string camera =
        R"("camera": {"type": "perspective", "eye": [0, 1, 5], "look_at": [0, 0, 0], "up": [0, 1, 0], "fov": 40})";
    moved.replace(moved.find(camera), camera.size(),
                  R"("camera": {"eye": [3, 1.5, 4], "look_at": [0, 0.25, 0], "up": [0.1, 1, 0], "fov": 30})");
    const std::string reference = dir.write("moved.json", moved);
    CHECK(cli::run("render " + reference + " -o " + dir.file("ref.exr") + " --quiet").exitCode == 0);
    const cli::Result r =
        cli::run("render " + scene + " -o " + dir.file("flags.exr") +
                 " --quiet --eye 3,1.5,4 --look-at 0,0.25,0 --camera-up 0.1,1,0 --fov 30");
    CHECK(r.exitCode == 0);
    CHECK(cli::run("compare " + dir.file("ref.exr") + " " + dir.file("flags.exr")).exitCode == 0);
    // And differ from the scene's own camera.
    CHECK(cli::run("render " + scene + " -o " + dir.file("own.exr") + " --quiet").exitCode == 0);
    CHECK(cli::run("compare " + dir.file("own.exr") + " " + dir.file("flags.exr")).exitCode != 0);

    // A bare OBJ: a tall box standing on +z renders upright with --up z.
    const std::string obj = dir.write(
        "tower.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 4\nv 1 0 4\nv 1 1 4\nv 0 1 4\n"
                     "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
    CHECK(cli::run("render " + obj + " -o " + dir.file("y.exr") + " --quiet --width 32 --height 24").exitCode == 0);
    CHECK(cli::run("render " + obj + " -o " + dir.file("z.exr") +
                   " --quiet --width 32 --height 24 --up z --normals smooth")
              .exitCode == 0);
    CHECK(cli::run("compare " + dir.file("y.exr") + " " + dir.file("z.exr")).exitCode != 0);

    const cli::Result help = cli::run("render --help");
    for (const char* flag : {"--eye X,Y,Z", "--look-at X,Y,Z", "--camera-up X,Y,Z", "--fov DEG",
                             "--up x|y|z|-x|-y|-z", "--normals file|flat|smooth"})
        CHECK_MESSAGE(help.out.find(flag) != std::string::npos, flag);
}

TEST_CASE("cli: bad camera overrides are usage errors, one line, exit 2") {
    cli::TempDir dir;
    const std::string scene = dir.write("tiny.json", kTinyScene);
    const std::string obj = dir.write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string out = " -o " + dir.file("o.exr");
    for (const std::string& args :
         {scene + out + " --eye 1,2", scene + out + " --eye 1,2,x", scene + out + " --eye 1,2,3,4",
          scene + out + " --look-at ,1,2", scene + out + " --camera-up 1,nan,0",
          scene + out + " --fov 0", scene + out + " --fov 180", scene + out + " --fov -5",
          scene + out + " --eye 0,0,0 --look-at 0,0,0", scene + out + " --camera-up 0,0,0",
          scene + out + " --up z", scene + out + " --normals smooth", obj + out + " --up w",
          obj + out + " --up z --up y", scene + out + " --frames 1:2 --eye 1,2,3"}) {
        CAPTURE(args);
        const cli::Result r = cli::run("render " + args);
        CHECK(r.exitCode == 2);
        CHECK(cli::lineCount(r.err) == 1);
        CHECK(r.err.rfind("raylab: error: ", 0) == 0);
        CHECK_FALSE(fs::exists(dir.file("o.exr")));
    }
}

TEST_CASE("cli: --compression writes the same picture in every scheme") {
    cli::TempDir dir;
    const std::string scene = dir.write("tiny.json", kTinyScene);
    std::string first;
    for (const char* c : {"zip", "none", "rle", "zips", "piz"}) {
        CAPTURE(c);
        const std::string out = dir.file(std::string(c) + ".exr");
        const cli::Result r = cli::run("render " + scene + " -o " + out + " --quiet --compression " + c);
        REQUIRE(r.exitCode == 0);
        if (first.empty()) {
            first = out;
            continue;
        }
        // raylab compare: exit 0 only for bit-identical RGBA.
        CHECK(cli::run("compare " + first + " " + out).exitCode == 0);
    }
}

TEST_CASE("cli: without an EXR output no AOV layer is computed, and every pixel is the same") {
    // The layers (depth, normal, albedo, objectId, Cryptomatte) are computed
    // only for an EXR: a PNG alone comes from an RGBA-only film. Its bytes
    // must equal the PNG written beside an EXR, on every sampling path (with
    // --alpha transparent the background is left out by coverage).
    cli::TempDir dir;
    const std::string json = dir.write("tiny.json", kTinyScene);
    const std::string nff = dir.write("tiny.nff",
                                      "v\nfrom 0 1 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 0.01\n"
                                      "resolution 20 14\nb 0.1 0.2 0.3\nl 2 4 3\n"
                                      "f 0.8 0.1 0.1 0.7 0.3 20 0.4 1.5\ns 0 0 0 1\n"
                                      "f 0.2 0.8 0.2 1 0 1 0 0\np 4\n-3 -1 -3\n3 -1 -3\n3 -1 3\n-3 -1 3\n");
    const std::pair<std::string, std::string> cases[] = {
        {json, ""}, {json, "--spp 4"}, {json, "--adaptive 0.05"}, {json, "--crop 0.2,0.7,0.1,0.9"},
        {json, "--spp 4 --alpha transparent"}, {json, "--adaptive 0.05 --alpha transparent"},
        {nff, "--spd"}, {nff, "--spd --crop 0.3,1,0,0.5"}, {nff, "--spd --alpha transparent"}};
    int k = 0;
    for (const auto& entry : cases) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& scene = entry.first;
        const auto& flags = entry.second;
        CAPTURE(flags);
        const std::string n = std::to_string(k++);
        const std::string both = "render " + scene + " " + flags + " --quiet -o " + dir.file(n + ".exr") +
                                 " --png " + dir.file(n + "a.png") + " --stats " + dir.file(n + "a.json");
        const std::string alone = "render " + scene + " " + flags + " --quiet -o " + dir.file(n + "b.png") +
                                  " --stats " + dir.file(n + "b.json");
        REQUIRE(cli::run(both).exitCode == 0);
        REQUIRE(cli::run(alone).exitCode == 0);
        // Byte for byte: two processes write the same file (igzip's streams
        // are placed so that its output cannot depend on their address,
        // renderer/io/igzip_stream.h).
        CHECK(cli::readFile(dir.file(n + "a.png")) == cli::readFile(dir.file(n + "b.png")));
        // The statistics name the layers as an effect only where they were made.
        CHECK(cli::readFile(dir.file(n + "a.json")).find("\"aovs\"") != std::string::npos);
        CHECK(cli::readFile(dir.file(n + "b.json")).find("\"aovs\"") == std::string::npos);
    }
}
