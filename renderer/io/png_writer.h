#pragma once
// 8-bit sRGB PNG preview of a Film's colour.

#include <string>

#include "renderer/film.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/srgb8_encoder.h"  // toneMapSrgb8, the codes the PNG holds

namespace raylab {

/// \brief Writes the RGB of `film` as an 8-bit RGB PNG (toneMapSrgb8 per
/// pixel, row 0 at the top, sRGB chunk; encodePng, png_memory.h),
/// atomically. Alpha is not written.
/// \throws InputError(path, 0, reason) when the film is empty or inconsistent
///         or the file cannot be written; `path` is then left untouched.
/// With `group`, the file is staged in it and appears at group->commit().
void writePng(const std::string& path, const Film& film, double exposure = 0,
              AtomicFileGroup* group = nullptr);

}  // namespace raylab
