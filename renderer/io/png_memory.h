#pragma once
// PNG bytes in memory, for pages that embed their images (data: URIs).

#include <cstdint>
#include <vector>

#include "renderer/film.h"

namespace raylab {

/// 8-bit RGB pixels, row 0 at the top.
struct Rgb8Image {
    int width = 0, height = 0;
    std::vector<uint8_t> pixels;  ///< 3 bytes per pixel
};

/// The film's colour as the PNG preview shows it: toneMapSrgb8's codes
/// (png_writer.h), by Srgb8Encoder, rows in parallel.
Rgb8Image toneMappedImage(const Film& film, double exposure = 0);

/// \brief The image encoded as a PNG file's bytes: IHDR (8-bit RGB), sRGB,
/// one IDAT, IEND. Every row has filter type 4 (Paeth), and the rows are one
/// zlib stream by igzip (ISA-L) at level 1: libpng's writer with zlib took
/// longer than the render of a small scene (docs/benchmarks.md, "The 8-bit
/// outputs"). libpng still reads PNGs (tests decode these files with it).
/// \throws std::runtime_error when the image is empty or inconsistent, or
///         igzip fails.
std::vector<unsigned char> encodePng(const Rgb8Image& image);

}  // namespace raylab
