#include "renderer/io/oiio_writer.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "renderer/io/errors.h"
#include "renderer/io/image_module_loader.h"
#include "renderer/io/srgb8_encoder.h"

namespace raylab {

namespace {

/// OpenImageIO's name of the plug-in that writes `format`: the temporary file
/// has no image extension, so the format is named rather than guessed.
const char* oiioFormat(OutputFormat format) {
    switch (format) {
        case OutputFormat::Jpeg: return "jpeg";
        case OutputFormat::Hdr: return "hdr";
        case OutputFormat::Tiff: return "tiff";
        default: return nullptr;
    }
}

/// OpenImageIO's module, loaded now if it is not yet (image_module.h): EXR and
/// PNG renders never map it.
const image_module::Api& oiioWriter(const std::string& path, OutputFormat format) {
    const image_module::Api* oiio = nullptr;
    try {
        oiio = &imageModule();
    } catch (const ImageModuleUnavailable& e) {
        throw InputError(path, 0,
                         std::string("cannot write ") + outputFormatName(format) + ": " + e.what());
    }
    if (!oiio->write)
        throw InputError(path, 0, std::string("cannot write ") + outputFormatName(format) +
                                      ": the OpenImageIO module has no writer");
    return *oiio;
}

}  // namespace

void prepareOiioImageWriter(const std::string& path, OutputFormat format) {
    (void)oiioWriter(path, format);
}

void writeOiioImage(const std::string& path, const Film& film, OutputFormat format,
                    double exposure, const std::string& software, AtomicFileGroup* group) {
    const char* plugin = oiioFormat(format);
    if (!plugin)
        throw InputError(path, 0, std::string("cannot write ") + outputFormatName(format) +
                                      " through OpenImageIO");
    if (film.width <= 0 || film.height <= 0)
        throw InputError(path, 0,
                         std::string("cannot write ") + outputFormatName(format) +
                             ": empty image (" + std::to_string(film.width) + "x" +
                             std::to_string(film.height) + ")");
    const size_t n = size_t(film.width) * size_t(film.height);
    if (film.rgba.size() != n * 4)
        throw InputError(path, 0,
                         std::string("cannot write ") + outputFormatName(format) + ": film has " +
                             std::to_string(film.rgba.size()) + " RGBA values, expected " +
                             std::to_string(n * 4));

    const image_module::Api* oiio = &oiioWriter(path, format);

    const bool eightBit = format == OutputFormat::Jpeg;
    const int channels = format == OutputFormat::Tiff ? 4 : 3;
    image_module::WriteRequest request;
    request.format = plugin;
    request.width = film.width;
    request.height = film.height;
    request.channels = channels;
    request.uint8 = eightBit;
    auto& attributes = request.attributes;
    std::vector<uint8_t> bytes;
    std::vector<float> floats;
    if (eightBit) {
        bytes = toneMappedImage(film, exposure).pixels;
        attributes.push_back({"oiio:ColorSpace", "sRGB"});
        attributes.push_back({"Compression", "jpeg:95"});
        request.pixels = bytes.data();
    } else {
        floats.resize(n * size_t(channels));
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < channels; ++c) {
                float v = film.rgba[4 * i + size_t(c)];
                if (!std::isfinite(v)) v = 0.f;  // defensive: the film is finite
                if (format == OutputFormat::Hdr) v = std::max(v, 0.f);
                floats[i * size_t(channels) + size_t(c)] = v;
            }
        attributes.push_back({"oiio:ColorSpace", "linear"});
        if (format == OutputFormat::Tiff) {
            request.alphaChannel = 3;
            attributes.push_back({"Compression", "zip"});
        }
        request.pixels = floats.data();
    }
    if (!software.empty()) attributes.push_back({"Software", software});
    // OpenImageIO's TIFF writer stamps the current time unless DateTime is
    // set; an empty one is left out, so the same render writes the same bytes.
    attributes.push_back({"DateTime", ""});

    writeFileAtomically(path, [&](const std::string& tmp) {
        request.path = tmp;
        std::string error;
        if (!oiio->write(request, error)) throw InputError("OpenImageIO: " + error);
    }, group);
}

}  // namespace raylab
