#include "distributed/frame_sequence.h"

#include <cstdio>

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

}  // namespace raylab
