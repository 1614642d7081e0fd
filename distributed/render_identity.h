#pragma once
// What defines the pictures a rank renders, in a form ranks can compare before
// the first frame: every rank of a job must load the same scene bytes and
// resolve the same options, or rank 0 would assemble a patchwork of tiles
// from different pictures (launched MPMD with two scenes, say).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "distributed/frame_sequence.h"
#include "renderer/io/input_files.h"
#include "renderer/render_options.h"

namespace raylab {

struct RenderIdentity {
    std::string scene;       ///< the scene file as named on the command line (messages only)
    uint32_t files = 0;      ///< files read for the scene: the scene file, meshes, MTL libraries
    uint64_t bytes = 0;      ///< their total size
    uint64_t sceneHash = 0;  ///< content hash of their bytes, file by file in reading order
    /// Every setting that changes pixels, as "name=value" words: the resolved
    /// render options, the frames, and what the command line did to the
    /// loaded scene. Compared as text, so a difference can be named.
    std::string settings;
};

/// The identity of rendering `scenePath`, for which the files `inputs` were
/// read (InputFileLog::files(), in reading order), with `options`; `frames`
/// as --frames gave them (nullopt: one image), `triangulated` when
/// --polygons triangles ear-clipped the polygons. What does not change a
/// pixel (threads, output names, PNG exposure) is left out.
RenderIdentity renderIdentity(const std::string& scenePath, const std::vector<InputFile>& inputs,
                              const RenderOptions& options, const std::optional<FrameRange>& frames,
                              bool triangulated);

/// "" when `other` (named `otherName`, e.g. "rank 1 (node7)") renders what
/// rank 0's `root` renders; otherwise one line saying what differs.
std::string disagreement(const RenderIdentity& root, const RenderIdentity& other,
                         const std::string& otherName);

}  // namespace raylab
