#include "renderer/io/png_memory.h"

#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "renderer/io/igzip_stream.h"

namespace raylab {

namespace {

/// Filtered rows handed to igzip at a time (at least one row): bounds the
/// memory beside the image whatever its size.
constexpr size_t kBlockBytes = size_t(16) << 20;
/// Compressed bytes per IDAT chunk (PNG caps a chunk at 2^31 - 1).
constexpr size_t kIdatBytes = size_t(1) << 20;
/// igzip takes at most this many input bytes per call (its counts are 32-bit).
constexpr size_t kDeflateInput = size_t(1) << 30;

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
void filterRow(const Rgb8Image& image, size_t y, uint8_t* out) {
    const size_t stride = size_t(image.width) * 3;
    const uint8_t* row = image.pixels.data() + y * stride;
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

/// The rows' zlib stream (RFC 1950) by igzip level 1, appended to a PNG as
/// IDAT chunks while it is made.
class IdatWriter {
public:
    explicit IdatWriter(std::vector<unsigned char>& png)
        // The level buffer zeroed (make_unique value-initialises): igzip
        // reads parts of its hash table it has not written.
        : m_png(png), m_levelBuffer(std::make_unique<uint8_t[]>(ISAL_DEF_LVL1_DEFAULT)),
          m_out(kIdatBytes) {
        m_stream.reset();
        isal_deflate_init(m_stream.get());
        m_stream->level = 1;
        m_stream->level_buf = m_levelBuffer.get();
        m_stream->level_buf_size = ISAL_DEF_LVL1_DEFAULT;
        m_stream->gzip_flag = IGZIP_ZLIB;
        m_stream->flush = NO_FLUSH;
        m_stream->next_out = m_out.data();
        m_stream->avail_out = uint32_t(m_out.size());
    }

    /// Deflates in[0, n); `last`: the stream ends with it.
    void write(const unsigned char* in, size_t n, bool last) {
        do {
            const size_t piece = std::min(n, kDeflateInput);
            m_stream->next_in = const_cast<uint8_t*>(in);
            m_stream->avail_in = uint32_t(piece);
            in += piece;
            n -= piece;
            m_stream->end_of_stream = last && n == 0;
            // Until igzip has taken the piece (and, at the end, finished the stream).
            while (m_stream->avail_in > 0 ||
                   (m_stream->end_of_stream && m_stream->internal_state.state != ZSTATE_END)) {
                const int result = isal_deflate(m_stream.get());
                if (result != COMP_OK)
                    throw std::runtime_error("igzip deflate failed (" + std::to_string(result) + ")");
                if (m_stream->avail_out == 0) flush();
            }
        } while (n > 0);
        if (last) flush();
    }

private:
    void flush() {
        const size_t used = m_out.size() - m_stream->avail_out;
        if (used > 0) putChunk(m_png, "IDAT", m_out.data(), used);
        m_stream->next_out = m_out.data();
        m_stream->avail_out = uint32_t(m_out.size());
    }

    std::vector<unsigned char>& m_png;
    IgzipStream m_stream;  // placed: igzip's bytes must not depend on its address
    std::unique_ptr<uint8_t[]> m_levelBuffer;
    std::vector<unsigned char> m_out;
};

}  // namespace

std::vector<unsigned char> encodePng(const Rgb8Image& in) {
    if (in.width <= 0 || in.height <= 0 ||
        in.pixels.size() != size_t(in.width) * size_t(in.height) * 3)
        throw std::runtime_error("empty or inconsistent image");
    std::vector<unsigned char> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
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

    // Blocks of rows: filtered in parallel (a row reads only raw rows), then
    // deflated, the stream going on from block to block.
    const size_t rowBytes = size_t(in.width) * 3 + 1;
    const size_t rows = size_t(in.height);
    const size_t blockRows = std::max<size_t>(1, kBlockBytes / rowBytes);
    std::vector<unsigned char> filtered(std::min(blockRows, rows) * rowBytes);
    IdatWriter idat(out);
    for (size_t y0 = 0; y0 < rows; y0 += blockRows) {
        const size_t y1 = std::min(rows, y0 + blockRows);
        tbb::parallel_for(tbb::blocked_range<size_t>(y0, y1, 16), [&](const tbb::blocked_range<size_t>& r) {
            for (size_t y = r.begin(); y < r.end(); ++y)
                filterRow(in, y, filtered.data() + (y - y0) * rowBytes);
        });
        idat.write(filtered.data(), (y1 - y0) * rowBytes, y1 == rows);
    }
    putChunk(out, "IEND", nullptr, 0);
    return out;
}

}  // namespace raylab
