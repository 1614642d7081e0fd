#pragma once
// OpenEXR files with ZIP or ZIPS compression, written by raylab with igzip
// (Intel's ISA-L) instead of through Imf::OutputFile and zlib.
//
// Why: on the SPD scenes, zlib's deflate and OpenEXR's line-buffer copies were
// a third of balls' instructions and three fifths of tetra's (docs/
// benchmarks.md, "The EXR's deflate"). The file is the one OpenEXR writes
// (OpenEXR 3.2 too left zlib, for libdeflate): the same magic,
// version and header bytes (Imf::Header::writeTo), the same scan-line chunks
// of 16 (ZIP) or 1 (ZIPS) lines with OpenEXR's byte reordering and predictor,
// a block stored raw when deflate does not make it smaller. Only the deflate
// stream differs, so any zlib reads it and every decoded value is the same.
//
// Blocks are compressed in parallel and written in scan-line order: the bytes
// do not depend on the thread count. igzip picks its code for the CPU it runs
// on (SSE, AVX2, AVX-512), so two kinds of CPU may write different deflate
// streams of the same pixels; one machine always writes the same bytes.

#include <cstddef>
#include <string>

#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>

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

/// \brief The bytes of an OpenEXR file of `header` (ZIP_COMPRESSION or
/// ZIPS_COMPRESSION, scan lines, one part) with the pixels of `frameBuffer`,
/// compressing blocks on up to `threads` threads (0: all TBB may use). The
/// caller writes them (writeFileAtomically).
///
/// Every channel of the header needs a slice of its own pixel type in the
/// frame buffer (a channel without one is written as zeros, like
/// Imf::OutputFile does), and sampling 1x1.
/// \throws std::logic_error / Iex errors when the header or a slice is not
///         one this writer handles, std::runtime_error when igzip fails.
std::string encodeExrZipFile(const Imf::Header& header, const Imf::FrameBuffer& frameBuffer,
                             int threads);

}  // namespace raylab
