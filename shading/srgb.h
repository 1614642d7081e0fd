#pragma once
// The sRGB transfer function (IEC 61966-2-1): 8- and 16-bit colour maps are
// stored sRGB-encoded and must be decoded to linear before any filtering, or
// a blurred edge between black and white comes out too dark.

#include <cmath>
#include <cstdint>

namespace raylab {

/// sRGB-encoded value in [0, 1] -> linear value in [0, 1].
inline double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Linear value in [0, 1] -> sRGB-encoded value in [0, 1].
inline double linearToSrgb(double c) {
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

/// The 256 linear values of the 8-bit sRGB codes, computed once.
const float* srgb8ToLinearTable();

}  // namespace raylab
