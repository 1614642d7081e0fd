#pragma once
// Texture images read through OpenImageIO (PNG, JPEG, TGA, TIFF, BMP, HDR,
// EXR, ...; 8/16-bit and float; 1-4 channels) as linear floats, row 0 at the
// top. Colour maps stored as integers (8- or 16-bit) are sRGB-encoded and are
// decoded here, before any filtering; float images and data maps (bump,
// normal, exponent, alpha) are taken as stored. Alpha is read unassociated
// (as stored), never premultiplied into the colour.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "renderer/memory_limit.h"

namespace raylab {

/// How a file's values are meant.
enum class ImageRole {
    Color,  ///< reflectance: integer formats are sRGB-decoded
    Data,   ///< heights, normals, exponents: values as stored
};

struct ImageData {
    int width = 0, height = 0, channels = 0;  ///< channels: the file's first 1..4
    std::vector<float> texels;                ///< width × height × channels, row 0 at the top
    bool srgbDecoded = false;
};

/// Largest texture side raylab reads (as for rendered images).
constexpr int kMaxTextureSide = 65536;

/// Bytes the MIP pyramid of a width × height × channels image takes (4/3 of
/// its float texels).
double textureBytes(int width, int height, int channels);

/// Reads `path`. Refuses, before decoding any pixel, a file that is not a
/// regular file, larger than 1 GiB, or whose pyramid would not fit in `limit`
/// (the memory guard's bound; nullopt: nothing known). Throws
/// InputError(path, 0, reason) for those and for anything OpenImageIO cannot read.
ImageData readImage(const std::string& path, ImageRole role,
                    const std::optional<MemoryLimit>& limit);

}  // namespace raylab
