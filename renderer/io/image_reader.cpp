#include "renderer/io/image_reader.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/io/errors.h"
#include "renderer/io/text_file.h"
#include "shading/srgb.h"

namespace raylab {

namespace {

std::string mib(double bytes) { return std::to_string(int64_t(bytes / (1 << 20))); }

/// OpenImageIO's last message, on one line.
std::string oiioError(const OIIO::ImageInput* in) {
    std::string e = in ? in->geterror() : OIIO::geterror();
    while (!e.empty() && (e.back() == '\n' || e.back() == ' ')) e.pop_back();
    for (char& c : e)
        if (c == '\n') c = ' ';
    return e.empty() ? "unknown image format or broken file" : e;
}

}  // namespace

double textureBytes(int width, int height, int channels) {
    return double(width) * double(height) * double(channels) * sizeof(float) * 4.0 / 3.0;
}

ImageData readImage(const std::string& path, ImageRole role,
                    const std::optional<MemoryLimit>& limit) {
    // Devices, FIFOs (which would block), directories, missing files and files
    // beyond the input size limit never reach a decoder. The bytes are read
    // here once so the file is recorded as an input of the run by identity
    // and content (outputs may not overwrite it; MPI ranks compare it).
    (void)readTextFile(path);
    // PNG and TIFF alpha is stored unassociated; keep it so, or OpenImageIO
    // would premultiply the colour of every partly transparent texel.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) throw InputError(path, 0, "cannot read image: " + oiioError(nullptr));
    const OIIO::ImageSpec& spec = in->spec();
    ImageData image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(spec.nchannels, 4);
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.depth > 1)
        throw InputError(path, 0, "cannot read image: not a 2D image with pixels");
    if (spec.width > kMaxTextureSide || spec.height > kMaxTextureSide)
        throw InputError(path, 0, "image is " + std::to_string(spec.width) + "x" +
                                      std::to_string(spec.height) + ", larger than " +
                                      std::to_string(kMaxTextureSide) + " texels on a side");
    const double bytes = textureBytes(image.width, image.height, image.channels);
    if (limit && bytes > limit->bytes)
        throw InputError(path, 0, "a " + std::to_string(image.width) + "x" +
                                      std::to_string(image.height) + " texture of " +
                                      std::to_string(image.channels) + " channels needs about " +
                                      mib(bytes) + " MiB, more than the " + mib(limit->bytes) +
                                      " MiB that " + limit->source + " allows");

    const size_t count = size_t(image.width) * size_t(image.height) * size_t(image.channels);
    image.texels.resize(count);
    image.srgbDecoded = role == ImageRole::Color && !spec.format.is_floating_point();
    const int alpha = spec.alpha_channel;
    if (image.srgbDecoded && spec.format == OIIO::TypeDesc::UINT8) {
        // 8-bit codes go through the exact 256-entry table.
        std::vector<uint8_t> codes(count);
        if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT8, codes.data()))
            throw InputError(path, 0, "cannot read image: " + oiioError(in.get()));
        const float* table = srgb8ToLinearTable();
        for (size_t i = 0; i < count; ++i) {
            const int c = int(i % size_t(image.channels));
            image.texels[i] = c == alpha ? codes[i] / 255.0f : table[codes[i]];
        }
        return image;
    }
    if (!in->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.texels.data()))
        throw InputError(path, 0, "cannot read image: " + oiioError(in.get()));
    for (size_t i = 0; i < count; ++i) {
        float& v = image.texels[i];
        // No NaN or Inf may reach a pixel, nor a negative reflectance.
        if (!std::isfinite(v) || (role == ImageRole::Color && v < 0)) v = 0;
        if (image.srgbDecoded && int(i % size_t(image.channels)) != alpha)
            v = float(srgbToLinear(double(v)));
    }
    return image;
}

}  // namespace raylab
