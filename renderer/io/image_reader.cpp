#include "renderer/io/image_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/io/errors.h"
#include "renderer/io/image_module_loader.h"
#include "renderer/io/text_file.h"
#include "shading/srgb.h"

namespace raylab {

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
    // OpenImageIO is loaded here, by the first texture a scene reads.
    const image_module::Api* codecs = nullptr;
    try {
        codecs = &imageModule(path);
    } catch (const ImageModuleUnavailable& e) {
        throw InputError(path, 0, std::string("cannot read image: ") + e.what());
    }
    std::string error;
    const std::unique_ptr<image_module::ImageFile> in = codecs->open(path, error);
    if (!in) throw InputError(path, 0, "cannot read image: " + error);
    const image_module::ImageHeader& spec = in->header();
    ImageData image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(spec.channels, 4);
    if (spec.width < 1 || spec.height < 1 || spec.channels < 1 || spec.depth > 1)
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
                                      describeBytes(bytes) + ", more than the " +
                                      describeBytes(limit->bytes) + " that " + limit->source);

    const size_t count = size_t(image.width) * size_t(image.height) * size_t(image.channels);
    image.texels.resize(count);
    image.srgbDecoded = role == ImageRole::Color && !spec.floating;
    const int alpha = spec.alphaChannel;
    if (image.srgbDecoded && spec.uint8) {
        // 8-bit codes go through the exact 256-entry table.
        std::vector<uint8_t> codes(count);
        if (!in->readUint8(image.channels, codes.data(), error))
            throw InputError(path, 0, "cannot read image: " + error);
        const float* table = srgb8ToLinearTable();
        for (size_t i = 0; i < count; ++i) {
            const int c = int(i % size_t(image.channels));
            image.texels[i] = c == alpha ? codes[i] / 255.0f : table[codes[i]];
        }
        return image;
    }
    if (!in->readFloat(image.channels, image.texels.data(), error))
        throw InputError(path, 0, "cannot read image: " + error);
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
