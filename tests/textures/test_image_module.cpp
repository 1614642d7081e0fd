// OpenImageIO sits behind dlopen (renderer/io/image_module.h): a scene
// without image textures never loads it; the first image texture does.
#include <doctest/doctest.h>

#include <filesystem>

#include "image_files.h"
#include "renderer/io/exr_writer.h"
#include "renderer/io/image_module_loader.h"
#include "renderer/io/oiio_writer.h"
#include "renderer/io/png_writer.h"
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

TEST_CASE("image module: EXR and PNG outputs never load it, the first JPEG, HDR or TIFF does") {
    if (imageModuleLoaded()) {
        MESSAGE("module loaded by an earlier case of this process; run alone to check");
        return;
    }
    test::TempDir dir;
    Film film(3, 2);
    for (size_t i = 0; i < film.rgba.size(); ++i) film.rgba[i] = float(i % 4) * 0.25f;
    writeExr(dir.file("a.exr"), film, ExrOptions{});
    writePng(dir.file("a.png"), film);
    CHECK_FALSE(imageModuleLoaded());
    writeOiioImage(dir.file("a.hdr"), film, OutputFormat::Hdr, 0, "raylab test");
    CHECK(imageModuleLoaded());
    // Read back through the module: 3 linear channels, the film's RGB.
    std::string error;
    const auto file = imageModule().open(dir.file("a.hdr"), error);
    REQUIRE_MESSAGE(file, error);
    CHECK(file->header().width == 3);
    CHECK(file->header().height == 2);
    CHECK(file->header().channels == 3);
    std::vector<float> back(18);
    REQUIRE(file->readFloat(3, back.data(), error));
    // 0, 0.25, 0.5 per pixel: exact in RGBE (shared exponent of 0.5).
    for (size_t i = 0; i < 6; ++i)
        for (size_t c = 0; c < 3; ++c) CHECK(back[3 * i + c] == film.rgba[4 * i + c]);
}

TEST_CASE("image module: a write it cannot do comes back as text, never thrown") {
    const image_module::Api& api = imageModule();
    REQUIRE((api.write != nullptr));
    test::TempDir dir;
    const float pixels[3] = {1, 2, 3};
    image_module::WriteRequest r;
    r.path = dir.file("x");
    r.format = "no-such-format";
    r.width = r.height = 1;
    r.channels = 3;
    r.pixels = pixels;
    std::string error;
    CHECK_FALSE(api.write(r, error));
    CHECK_FALSE(error.empty());
    r.format = "tiff";
    r.path = dir.file("missing-folder/x.tif");
    error.clear();
    CHECK_FALSE(api.write(r, error));
    CHECK_FALSE(error.empty());
    CHECK_FALSE(std::filesystem::exists(r.path));
}
