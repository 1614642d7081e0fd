#pragma once
// Numbered image sequences: `raylab render SCENE -o out.exr --frames 1:24`
// writes out_0001.exr ... out_0024.exr, one frame per position of the
// scene's camera_path.

#include <string>

#include "renderer/camera_path.h"
#include "renderer/scene.h"

namespace raylab {

/// Frames first..last, inclusive.
struct FrameRange {
    int first = 1;
    int last = 1;
    /// Number of frames.
    int count() const { return last - first + 1; }
};

/// Parses "A:B" or "A" (one frame) with 0 <= A <= B <= kMaxFrame.
/// Throws UsageError naming --frames and the text otherwise.
FrameRange parseFrameRange(const std::string& text);

/// The file of frame `frame`: "_NNNN" (at least four digits) inserted before
/// the extension of the file name: ("out.exr", 7) -> "out_0007.exr",
/// ("dir.v2/out", 12345) -> "dir.v2/out_12345".
std::string sequenceFileName(const std::string& path, int frame);

/// The scene's camera_path with the camera of every frame in `frames`
/// checked before the first one renders. Throws InputError at the scene
/// file when it has no camera_path or a frame's camera is degenerate.
CameraPath sequenceCameraPath(const Scene& scene, const FrameRange& frames);

}  // namespace raylab
