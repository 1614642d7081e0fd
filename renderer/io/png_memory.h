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

/// The film's colour as the PNG preview shows it (toneMapSrgb8 per pixel).
Rgb8Image toneMappedImage(const Film& film, double exposure = 0);

/// \brief The image encoded as a PNG file's bytes.
/// \throws std::runtime_error when libpng fails (or the image is empty).
std::vector<unsigned char> encodePng(const Rgb8Image& image);

}  // namespace raylab
