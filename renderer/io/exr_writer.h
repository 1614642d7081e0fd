#pragma once
// OpenEXR output of a Film: the beauty pass plus the AOV layers.
//
// Channels (scan-line image, row 0 = top of the image, lossless compression
// chosen in ExrOptions):
//   R G B A                   HALF (FLOAT with ExrOptions::floatPixels)
//   Z                         FLOAT, eye distance; +inf where nothing is hit
//   N.X N.Y N.Z               FLOAT, world shading normal of the first hit
//   albedo.R albedo.G albedo.B HALF, diffuse reflectance of the first hit
//   objectId                  FLOAT, index of the first object hit, -1 for the
//                             background (FLOAT rather than UINT so the -1 of
//                             the Film survives; ids below 2^24 are exact)
// Header attributes: "raylab/command" (string), "raylab/spp" (int),
// "raylab/maxDepth" (int), and when non-empty "raylab/scene" and
// "raylab/accel" (strings). Nothing that varies between runs (times, dates,
// host names) goes into the file: the same command writes the same bytes.

#include <string>

#include "renderer/film.h"
#include "renderer/io/atomic_file.h"

namespace raylab {

/// Lossless compressions of OpenEXR that `raylab render --compression` offers
/// (docs/benchmarks.md measures each: CPU time, bytes).
enum class ExrCompression { None, Rle, Zips, Zip, Piz };

/// --compression names, in the enum's order.
inline constexpr const char* kExrCompressionNames[] = {"none", "rle", "zips", "zip", "piz"};

struct ExrOptions {
    bool floatPixels = false;  ///< RGBA as 32-bit FLOAT instead of HALF
    ExrCompression compression = ExrCompression::Zip;
    std::string commandLine;   ///< the command that produced the image
    std::string scenePath;     ///< scene file rendered (omitted when empty)
    std::string accel;         ///< accelerator name (omitted when empty)
    int spp = 0;               ///< samples per pixel
    int maxDepth = 0;          ///< maximum ray depth
    /// Threads compressing scan-line blocks (0: one per hardware thread). OpenEXR's
    /// process-wide worker pool is grown to this size if it is smaller. The file's
    /// bytes do not depend on it.
    int threads = 0;
};

/// \brief Writes `film` to `path` as an OpenEXR file (layout above), atomically.
///
/// Values are made safe for their channel type before conversion: NaN becomes
/// 0 and magnitudes beyond the largest finite value of the type (65504 for
/// HALF) are clamped to it, so RGBA and albedo never hold Inf or NaN. Z keeps
/// its +inf background. An empty AOV vector is written as the Film default
/// (Z +inf, N and albedo 0, objectId -1), so every file has all 12 channels.
/// \throws InputError(path, 0, reason) when the film is empty or inconsistent
///         or the file cannot be written; `path` is then left untouched.
/// With `group`, the file is staged in it and appears at group->commit().
void writeExr(const std::string& path, const Film& film, const ExrOptions& opts,
              AtomicFileGroup* group = nullptr);

}  // namespace raylab
