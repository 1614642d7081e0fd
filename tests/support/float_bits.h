#pragma once
// Bit patterns of floats and doubles, for tests that compare values bit for
// bit (-0, NaN payloads, subnormals) or build awkward values from their bits.

#include <cstdint>
#include <cstring>

namespace raylab::test {

inline float floatFromBits(uint32_t bits) {
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

inline uint32_t bitsOf(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return bits;
}

inline uint64_t bitsOf(double d) {
    uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    return bits;
}

}  // namespace raylab::test
