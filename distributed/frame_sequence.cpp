#include "distributed/frame_sequence.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>

#include "renderer/io/errors.h"

namespace raylab {

namespace {

/// A decimal integer in [0, kMaxFrame] filling all of `s`, or -1.
int frameNumber(const std::string& s) {
    if (s.empty() || s.size() > 7) return -1;
    int n = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return -1;
        n = n * 10 + (c - '0');
    }
    return n;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
    const size_t colon = text.find(':');
    const int a = frameNumber(text.substr(0, colon));
    const int b = colon == std::string::npos ? a : frameNumber(text.substr(colon + 1));
    if (a < 0 || b < 0 || a > b)
        throw UsageError("--frames: expected FIRST:LAST with 0 <= FIRST <= LAST <= " +
                         std::to_string(kMaxFrame) + " (got '" + terminalSafe(text, 40) + "')");
    return {a, b};
}

std::string sequenceFileName(const std::string& path, int frame) {
    char number[16];
    std::snprintf(number, sizeof number, "_%04d", frame);
    // The extension is the last dot of the file name, not of a directory.
    const size_t slash = path.find_last_of('/');
    const size_t nameStart = slash == std::string::npos ? 0 : slash + 1;
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || dot <= nameStart) return path + number;
    return path.substr(0, dot) + number + path.substr(dot);
}

CameraPath sequenceCameraPath(const Scene& scene, const FrameRange& frames) {
    const std::optional<CameraPath>& path = scene.cameraPath;
    if (!path)
        throw InputError(scene.sourcePath, 0,
                         "--frames needs a \"camera_path\" in the scene (a .json scene; see "
                         "docs/distributed.md)");
    // Outside the keyframes the camera holds still: checking the covered
    // frames and one on each side checks them all.
    const int lo = std::max(frames.first, path->keyframes().front().frame - 1);
    const int hi = std::min(frames.last, path->keyframes().back().frame + 1);
    const auto check = [&](int f) {
        try {
            (void)path->cameraAt(f);
        } catch (const std::invalid_argument& e) {
            throw InputError(scene.sourcePath, 0,
                             "camera_path: frame " + std::to_string(f) + ": " + e.what());
        }
    };
    check(frames.first);
    check(frames.last);
    for (int f = lo; f <= hi; ++f) check(f);
    return *path;
}

}  // namespace raylab
