#pragma once
// The output formats written through OpenImageIO: JPEG (8-bit sRGB,
// tone-mapped like the PNG), Radiance HDR (linear RGB) and TIFF (32-bit float
// linear RGBA, the EXR's beauty pass). raylab does not link OpenImageIO: the
// first such write loads its module (image_module.h), so EXR and PNG renders
// never pay for its libraries.

#include <string>

#include "renderer/film.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/output_format.h"

namespace raylab {

/// \brief Writes the colour of `film` to `path` as `format` (Jpeg, Hdr or
/// Tiff), atomically, with a "Software" tag of `software` when non-empty.
///
/// JPEG: toneMapSrgb8 per pixel (exposure in stops), quality 95, no alpha.
/// HDR: linear RGB, negative values clamped to 0 (RGBE has no sign).
/// TIFF: linear RGBA as rendered (A as in the EXR), ZIP compressed.
/// Values are finite (the film never holds NaN or Inf).
/// \throws InputError(path, 0, reason) when the film is empty or inconsistent,
///         the format is not one of these three, OpenImageIO's module is not
///         available (not found, or over the `ulimit -v` budget), or the file
///         cannot be written; `path` is then left untouched.
/// With `group`, the file is staged in it and appears at group->commit().
/// \brief Loads OpenImageIO's module for writing `path` as `format`, so that a
/// render fails before it starts, not after, when the module is missing or
/// does not fit the address-space limit.
/// \throws InputError(path, 0, reason) when it is not available.
void prepareOiioImageWriter(const std::string& path, OutputFormat format);

void writeOiioImage(const std::string& path, const Film& film, OutputFormat format,
                    double exposure, const std::string& software,
                    AtomicFileGroup* group = nullptr);

}  // namespace raylab
