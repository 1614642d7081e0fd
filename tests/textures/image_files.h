#pragma once
// Writes test images with OpenImageIO: the project ships no image, so the
// tests make their own (8- and 16-bit PNG, float EXR, ...).

#include <OpenImageIO/imageio.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace raylab::testing {

/// Writes `values` (width × height × channels, row 0 at the top) to `path` in
/// the file's format, stored as `type` (UINT8, UINT16, HALF, FLOAT).
inline void writeImage(const std::string& path, int width, int height, int channels,
                       const std::vector<float>& values, OIIO::TypeDesc type) {
    auto out = OIIO::ImageOutput::create(path);
    if (!out) throw std::runtime_error("cannot create " + path);
    OIIO::ImageSpec spec(width, height, channels, type);
    if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, values.data()) ||
        !out->close())
        throw std::runtime_error("cannot write " + path + ": " + out->geterror());
}

}  // namespace raylab::testing
