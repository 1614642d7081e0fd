#include "renderer/io/png_writer.h"

#include <cmath>
#include <vector>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/png_memory.h"

namespace raylab {

uint8_t srgb8Code(float c, double scale) {
    double v = double(c) * scale;
    // NaN never reaches a pixel (defensive); an overflow (+Inf, e.g. after a
    // huge exposure) is as white as any value above 1, never black.
    if (std::isnan(v)) return 0;
    v = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
    // Round half up; the argument is in [0.5, 255.5] so the cast is in range.
    return uint8_t(std::floor(linearToSrgb(v) * 255.0 + 0.5));
}

std::array<uint8_t, 3> toneMapSrgb8(float r, float g, float b, double exposure) {
    const double scale = std::exp2(exposure);
    return {srgb8Code(r, scale), srgb8Code(g, scale), srgb8Code(b, scale)};
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
    std::vector<unsigned char> bytes;
    try {
        bytes = encodePng(toneMappedImage(film, exposure));
    } catch (const std::exception& e) {
        throw InputError(path, 0, std::string("cannot write PNG: ") + e.what());
    }
    writeFileAtomically(path, bytes.data(), bytes.size(), group);
}

}  // namespace raylab
