#include "renderer/io/oiio_writer.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "renderer/io/errors.h"
#include "renderer/io/png_writer.h"

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

}  // namespace

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

    const bool eightBit = format == OutputFormat::Jpeg;
    const int channels = format == OutputFormat::Tiff ? 4 : 3;
    OIIO::ImageSpec spec(film.width, film.height, channels,
                         eightBit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    std::vector<uint8_t> bytes;
    std::vector<float> floats;
    if (eightBit) {
        bytes.resize(n * 3);
        for (size_t i = 0; i < n; ++i) {
            const float* c = &film.rgba[4 * i];
            const auto rgb = toneMapSrgb8(c[0], c[1], c[2], exposure);
            std::copy(rgb.begin(), rgb.end(), bytes.begin() + std::ptrdiff_t(3 * i));
        }
        spec.attribute("oiio:ColorSpace", "sRGB");
        spec.attribute("Compression", "jpeg:95");
    } else {
        floats.resize(n * size_t(channels));
        for (size_t i = 0; i < n; ++i)
            for (int c = 0; c < channels; ++c) {
                float v = film.rgba[4 * i + size_t(c)];
                if (!std::isfinite(v)) v = 0.f;  // defensive: the film is finite
                if (format == OutputFormat::Hdr) v = std::max(v, 0.f);
                floats[i * size_t(channels) + size_t(c)] = v;
            }
        spec.attribute("oiio:ColorSpace", "linear");
        if (format == OutputFormat::Tiff) {
            spec.alpha_channel = 3;
            spec.attribute("Compression", "zip");
        }
    }
    if (!software.empty()) spec.attribute("Software", software);
    // OpenImageIO's TIFF writer stamps the current time unless DateTime is
    // set; an empty one is left out, so the same render writes the same bytes.
    spec.attribute("DateTime", "");

    writeFileAtomically(path, [&](const std::string& tmp) {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(plugin);
        if (!out) throw InputError("OpenImageIO has no " + std::string(plugin) + " writer: " +
                                   OIIO::geterror());
        if (!out->open(tmp, spec)) throw InputError("OpenImageIO: " + out->geterror());
        const bool ok = eightBit ? out->write_image(OIIO::TypeDesc::UINT8, bytes.data())
                                 : out->write_image(OIIO::TypeDesc::FLOAT, floats.data());
        if (!ok) {
            const std::string message = out->geterror();
            out->close();
            throw InputError("OpenImageIO: " + message);
        }
        if (!out->close()) throw InputError("OpenImageIO: " + out->geterror());
    }, group);
}

}  // namespace raylab
