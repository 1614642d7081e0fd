#pragma once
// The 8-bit sRGB code of a linear film value: its formula (srgb8Code,
// toneMapSrgb8), and Srgb8Encoder, which gives the same codes without a pow
// per channel.
//
// Why: writing a 512x512 PNG spent more time in that formula's pow than the
// render of tetra took (docs/benchmarks.md, "The 8-bit outputs").
//
// How: the formula is a non-decreasing step function of its float input:
// the scale by 2^exposure, the clamp to [0, 1], the sRGB curve and the
// rounding are each monotone. Non-negative floats order as their bit
// patterns, so 255 bisections over the bits find the smallest float of each
// code, and a table indexed by the top 16 bits of a float (1/128 of an
// octave) holds the code at the start of its slice. At most 0.62 codes lie
// in a slice of normal floats (the curve's steepest relative slope,
// 255·1.055/2.4 per unit of ln v, times ln 2/128), so a lookup ends after one
// or two compares; only subnormal inputs under a huge exposure (slices linear
// in the bits) may walk further, to the same code.
//
// Exact, not an approximation: the computed curve can only step backwards
// where pow and the last roundings are within a few double ULPs of a code
// boundary, a region far narrower than the spacing of floats, so over float
// inputs the formula is monotone and the bisection finds its steps.
// tests/output/test_srgb8_encoder.cpp compares the two on every float within
// 4096 ULPs of each step, at several exposures, and on random bit patterns.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/film.h"
#include "shading/srgb.h"  // linearToSrgb: 12.92·v up to 0.0031308, else 1.055·v^(1/2.4) − 0.055

namespace raylab {

/// \brief One channel's 8-bit sRGB code: c·scale clamped to [0, 1], encoded
/// with linearToSrgb and rounded half up to 0..255; 0 for NaN (before or
/// after scaling), 255 for +Inf. The definition every 8-bit output follows;
/// Srgb8Encoder (below) gives the same codes faster.
uint8_t srgb8Code(float c, double scale);

/// \brief Maps one linear RGB colour to 8-bit sRGB.
///
/// Each channel is scaled by 2^exposure, clamped to [0, 1], encoded with
/// linearToSrgb and rounded to the nearest of 0..255 (srgb8Code with scale
/// 2^exposure): NaN maps to 0, +Inf to 255.
std::array<uint8_t, 3> toneMapSrgb8(float r, float g, float b, double exposure);

class Srgb8Encoder {
public:
    /// Codes for a film scaled by 2^exposure (toneMapSrgb8's `exposure`).
    explicit Srgb8Encoder(double exposure);

    /// toneMapSrgb8's code of one channel: 0 for a negative value or NaN,
    /// 255 from 1 (after the scale) up, +Inf included.
    uint8_t operator()(float c) const {
        const uint32_t bits = bitsOf(c);
        // Negative (sign bit set, -0 and -NaN included) or +NaN: 0.
        if (bits > kPositiveInfinity) return 0;
        unsigned code = m_sliceStart[bits >> kSliceShift];
        while (code < 255 && bits >= m_firstOf[code + 1]) ++code;
        return uint8_t(code);
    }

    /// The RGB codes of `count` RGBA pixels (alpha dropped), 3 bytes each.
    void encodeRgba(const float* rgba, size_t count, uint8_t* rgb) const;

    /// The smallest non-negative float (as its bits) whose code is at least
    /// `code` (1..255); kNever when none has it.
    uint32_t firstBitsOf(int code) const { return m_firstOf[size_t(code)]; }
    static constexpr uint32_t kNever = 0x7F800001u;

private:
    static constexpr uint32_t kPositiveInfinity = 0x7F800000u;
    static constexpr int kSliceShift = 16;
    static uint32_t bitsOf(float c);

    std::array<uint32_t, 256> m_firstOf{};  ///< [k]: first bits with code >= k; [0] = 0
    std::vector<uint8_t> m_sliceStart;      ///< code of the first float of each slice
};

/// 8-bit RGB pixels, row 0 at the top.
struct Rgb8Image {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  ///< 3 bytes per pixel
};

/// The film's colour as the 8-bit outputs (PNG, JPEG) show it: toneMapSrgb8's
/// codes, by Srgb8Encoder, rows in parallel.
Rgb8Image toneMappedImage(const Film& film, double exposure = 0);

}  // namespace raylab
