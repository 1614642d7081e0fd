#pragma once
// PNG bytes in memory: the PNG output (png_writer.h) and pages that embed
// their images (data: URIs).

#include <cstdint>
#include <vector>

#include "renderer/io/srgb8_encoder.h"  // Rgb8Image, toneMappedImage

namespace raylab {

/// \brief The image encoded as a PNG file's bytes: IHDR (8-bit RGB), sRGB,
/// IDAT chunks of up to 1 MiB, IEND. Every row has filter type 4 (Paeth),
/// and the rows are one zlib stream by igzip (ISA-L) at level 1, made block
/// of rows by block of rows (no copy of the whole image): libpng's writer
/// with zlib took longer than the render of a small scene (docs/
/// benchmarks.md, "The 8-bit outputs"). The tests decode these files with
/// libpng.
/// \throws std::runtime_error when the image is empty or inconsistent, or
///         igzip fails.
std::vector<unsigned char> encodePng(const Rgb8Image& image);

}  // namespace raylab
