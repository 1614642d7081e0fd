// Srgb8Encoder against the formula it replaces (srgb8Code): the same code
// for every float near each of its 255 steps and for random bit patterns.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "renderer/io/png_writer.h"
#include "renderer/io/srgb8_encoder.h"

using namespace raylab;

namespace {

float floatOf(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

/// Every float within `window` ULPs of each step, and of 0 and +Inf, gets
/// the formula's code; returns the number of floats compared.
size_t compareNearSteps(const Srgb8Encoder& encode, double exposure, uint32_t window) {
    const double scale = std::exp2(exposure);
    size_t compared = 0, differ = 0;
    const auto check = [&](uint32_t bits) {
        const float c = floatOf(bits);
        ++compared;
        if (encode(c) != srgb8Code(c, scale)) ++differ;
    };
    for (int k = 1; k < 256; ++k) {
        const uint32_t at = encode.firstBitsOf(k);
        if (at == Srgb8Encoder::kNever) continue;
        const uint32_t lo = at > window ? at - window : 0;
        const uint32_t hi = std::min<uint64_t>(uint64_t(at) + window, 0x7F800000u);
        for (uint32_t b = lo; b <= hi; ++b) check(b);
    }
    for (uint32_t b = 0; b <= window; ++b) check(b);                   // 0 and the subnormals
    for (uint32_t b = 0x7F800000u - window; b <= 0x7F800000u; ++b) check(b);  // up to +Inf
    CHECK_MESSAGE(differ == 0, "exposure ", exposure, ": ", differ, " of ", compared, " differ");
    return compared;
}

}  // namespace

TEST_CASE("srgb8 encoder: the formula's code for every float near each step, at several exposures") {
    for (const double exposure : {0.0, 1.0, -1.0, 0.5, 2.3, -7.25, 12.0, -20.0}) {
        CAPTURE(exposure);
        const Srgb8Encoder encode(exposure);
        // Each step is the first float with its code: the float before it
        // has a lower one (the bisection found the boundary, not a float inside).
        const double scale = std::exp2(exposure);
        for (int k = 1; k < 256; ++k) {
            const uint32_t at = encode.firstBitsOf(k);
            REQUIRE(at != Srgb8Encoder::kNever);
            CHECK(srgb8Code(floatOf(at), scale) >= k);
            if (at > 0) CHECK(srgb8Code(floatOf(at - 1), scale) < k);
        }
        CHECK(compareNearSteps(encode, exposure, 4096) > 255 * 8192);
    }
}

TEST_CASE("srgb8 encoder: random bit patterns, specials and hand-computed codes") {
    std::mt19937 rng(20261205);
    for (const double exposure : {0.0, -3.5, 4.0}) {
        const Srgb8Encoder encode(exposure);
        const double scale = std::exp2(exposure);
        size_t differ = 0;
        for (int i = 0; i < 1000000; ++i) {
            // Whole float space (negatives, NaNs, infinities), and [0, 2] densely.
            const uint32_t bits = i % 2 ? uint32_t(rng()) : uint32_t(rng() % 0x40000001u);
            const float c = floatOf(bits);
            if (encode(c) != srgb8Code(c, scale)) ++differ;
        }
        CHECK(differ == 0);
    }
    const Srgb8Encoder encode(0);
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    // As test_png's hand-computed values: 0.5 -> 188, 0.18 -> 118, 0.25 -> 137,
    // 0.01 -> 25, 0.001 -> 3, 0.002 -> 7, 0.2140 -> 127, 0.2141 -> 128.
    CHECK(encode(0.5f) == 188);
    CHECK(encode(0.18f) == 118);
    CHECK(encode(0.25f) == 137);
    CHECK(encode(0.01f) == 25);
    CHECK(encode(0.001f) == 3);
    CHECK(encode(0.002f) == 7);
    CHECK(encode(0.2140f) == 127);
    CHECK(encode(0.2141f) == 128);
    CHECK(encode(0.f) == 0);
    CHECK(encode(-0.f) == 0);
    CHECK(encode(-1.f) == 0);
    CHECK(encode(1.f) == 255);
    CHECK(encode(2.f) == 255);
    CHECK(encode(inf) == 255);
    CHECK(encode(-inf) == 0);
    CHECK(encode(nan) == 0);
    CHECK(encode(-nan) == 0);
    // A scale of 0 (exposure -2000): every code 0, +Inf too (Inf·0 is NaN).
    const Srgb8Encoder dark(-2000);
    CHECK(dark.firstBitsOf(1) == Srgb8Encoder::kNever);
    CHECK(dark(inf) == 0);
    CHECK(dark(1e30f) == 0);
    CHECK(srgb8Code(inf, std::exp2(-2000.0)) == 0);
    // An infinite scale (exposure 2000): 0 stays 0 (0·Inf is NaN), any positive value is white.
    const Srgb8Encoder bright(2000);
    CHECK(bright(0.f) == 0);
    CHECK(bright(1e-45f) == 255);
    CHECK(bright.firstBitsOf(1) == 1);
}

TEST_CASE("srgb8 encoder: encodeRgba drops alpha and keeps pixel order") {
    const float rgba[] = {0.5f, 0.18f, 0.25f, 0.3f, 1.f, 0.f, -1.f, 1.f};
    uint8_t rgb[6] = {};
    Srgb8Encoder(0).encodeRgba(rgba, 2, rgb);
    const uint8_t expected[6] = {188, 118, 137, 255, 0, 0};
    CHECK(std::memcmp(rgb, expected, 6) == 0);
}
