#include "renderer/io/png_memory.h"

#include <png.h>

#include <array>
#include <cstring>
#include <stdexcept>
#include <string>

#include "renderer/io/png_writer.h"

namespace raylab {

Rgb8Image toneMappedImage(const Film& film, double exposure) {
    Rgb8Image image;
    image.width = film.width;
    image.height = film.height;
    const size_t n = size_t(film.width) * size_t(film.height);
    image.pixels.resize(n * 3);
    for (size_t i = 0; i < n && 4 * i + 3 < film.rgba.size(); ++i) {
        const float* c = &film.rgba[4 * i];
        const std::array<uint8_t, 3> rgb = toneMapSrgb8(c[0], c[1], c[2], exposure);
        std::memcpy(&image.pixels[3 * i], rgb.data(), 3);
    }
    return image;
}

std::vector<unsigned char> encodePng(const Rgb8Image& in) {
    if (in.width <= 0 || in.height <= 0 ||
        in.pixels.size() != size_t(in.width) * size_t(in.height) * 3)
        throw std::runtime_error("cannot encode PNG: empty or inconsistent image");
    // libpng's simplified API: size first, then the bytes (errors through
    // image.message, no longjmp across C++ frames).
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(in.width);
    image.height = png_uint_32(in.height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    const png_int_32 stride = png_int_32(3 * in.width);
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, in.pixels.data(), stride, nullptr)) {
        const std::string message = image.message;
        png_image_free(&image);
        throw std::runtime_error("libpng: " + message);
    }
    std::vector<unsigned char> bytes(size);
    const int ok =
        png_image_write_to_memory(&image, bytes.data(), &size, 0, in.pixels.data(), stride, nullptr);
    const std::string message = image.message;
    png_image_free(&image);
    if (!ok) throw std::runtime_error("libpng: " + message);
    bytes.resize(size);
    return bytes;
}

}  // namespace raylab
