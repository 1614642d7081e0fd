#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "renderer/image_compare.h"
#include "renderer/io/errors.h"

using namespace raylab;

namespace {

Film twoPixels(float r0, float g0, float b0, float r1, float g1, float b1) {
    Film f(2, 1);
    f.rgba = {r0, g0, b0, 1.f, r1, g1, b1, 0.f};
    return f;
}

}  // namespace

TEST_CASE("image compare: identical films") {
    const Film a = twoPixels(0.5f, 0.25f, 1.f, 0.f, 0.f, 0.f);
    const ImageComparison c = compareImages(a, a);
    CHECK(c.width == 2);
    CHECK(c.height == 1);
    CHECK(c.pixelCount == 2);
    CHECK(c.rmse == 0);
    CHECK(std::isinf(c.psnr));
    CHECK(c.psnr > 0);
    CHECK(formatPsnr(c.psnr) == "inf");
    CHECK(c.maxAbsError == 0);
    CHECK(c.pixelsOverThreshold == 0);
    CHECK(c.identicalPixels == 2);
    CHECK(c.nonFiniteA == 0);
    CHECK(c.nonFiniteB == 0);
}

TEST_CASE("image compare: one channel off by 0.5") {
    // Six RGB values, one differs by 0.5 (exact in float): mse = 0.25 / 6,
    // rmse = 0.5 / sqrt(6) = 0.2041241452, psnr = 20 log10(sqrt(6) / 0.5)
    // = 20 * log10(4.898979486) = 20 * 0.6901056 = 13.802112 dB.
    const Film a = twoPixels(0.5f, 0.25f, 1.f, 0.f, 0.f, 0.f);
    const Film b = twoPixels(0.5f, 0.25f, 1.f, 0.f, 0.5f, 0.f);
    const ImageComparison c = compareImages(a, b, 0.1);
    CHECK(c.rmse == doctest::Approx(0.2041241452).epsilon(1e-9));
    CHECK(c.psnr == doctest::Approx(13.802112).epsilon(1e-6));
    CHECK(formatPsnr(c.psnr) == "13.80");
    CHECK(c.maxAbsError == 0.5);
    CHECK(c.threshold == 0.1);
    CHECK(c.pixelsOverThreshold == 1);
    CHECK(c.identicalPixels == 1);
    // Threshold is strict: an error equal to it does not count.
    CHECK(compareImages(a, b, 0.5).pixelsOverThreshold == 0);
    CHECK(compareImages(a, b, 0.4999).pixelsOverThreshold == 1);
}

TEST_CASE("image compare: alpha counts for bit identity only, -0 equals +0 numerically") {
    Film a = twoPixels(0.f, 0.f, 0.f, 1.f, 1.f, 1.f);
    Film b = a;
    b.rgba[3] = 0.5f;  // alpha of pixel 0 differs
    b.rgba[4] = 1.f;
    b.rgba[0] = -0.f;  // same value, different bits
    const ImageComparison c = compareImages(a, b);
    CHECK(c.rmse == 0);
    CHECK(c.maxAbsError == 0);
    CHECK(c.pixelsOverThreshold == 0);
    CHECK(c.identicalPixels == 1);  // only pixel 1
}

TEST_CASE("image compare: non-finite values are counted, not averaged") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    // a: NaN in pixel 0 R, +inf in pixel 1 G; b: +inf in pixel 1 G as well and
    // pixel 0 B off by 0.25. Finite pairs: 4 values, one error 0.25:
    // rmse = sqrt(0.0625 / 4) = 0.125.
    const Film a = twoPixels(nan, 0.f, 0.f, 0.f, inf, 0.f);
    const Film b = twoPixels(0.f, 0.f, 0.25f, 0.f, inf, 0.f);
    const ImageComparison c = compareImages(a, b, 1.0);
    CHECK(c.nonFiniteA == 2);
    CHECK(c.nonFiniteB == 1);
    CHECK(c.rmse == 0.125);
    CHECK(c.maxAbsError == 0.25);
    // Pixel 0: NaN vs 0 is an unbounded error, counted whatever the threshold;
    // pixel 1: inf vs inf agrees, so it is bit-identical and not counted.
    CHECK(c.pixelsOverThreshold == 1);
    CHECK(c.identicalPixels == 1);
}

TEST_CASE("image compare: size mismatch is an InputError") {
    CHECK_THROWS_AS(compareImages(Film(2, 1), Film(1, 2)), InputError);
    Film broken(2, 2);
    broken.rgba.resize(3);
    CHECK_THROWS_AS(compareImages(broken, Film(2, 2)), InputError);
}
