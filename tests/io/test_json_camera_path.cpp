// The "camera_path" of a JSON scene is read with the rest of the scene, in one
// parse: the keyframes land in Scene::cameraPath, and its errors carry the
// scene file's own lines (the path's parsing itself: distributed/test_camera_path.cpp).
#include <doctest/doctest.h>

#include <string>

#include "io/io_test_helpers.h"
#include "renderer/io/scene_loader.h"

using namespace raylab;
using raylab::test::failureOf;

namespace {

/// Line 1 "{", line 2 the camera, line 3 the path's first line, then `keys`.
std::string sceneWithPath(const std::string& keys) {
    return "{\n"
           "\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 33},\n"
           "\"camera_path\": {\"interpolation\": \"linear\", \"keyframes\": [\n" +
           keys + "]},\n\"objects\": []}\n";
}

}  // namespace

TEST_CASE("json scene: camera_path is part of the scene") {
    const Scene s = loadJsonScene(
        sceneWithPath("{\"frame\": 1, \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
                      "{\"frame\": 5, \"eye\": [4, 0, 5], \"look_at\": [0, 0, 0], \"fov\": 50}\n"),
        "t.json");
    REQUIRE(s.cameraPath.has_value());
    CHECK(s.cameraPath->keyframes().size() == 2);
    CHECK(s.cameraPath->interpolation() == CameraPath::Interpolation::Linear);
    CHECK(s.cameraPath->at(1).fov == 33);  // no "fov": the scene camera's
    CHECK(s.cameraPath->at(3).eye.x == 2);
    CHECK(s.cameraPath->at(3).fov == doctest::Approx(41.5).epsilon(1e-15));
    // The scene's own camera is not moved by the path.
    CHECK(s.camera.frame().eye == Vec3(0, 0, 5));
}

TEST_CASE("json scene: no camera_path, no path") {
    const Scene s = loadJsonScene(
        "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]}, \"objects\": []}", "t.json");
    CHECK_FALSE(s.cameraPath.has_value());
}

TEST_CASE("json scene: camera_path errors name the scene file's line") {
    const auto keyFailure = failureOf([] {
        loadJsonScene(sceneWithPath("{\"frame\": 4, \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
                                    "{\"frame\": 4, \"eye\": [1, 0, 5], \"look_at\": [0, 0, 0]}\n"),
                      "t.json");
    });
    CHECK(keyFailure.located ==
          "t.json:5: camera_path.keyframes[1].frame: must be greater than the previous "
          "keyframe's (4)");
    const auto typo = failureOf([] {
        loadJsonScene(sceneWithPath("{\"frame\": 1, \"eye\": [0, 0, 5], \"look_at\": [0, 0, 0],\n"
                                    "\"fvo\": 30}\n"),
                      "t.json");
    });
    CHECK(typo.located ==
          "t.json:5: camera_path.keyframes[0].fvo: unknown key for a keyframe (expected 'frame', "
          "'eye', 'look_at', 'up', 'fov')");
}
