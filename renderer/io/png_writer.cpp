#include "renderer/io/png_writer.h"

#include <cmath>
#include <cstring>
#include <vector>

#include <png.h>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"

namespace raylab {

namespace {

uint8_t encodeChannel(float c, double scale) {
    double v = double(c) * scale;
    // NaN never reaches a pixel (defensive); an overflow (+Inf, e.g. after a
    // huge exposure) is as white as any value above 1, never black.
    if (std::isnan(v)) return 0;
    v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
    // Round half up; the argument is in [0.5, 255.5] so the cast is in range.
    return uint8_t(std::floor(linearToSrgb(v) * 255.0 + 0.5));
}

}  // namespace

double linearToSrgb(double v) {
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
}

std::array<uint8_t, 3> toneMapSrgb8(float r, float g, float b, double exposure) {
    const double scale = std::exp2(exposure);
    return {encodeChannel(r, scale), encodeChannel(g, scale), encodeChannel(b, scale)};
}

void writePng(const std::string& path, const Film& film, double exposure, AtomicFileGroup* group) {
    if (film.width <= 0 || film.height <= 0)
        throw InputError(path, 0,
                         "cannot write PNG: empty image (" + std::to_string(film.width) + "x" +
                             std::to_string(film.height) + ")");
    const size_t n = size_t(film.width) * size_t(film.height);
    if (film.rgba.size() != n * 4)
        throw InputError(path, 0,
                         "cannot write PNG: film has " + std::to_string(film.rgba.size()) +
                             " RGBA values, expected " + std::to_string(n * 4));

    std::vector<uint8_t> pixels(n * 3);
    for (size_t i = 0; i < n; ++i) {
        const float* c = &film.rgba[4 * i];
        const std::array<uint8_t, 3> rgb = toneMapSrgb8(c[0], c[1], c[2], exposure);
        std::memcpy(&pixels[3 * i], rgb.data(), 3);
    }

    writeFileAtomically(path, [&](const std::string& tmp) {
        // libpng's simplified API reports errors through image.message instead
        // of longjmp, which would skip C++ destructors.
        png_image image;
        std::memset(&image, 0, sizeof image);
        image.version = PNG_IMAGE_VERSION;
        image.width = png_uint_32(film.width);
        image.height = png_uint_32(film.height);
        image.format = PNG_FORMAT_RGB;
        const int ok = png_image_write_to_file(&image, tmp.c_str(), 0, pixels.data(),
                                               png_int_32(3 * film.width), nullptr);
        const std::string message = image.message;
        png_image_free(&image);
        if (!ok) throw InputError("libpng: " + message);
    }, group);
}

}  // namespace raylab
