// Texture files through OpenImageIO: sRGB decoding of 8- and 16-bit colour
// maps, data maps and float images as stored, unassociated alpha, one read
// per file, and refusals (missing files, FIFOs, the memory guard).
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <cmath>

#include "image_files.h"
#include "renderer/io/errors.h"
#include "renderer/io/image_reader.h"
#include "renderer/io/texture_library.h"
#include "support/temp_dir.h"

using namespace raylab;
using namespace raylab::testing;

TEST_CASE("8-bit PNG colour map: codes 0, 10, 64, 128, 255 decode through sRGB") {
    test::TempDir dir;
    const std::string path = dir.file("codes.png");
    // Values are written as code / 255 so the PNG holds exactly these codes.
    const std::vector<int> codes{0, 10, 64, 128, 255};
    std::vector<float> v;
    for (int c : codes) v.push_back(float(c) / 255.0f);
    writeImage(path, 5, 1, 1, v, OIIO::TypeDesc::UINT8);
    const ImageData colour = readImage(path, ImageRole::Color, std::nullopt);
    REQUIRE(colour.width == 5);
    CHECK(colour.srgbDecoded);
    // Hand-computed: ((c/255 + 0.055)/1.055)^2.4, or c/255/12.92 below 0.04045.
    CHECK(colour.texels[0] == 0.0f);
    CHECK(colour.texels[1] == doctest::Approx(0.003035269835488375).epsilon(1e-6));
    CHECK(colour.texels[2] == doctest::Approx(0.05126945837404324).epsilon(1e-6));
    CHECK(colour.texels[3] == doctest::Approx(0.21586050011389926).epsilon(1e-6));
    CHECK(colour.texels[4] == 1.0f);
    // The same file as a data map (heights, normals) is read as stored.
    const ImageData data = readImage(path, ImageRole::Data, std::nullopt);
    CHECK_FALSE(data.srgbDecoded);
    CHECK(data.texels[3] == doctest::Approx(128 / 255.0).epsilon(1e-6));
}

TEST_CASE("16-bit PNG is sRGB-decoded, float EXR taken as stored, alpha never premultiplied") {
    test::TempDir dir;
    const std::string png16 = dir.file("g16.png");
    writeImage(png16, 1, 1, 1, {0.5f}, OIIO::TypeDesc::UINT16);
    const ImageData a = readImage(png16, ImageRole::Color, std::nullopt);
    // 0.5 stored as 32768/65535 (OpenImageIO rounds), decoded: ≈ 0.21404.
    CHECK(a.texels[0] == doctest::Approx(0.2140411).epsilon(1e-4));
    const std::string exr = dir.file("f.exr");
    writeImage(exr, 2, 1, 3, {0.5f, 2.0f, 0.25f, 0, 1, 0}, OIIO::TypeDesc::FLOAT);
    const ImageData b = readImage(exr, ImageRole::Color, std::nullopt);
    CHECK_FALSE(b.srgbDecoded);
    CHECK(b.channels == 3);
    CHECK(b.texels[0] == 0.5f);
    CHECK(b.texels[1] == 2.0f);
    // RGBA with alpha 0.5: the colour stays as stored (only decoded).
    const std::string rgba = dir.file("rgba.png");
    writeImage(rgba, 1, 1, 4, {1.0f, 1.0f, 1.0f, 128 / 255.0f}, OIIO::TypeDesc::UINT8);
    const ImageData c = readImage(rgba, ImageRole::Color, std::nullopt);
    REQUIRE(c.channels == 4);
    CHECK(c.texels[0] == 1.0f);
    CHECK(c.texels[3] == doctest::Approx(128 / 255.0).epsilon(1e-6));  // alpha is linear
}

TEST_CASE("image files: missing, FIFO, not an image, over the memory limit") {
    test::TempDir dir;
    CHECK_THROWS_WITH_AS(readImage(dir.file("none.png"), ImageRole::Color, std::nullopt),
                         doctest::Contains("cannot open"), InputError);
    const std::string fifo = dir.file("pipe.png");
    REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
    CHECK_THROWS_WITH_AS(readImage(fifo, ImageRole::Color, std::nullopt),
                         doctest::Contains("not a regular file"), InputError);
    const std::string junk = dir.write("junk.png", "this is not a PNG file at all");
    CHECK_THROWS_WITH_AS(readImage(junk, ImageRole::Color, std::nullopt),
                         doctest::Contains("cannot read image"), InputError);
    const std::string big = dir.file("big.png");
    writeImage(big, 64, 64, 3, std::vector<float>(64 * 64 * 3, 0.5f), OIIO::TypeDesc::UINT8);
    // 64 x 64 x 3 floats x 4/3 = 65536 bytes: refused under a 60000-byte limit.
    CHECK(textureBytes(64, 64, 3) == 65536.0);
    CHECK_THROWS_WITH_AS(readImage(big, ImageRole::Color, MemoryLimit{60000, "the test's limit allows"}),
                         // 65536 B = 64 KiB; 60000 B = 58.6 KiB, rounded up.
                         doctest::Contains("needs about 64 KiB, more than the 59 KiB that the test's limit allows"),
                         InputError);
    CHECK_NOTHROW(readImage(big, ImageRole::Color, MemoryLimit{70000, "the test's limit allows"}));
}

TEST_CASE("texture library: one read per file and role, failures reported once") {
    test::TempDir dir;
    const std::string path = dir.file("t.png");
    writeImage(path, 4, 2, 3, std::vector<float>(24, 1.0f), OIIO::TypeDesc::UINT8);
    TextureLibrary lib([] { return std::optional<MemoryLimit>(); });
    const auto a = lib.load(path, ImageRole::Color);
    const auto b = lib.load(dir.path().string() + "/./t.png", ImageRole::Color);
    REQUIRE(a.image);
    CHECK(a.image == b.image);  // shared, not read twice
    CHECK(lib.fileCount() == 1);
    const auto c = lib.load(path, ImageRole::Data);  // another role: another pyramid
    CHECK(c.image != a.image);
    CHECK(lib.bytes() == 2.0 * double(a.image->bytes()));
    const auto m1 = lib.load(dir.file("missing.png"), ImageRole::Color);
    const auto m2 = lib.load(dir.file("missing.png"), ImageRole::Color);
    CHECK_FALSE(m1.image);
    CHECK(m1.firstFailure);
    CHECK_FALSE(m2.firstFailure);
    CHECK(m2.error == m1.error);
}
