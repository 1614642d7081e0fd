// Bad JSON scenes through the real binary: refused with one
// "raylab: error: FILE:LINE: ..." line and exit 1, nothing written; odd but
// valid scenes render. Renders are 8x8.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "robustness_helpers.h"

using namespace raylab::robust;

namespace {

/// A valid scene; `objects` (a JSON array body) and `extra` (members) are spliced in.
/// Line 1 "{", line 2 camera, line 3 lights, line 4 objects.
const char* const kSphere = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";

std::string scene(const std::string& objects = kSphere,
                  const std::string& camera = R"("eye": [0, 0, 5], "look_at": [0, 0, 0])",
                  const std::string& extra = "") {
    return "{\n"
           "  \"camera\": {" + camera + "},\n"
           "  \"lights\": [{\"type\": \"point\", \"position\": [2, 3, 4]}],\n"
           "  \"objects\": [" + objects + "]" + extra + "\n"
           "}\n";
}

void refused(const std::string& text, int line, const std::string& fragment,
             const std::vector<std::string>& extraFiles = {},
             const std::vector<std::pair<std::string, std::string>>& files = {}) {
    TempDir dir;
    for (const auto& [name, body] : files) dir.write(name, body);
    const std::string path = dir.write("scene.json", text);
    const RunResult r = runRaylab(tinyRender(dir, path));
    std::vector<std::string> inputs{"scene.json"};
    for (const auto& [name, body] : files) inputs.push_back(name);
    inputs.insert(inputs.end(), extraFiles.begin(), extraFiles.end());
    checkRefused(r, dir, inputs, 1, path + ":" + (line > 0 ? std::to_string(line) + ":" : ""),
                 fragment);
}

void rendered(const std::string& text,
              const std::vector<std::pair<std::string, std::string>>& files = {},
              const std::vector<std::string>& extra = {}) {
    TempDir dir;
    std::vector<std::string> inputs{"scene.json"};
    for (const auto& [name, body] : files) {
        dir.write(name, body);
        inputs.push_back(name);
    }
    const std::string path = dir.write("scene.json", text);
    checkRendered(runRaylab(tinyRender(dir, path, extra)), dir, inputs);
}

}  // namespace

TEST_CASE("json: empty files and binary garbage are refused") {
    refused("", 1, "empty file");
    refused(" \n\t\n", 3, "empty file");
    // A PNG header: its first NUL byte is on line 3 (after "\r\n" and "\n").
    refused(std::string("\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR", 16), 3, "NUL byte");
    refused("\x80\xff\xfe garbage", 1, "");
    refused("\x1b[2J\x1b[31m", 1, "");
}

TEST_CASE("json: a file truncated in the middle of an entity names the last line") {
    const std::string full = scene();
    // Cut inside the sphere's "center" array (line 4) and inside a string.
    refused(full.substr(0, full.rfind("[0, 0, 0]") + 4), 4, "end of input");
    refused(full.substr(0, full.find("sphere") + 3), 4, "unterminated string");
    refused(full.substr(0, full.size() - 3), 4, "end of input");
    refused("{\"camera\": {\"eye\": [0, 0, 5], /* never closed", 1, "unterminated /* comment");
}

TEST_CASE("json: NaN, infinities and out-of-range numbers are refused with their line") {
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": NaN})"), 4, "NaN");
    refused(scene(R"({"type": "sphere", "center": [Infinity, 0, 0], "radius": 1})"), 4, "infinity");
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1e400})"), 4,
            "out of range");
    refused(scene(R"({"type": "sphere", "center": [-1e400, 0, 0], "radius": 1})"), 4,
            "out of range");
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": -nan})"), 4, "");
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 0x10})"), 4,
            "invalid number");
}

TEST_CASE("json: zero, negative and absurd counts and resolutions are refused") {
    const std::string objs = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
    const std::string cam = R"("eye": [0, 0, 5], "look_at": [0, 0, 0])";
    auto withImage = [&](const std::string& image) {
        return scene(objs, cam, ",\n  \"image\": " + image);
    };
    refused(withImage(R"({"width": 0, "height": 0})"), 5, "image.width");
    refused(withImage(R"({"width": -8, "height": 8})"), 5, "image.width");
    refused(withImage(R"({"width": 8.5, "height": 8})"), 5, "integer");
    refused(withImage(R"({"width": 1000000000, "height": 8})"), 5, "image.width");
    refused(withImage(R"({"width": 8, "height": 8, "spp": 0})"), 5, "image.spp");
    refused(withImage(R"({"width": 8, "height": 8, "depth": -1})"), 5, "image.depth");
    // The same limits as the command line: depth 1..64, width and height 1..65536.
    refused(withImage(R"({"width": 8, "height": 8, "depth": 65})"), 5, "[1, 64]");
    refused(withImage(R"({"width": 65537, "height": 8})"), 5, "[1, 65536]");
    refused(scene(R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0]]})"), 4, "at least 3");
    refused(scene(R"({"type": "checkerboard", "origin": [0, 0, 0], "edge_u": [1, 0, 0],
  "edge_v": [0, 0, 1], "divisions": 0, "materials": ["a", "a"]})"),
            5, "divisions");
    refused(scene(R"({"type": "checkerboard", "origin": [0, 0, 0], "edge_u": [1, 0, 0],
  "edge_v": [0, 0, 1], "divisions": [2000000000, 1], "materials": ["a", "a"]})"),
            5, "divisions");
}

TEST_CASE("json: a degenerate camera is refused at the camera's line") {
    const std::string objs = R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})";
    refused(scene(objs, R"("eye": [1, 2, 3], "look_at": [1, 2, 3])"), 2, "coincide");
    refused(scene(objs, R"("eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 0])"), 2,
            "camera.up");
    refused(scene(objs, R"("eye": [0, 0, 5], "look_at": [0, 0, 0], "up": [0, 0, 3])"), 2,
            "parallel");
    refused(scene(objs, R"("eye": [0, 0, 5], "look_at": [0, 0, 0], "fov": 0)"), 2, "camera.fov");
    refused(scene(objs, R"("type": "orthographic", "eye": [0, 0, 5], "direction": [0, 0, 0],
                            "width": 2)"),
            2, "camera.direction");
    refused(scene(objs, R"("eye": [1e308, 0, 0], "look_at": [-1e308, 0, 0])"), 2, "");
}

TEST_CASE("json: deeply nested and huge documents") {
    // 100000 nested arrays: refused at depth 257, no stack overflow.
    refused(std::string(100000, '[') + std::string(100000, ']'), 1, "nesting deeper than");
    refused("{\"camera\": " + std::string(5000, '{'), 1, "");
    // 100000 spheres (about 7 MB): accepted and rendered.
    std::string many;
    for (int i = 0; i < 100000; ++i)
        many += std::string(i ? "," : "") + "\n{\"type\": \"sphere\", \"center\": [" +
                std::to_string(i % 50 - 25) + ", " + std::to_string(i / 50 % 50 - 25) +
                ", -20], \"radius\": 0.3}";
    rendered(scene(many));
    // A polygon of 300000 vertices: accepted and rendered.
    std::string verts;
    for (int i = 0; i < 300000; ++i) {
        const double a = 6.283185307179586 * i / 300000;
        verts += std::string(i ? "," : "") + "[" + std::to_string(std::cos(a)) + ", " +
                 std::to_string(std::sin(a)) + ", 0]";
    }
    rendered(scene("{\"type\": \"polygon\", \"vertices\": [" + verts + "], \"sides\": \"both\"}"));
    // The same polygon with "triangulate": true: the ear clipping is quadratic
    // (20000 vertices take 2 s, 40000 take 7 s), so 300000 would take minutes.
    // It must be refused at its line or rendered within 30 s.
    TempDir dir;
    const std::string path = dir.write(
        "scene.json", scene("{\"type\": \"polygon\", \"vertices\": [" + verts +
                            "], \"triangulate\": true}"));
    const RunResult r = runRaylab(tinyRender(dir, path), 30);
    CAPTURE(r.seconds);
    checkHandled(r, dir, {"scene.json"}, path + ":4:");
}

TEST_CASE("json: very long lines and keys neither hang nor flood the terminal") {
    // The whole scene on one line, padded with 4 MB of spaces: renders.
    std::string oneLine = scene();
    for (char& c : oneLine)
        if (c == '\n') c = ' ';
    rendered(oneLine + std::string(4 << 20, ' '));
    // A 1 MB unknown key, a 1 MB bare word and a 1 MB material name: refused
    // with a short message (the echo of the input is cut).
    refused("{\"" + std::string(1 << 20, 'k') + "\": 1}", 1, "kkkk");
    refused("{\"camera\": " + std::string(1 << 20, 'x') + "}", 1, "invalid literal");
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": ")" +
                  std::string(1 << 20, 'm') + "\"}"),
            4, "unknown material");
    refused(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": )" +
                  std::string(1 << 20, '1') + ".x}"),
            4, "invalid number");
}

TEST_CASE("json: control characters from the input are not echoed raw to the terminal") {
    // An unknown key holding ESC sequences (written as JSON escapes): the
    // error line must not carry raw control bytes.
    TempDir dir;
    const std::string path = dir.write("scene.json", "{\"\\u001b[2J\\u001b]0;pwned\\u0007\": 1}");
    const RunResult r = runRaylab(tinyRender(dir, path));
    CHECK(r.exitCode == 1);
    for (char c : r.err) CHECK_MESSAGE((c == '\n' || (unsigned char)c >= 0x20), "raw control byte");
}

TEST_CASE("json: UTF-16 files are refused, a UTF-8 BOM and CRLF line ends are accepted") {
    std::string le = "\xff\xfe", be = "\xfe\xff", noBom;
    for (char c : scene()) {
        le += c;
        le += '\0';
        be += '\0';
        be += c;
        noBom += c;
        noBom += '\0';
    }
    refused(le, 1, "UTF-16");
    refused(be, 1, "UTF-16");
    refused(noBom, 1, "NUL byte");

    std::string crlf;
    for (char c : scene()) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    rendered(crlf);
    rendered("\xEF\xBB\xBF" + scene());
    // Line numbers count CRLF once: the bad radius is on line 4.
    std::string bad;
    for (char c : scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": -1})")) {
        if (c == '\n') bad += '\r';
        bad += c;
    }
    refused(bad, 4, "objects[0].radius");
}

TEST_CASE("json: mesh files that are missing, broken, or miss their MTL") {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    // Missing OBJ: refused at the scene line that names it.
    refused(scene(R"({"type": "mesh", "file": "nope.obj"})"), 4, "nope.obj");
    // An OBJ with a face index out of range: the OBJ's own line.
    {
        TempDir dir;
        dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        const std::string path =
            dir.write("scene.json", scene(R"({"type": "mesh", "file": "bad.obj"})"));
        checkRefused(runRaylab(tinyRender(dir, path)), dir, {"scene.json", "bad.obj"}, 1,
                     dir.file("bad.obj") + ":4:", "vertex 4");
    }
    // A scale that collapses every triangle: the message says the transform
    // did it, not the OBJ (which is fine on its own).
    {
        TempDir dir;
        dir.write("tri.obj", tri);
        const std::string path = dir.write(
            "scene.json",
            scene(R"({"type": "mesh", "file": "tri.obj", "transform": {"scale": 1e-300}})"));
        checkRefused(runRaylab(tinyRender(dir, path)), dir, {"scene.json", "tri.obj"}, 1,
                     dir.file("tri.obj") + ":4:", "once the scene's transform");
    }
    // Missing MTL library and texture: warnings, and the render goes on.
    rendered(scene(R"({"type": "mesh", "file": "m.obj"})"),
             {{"m.obj", "mtllib missing.mtl\nusemtl red\n" + tri}});
    rendered(scene(R"({"type": "mesh", "file": "m.obj"})"),
             {{"m.obj", "mtllib m.mtl\nusemtl red\n" + tri},
              {"m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd missing.png\nbump missing_bump.png\n"}});
}

TEST_CASE("json: lights inside objects and other odd but valid scenes render") {
    rendered("{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
             " \"lights\": [{\"type\": \"point\", \"position\": [0, 0, 0]}],\n"
             " \"materials\": {\"glass\": {\"kd\": 0, \"kt\": 0.9, \"ior\": 1.5}},\n"
             " \"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1},\n"
             "             {\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 0.5,"
             " \"material\": \"glass\"}]}\n");
    rendered(scene("", R"("eye": [0, 0, 5], "look_at": [0, 0, 0])"));  // no objects
    rendered(scene(R"({"type": "sphere", "center": [0, 0, -1e300], "radius": 1e299},
                     {"type": "sphere", "center": [0, 0, 0], "radius": 1e-300})"));
    // Vectors whose squares overflow or underflow are still directions: an
    // eye 1e300 away is a valid (if useless) camera, not "up parallel to the
    // view", and a normal of length 1e-300 is not "the zero vector".
    rendered(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1})",
                   R"("eye": [0, 0, 1e300], "look_at": [0, 0, 0], "up": [0, 1e-300, 0])"));
    rendered(scene(R"({"type": "plane", "point": [0, -1, 0], "normal": [0, 1e-300, 0]},
                     {"type": "disk", "center": [0, 0, 0], "normal": [0, 0, 1e300], "radius": 1})"));
}

TEST_CASE("json: a \\u0000 escape in a key is shown, not the end of the message") {
    // Issue 22: the message stopped at the NUL ("objects[0].rad").
    refused("{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
            " \"objects\": [{\"type\": \"sphere\", \"rad\\u0000ius\": 1}]}\n",
            2, "objects[0].rad\\x00ius: unknown key");
}

TEST_CASE("json: a mesh scaled beyond float range says so, not \"zero area\" (issue 22)") {
    // 1e200 times a unit triangle: finite in double, but beyond the float the
    // renderer traces in; before, its overflowing areas read as "every face
    // has zero area". Now the OBJ line of the first vertex moved too far.
    TempDir dir;
    dir.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string path = dir.write(
        "scene.json", scene(R"({"type": "mesh", "file": "tri.obj", "transform": {"scale": 1e200}})"));
    const RunResult r = runRaylab(tinyRender(dir, path));
    checkRefused(r, dir, {"scene.json", "tri.obj"}, 1, dir.file("tri.obj") + ":2:",
                 "the mesh's transform (scale, rotate, translate) moves vertex 2 to (1e+200, 0, 0), "
                 "beyond float range");
    CHECK(!contains(r.err, "zero area"));
}
