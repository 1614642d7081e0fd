// OpenImageIO sits behind dlopen (renderer/io/image_module.h): a scene
// without image textures never loads it; the first image texture does.
#include <doctest/doctest.h>

#include "image_files.h"
#include "renderer/io/image_module_loader.h"
#include "renderer/io/scene_loader.h"
#include "support/temp_dir.h"

using namespace raylab;
using namespace raylab::testing;

namespace {

std::string sphereScene(const std::string& kd) {
    return "{\"camera\": {\"eye\": [0, 0, 5], \"look_at\": [0, 0, 0]},\n"
           "\"materials\": {\"m\": {\"kd\": " + kd + "}},\n"
           "\"objects\": [{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1, "
           "\"material\": \"m\"}]}\n";
}

}  // namespace

TEST_CASE("image module: loaded by the first image texture, not by checkers or plain colours") {
    // ctest runs every case in a process of its own; run with the other
    // cases of this executable, an earlier one may have loaded it already.
    if (imageModuleLoaded()) {
        MESSAGE("module loaded by an earlier case of this process; run alone to check");
        return;
    }
    test::TempDir dir;
    // Written through this test's own OpenImageIO, not the module.
    writeImage(dir.file("a.png"), 2, 2, 3, std::vector<float>(12, 0.5f), OIIO::TypeDesc::UINT8);
    const std::string path = dir.file("s.json");
    (void)loadJsonScene(sphereScene("[0.5, 0.5, 0.5]"), path);
    (void)loadJsonScene(sphereScene("{\"checker\": [0.1, 0.9], \"scale\": [8, 8]}"), path);
    CHECK_FALSE(imageModuleLoaded());
    const Scene s = loadJsonScene(sphereScene("{\"texture\": \"a.png\"}"), path);
    CHECK(imageModuleLoaded());
    REQUIRE(s.textures.size() == 1);
    // 8-bit code 128 decoded from sRGB: ((128/255 + 0.055) / 1.055)^2.4 = 0.21586.
    CHECK(s.textures[0].image()->texel(0, 0, 0, WrapMode::Clamp)[0] == doctest::Approx(0.21586).epsilon(1e-4));
}

TEST_CASE("image module: writes and reads back through the same entry points") {
    const image_module::Api& api = imageModule();
    test::TempDir dir;
    const std::string path = dir.file("w.exr");
    const float pixels[2 * 1 * 3] = {0.25f, 0.5f, 1.0f, 2.0f, 4.0f, 8.0f};
    std::string error;
    REQUIRE(api.writeFloat(path, 2, 1, 3, pixels, error));
    const auto file = api.open(path, error);
    REQUIRE(file);
    CHECK(file->header().width == 2);
    CHECK(file->header().height == 1);
    CHECK(file->header().channels == 3);
    CHECK(file->header().floating);
    float back[6] = {};
    REQUIRE(file->readFloat(3, back, error));
    for (int i = 0; i < 6; ++i) CHECK(back[i] == pixels[i]);  // EXR half holds these exactly
    CHECK_FALSE(api.open(dir.file("missing.png"), error));
    CHECK_FALSE(error.empty());
}
