// floatsToHalf (F16C where the CPU has it) against Imath's half(float), the
// conversion the EXR writer used before: bit for bit on every value class.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include <Imath/half.h>

#include "renderer/io/finite_clamp.h"
#include "renderer/io/half_convert.h"
#include "support/float_bits.h"

using namespace raylab;
using raylab::test::bitsOf;
using raylab::test::floatFromBits;

namespace {

/// What the EXR writer promises: NaN -> 0, clamp to ±65504, then Imath.
uint16_t reference(float v) {
    if (std::isnan(v)) v = 0.f;
    v = std::fmax(-65504.f, std::fmin(65504.f, v));
    return Imath::half(v).bits();
}

/// Converts `values` (an odd count, so the vector path and its scalar tail
/// both run) with both paths and compares them with the reference.
void checkAll(const std::vector<float>& values) {
    std::vector<uint16_t> fast(values.size()), portable(values.size());
    floatsToHalf(values.data(), fast.data(), values.size());
    floatsToHalfPortable(values.data(), portable.data(), values.size());
    size_t wrong = 0;
    for (size_t i = 0; i < values.size(); ++i) {
        const uint16_t want = reference(values[i]);
        if (fast[i] != want || portable[i] != want) {
            if (++wrong <= 5)
                MESSAGE("value " << values[i] << " (bits " << std::hex
                                 << bitsOf(values[i]) << "): fast "
                                 << fast[i] << ", portable " << portable[i] << ", want " << want);
        }
    }
    CHECK(wrong == 0);
}

}  // namespace

TEST_CASE("half conversion: special values, clamps and the rounding ties") {
    MESSAGE("F16C path in use: " << (halfConversionUsesF16c() ? "yes" : "no"));
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> v = {0.f, -0.f, 1.f, -1.f, 0.1f, 65504.f, -65504.f, 65519.f, 65520.f,
                            65536.f, 1e9f, -1e9f, inf, -inf,
                            std::numeric_limits<float>::quiet_NaN(),
                            -std::numeric_limits<float>::quiet_NaN(),
                            floatFromBits(0x7f800001u),  // signalling NaN
                            std::numeric_limits<float>::denorm_min(),
                            -std::numeric_limits<float>::denorm_min(),
                            std::numeric_limits<float>::min(), 0x1p-24f, 0x1p-25f, 0x1.8p-25f,
                            0x1p-14f, 0x1.ffcp-15f, 0x1.ffep-15f, 0x1.0008p0f, 0x1.0018p0f};
    if (v.size() % 2 == 0) v.push_back(0.5f);
    checkAll(v);
}

TEST_CASE("half conversion: every float whose low 13 bits decide the rounding, all exponents") {
    // For each sign and exponent (subnormals to infinity), mantissas whose 13
    // dropped bits are 0, 1, just below, at and just above the tie, and all
    // ones, for 1024 spread upper mantissas: ~5.2 M values.
    std::vector<float> v;
    v.reserve(5300000);
    const uint32_t lows[] = {0x0000, 0x0001, 0x0fff, 0x1000, 0x1001, 0x1fff};
    for (uint32_t sign = 0; sign < 2; ++sign)
        for (uint32_t exponent = 0; exponent < 256; ++exponent)
            for (uint32_t upper = 0; upper < 1024; ++upper)
                for (uint32_t low : lows)
                    v.push_back(floatFromBits(sign << 31 | exponent << 23 | upper << 13 | low));
    v.push_back(1.f);  // odd count: the scalar tail runs too
    checkAll(v);
}

TEST_CASE("half conversion: every float of one binade around 1 and the subnormal halves") {
    std::vector<float> v;
    for (uint32_t m = 0; m < (1u << 23); ++m) v.push_back(floatFromBits(0x3f800000u | m));  // [1, 2)
    for (uint32_t m = 0; m < (1u << 23); m += 3) v.push_back(floatFromBits(0x33000000u | m));  // ~2^-25
    for (uint32_t m = 0; m < (1u << 23); m += 3) v.push_back(floatFromBits(0x38000000u | m));  // ~2^-15
    if (v.size() % 2 == 0) v.push_back(2.f);
    checkAll(v);
}

TEST_CASE("finiteClamp: the one rule that makes a value safe for a channel") {
    constexpr float inf = std::numeric_limits<float>::infinity();
    constexpr float fmax = std::numeric_limits<float>::max();
    CHECK(finiteClamp(std::numeric_limits<float>::quiet_NaN(), 65504.f) == 0.f);
    CHECK(finiteClamp(inf, 65504.f) == 65504.f);
    CHECK(finiteClamp(-inf, 65504.f) == -65504.f);
    CHECK(finiteClamp(65520.f, 65504.f) == 65504.f);  // would round to Inf as a half
    CHECK(finiteClamp(-1e30f, 65504.f) == -65504.f);
    CHECK(finiteClamp(65504.f, 65504.f) == 65504.f);
    CHECK(finiteClamp(-3.25f, 65504.f) == -3.25f);
    CHECK(finiteClamp(inf, fmax) == fmax);
    CHECK(finiteClamp(1e38f, fmax) == 1e38f);
    CHECK(finiteClamp(1.5f, 1.f) == 1.f);  // a Cryptomatte coverage
    CHECK(std::signbit(finiteClamp(-0.f, 1.f)));  // -0 stays -0: the bits are the input's
}
