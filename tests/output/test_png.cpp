#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include <png.h>

#include "renderer/io/errors.h"
#include "renderer/io/png_memory.h"
#include "renderer/io/png_writer.h"
#include "support/temp_dir.h"

using namespace raylab;
using raylab::test::readFile;
using raylab::test::TempDir;

namespace {

std::array<uint8_t, 3> grey(uint8_t v) { return {v, v, v}; }

uint32_t bigEndian32(const std::string& s, size_t at) {
    return uint32_t(uint8_t(s[at])) << 24 | uint32_t(uint8_t(s[at + 1])) << 16 |
           uint32_t(uint8_t(s[at + 2])) << 8 | uint32_t(uint8_t(s[at + 3]));
}

}  // namespace

TEST_CASE("png: sRGB transfer function branches") {
    // Linear segment up to and including the threshold: 12.92 * 0.0031308 = 0.040449936.
    CHECK(linearToSrgb(0.0) == 0.0);
    CHECK(linearToSrgb(0.0031308) == 12.92 * 0.0031308);
    CHECK(linearToSrgb(0.0031308) == doctest::Approx(0.040449936).epsilon(1e-12));
    // Just above it the power branch applies: 1.055 * 0.0031309^(1/2.4) - 0.055
    // = 0.0404511777786 (the linear formula would give 0.0404512280).
    CHECK(linearToSrgb(0.0031309) == doctest::Approx(0.0404511777786).epsilon(1e-10));
    CHECK(linearToSrgb(0.0031309) != doctest::Approx(12.92 * 0.0031309).epsilon(1e-9));
    // The two pieces meet at the threshold (to ~1e-7, the curve's known tiny gap).
    CHECK(std::fabs(1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055 - 12.92 * 0.0031308) < 1e-7);
    CHECK(linearToSrgb(1.0) == doctest::Approx(1.0).epsilon(1e-15));
}

TEST_CASE("png: toneMapSrgb8 hand-computed values") {
    // 0 -> 0 and 1 -> 1.055 - 0.055 = 1 -> 255.
    CHECK(toneMapSrgb8(0.f, 0.f, 0.f, 0) == grey(0));
    CHECK(toneMapSrgb8(1.f, 1.f, 1.f, 0) == grey(255));
    // 0.5: 0.5^(1/2.4) = exp(ln 0.5 / 2.4) = exp(-0.2888113) = 0.7491535;
    // 1.055 * 0.7491535 - 0.055 = 0.7353570; * 255 = 187.516 -> rounds to 188.
    CHECK(toneMapSrgb8(0.5f, 0.5f, 0.5f, 0) == grey(188));
    // 0.18 (mid grey): 1.055 * 0.18^(1/2.4) - 0.055 = 0.4613561; * 255 = 117.646 -> 118.
    // 0.25: 1.055 * 0.25^(1/2.4) - 0.055 = 0.5370987; * 255 = 136.960 -> 137.
    // 0.01: 1.055 * 0.01^(1/2.4) - 0.055 = 0.0998528; * 255 = 25.462 -> 25.
    CHECK(toneMapSrgb8(0.18f, 0.25f, 0.01f, 0) == std::array<uint8_t, 3>{118, 137, 25});
    // Linear segment: 0.001 * 12.92 * 255 = 3.2946 -> 3; 0.002 -> 6.5892 -> 7 (rounds up,
    // not truncated); threshold 0.0031308 -> 0.040449936 * 255 = 10.3147 -> 10.
    CHECK(toneMapSrgb8(0.001f, 0.002f, 0.0031308f, 0) == std::array<uint8_t, 3>{3, 7, 10});
    // Rounding at the middle: sRGB 0.5 is linear ((0.5 + 0.055) / 1.055)^2.4 = 0.2140411,
    // i.e. 127.5 exactly; 0.2140 -> 0.4999555 * 255 = 127.489 -> 127 and
    // 0.2141 -> 1.055 * 0.2141^(1/2.4) - 0.055 = 0.5000563; * 255 = 127.514 -> 128.
    CHECK(toneMapSrgb8(0.2140f, 0.2141f, 0.f, 0)[0] == 127);
    CHECK(toneMapSrgb8(0.2140f, 0.2141f, 0.f, 0)[1] == 128);
}

TEST_CASE("png: exposure, clamping and non-finite input") {
    // Exposure scales by 2^e before the curve: 0.25 * 2 = 0.5 -> 188, 1 * 2^-1 -> 188,
    // 0.125 * 4 -> 188.
    CHECK(toneMapSrgb8(0.25f, 1.f, 0.125f, 0)[0] == 137);
    CHECK(toneMapSrgb8(0.25f, 0.25f, 0.25f, 1) == grey(188));
    CHECK(toneMapSrgb8(1.f, 1.f, 1.f, -1) == grey(188));
    CHECK(toneMapSrgb8(0.125f, 0.125f, 0.125f, 2) == grey(188));
    // Over-range clamps to white, negative to black.
    CHECK(toneMapSrgb8(2.f, 1e30f, 1.0001f, 0) == grey(255));
    CHECK(toneMapSrgb8(0.6f, 0.6f, 0.6f, 1) == grey(255));
    CHECK(toneMapSrgb8(-1.f, -0.f, -1e-30f, 0) == grey(0));
    // NaN -> 0; an overflow is white, never black (issue 22: an overflow must
    // not be hidden as black): +Inf, and a finite value that overflows after
    // scaling, clamp like any value above 1; -Inf like any negative one.
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(toneMapSrgb8(nan, inf, -inf, 0) == std::array<uint8_t, 3>{0, 255, 0});
    CHECK(toneMapSrgb8(3e38f, 0.5f, 0.5f, 1e4)[0] == 255);
}

TEST_CASE("png: file has the PNG signature, IHDR size and the tone-mapped pixels") {
    TempDir dir;
    const std::string path = dir.file("img.png");
    Film film(3, 2);
    const float values[6][3] = {{0, 0, 0},         {1, 1, 1},   {0.5f, 0.18f, 0.25f},
                                {0.001f, 2.f, -1}, {0.01f, 0, 0}, {0.2141f, 0.214f, 1}};
    for (int i = 0; i < 6; ++i)
        for (int c = 0; c < 3; ++c) film.rgba[4 * i + c] = values[i][c];
    writePng(path, film);
    CHECK(dir.entries() == std::vector<std::string>{"img.png"});

    const std::string bytes = readFile(path);
    REQUIRE(bytes.size() > 33);
    CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
    // First chunk: length 13, "IHDR", width, height (big-endian), depth 8, colour type 2 (RGB).
    CHECK(bigEndian32(bytes, 8) == 13);
    CHECK(bytes.compare(12, 4, "IHDR") == 0);
    CHECK(bigEndian32(bytes, 16) == 3);
    CHECK(bigEndian32(bytes, 20) == 2);
    CHECK(uint8_t(bytes[24]) == 8);
    CHECK(uint8_t(bytes[25]) == 2);

    // Decode and compare with hand-computed bytes, row 0 first (top of the image).
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, path.c_str()));
    image.format = PNG_FORMAT_RGB;
    std::vector<uint8_t> px(PNG_IMAGE_SIZE(image));
    REQUIRE(png_image_finish_read(&image, nullptr, px.data(), 0, nullptr));
    const std::vector<uint8_t> expected = {0,  0,   0,   255, 255, 255, 188, 118, 137,
                                           3,  255, 0,   25,  0,   0,   128, 127, 255};
    CHECK(px == expected);
}

TEST_CASE("png: exposure is applied in the file, errors are InputErrors") {
    TempDir dir;
    Film film(1, 1);
    film.rgba = {0.25f, 0.5f, 1.f, 1.f};
    writePng(dir.file("e.png"), film, 1.0);  // -> 0.5, 1, 2 -> 188, 255, 255
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&image, dir.file("e.png").c_str()));
    image.format = PNG_FORMAT_RGB;
    uint8_t px[3] = {};
    REQUIRE(png_image_finish_read(&image, nullptr, px, 0, nullptr));
    CHECK(px[0] == 188);
    CHECK(px[1] == 255);
    CHECK(px[2] == 255);

    const std::string bad = dir.file("missing/dir.png");
    try {
        writePng(bad, film);
        FAIL("expected InputError");
    } catch (const InputError& e) {
        CHECK(e.file() == bad);
    }
    CHECK_THROWS_AS(writePng(dir.file("empty.png"), Film()), InputError);
    CHECK(dir.entries() == std::vector<std::string>{"e.png"});
}

namespace {

/// The RGB pixels libpng decodes from PNG bytes (libpng checks every
/// chunk's CRC-32 and the zlib stream's Adler-32 on the way).
std::vector<uint8_t> decodeWithLibpng(const std::vector<unsigned char>& bytes, int& w, int& h) {
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()));
    image.format = PNG_FORMAT_RGB;
    w = int(image.width);
    h = int(image.height);
    std::vector<uint8_t> px(PNG_IMAGE_SIZE(image));
    const bool ok = png_image_finish_read(&image, nullptr, px.data(), 0, nullptr);
    if (!ok) FAIL("libpng: ", image.message);
    return px;
}

}  // namespace

TEST_CASE("png: encodePng round-trips through libpng (noise, gradients, 1x1, strips)") {
    std::mt19937 rng(7);
    const std::pair<int, int> sizes[] = {{1, 1}, {1, 300}, {777, 2}, {64, 48}, {257, 129}, {70000, 1}};
    for (const auto& entry : sizes) {
        // No structured binding: CAPTURE's lambda may not capture one (clang, C++17).
        const auto& w = entry.first;
        const auto& h = entry.second;
        for (int pattern = 0; pattern < 3; ++pattern) {
            CAPTURE(w);
            CAPTURE(h);
            CAPTURE(pattern);
            Rgb8Image image;
            image.width = w;
            image.height = h;
            image.pixels.resize(size_t(w) * size_t(h) * 3);
            for (size_t i = 0; i < image.pixels.size(); ++i) {
                const size_t x = (i / 3) % size_t(w), y = (i / 3) / size_t(w);
                image.pixels[i] = pattern == 0   ? uint8_t(rng())                // incompressible
                                  : pattern == 1 ? uint8_t(x * 3 + y * 5 + i % 3)  // smooth: Paeth's case
                                                 : uint8_t(255 * ((x / 7 + y / 5) % 2));  // hard edges
            }
            const std::vector<unsigned char> bytes = encodePng(image);
            int dw = 0, dh = 0;
            CHECK(decodeWithLibpng(bytes, dw, dh) == image.pixels);
            CHECK(dw == w);
            CHECK(dh == h);
            // Chunks in order, the sRGB chunk marking the samples as sRGB.
            const std::string s(bytes.begin(), bytes.end());
            CHECK(s.compare(12, 4, "IHDR") == 0);
            CHECK(s.compare(37, 4, "sRGB") == 0);
            CHECK(s.compare(50, 4, "IDAT") == 0);
            CHECK(s.compare(s.size() - 8, 4, "IEND") == 0);
        }
    }
    // Beyond one IDAT chunk (1 MiB of compressed rows) and one block of
    // rows handed to igzip at a time (16 MiB): noise that does not compress.
    Rgb8Image large;
    large.width = 2100;
    large.height = 2900;
    large.pixels.resize(size_t(large.width) * size_t(large.height) * 3);
    for (uint8_t& b : large.pixels) b = uint8_t(rng());
    const std::vector<unsigned char> bytes = encodePng(large);
    int w = 0, h = 0;
    CHECK(decodeWithLibpng(bytes, w, h) == large.pixels);
    // IDAT chunks of exactly 1 MiB of data, the last one up to that.
    std::vector<uint32_t> idat;
    for (size_t at = 8; at + 8 <= bytes.size();) {
        const std::string s(bytes.begin() + std::ptrdiff_t(at), bytes.begin() + std::ptrdiff_t(at) + 8);
        if (s.compare(4, 4, "IDAT") == 0) idat.push_back(bigEndian32(s, 0));
        at += 12 + bigEndian32(s, 0);
    }
    REQUIRE(idat.size() > 10);  // 18 MB of noise
    for (size_t k = 0; k + 1 < idat.size(); ++k) CHECK(idat[k] == 1u << 20);
    CHECK(idat.back() > 0u);
    CHECK(idat.back() <= 1u << 20);

    Rgb8Image bad;
    CHECK_THROWS_AS(encodePng(bad), std::runtime_error);
    bad.width = bad.height = 2;
    bad.pixels.resize(11);
    CHECK_THROWS_AS(encodePng(bad), std::runtime_error);
}

TEST_CASE("png: toneMappedImage is toneMapSrgb8 at every pixel, any exposure") {
    Film film(67, 45);  // several row blocks of the parallel encoder, a ragged last one
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> value(-0.1f, 1.3f);
    for (float& v : film.rgba) v = value(rng);
    film.rgba[0] = std::numeric_limits<float>::infinity();
    film.rgba[1] = std::numeric_limits<float>::quiet_NaN();
    for (const double exposure : {0.0, 0.7, -2.0}) {
        const Rgb8Image image = toneMappedImage(film, exposure);
        REQUIRE(image.pixels.size() == 67u * 45u * 3u);
        size_t differ = 0;
        for (size_t i = 0; i < 67u * 45u; ++i) {
            const float* c = &film.rgba[4 * i];
            const auto rgb = toneMapSrgb8(c[0], c[1], c[2], exposure);
            if (std::memcmp(rgb.data(), &image.pixels[3 * i], 3) != 0) ++differ;
        }
        CHECK(differ == 0);
    }
}
