#pragma once
// The image formats a render writes, chosen by the output name's extension
// (-o out.exr, -o out.png, ...; docs/output.md).

#include <optional>
#include <string>

namespace raylab {

enum class OutputFormat {
    Exr,   ///< .exr: every layer (exr_writer.h)
    Png,   ///< .png: 8-bit sRGB, tone-mapped (png_writer.h)
    Jpeg,  ///< .jpg, .jpeg: 8-bit sRGB, tone-mapped (OpenImageIO)
    Hdr,   ///< .hdr: Radiance RGBE, linear RGB (OpenImageIO)
    Tiff,  ///< .tif, .tiff: 32-bit float linear RGBA (OpenImageIO)
};

/// The format of `path` by its extension, in any letter case; nullopt for
/// any other name.
std::optional<OutputFormat> outputFormatOf(const std::string& path);

/// "OpenEXR", "PNG", "JPEG", "Radiance HDR", "TIFF".
const char* outputFormatName(OutputFormat format);

/// The accepted extensions, for messages: ".exr, .png, .jpg/.jpeg, .hdr, .tif/.tiff".
const char* outputExtensionList();

}  // namespace raylab
