#pragma once
// 8-bit sRGB PNG preview of a Film's colour.

#include <array>
#include <cstdint>
#include <string>

#include "renderer/film.h"
#include "renderer/io/atomic_file.h"
#include "shading/srgb.h"  // linearToSrgb: 12.92·v up to 0.0031308, else 1.055·v^(1/2.4) − 0.055

namespace raylab {

/// \brief One channel's 8-bit sRGB code: c·scale clamped to [0, 1], encoded
/// with linearToSrgb and rounded half up to 0..255; 0 for NaN (before or
/// after scaling), 255 for +Inf. The definition every 8-bit output follows;
/// Srgb8Encoder (srgb8_encoder.h) gives the same codes faster.
uint8_t srgb8Code(float c, double scale);

/// \brief Maps one linear RGB colour to 8-bit sRGB.
///
/// Each channel is scaled by 2^exposure, clamped to [0, 1], encoded with
/// linearToSrgb and rounded to the nearest of 0..255. A non-finite channel
/// (before or after scaling) maps to 0.
std::array<uint8_t, 3> toneMapSrgb8(float r, float g, float b, double exposure);

/// \brief Writes the RGB of `film` as an 8-bit RGB PNG (toneMapSrgb8 per
/// pixel, row 0 at the top, sRGB chunk; encodePng, png_memory.h),
/// atomically. Alpha is not written.
/// \throws InputError(path, 0, reason) when the film is empty or inconsistent
///         or the file cannot be written; `path` is then left untouched.
/// With `group`, the file is staged in it and appears at group->commit().
void writePng(const std::string& path, const Film& film, double exposure = 0,
              AtomicFileGroup* group = nullptr);

}  // namespace raylab
