#pragma once
// OpenEXR files with ZIP or ZIPS compression, written by raylab with igzip
// (Intel's ISA-L) instead of through Imf::OutputFile and zlib.
//
// Why: on the SPD scenes, zlib's deflate and OpenEXR's line-buffer copies were
// a third of balls' instructions and three fifths of tetra's (docs/
// benchmarks.md, "The EXR's deflate"). The file is the one OpenEXR writes
// (OpenEXR 3.2 too left zlib, for libdeflate): the same magic,
// version and header bytes (ExrHeader, which writes Imf::Header::writeTo's
// bytes: exr_header.h), the same scan-line chunks
// of 16 (ZIP) or 1 (ZIPS) lines with OpenEXR's byte reordering and predictor,
// a block stored raw when deflate does not make it smaller. Only the deflate
// stream differs, so any zlib reads it and every decoded value is the same.
//
// Blocks are compressed in parallel and written in scan-line order: the bytes
// do not depend on the thread count. igzip picks its code for the CPU it runs
// on (SSE, AVX2, AVX-512), so two kinds of CPU may write different deflate
// streams of the same pixels; one machine always writes the same bytes.

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "renderer/io/exr_header.h"

namespace raylab {

/// igzip's level for EXR ZIP blocks. On balls --spd's 18.4 MB of blocks (one
/// thread): level 2 deflated them in 33 ms, against 113 for libdeflate's
/// fastest level and 232 for the zlib level 3 it replaces, into 3.82 MB
/// (zlib 3: 3.79 MB; igzip's level 0 is no faster and 4.46 MB).
/// docs/benchmarks.md, "The EXR's deflate".
constexpr int kExrDeflateLevel = 2;

/// OpenEXR's ZIP pre-pass over one block of `n` raw bytes: the even-indexed
/// bytes, then the odd-indexed ones (the two bytes of a HALF, the high and low
/// bytes of a FLOAT, end up in separate runs), then each byte but the first
/// replaced by its difference to the previous one plus 128, modulo 256.
/// `out` holds n bytes and does not overlap `raw`.
void exrZipPrepass(const unsigned char* raw, size_t n, unsigned char* out);

/// Where one channel's values come from for a run of lines: value x of line
/// k (k = 0 for the run's first line) at base + x * xStride + k * yStride.
struct ExrChannelSource {
    const char* base = nullptr;  ///< null: zeros
    size_t size = 0;             ///< bytes per value: 2 (HALF) or 4 (FLOAT, UINT)
    ptrdiff_t xStride = 0;
    ptrdiff_t yStride = 0;
};

/// The uncompressed bytes of `lines` lines in `raw`, as an EXR block holds
/// them: per line, each channel's `width` values in the order of `sources`
/// (the header's channel order).
void gatherExrLines(const std::vector<ExrChannelSource>& sources, int width, int lines,
                    unsigned char* raw);

/// Fills `raw` with the uncompressed bytes (gatherExrLines' layout) of the
/// data window's lines [y0, y1). Called from several threads at once, each
/// with its own block.
using ExrBlockLines = std::function<void(int y0, int y1, unsigned char* raw)>;

/// \brief Writes an OpenEXR file of `header` (ZIP or ZIPS compression,
/// scan lines, one part) to `path` (created or truncated;
/// the caller writes to a temporary, writeFileAtomically), its pixels from
/// `lines`, compressing blocks on up to `threads` threads (0: all TBB may
/// use).
///
/// Blocks stream through a TBB pipeline: each is gathered, pre-passed and
/// deflated by one thread into buffers that thread reuses, and written as
/// soon as the blocks before it are, so the memory it needs does not grow
/// with the image (docs/benchmarks.md, "Fresh memory"). The offset table is
/// written last, into the place kept for it after the header.
/// \throws std::logic_error when the header's compression is another,
///         std::runtime_error when igzip fails or the file cannot be written.
void writeExrZipFile(const std::string& path, const ExrHeader& header,
                     const ExrBlockLines& lines, int threads);

/// \brief The bytes writeExrZipFile writes for `header`, with channel k's
/// values (the header's order, sorted by name) from sources[k], addressed from
/// the data window's first pixel (a null base: zeros).
/// \throws as writeExrZipFile, and std::logic_error when the sources are not
///         one per channel.
std::string encodeExrZipFile(const ExrHeader& header, const std::vector<ExrChannelSource>& sources,
                             int threads);

}  // namespace raylab
