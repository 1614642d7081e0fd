#pragma once
// Numbered image sequences: `raylab render SCENE -o out.exr --frames 1:24`
// writes out_0001.exr ... out_0024.exr, one frame per camera_path position.

#include <string>

namespace raylab {

/// Frames first..last, inclusive.
struct FrameRange {
    int first = 1;
    int last = 1;
    /// Number of frames.
    int count() const { return last - first + 1; }
};

/// Largest frame number --frames accepts.
constexpr int kMaxFrame = 9999999;

/// Parses "A:B" or "A" (one frame) with 0 <= A <= B <= kMaxFrame.
/// Throws UsageError naming --frames and the text otherwise.
FrameRange parseFrameRange(const std::string& text);

/// The file of frame `frame`: "_NNNN" (at least four digits) inserted before
/// the extension of the file name: ("out.exr", 7) -> "out_0007.exr",
/// ("dir.v2/out", 12345) -> "dir.v2/out_12345".
std::string sequenceFileName(const std::string& path, int frame);

}  // namespace raylab
