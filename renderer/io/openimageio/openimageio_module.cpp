// raylab's OpenImageIO module (see renderer/io/image_module.h): the only
// source that includes OpenImageIO, built as raylab-openimageio.so and loaded
// on first use. Every entry point catches everything: nothing may be thrown
// across the dlopen boundary, and OpenImageIO may fail to start threads or
// allocate under a memory limit.

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <exception>
#include <memory>
#include <string>

#include "renderer/io/image_module.h"
#include "renderer/io/module_failure.h"

namespace {

using namespace raylab::image_module;

/// OpenImageIO's last message, on one line.
std::string oneLine(std::string e, const char* fallback) {
    while (!e.empty() && (e.back() == '\n' || e.back() == ' ')) e.pop_back();
    for (char& c : e)
        if (c == '\n') c = ' ';
    return e.empty() ? fallback : e;
}

class OiioImageFile final : public ImageFile {
public:
    explicit OiioImageFile(std::unique_ptr<OIIO::ImageInput> in) : m_in(std::move(in)) {
        const OIIO::ImageSpec& spec = m_in->spec();
        m_header.width = spec.width;
        m_header.height = spec.height;
        m_header.depth = spec.depth;
        m_header.channels = spec.nchannels;
        m_header.alphaChannel = spec.alpha_channel;
        m_header.floating = spec.format.is_floating_point();
        m_header.uint8 = spec.format == OIIO::TypeDesc::UINT8;
    }
    const ImageHeader& header() const override { return m_header; }
    bool readUint8(int channels, uint8_t* texels, std::string& error) override {
        return read(channels, OIIO::TypeDesc::UINT8, texels, error);
    }
    bool readFloat(int channels, float* texels, std::string& error) override {
        return read(channels, OIIO::TypeDesc::FLOAT, texels, error);
    }

private:
    bool read(int channels, OIIO::TypeDesc type, void* texels, std::string& error) {
        try {
            if (m_in->read_image(0, 0, 0, channels, type, texels)) return true;
            error = oneLine(m_in->geterror(), "broken image data");
        } catch (...) {
            error = raylab::describeFailure(std::current_exception());
        }
        return false;
    }
    std::unique_ptr<OIIO::ImageInput> m_in;
    ImageHeader m_header;
};

std::unique_ptr<ImageFile> openImage(const std::string& path, std::string& error) {
    try {
        // PNG and TIFF alpha is stored unassociated; keep it so, or
        // OpenImageIO would premultiply the colour of every partly
        // transparent texel.
        OIIO::ImageSpec config;
        config.attribute("oiio:UnassociatedAlpha", 1);
        auto in = OIIO::ImageInput::open(path, &config);
        if (!in) {
            error = oneLine(OIIO::geterror(), "unknown image format or broken file");
            return nullptr;
        }
        return std::make_unique<OiioImageFile>(std::move(in));
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
        return nullptr;
    }
}

bool writeFloat(const std::string& path, int width, int height, int channels,
                const float* pixels, std::string& error) {
    try {
        auto out = OIIO::ImageOutput::create(path);
        if (!out) {
            error = oneLine(OIIO::geterror(), "no writer for this file name");
            return false;
        }
        const OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
        if (out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels) &&
            out->close())
            return true;
        error = oneLine(out->geterror(), "cannot write the image");
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
    }
    return false;
}

OIIO::TextureOpt optionsFor(Filter filter) {
    OIIO::TextureOpt opt;
    opt.swrap = opt.twrap = OIIO::TextureOpt::WrapPeriodic;
    opt.interpmode = OIIO::TextureOpt::InterpBilinear;
    switch (filter) {
    case Filter::Point:
        opt.mipmode = OIIO::TextureOpt::MipModeNoMIP;
        opt.interpmode = OIIO::TextureOpt::InterpClosest;
        break;
    case Filter::Bilinear: opt.mipmode = OIIO::TextureOpt::MipModeNoMIP; break;
    case Filter::Trilinear: opt.mipmode = OIIO::TextureOpt::MipModeTrilinear; break;
    case Filter::Anisotropic:
        opt.mipmode = OIIO::TextureOpt::MipModeAniso;
        opt.anisotropic = 8;
        break;
    }
    return opt;
}

class OiioTextureSystemFile final : public TextureSystemFile {
public:
    explicit OiioTextureSystemFile(const std::string& path)
        : m_system(OIIO::TextureSystem::create(false)) {
        // Untiled files get their MIP levels built on first use, as a render would.
        m_system->attribute("automip", 1);
        m_system->attribute("accept_untiled", 1);
        m_handle = m_system->get_texture_handle(OIIO::ustring(path));
        m_thread = m_system->create_thread_info();
    }
    ~OiioTextureSystemFile() override {
        m_system->destroy_thread_info(m_thread);
        OIIO::TextureSystem::destroy(m_system);
    }
    void lookup(Filter filter, float s, float t, float dsdx, float dtdx, float dsdy, float dtdy,
                int channels, float* result) override {
        OIIO::TextureOpt opt = optionsFor(filter);
        m_system->texture(m_handle, m_thread, opt, s, t, dsdx, dtdx, dsdy, dtdy, channels,
                          result);
    }

private:
    OIIO::TextureSystem* m_system;
    OIIO::TextureSystem::TextureHandle* m_handle = nullptr;
    OIIO::TextureSystem::Perthread* m_thread = nullptr;
};

std::unique_ptr<TextureSystemFile> openTextureSystem(const std::string& path,
                                                     std::string& error) {
    try {
        return std::make_unique<OiioTextureSystemFile>(path);
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
        return nullptr;
    }
}

bool writeImage(const WriteRequest& r, std::string& error) {
    try {
        // Named by plug-in: the temporary file has no image extension.
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(r.format);
        if (!out) {
            error = oneLine(OIIO::geterror(), "no writer for this format");
            return false;
        }
        const OIIO::TypeDesc type = r.uint8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
        OIIO::ImageSpec spec(r.width, r.height, r.channels, type);
        spec.alpha_channel = r.alphaChannel;
        for (const auto& [name, value] : r.attributes) spec.attribute(name, value);
        if (!out->open(r.path, spec)) {
            error = oneLine(out->geterror(), "cannot create the file");
            return false;
        }
        if (!out->write_image(type, r.pixels)) {
            error = oneLine(out->geterror(), "cannot write the image");
            out->close();
            return false;
        }
        if (out->close()) return true;
        error = oneLine(out->geterror(), "cannot finish the file");
    } catch (...) {
        error = raylab::describeFailure(std::current_exception());
    }
    return false;
}

const Api kApi{kVersion, &openImage, &writeFloat, &openTextureSystem, &writeImage};

}  // namespace

extern "C" __attribute__((visibility("default"))) const Api* raylab_image_module_v1() {
    return &kApi;
}
