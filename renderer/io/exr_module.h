#pragma once
// The narrow interface between raylab and its OpenEXR module
// (raylab-openexr.so, built from renderer/io/openexr/). raylab writes its
// default EXR files (ZIP and ZIPS) itself, header included (exr_header.h,
// exr_zip_file.h); OpenEXR's libraries (OpenEXR, Imath, IlmThread, Iex, zlib)
// are needed only for the other compressions and for reading an EXR
// (`raylab compare`), and cost 2.3-2.9 ms of start-up and ~54 page faults in
// every process that links them (docs/benchmarks.md, session 2026-12-06
// 08:45). So they are loaded with dlopen on first use (exr_module_loader.h),
// as the OpenImageIO and MPI modules are.
//
// Only standard-library types cross this boundary (raylab and the module are
// built together, by the same compiler), and nothing is thrown across it:
// failures come back as text.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "renderer/io/exr_header.h"

namespace raylab::exr_module {

/// Bumped whenever anything below changes shape.
constexpr int kVersion = 2;
/// The module's one exported symbol: `extern "C" const Api* raylab_exr_module_v1()`.
constexpr const char* kEntryPoint = "raylab_exr_module_v1";

/// One channel's values in memory: value (x, y) of the data window at
/// origin + (x - xMin) * xStride + (y - yMin) * yStride.
struct Slice {
    std::string name;
    int32_t type = 2;  ///< OpenEXR's pixel type: 0 UINT, 1 HALF, 2 FLOAT
    char* origin = nullptr;
    ptrdiff_t xStride = 0, yStride = 0;
    double fill = 0.0;  ///< read: the value of a channel the file lacks
};

/// A scan-line file to write with OpenEXR's OutputFile.
struct WriteRequest {
    std::string path;
    /// The header's attributes but its channel list (ExrHeader::attributes),
    /// each value as the file holds it: OpenEXR reads each back itself.
    std::vector<ExrAttribute> attributes;
    std::vector<Slice> slices;  ///< one per channel: the channel list
    int threads = 1;         ///< OpenEXR's global pool is grown to this many
    int blocksInFlight = 1;  ///< OutputFile's thread count (it keeps two blocks per count)
};

/// What a file to read holds, before its pixels are read.
struct ReadInfo {
    int32_t dataWindow[4] = {0, 0, -1, -1};     ///< xMin, yMin, xMax, yMax
    int32_t displayWindow[4] = {0, 0, -1, -1};  ///< xMin, yMin, xMax, yMax
    std::vector<std::string> channels;
};
/// Given what a file holds, where its channels go (FLOAT slices); empty: read nothing.
using SlicesFor = std::function<std::vector<Slice>(const ReadInfo&)>;

struct Api {
    int version = kVersion;
    /// False (and `error` set, the file perhaps partly written) when it cannot.
    bool (*write)(const WriteRequest& request, std::string& error) = nullptr;
    /// Reads every scan line of `path` into the slices `slicesFor` returns;
    /// false (and `error` set) when the file cannot be opened or read, or
    /// `slicesFor` fails (its message is `error`).
    bool (*read)(const std::string& path, const SlicesFor& slicesFor, std::string& error) = nullptr;
};

}  // namespace raylab::exr_module
