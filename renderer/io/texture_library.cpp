#include "renderer/io/texture_library.h"

#include <filesystem>
#include <system_error>

#include "renderer/io/errors.h"

namespace raylab {

TextureLibrary::TextureLibrary(LimitSource limit) : m_limit(std::move(limit)) {
    if (!m_limit) m_limit = [] { return tightestMemoryLimit(readMemoryFacts()); };
}

TextureLibrary::Result TextureLibrary::load(const std::string& path, ImageRole role) {
    // One entry per file, however a scene spells its path.
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    const std::string key = ec ? path : canonical.string();
    auto [it, inserted] = m_images.try_emplace({key, role});
    Result& entry = it->second;
    if (!inserted) {
        Result again = entry;
        again.firstFailure = false;
        return again;
    }
    try {
        ImageData image = readImage(path, role, m_limit());
        auto mip = std::make_shared<const MipMap>(image.width, image.height, image.channels,
                                                  std::move(image.texels));
        m_bytes += double(mip->bytes());
        entry.image = std::move(mip);
    } catch (const InputError& e) {
        entry.error = e.located();
        entry.firstFailure = true;
    }
    return entry;
}

}  // namespace raylab
