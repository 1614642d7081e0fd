#include "renderer/io/exr_zip_file.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <emmintrin.h>
#include <isa-l/igzip_lib.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>


#include "renderer/huge_array.h"
#include "renderer/io/igzip_stream.h"
#include "renderer/thread_arena.h"

namespace raylab {

namespace {

constexpr int32_t kExrMagic = 20000630;

/// One thread's buffers: the raw block, its pre-pass, and igzip's hash
/// tables, reused block after block (fresh zeroed pages for each block were
/// 3% of balls' process: perf, clear_page). One huge-page mapping for all
/// three: 1.5 MB for a 512-wide frame, one fault instead of ~370 of 4 KiB.
struct Deflater {
    HugeArray<unsigned char> memory;
    unsigned char* raw = nullptr;
    unsigned char* prepassed = nullptr;
    uint8_t* levelBuffer = nullptr;
    IgzipStream stream;  // placed: igzip's bytes must not depend on its address
    static constexpr size_t kLevelBufferSize = ISAL_DEF_LVL2_DEFAULT;

    /// Makes room for blocks of up to `blockBytes` (the first call sizes it).
    void reserve(size_t blockBytes) {
        if (raw) return;
        // Each part 64-byte aligned: igzip's level buffer holds pointers and
        // 64-bit fields (a ZIPS line of an odd width is 4-byte aligned).
        const size_t part = (blockBytes + 63) & ~size_t(63);
        memory = HugeArray<unsigned char>(2 * part + kLevelBufferSize);
        raw = memory.data();
        prepassed = raw + part;
        levelBuffer = prepassed + part;
    }

    /// The zlib stream of in[0, n) in `out` (capacity n - 1), or 0 when it
    /// would not be smaller than n bytes.
    size_t deflate(const unsigned char* in, size_t n, unsigned char* out) {
        static_assert(kExrDeflateLevel == 2, "levelBuffer's size is igzip level 2's");
        if (n < 2 || n > std::numeric_limits<uint32_t>::max()) return 0;
        // Zeroed first: isal_deflate_stateless_init leaves fields that the
        // deflate reads (memcheck showed it), and the bytes must not depend on
        // what the last block left.
        stream.reset();
        isal_deflate_stateless_init(stream.get());
        stream->level = kExrDeflateLevel;
        stream->level_buf = levelBuffer;
        stream->level_buf_size = uint32_t(kLevelBufferSize);
        stream->gzip_flag = IGZIP_ZLIB;  // zlib header and Adler-32, as OpenEXR writes
        stream->end_of_stream = 1;
        stream->flush = NO_FLUSH;
        stream->next_in = const_cast<uint8_t*>(in);
        stream->avail_in = uint32_t(n);
        stream->next_out = out;
        stream->avail_out = uint32_t(n - 1);
        const int result = isal_deflate_stateless(stream.get());
        if (result == STATELESS_OVERFLOW) return 0;
        if (result != COMP_OK)
            throw std::runtime_error("igzip deflate failed (" + std::to_string(result) + ")");
        return stream->total_out;
    }
};

/// Where the file's bytes go: appended in order, and the offset table
/// written over the place kept for it.
class ByteSink {
public:
    virtual ~ByteSink() = default;
    virtual void append(const void* bytes, size_t n) = 0;
    virtual void writeAt(uint64_t offset, const void* bytes, size_t n) = 0;
};

class StringSink final : public ByteSink {
public:
    explicit StringSink(std::string& out) : m_out(out) {}
    void append(const void* bytes, size_t n) override {
        m_out.append(static_cast<const char*>(bytes), n);
    }
    void writeAt(uint64_t offset, const void* bytes, size_t n) override {
        std::memcpy(m_out.data() + offset, bytes, n);
    }

private:
    std::string& m_out;
};

class FileSink final : public ByteSink {
public:
    explicit FileSink(const std::string& path) : m_file(std::fopen(path.c_str(), "wb")) {
        if (!m_file) fail("cannot open");
    }
    ~FileSink() override {
        if (m_file) std::fclose(m_file);
    }
    void append(const void* bytes, size_t n) override {
        if (std::fwrite(bytes, 1, n, m_file) != n) fail("short write");
    }
    void writeAt(uint64_t offset, const void* bytes, size_t n) override {
        if (fseeko(m_file, off_t(offset), SEEK_SET) != 0) fail("cannot seek");
        append(bytes, n);
    }
    /// Flushes and closes (a full disk may only show up here).
    void close() {
        std::FILE* f = std::exchange(m_file, nullptr);
        if (std::fclose(f) != 0) fail("close failed");
    }

private:
    [[noreturn]] static void fail(const char* what) {
        throw std::runtime_error(std::string(what) + ": " + std::strerror(errno));
    }
    std::FILE* m_file;
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

void gatherExrLines(const std::vector<ExrChannelSource>& sources, int width, int lines,
                    unsigned char* raw) {
    for (int k = 0; k < lines; ++k)
        for (const ExrChannelSource& s : sources) {
            const size_t lineBytes = s.size * size_t(width);
            if (!s.base) {
                std::memset(raw, 0, lineBytes);
            } else {
                const char* p = s.base + ptrdiff_t(k) * s.yStride;
                if (s.xStride == ptrdiff_t(s.size)) {
                    std::memcpy(raw, p, lineBytes);
                } else if (s.size == 4) {
                    for (int x = 0; x < width; ++x, p += s.xStride)
                        std::memcpy(raw + 4 * size_t(x), p, 4);
                } else {
                    for (int x = 0; x < width; ++x, p += s.xStride)
                        std::memcpy(raw + 2 * size_t(x), p, 2);
                }
            }
            raw += lineBytes;
        }
}

namespace {

/// The shape of a ZIP or ZIPS scan-line file.
struct BlockLayout {
    ExrBox dataWindow;
    int width = 0, linesPerBlock = 0, blocks = 0;
    size_t bytesPerLine = 0;
};

BlockLayout blockLayout(const ExrHeader& header) {
    if (header.compression() != ExrCompressionId::Zip &&
        header.compression() != ExrCompressionId::Zips)
        throw std::logic_error("writeExrZipFile: the header's compression is not ZIP or ZIPS");
    BlockLayout l;
    l.dataWindow = header.dataWindow();
    l.width = l.dataWindow.width();
    l.linesPerBlock = exrLinesPerBlock(header.compression());
    l.blocks = (l.dataWindow.height() + l.linesPerBlock - 1) / l.linesPerBlock;
    for (const ExrHeader::Channel& c : header.channels())
        l.bytesPerLine += exrPixelTypeSize(c.type) * size_t(l.width);
    return l;
}

/// Magic, version, header, a kept place for the offset table, then each
/// block (gathered raw lines -> pre-pass -> zlib stream, or raw when deflate
/// does not shrink it, which OpenEXR's reader recognises by size) in
/// scan-line order; the offset table last.
void streamFile(const ExrHeader& header, const ExrBlockLines& lines, int threads,
                ByteSink& sink) {
    const BlockLayout layout = blockLayout(header);
    const ExrBox& dw = layout.dataWindow;
    std::string head;
    appendBytes(head, kExrMagic);
    appendBytes(head, header.versionField());
    header.appendTo(head);
    sink.append(head.data(), head.size());
    // The table's place (zeros until the chunks' offsets are known).
    const uint64_t tableOffset = head.size();
    std::vector<uint64_t> offsets(size_t(layout.blocks), 0);
    sink.append(offsets.data(), 8 * offsets.size());
    uint64_t offset = tableOffset + 8 * offsets.size();

    const size_t maxBlockBytes = layout.bytesPerLine * size_t(layout.linesPerBlock);
    runWithThreads(threads, [&] {
        // Two blocks in flight per thread: one compressing, one waiting for
        // its turn to be written.
        const size_t tokens = 2 * size_t(std::max(1, tbb::this_task_arena::max_concurrency()));
        struct Chunk {
            int block = 0;
            size_t size = 0;
            /// Left uninitialised: only the pages a deflate stream writes are touched.
            std::unique_ptr<unsigned char[]> bytes;
        };
        // A block's chunk is slot block % tokens: the pipeline starts a block
        // only when fewer than `tokens` are in flight, and finishes them in
        // order, so the block `tokens` before it has been written.
        std::vector<Chunk> slots(tokens);
        tbb::enumerable_thread_specific<Deflater> deflaters;
        int next = 0;
        tbb::parallel_pipeline(
            tokens,
            tbb::make_filter<void, Chunk*>(tbb::filter_mode::serial_in_order,
                                           [&](tbb::flow_control& control) -> Chunk* {
                                               if (next == layout.blocks) {
                                                   control.stop();
                                                   return nullptr;
                                               }
                                               Chunk* c = &slots[size_t(next) % tokens];
                                               c->block = next++;
                                               return c;
                                           }) &
                tbb::make_filter<Chunk*, Chunk*>(
                    tbb::filter_mode::parallel,
                    [&](Chunk* c) {
                        Deflater& d = deflaters.local();
                        const int y0 = dw.yMin + c->block * layout.linesPerBlock;
                        const int y1 = std::min(y0 + layout.linesPerBlock, dw.yMax + 1);
                        const size_t n = layout.bytesPerLine * size_t(y1 - y0);
                        d.reserve(maxBlockBytes);
                        lines(y0, y1, d.raw);
                        exrZipPrepass(d.raw, n, d.prepassed);
                        if (!c->bytes) c->bytes.reset(new unsigned char[maxBlockBytes]);
                        c->size = d.deflate(d.prepassed, n, c->bytes.get());
                        if (c->size == 0) {
                            std::memcpy(c->bytes.get(), d.raw, n);
                            c->size = n;
                        }
                        return c;
                    }) &
                tbb::make_filter<Chunk*, void>(tbb::filter_mode::serial_in_order, [&](Chunk* c) {
                    offsets[size_t(c->block)] = offset;
                    int32_t head[2] = {dw.yMin + c->block * layout.linesPerBlock,
                                       int32_t(c->size)};
                    sink.append(head, sizeof head);
                    sink.append(c->bytes.get(), c->size);
                    offset += 8 + c->size;
                }));
    });
    sink.writeAt(tableOffset, offsets.data(), 8 * offsets.size());
}

}  // namespace

void writeExrZipFile(const std::string& path, const ExrHeader& header,
                     const ExrBlockLines& lines, int threads) {
    FileSink sink(path);
    streamFile(header, lines, threads, sink);
    sink.close();
}

std::string encodeExrZipFile(const ExrHeader& header,
                             const std::vector<ExrChannelSource>& sources, int threads) {
    const BlockLayout layout = blockLayout(header);
    if (sources.size() != header.channels().size())
        throw std::logic_error("encodeExrZipFile: one source per channel of the header");
    const ExrBlockLines lines = [&](int y0, int y1, unsigned char* raw) {
        std::vector<ExrChannelSource> block = sources;
        for (ExrChannelSource& s : block)
            if (s.base) s.base += ptrdiff_t(y0 - layout.dataWindow.yMin) * s.yStride;
        gatherExrLines(block, layout.width, y1 - y0, raw);
    };
    std::string file;
    StringSink sink(file);
    streamFile(header, lines, threads, sink);
    return file;
}

}  // namespace raylab
