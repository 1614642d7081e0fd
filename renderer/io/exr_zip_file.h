#pragma once
// OpenEXR files with ZIP or ZIPS compression, written by raylab with
// libdeflate instead of through Imf::OutputFile and zlib.
//
// Why: on the SPD scenes, zlib's deflate and OpenEXR's line-buffer copies were
// a third of balls' instructions and three fifths of tetra's (docs/
// benchmarks.md, "The EXR's deflate"). The file is the one OpenEXR writes
// (OpenEXR 3.2 made the same move for its own ZIP codec): the same magic,
// version and header bytes (Imf::Header::writeTo), the same scan-line chunks
// of 16 (ZIP) or 1 (ZIPS) lines with OpenEXR's byte reordering and predictor,
// a block stored raw when deflate does not make it smaller. Only the deflate
// stream differs, so any zlib reads it and every decoded value is the same.
//
// Blocks are compressed in parallel and written in scan-line order: the bytes
// do not depend on the thread count.

#include <cstddef>
#include <string>

#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>

namespace raylab {

/// libdeflate's level for EXR ZIP blocks. Level 1 took half the instructions
/// of the zlib level 3 it replaces (balls --spd: 388 M against 818 M; levels
/// 2-6 cost 734-860 M) and still gave smaller files (3.91 MB against 3.97).
/// docs/benchmarks.md, "The EXR's deflate".
constexpr int kExrDeflateLevel = 1;

/// OpenEXR's ZIP pre-pass over one block of `n` raw bytes: the even-indexed
/// bytes, then the odd-indexed ones (the two bytes of a HALF, the high and low
/// bytes of a FLOAT, end up in separate runs), then each byte but the first
/// replaced by its difference to the previous one plus 128, modulo 256.
/// `out` holds n bytes and does not overlap `raw`.
void exrZipPrepass(const unsigned char* raw, size_t n, unsigned char* out);

/// \brief Writes `header` (ZIP_COMPRESSION or ZIPS_COMPRESSION, scan lines,
/// one part) with the pixels of `frameBuffer` to the file `path`, compressing
/// blocks on up to `threads` threads (0: all TBB may use).
///
/// Every channel of the header needs a slice of its own pixel type in the
/// frame buffer (a channel without one is written as zeros, like
/// Imf::OutputFile does), and sampling 1x1.
/// \throws std::runtime_error (Iex or std) when the header is invalid, a slice
///         does not fit, or the file cannot be written.
void writeExrZipFile(const std::string& path, const Imf::Header& header,
                     const Imf::FrameBuffer& frameBuffer, int threads);

}  // namespace raylab
