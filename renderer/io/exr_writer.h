#pragma once
// OpenEXR output of a Film: the beauty pass plus the AOV layers, written the
// way compositors (Nuke, Blender, OpenImageIO) expect them; docs/output.md
// explains each channel and attribute and how to open the file.
//
// Channels (scan-line image, row 0 = top of the image, lossless compression
// chosen in ExrOptions):
//   R G B A                   HALF (FLOAT with ExrOptions::floatPixels); A per
//                             the alpha mode (raylab/alpha)
//   Z                         FLOAT, planar camera depth of the first hit (along
//                             the view axis), 1e10 where nothing is hit (Cycles)
//   distance                  FLOAT, Euclidean eye distance of the first hit, 1e10
//                             where nothing is hit
//   N.X N.Y N.Z               FLOAT, world shading normal of the first hit
//   albedo.R albedo.G albedo.B HALF, diffuse reflectance of the first hit
//   objectId                  FLOAT, index of the first object hit, -1 for the
//                             background (FLOAT so the -1 survives; exact below 2^24)
//   CryptoObject00.R .G .B .A FLOAT, Cryptomatte: id and coverage of ranks 0 and
//   CryptoObject01, 02        1, then 2 and 3, 4 and 5 (cryptomatte_id.h); only
//                             the layers ExrOptions::matteRanks needs
// Header attributes: software ("raylab VERSION"), worldToCamera and worldToNDC
// (M44f, camera_matrices.h), cryptomatte/<key>/name|hash|conversion|manifest,
// raylab/settings (the render settings that define the image, one line),
// raylab/alpha, raylab/spp, raylab/maxDepth, and when set raylab/scene,
// raylab/accel and raylab/frame. Nothing that varies between runs of the same
// render (times, dates, host names, thread counts, output names) goes into
// the file: the same render writes the same bytes.

#include <optional>
#include <string>
#include <vector>

#include "renderer/camera_matrices.h"
#include "renderer/film.h"
#include "renderer/io/atomic_file.h"

namespace raylab {

/// Lossless compressions of OpenEXR that `raylab render --compression` offers
/// (docs/benchmarks.md measures each: CPU time, bytes). ZIP and ZIPS files are
/// written by raylab itself (exr_zip_file.h); the others by OpenEXR, loaded
/// for them (exr_module.h).
enum class ExrCompression { None, Rle, Zips, Zip, Piz };

/// --compression names, in the enum's order.
inline constexpr const char* kExrCompressionNames[] = {"none", "rle", "zips", "zip", "piz"};

struct ExrOptions {
    bool floatPixels = false;  ///< RGBA as 32-bit FLOAT instead of HALF
    ExrCompression compression = ExrCompression::Zip;
    std::string software;      ///< "raylab 0.1.0" (omitted when empty)
    std::string settings;      ///< renderSettingsText of the render (omitted when empty)
    std::string alpha;         ///< alphaModeName of the render (omitted when empty)
    std::string scenePath;     ///< scene file rendered (omitted when empty)
    std::string accel;         ///< accelerator name (omitted when empty)
    int spp = 0;               ///< samples per pixel
    int maxDepth = 0;          ///< maximum ray depth
    int frame = 0;             ///< frame number of a sequence (omitted when 0)
    std::optional<CameraMatrices> camera;  ///< worldToCamera, worldToNDC (omitted when unset)
    /// Object names by index, hashed into the Cryptomatte ids; an index
    /// without a name is called "object<index>".
    std::vector<std::string> objectNames;
    /// Cryptomatte ranks to write (1..kMatteRanks, rounded up to a whole layer
    /// of two): the most objects a pixel can see with the render's sampling
    /// (matteRanksOfSampling). Unused ranks would be zeros that cost as much
    /// to compress as data. More are written if a pixel of the film needs them.
    int matteRanks = kMatteRanks;
    /// Threads compressing scan-line blocks (0: one per hardware thread): TBB
    /// tasks for ZIP and ZIPS (exr_zip_file.h); for the other compressions
    /// OpenEXR's process-wide worker pool, grown to this size if it is smaller.
    /// The file's bytes do not depend on it.
    int threads = 0;
};

/// The Cryptomatte layer raylab writes (CryptoObject00, ...).
constexpr const char* kCryptoObjectLayer = "CryptoObject";

/// The name under which object `index` is hashed: objectNames[index], or
/// "object<index>" when there is none (or it is empty).
std::string matteName(const std::vector<std::string>& objectNames, int index);

/// \brief Writes `film` to `path` as an OpenEXR file (layout above), atomically.
///
/// Values are made safe for their channel type before conversion: NaN becomes
/// 0 and magnitudes beyond the largest finite value of the type (65504 for
/// HALF) are clamped to it, so no channel holds Inf or NaN; Z and distance
/// hold 1e10 where they are NaN or infinite. An empty AOV vector is written
/// as the Film default (Z and distance 1e10, N and albedo 0, objectId -1, no
/// Cryptomatte coverage), so every file has the 17 channels up to CryptoObject00
/// and 4 more per further Cryptomatte layer (25 with all three).
/// \throws InputError(path, 0, reason) when the film is empty or inconsistent
///         or the file cannot be written; `path` is then left untouched.
/// With `group`, the file is staged in it and appears at group->commit().
void writeExr(const std::string& path, const Film& film, const ExrOptions& opts,
              AtomicFileGroup* group = nullptr);

/// \brief Makes sure an EXR of `compression` can be written to `path`: ZIP
/// and ZIPS are raylab's own; the others load OpenEXR's module now
/// (exr_module.h), so that a render fails before it starts, not after.
/// \throws InputError(path, 0, reason) when the module cannot be loaded.
void prepareExrWriter(const std::string& path, ExrCompression compression);

}  // namespace raylab
