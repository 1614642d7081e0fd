#pragma once
// The narrow interface between raylab and its OpenImageIO module
// (raylab-openimageio.so, built from renderer/io/openimageio/). OpenImageIO
// brings about twenty shared libraries (GDAL, ICU, ...): some 450 MiB of
// address space and a few hundred milliseconds of start-up, which a render
// without image textures must not pay, nor fail on under `ulimit -v`. So the
// module is loaded with dlopen on first use (image_module_loader.h) and every
// other run starts without it.
//
// Only standard-library types cross this boundary (raylab and the module are
// built together, by the same compiler), and nothing is thrown across it:
// failures come back as text.

#include <cstdint>
#include <memory>
#include <string>

namespace raylab::image_module {

/// Bumped whenever anything below changes shape.
constexpr int kVersion = 1;
/// The module's one exported symbol: `extern "C" const Api* raylab_image_module_v1()`.
constexpr const char* kEntryPoint = "raylab_image_module_v1";

struct ImageHeader {
    int width = 0, height = 0, depth = 1;
    int channels = 0;       ///< in the file
    int alphaChannel = -1;  ///< -1: none
    bool floating = false;  ///< half, float or double samples
    bool uint8 = false;     ///< 8-bit unsigned samples
};

/// An opened image file: its header first, then its pixels (subimage 0,
/// full resolution, channels 0..channels-1, rows top to bottom). Alpha is
/// kept unassociated, as PNG and TIFF store it.
class ImageFile {
public:
    virtual ~ImageFile() = default;
    virtual const ImageHeader& header() const = 0;
    virtual bool readUint8(int channels, uint8_t* texels, std::string& error) = 0;
    virtual bool readFloat(int channels, float* texels, std::string& error) = 0;
};

/// OpenImageIO's own filtered lookups (its TextureSystem) on one file, the
/// yardstick `raylab bench textures` measures raylab's MIP pyramid against.
enum class Filter { Point, Bilinear, Trilinear, Anisotropic };
class TextureSystemFile {
public:
    virtual ~TextureSystemFile() = default;
    /// Periodic wrap; OpenImageIO's t runs down the image.
    virtual void lookup(Filter filter, float s, float t, float dsdx, float dtdx, float dsdy,
                        float dtdy, int channels, float* result) = 0;
};

struct Api {
    int version = kVersion;
    /// nullptr (and `error` set) when the file cannot be opened or read.
    std::unique_ptr<ImageFile> (*open)(const std::string& path, std::string& error) = nullptr;
    /// Writes width × height × channels floats in the format of the path's extension.
    bool (*writeFloat)(const std::string& path, int width, int height, int channels,
                       const float* pixels, std::string& error) = nullptr;
    std::unique_ptr<TextureSystemFile> (*openTextureSystem)(const std::string& path,
                                                            std::string& error) = nullptr;
};

}  // namespace raylab::image_module
