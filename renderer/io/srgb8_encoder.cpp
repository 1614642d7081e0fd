#include "renderer/io/srgb8_encoder.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstring>

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

uint32_t Srgb8Encoder::bitsOf(float c) {
    uint32_t bits;
    std::memcpy(&bits, &c, sizeof bits);
    return bits;
}

Srgb8Encoder::Srgb8Encoder(double exposure) {
    const double scale = std::exp2(exposure);  // as toneMapSrgb8 scales
    const auto codeOfBits = [scale](uint32_t bits) {
        float c;
        std::memcpy(&c, &bits, sizeof c);
        return srgb8Code(c, scale);
    };
    // m_firstOf[k]: the first bits in [0, +Inf] with a code >= k, by
    // bisection (the codes do not decrease along the bits, see the header);
    // kNever when even +Inf has a lower code (a scale of 0, say).
    m_firstOf[0] = 0;
    for (unsigned k = 1; k < 256; ++k) {
        uint32_t lo = m_firstOf[k - 1], hi = kNever;  // code(lo - 1) < k <= code(hi)
        while (lo < hi) {
            const uint32_t mid = lo + (hi - lo) / 2;
            if (codeOfBits(mid) >= k) hi = mid;
            else lo = mid + 1;
        }
        m_firstOf[k] = lo;
    }
    // The code at the first float of every slice up to +Inf's.
    m_sliceStart.resize((kPositiveInfinity >> kSliceShift) + 1);
    unsigned code = 0;
    for (size_t s = 0; s < m_sliceStart.size(); ++s) {
        const uint32_t first = uint32_t(s) << kSliceShift;
        while (code < 255 && first >= m_firstOf[code + 1]) ++code;
        m_sliceStart[s] = uint8_t(code);
    }
}

void Srgb8Encoder::encodeRgba(const float* rgba, size_t count, uint8_t* rgb) const {
    for (size_t i = 0; i < count; ++i) {
        rgb[3 * i + 0] = (*this)(rgba[4 * i + 0]);
        rgb[3 * i + 1] = (*this)(rgba[4 * i + 1]);
        rgb[3 * i + 2] = (*this)(rgba[4 * i + 2]);
    }
}

Rgb8Image toneMappedImage(const Film& film, double exposure) {
    Rgb8Image image;
    image.width = film.width;
    image.height = film.height;
    const size_t width = size_t(std::max(film.width, 0));
    const size_t rows = size_t(std::max(film.height, 0));
    image.pixels.resize(width * rows * 3);
    if (film.rgba.size() < width * rows * 4) return image;  // inconsistent: black
    const Srgb8Encoder encode(exposure);
    // 16 rows a task: enough work for a task, and two cores share a small image.
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rows, 16), [&](const tbb::blocked_range<size_t>& r) {
        encode.encodeRgba(film.rgba.data() + r.begin() * width * 4, r.size() * width,
                          image.pixels.data() + r.begin() * width * 3);
    });
    return image;
}

}  // namespace raylab
