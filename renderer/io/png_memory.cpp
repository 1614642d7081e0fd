#include "renderer/io/png_memory.h"

#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "renderer/io/srgb8_encoder.h"

namespace raylab {

namespace {

/// Rows per task: enough work to be worth a task, few enough for two cores
/// to share a small image.
constexpr size_t kRowsPerTask = 16;

/// The Paeth predictor of PNG's filter type 4 (PNG specification, 9.4):
/// whichever of left, up and upper-left is nearest to left + up − upper-left.
inline uint8_t paeth(int a, int b, int c) {
    const int p = a + b - c;
    const int pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
    if (pa <= pb && pa <= pc) return uint8_t(a);
    return uint8_t(pb <= pc ? b : c);
}

/// Row y of `image` as PNG stores it: filter type 4 (Paeth), then each byte
/// minus its prediction from the raw bytes left of, above and above-left of
/// it (zero outside the image).
void filterRow(const Rgb8Image& image, int y, uint8_t* out) {
    const size_t stride = size_t(image.width) * 3;
    const uint8_t* row = image.pixels.data() + size_t(y) * stride;
    const uint8_t* up = y > 0 ? row - stride : nullptr;
    out[0] = 4;
    uint8_t* f = out + 1;
    for (size_t i = 0; i < stride; ++i) {
        const int a = i >= 3 ? row[i - 3] : 0;
        const int b = up ? up[i] : 0;
        const int c = up && i >= 3 ? up[i - 3] : 0;
        f[i] = uint8_t(row[i] - paeth(a, b, c));
    }
}

/// zlib stream (RFC 1950) of in[0, n), by igzip at level 1.
std::vector<unsigned char> zlibCompress(const std::vector<unsigned char>& in) {
    if (in.size() > std::numeric_limits<uint32_t>::max() / 2)
        throw std::runtime_error("cannot encode PNG: image too large for one zlib stream");
    // Room for stored blocks when nothing compresses (5 bytes per 64 KiB)
    // and the zlib header and trailer.
    std::vector<unsigned char> out(in.size() + in.size() / 1024 + ISAL_DEF_MAX_HDR_SIZE + 64);
    const std::unique_ptr<uint8_t[]> levelBuffer(new uint8_t[ISAL_DEF_LVL1_DEFAULT]);
    isal_zstream stream{};  // zeroed: the init leaves fields the deflate reads
    isal_deflate_stateless_init(&stream);
    stream.level = 1;
    stream.level_buf = levelBuffer.get();
    stream.level_buf_size = ISAL_DEF_LVL1_DEFAULT;
    stream.gzip_flag = IGZIP_ZLIB;
    stream.end_of_stream = 1;
    stream.flush = NO_FLUSH;
    stream.next_in = const_cast<uint8_t*>(in.data());
    stream.avail_in = uint32_t(in.size());
    stream.next_out = out.data();
    stream.avail_out = uint32_t(out.size());
    const int result = isal_deflate_stateless(&stream);
    if (result != COMP_OK)
        throw std::runtime_error("cannot encode PNG: igzip deflate failed (" + std::to_string(result) + ")");
    out.resize(stream.total_out);
    return out;
}

void putBigEndian32(std::vector<unsigned char>& out, uint32_t v) {
    out.push_back(uint8_t(v >> 24));
    out.push_back(uint8_t(v >> 16));
    out.push_back(uint8_t(v >> 8));
    out.push_back(uint8_t(v));
}

/// One chunk: length, type, data, CRC-32 of type and data.
void putChunk(std::vector<unsigned char>& out, const char (&type)[5], const unsigned char* data,
              size_t n) {
    putBigEndian32(out, uint32_t(n));
    const size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data, data + n);
    putBigEndian32(out, crc32_gzip_refl(0, out.data() + start, out.size() - start));
}

}  // namespace

Rgb8Image toneMappedImage(const Film& film, double exposure) {
    Rgb8Image image;
    image.width = film.width;
    image.height = film.height;
    const size_t width = size_t(std::max(film.width, 0));
    const size_t rows = size_t(std::max(film.height, 0));
    image.pixels.resize(width * rows * 3);
    if (film.rgba.size() < width * rows * 4) return image;  // inconsistent: black (as before)
    const Srgb8Encoder encode(exposure);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, rows, kRowsPerTask),
                      [&](const tbb::blocked_range<size_t>& r) {
                          encode.encodeRgba(film.rgba.data() + r.begin() * width * 4,
                                            r.size() * width,
                                            image.pixels.data() + r.begin() * width * 3);
                      });
    return image;
}

std::vector<unsigned char> encodePng(const Rgb8Image& in) {
    if (in.width <= 0 || in.height <= 0 ||
        in.pixels.size() != size_t(in.width) * size_t(in.height) * 3)
        throw std::runtime_error("cannot encode PNG: empty or inconsistent image");
    if (uint64_t(in.width) > 0x7FFFFFFFu || uint64_t(in.height) > 0x7FFFFFFFu)
        throw std::runtime_error("cannot encode PNG: image too large");
    // The filtered rows, each a filter byte and its 3·width bytes, filtered
    // in parallel (each row reads only raw rows).
    const size_t rowBytes = size_t(in.width) * 3 + 1;
    std::vector<unsigned char> filtered(rowBytes * size_t(in.height));
    tbb::parallel_for(tbb::blocked_range<int>(0, in.height, int(kRowsPerTask)),
                      [&](const tbb::blocked_range<int>& r) {
                          for (int y = r.begin(); y < r.end(); ++y)
                              filterRow(in, y, filtered.data() + size_t(y) * rowBytes);
                      });
    const std::vector<unsigned char> idat = zlibCompress(filtered);

    std::vector<unsigned char> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    out.reserve(idat.size() + 128);
    std::vector<unsigned char> ihdr;
    putBigEndian32(ihdr, uint32_t(in.width));
    putBigEndian32(ihdr, uint32_t(in.height));
    // 8 bits per sample, colour type 2 (RGB), deflate, adaptive filtering, no interlace.
    ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});
    putChunk(out, "IHDR", ihdr.data(), ihdr.size());
    // The samples are sRGB-encoded (rendering intent 0, perceptual), as
    // libpng's writer marked them before.
    const unsigned char srgbIntent = 0;
    putChunk(out, "sRGB", &srgbIntent, 1);
    putChunk(out, "IDAT", idat.data(), idat.size());
    putChunk(out, "IEND", nullptr, 0);
    return out;
}

}  // namespace raylab
