// Keyframed cameras for --frames sequences, and the sequence file names.

#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "distributed/frame_sequence.h"
#include "renderer/camera_path.h"
#include "renderer/io/errors.h"
#include "renderer/io/json.h"
#include "renderer/io/json_camera_path.h"

using namespace raylab;

namespace {

CameraPath parse(const std::string& json, double defaultFov = 45) {
    const JsonValue v = parseJson(json, "path.json");
    return parseCameraPath(v, "path.json", defaultFov);
}

/// The located message of the InputError that parsing `json` throws.
std::string parseError(const std::string& json) {
    try {
        parse(json);
    } catch (const InputError& e) {
        return e.located();
    }
    return "(no error)";
}

/// Keys at frames 0, 1, 2, 3 with eye.x = frame^2: 0, 1, 4, 9.
const char* const kSquares = R"({"interpolation": "%s", "keyframes": [
    {"frame": 0, "eye": [0, 0, 5], "look_at": [0, 0, 0]},
    {"frame": 1, "eye": [1, 0, 5], "look_at": [0, 0, 0]},
    {"frame": 2, "eye": [4, 0, 5], "look_at": [0, 0, 0], "fov": 60},
    {"frame": 3, "eye": [9, 0, 5], "look_at": [0, 0, 0], "fov": 30}
]})";

std::string squares(const char* interpolation) {
    std::string s = kSquares;
    s.replace(s.find("%s"), 2, interpolation);
    return s;
}

}  // namespace

TEST_CASE("CameraPath: keyframes are hit exactly, the ends hold") {
    const CameraPath path = parse(squares("catmull_rom"));
    CHECK(path.keyframes().size() == 4);
    CHECK(path.at(2).eye.x == 4);
    CHECK(path.at(3).eye.x == 9);
    CHECK(path.at(-10).eye.x == 0);  // before the first key
    CHECK(path.at(50).eye.x == 9);   // after the last
    CHECK(path.at(0).fov == 45);     // no "fov": the default
    CHECK(path.at(2).fov == 60);
}

TEST_CASE("CameraPath: linear interpolation") {
    const CameraPath path = parse(squares("linear"));
    // Half-way between eye.x 1 and 4, fov 45 and 60.
    CHECK(path.at(1.5).eye.x == doctest::Approx(2.5).epsilon(1e-15));
    CHECK(path.at(1.5).fov == doctest::Approx(52.5).epsilon(1e-15));
    CHECK(path.at(2.25).eye.x == doctest::Approx(4 + 0.25 * 5).epsilon(1e-15));
}

TEST_CASE("CameraPath: Catmull-Rom reproduces a parabola on interior segments") {
    const CameraPath path = parse(squares("catmull_rom"));
    // Segment 1..2 at t = 0.5: tangents m1 = (4 - 0) / 2 = 2, m2 = (9 - 1) / 2 = 4
    // (central differences per frame, h = 1); Hermite weights at t = 1/2 are
    // h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8:
    //   0.5 * 1 + 0.125 * 2 + 0.5 * 4 - 0.125 * 4 = 2.25 = 1.5^2.
    CHECK(path.at(1.5).eye.x == doctest::Approx(2.25).epsilon(1e-15));
    // Same segment at t = 1/4: h00 = 27/32, h10 = 9/64, h01 = 5/32, h11 = -3/64:
    //   27/32 + 18/64 + 20/32 - 12/64 = 1.5625 = 1.25^2.
    CHECK(path.at(1.25).eye.x == doctest::Approx(1.5625).epsilon(1e-15));
    // fov stays linear: 45 -> 60 between frames 1 and 2.
    CHECK(path.at(1.5).fov == doctest::Approx(52.5).epsilon(1e-15));
    // First segment: one-sided tangent m0 = 1, m1 = 2; at t = 1/2:
    //   0.5 * 0 + 0.125 * 1 + 0.5 * 1 - 0.125 * 2 = 0.375.
    CHECK(path.at(0.5).eye.x == doctest::Approx(0.375).epsilon(1e-15));
}

TEST_CASE("CameraPath: unevenly spaced keys use tangents per frame") {
    // Keys at frames 0, 10, 12 with eye.x = 0, 10, 12 (a straight line at one
    // unit per frame): every tangent is 1 unit/frame, so the curve stays on the
    // line: x(f) = f, also inside the long segment.
    const CameraPath path = parse(R"({"keyframes": [
        {"frame": 0, "eye": [0, 0, 5], "look_at": [0, 0, 0]},
        {"frame": 10, "eye": [10, 0, 5], "look_at": [0, 0, 0]},
        {"frame": 12, "eye": [12, 0, 5], "look_at": [0, 0, 0]}]})");
    CHECK(path.interpolation() == CameraPath::Interpolation::CatmullRom);  // the default
    CHECK(path.at(3).eye.x == doctest::Approx(3).epsilon(1e-14));
    CHECK(path.at(11).eye.x == doctest::Approx(11).epsilon(1e-14));
}

TEST_CASE("CameraPath: cameraAt builds the perspective camera of the frame") {
    const CameraPath path = parse(squares("linear"));
    const Camera c = path.cameraAt(2);
    CHECK(c.frame().eye == Vec3(4, 0, 5));
    CHECK(c.vfovDegrees() == 60);
    // w points from the look-at point back to the eye: (4, 0, 5) / |(4, 0, 5)|.
    CHECK(c.frame().w.x == doctest::Approx(4 / std::sqrt(41.0)));
}

TEST_CASE("parseCameraPath: located errors") {
    CHECK(parseError(R"({"keyframes": []})") ==
          "path.json:1: camera_path.keyframes: expected a non-empty array of keyframes");
    CHECK(parseError("{\"keyframes\": [\n{\"frame\": 2, \"eye\": [0,0,1], \"look_at\": [0,0,0]},\n"
                     "{\"frame\": 2, \"eye\": [0,0,2], \"look_at\": [0,0,0]}]}") ==
          "path.json:3: camera_path.keyframes[1].frame: must be greater than the previous "
          "keyframe's (2)");
    CHECK(parseError(R"({"keyframes": [{"frame": 1.5, "eye": [0,0,1], "look_at": [0,0,0]}]})") ==
          "path.json:1: camera_path.keyframes[0].frame: must be an integer in [0, 9999999] "
          "(got 1.5)");
    CHECK(parseError("{\"keyframes\": [{\"frame\": 1, \"eye\": [0,0,1], \"look_at\": [0,0,0],\n"
                     "\"fvo\": 30}]}") ==
          "path.json:2: camera_path.keyframes[0].fvo: unknown key for a keyframe (expected "
          "'frame', 'eye', 'look_at', 'up', 'fov')");
    CHECK(parseError(R"({"keyframes": [{"frame": 1, "eye": [0,0,1], "look_at": [0,0,0],
                      "fov": 180}]})") ==
          "path.json:2: camera_path.keyframes[0].fov: must be in (0, 180) degrees (got 180)");
    CHECK(parseError(R"({"keyframes": [{"frame": 1, "eye": [0,0,1]}]})") ==
          "path.json:1: camera_path.keyframes[0]: missing required key 'look_at'");
    CHECK(parseError(R"({"keyframes": [{"frame": 1, "eye": [0,0,1], "look_at": [0,0,1]}]})") ==
          "path.json:1: camera_path.keyframes[0]: camera: eye and look-at point coincide");
    CHECK(parseError(R"({"interpolation": "cubic", "keyframes": []})") ==
          "path.json:1: camera_path.interpolation: must be one of 'linear', 'catmull_rom' "
          "(got 'cubic')");
    CHECK(parseError(R"({"keyframes": [{"frame": 1, "eye": [0,0], "look_at": [0,0,0]}]})") ==
          "path.json:1: camera_path.keyframes[0].eye: expected [x, y, z], got an array of 2");
}

TEST_CASE("parseFrameRange") {
    CHECK(parseFrameRange("1:24").first == 1);
    CHECK(parseFrameRange("1:24").last == 24);
    CHECK(parseFrameRange("1:24").count() == 24);
    CHECK(parseFrameRange("7").first == 7);
    CHECK(parseFrameRange("7").last == 7);
    CHECK(parseFrameRange("0:0").count() == 1);
    for (const char* bad : {"", ":", "3:1", "-1:2", "1:", "a:b", "1:2:3", "1.5:2", "10000000"})
        CHECK_THROWS_AS_MESSAGE(parseFrameRange(bad), UsageError, bad);
    CHECK_THROWS_WITH(parseFrameRange("3:1"),
                      "--frames: expected FIRST:LAST with 0 <= FIRST <= LAST <= 9999999 (got "
                      "'3:1')");
    // Typed text is echoed as one short readable line: control bytes as \xNN, 40 bytes at most.
    CHECK_THROWS_WITH(parseFrameRange("1:\x1b[2J" + std::string(100, '9')),
                      ("--frames: expected FIRST:LAST with 0 <= FIRST <= LAST <= 9999999 (got "
                       "'1:\\x1b[2J" + std::string(31, '9') + "...')").c_str());  // 9 + 31 = 40 bytes
}

TEST_CASE("sequenceFileName: _NNNN before the extension of the file name") {
    CHECK(sequenceFileName("out.exr", 1) == "out_0001.exr");
    CHECK(sequenceFileName("out/demo.png", 24) == "out/demo_0024.png");
    CHECK(sequenceFileName("a.b/c", 7) == "a.b/c_0007");  // the dot is in a directory
    CHECK(sequenceFileName("stats", 12345) == "stats_12345");
    CHECK(sequenceFileName("x.tar.exr", 0) == "x.tar_0000.exr");
}
