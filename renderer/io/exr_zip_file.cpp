#include "renderer/io/exr_zip_file.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <emmintrin.h>
#include <isa-l/igzip_lib.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfStdIO.h>

#include "renderer/thread_arena.h"

namespace raylab {

namespace {

constexpr int32_t kExrMagic = 20000630;
constexpr int32_t kExrVersion = 2;
constexpr int32_t kLongNamesFlag = 0x400;  // a name of 32 characters or more

/// OpenEXR's rule for the version field's long-names flag (ImfHeader.cpp).
bool usesLongNames(const Imf::Header& header) {
    for (auto it = header.begin(); it != header.end(); ++it)
        if (std::strlen(it.name()) >= 32 || std::strlen(it.attribute().typeName()) >= 32)
            return true;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it)
        if (std::strlen(it.name()) >= 32) return true;
    return false;
}

size_t pixelTypeSize(Imf::PixelType type) { return type == Imf::HALF ? 2 : 4; }

/// Where one channel's values come from: base + x * xStride + y * yStride
/// (OpenEXR's slice addressing, in data-window coordinates).
struct ChannelSource {
    const char* base = nullptr;  ///< null: zeros
    size_t size = 0;             ///< bytes per value
    ptrdiff_t xStride = 0;
    ptrdiff_t yStride = 0;
};

/// One thread's buffers: the raw block, its pre-pass, its deflate stream, and
/// igzip's hash tables. Reused block after block: fresh zeroed pages for
/// each block's output were 3% of balls' process (perf, clear_page).
struct Deflater {
    std::vector<unsigned char> raw, prepassed, stream;
    std::vector<uint8_t> levelBuffer = std::vector<uint8_t>(ISAL_DEF_LVL2_DEFAULT);

    /// The zlib stream of in[0, n) in `out` (capacity n - 1), or 0 when it
    /// would not be smaller than n bytes.
    size_t deflate(const unsigned char* in, size_t n, unsigned char* out) {
        static_assert(kExrDeflateLevel == 2, "levelBuffer's size is igzip level 2's");
        if (n < 2 || n > std::numeric_limits<uint32_t>::max()) return 0;
        // Zeroed first: isal_deflate_stateless_init leaves fields that the
        // deflate reads (memcheck showed it), and the bytes must not depend on
        // whatever the stack held.
        isal_zstream stream{};
        isal_deflate_stateless_init(&stream);
        stream.level = kExrDeflateLevel;
        stream.level_buf = levelBuffer.data();
        stream.level_buf_size = uint32_t(levelBuffer.size());
        stream.gzip_flag = IGZIP_ZLIB;  // zlib header and Adler-32, as OpenEXR writes
        stream.end_of_stream = 1;
        stream.flush = NO_FLUSH;
        stream.next_in = const_cast<uint8_t*>(in);
        stream.avail_in = uint32_t(n);
        stream.next_out = out;
        stream.avail_out = uint32_t(n - 1);
        const int result = isal_deflate_stateless(&stream);
        if (result == STATELESS_OVERFLOW) return 0;
        if (result != COMP_OK)
            throw std::runtime_error("igzip deflate failed (" + std::to_string(result) + ")");
        return stream.total_out;
    }
};

/// The bytes of an int32 or uint64 field (EXR is little-endian, like every
/// machine raylab builds on).
template <class T>
void appendBytes(std::string& out, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out.append(b, sizeof(T));
}

}  // namespace

void exrZipPrepass(const unsigned char* raw, size_t n, unsigned char* out) {
    if (n == 0) return;
    // One pass: 32 raw bytes give 16 even and 16 odd bytes (SSE2 packs of the
    // low and high byte of each 16-bit lane), each run differenced against
    // its own previous 16 bytes. The even run starts the buffer; the odd run's
    // first predecessor is the even run's last byte.
    const size_t evenCount = (n + 1) / 2;
    unsigned char* even = out;
    unsigned char* odd = out + evenCount;
    unsigned char prevEven = 0;  // out[0] is fixed after the loops
    unsigned char prevOdd = raw[2 * (evenCount - 1)];
    const __m128i lowBytes = _mm_set1_epi16(0x00ff);
    const __m128i bias = _mm_set1_epi8(char(-128));
    __m128i lastEven = _mm_set1_epi8(char(prevEven)), lastOdd = _mm_set1_epi8(char(prevOdd));
    size_t i = 0;
    for (; i + 32 <= n; i += 32) {
        const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(raw + i));
        const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(raw + i + 16));
        const __m128i e = _mm_packus_epi16(_mm_and_si128(a, lowBytes), _mm_and_si128(b, lowBytes));
        const __m128i o = _mm_packus_epi16(_mm_srli_epi16(a, 8), _mm_srli_epi16(b, 8));
        // Each byte's predecessor: the vector shifted up one byte, with the
        // previous vector's top byte carried in.
        const __m128i ePrev = _mm_or_si128(_mm_slli_si128(e, 1), _mm_srli_si128(lastEven, 15));
        const __m128i oPrev = _mm_or_si128(_mm_slli_si128(o, 1), _mm_srli_si128(lastOdd, 15));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(even),
                         _mm_add_epi8(_mm_sub_epi8(e, ePrev), bias));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(odd),
                         _mm_add_epi8(_mm_sub_epi8(o, oPrev), bias));
        lastEven = e;
        lastOdd = o;
        even += 16;
        odd += 16;
    }
    if (i > 0) {
        prevOdd = (unsigned char)(_mm_extract_epi16(lastOdd, 7) >> 8);
        prevEven = (unsigned char)(_mm_extract_epi16(lastEven, 7) >> 8);
    }
    for (; i < n; i += 2) {
        *even++ = (unsigned char)(raw[i] - prevEven + 128u);
        prevEven = raw[i];
        if (i + 1 < n) {
            *odd++ = (unsigned char)(raw[i + 1] - prevOdd + 128u);
            prevOdd = raw[i + 1];
        }
    }
    out[0] = raw[0];  // the first byte has no predecessor
}

std::string encodeExrZipFile(const Imf::Header& header, const Imf::FrameBuffer& frameBuffer,
                             int threads) {
    const Imf::Compression compression = header.compression();
    if (compression != Imf::ZIP_COMPRESSION && compression != Imf::ZIPS_COMPRESSION)
        throw std::logic_error("encodeExrZipFile: the header's compression is not ZIP or ZIPS");
    if (header.hasTileDescription() || header.hasType())
        throw std::logic_error("encodeExrZipFile: only single-part scan-line images");
    header.sanityCheck();

    const Imath::Box2i& dw = header.dataWindow();
    const int width = dw.max.x - dw.min.x + 1;
    const int height = dw.max.y - dw.min.y + 1;
    const int linesPerBlock = compression == Imf::ZIP_COMPRESSION ? 16 : 1;
    const int blocks = (height + linesPerBlock - 1) / linesPerBlock;

    // Channels in the file's order (the channel list is sorted by name).
    std::vector<ChannelSource> sources;
    size_t bytesPerLine = 0;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        const Imf::Channel& channel = it.channel();
        if (channel.xSampling != 1 || channel.ySampling != 1)
            throw std::logic_error(std::string("encodeExrZipFile: channel ") + it.name() +
                                   " is subsampled");
        ChannelSource source;
        source.size = pixelTypeSize(channel.type);
        if (const Imf::Slice* slice = frameBuffer.findSlice(it.name())) {
            if (slice->type != channel.type || slice->xSampling != 1 || slice->ySampling != 1)
                throw std::logic_error(std::string("encodeExrZipFile: the slice of channel ") +
                                       it.name() + " has another type or sampling");
            source.base = slice->base;
            source.xStride = ptrdiff_t(slice->xStride);
            source.yStride = ptrdiff_t(slice->yStride);
        }
        sources.push_back(source);
        bytesPerLine += source.size * size_t(width);
    }

    // Each block: gathered raw lines -> pre-pass -> zlib stream (or raw when
    // deflate does not shrink it, which OpenEXR's reader recognises by size).
    std::vector<std::vector<unsigned char>> packed(static_cast<size_t>(blocks));
    tbb::enumerable_thread_specific<Deflater> deflaters;
    auto compressBlocks = [&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, blocks), [&](const tbb::blocked_range<int>& r) {
            Deflater& d = deflaters.local();
            for (int b = r.begin(); b != r.end(); ++b) {
                const int y0 = dw.min.y + b * linesPerBlock;
                const int y1 = std::min(y0 + linesPerBlock, dw.max.y + 1);
                const size_t n = bytesPerLine * size_t(y1 - y0);
                d.raw.resize(n);
                unsigned char* out = d.raw.data();
                for (int y = y0; y < y1; ++y)
                    for (const ChannelSource& s : sources) {
                        const size_t lineBytes = s.size * size_t(width);
                        if (!s.base) {
                            std::memset(out, 0, lineBytes);
                        } else {
                            const char* p = s.base + ptrdiff_t(y) * s.yStride +
                                            ptrdiff_t(dw.min.x) * s.xStride;
                            if (s.xStride == ptrdiff_t(s.size)) {
                                std::memcpy(out, p, lineBytes);
                            } else if (s.size == 4) {
                                for (int x = 0; x < width; ++x, p += s.xStride)
                                    std::memcpy(out + 4 * size_t(x), p, 4);
                            } else {
                                for (int x = 0; x < width; ++x, p += s.xStride)
                                    std::memcpy(out + 2 * size_t(x), p, 2);
                            }
                        }
                        out += lineBytes;
                    }
                d.prepassed.resize(n);
                exrZipPrepass(d.raw.data(), n, d.prepassed.data());
                d.stream.resize(n);
                const size_t size = d.deflate(d.prepassed.data(), n, d.stream.data());
                const unsigned char* chunk = size ? d.stream.data() : d.raw.data();
                packed[size_t(b)].assign(chunk, chunk + (size ? size : n));
            }
        });
    };
    runWithThreads(threads, compressBlocks);

    // Magic, version, header, then the offset table and the chunks in order.
    std::string file;
    appendBytes(file, kExrMagic);
    appendBytes(file, int32_t(kExrVersion | (usesLongNames(header) ? kLongNamesFlag : 0)));
    {
        Imf::StdOSStream os;
        header.writeTo(os);
        file += os.str();
    }
    uint64_t offset = uint64_t(file.size()) + 8 * uint64_t(blocks);
    for (int b = 0; b < blocks; ++b) {
        appendBytes(file, offset);
        offset += 8 + packed[size_t(b)].size();
    }
    file.reserve(offset);
    for (int b = 0; b < blocks; ++b) {
        const std::vector<unsigned char>& chunk = packed[size_t(b)];
        appendBytes(file, int32_t(dw.min.y + b * linesPerBlock));
        appendBytes(file, int32_t(chunk.size()));
        file.append(reinterpret_cast<const char*>(chunk.data()), chunk.size());
    }
    return file;
}

}  // namespace raylab
