#include "renderer/io/output_format.h"

#include <cctype>

namespace raylab {

std::optional<OutputFormat> outputFormatOf(const std::string& path) {
    const size_t dot = path.find_last_of("./");
    if (dot == std::string::npos || path[dot] != '.' || dot == 0 || path[dot - 1] == '/')
        return std::nullopt;  // no extension, or a hidden file's name alone (".exr")
    std::string ext = path.substr(dot + 1);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == "exr") return OutputFormat::Exr;
    if (ext == "png") return OutputFormat::Png;
    if (ext == "jpg" || ext == "jpeg") return OutputFormat::Jpeg;
    if (ext == "hdr") return OutputFormat::Hdr;
    if (ext == "tif" || ext == "tiff") return OutputFormat::Tiff;
    return std::nullopt;
}

const char* outputFormatName(OutputFormat format) {
    switch (format) {
        case OutputFormat::Exr: return "OpenEXR";
        case OutputFormat::Png: return "PNG";
        case OutputFormat::Jpeg: return "JPEG";
        case OutputFormat::Hdr: return "Radiance HDR";
        case OutputFormat::Tiff: return "TIFF";
    }
    return "?";
}

const char* outputExtensionList() { return ".exr, .png, .jpg/.jpeg, .hdr, .tif/.tiff"; }

}  // namespace raylab
