#pragma once
// The texture files of one scene: each file is read once per role and its
// MIP pyramid shared by every material that names it (JSON materials and the
// MTL libraries of every mesh alike). Failures are remembered too, so a
// missing file named by ten materials is reported once.

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "renderer/io/image_reader.h"
#include "shading/mipmap.h"

namespace raylab {

class TextureLibrary {
public:
    /// Where the memory bound comes from (the memory guard's tightest limit
    /// by default; tests inject their own).
    using LimitSource = std::function<std::optional<MemoryLimit>()>;
    explicit TextureLibrary(LimitSource limit = {});

    struct Result {
        std::shared_ptr<const MipMap> image;  ///< null when the file could not be read
        std::string error;                    ///< why not: "FILE: reason"
        bool firstFailure = false;            ///< the first request to fail on this file
    };
    /// The pyramid of `path` read in `role`, from the file on first use.
    Result load(const std::string& path, ImageRole role);

    size_t fileCount() const { return m_images.size(); }
    /// Bytes of every pyramid read so far.
    double bytes() const { return m_bytes; }

private:
    LimitSource m_limit;
    std::map<std::pair<std::string, ImageRole>, Result> m_images;
    double m_bytes = 0;
};

}  // namespace raylab
