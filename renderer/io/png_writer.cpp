#include "renderer/io/png_writer.h"

#include <vector>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/png_memory.h"

namespace raylab {

void writePng(const std::string& path, const Film& film, double exposure, AtomicFileGroup* group) {
    if (film.width <= 0 || film.height <= 0)
        throw InputError(path, 0,
                         "cannot write PNG: empty image (" + std::to_string(film.width) + "x" +
                             std::to_string(film.height) + ")");
    const size_t n = size_t(film.width) * size_t(film.height);
    if (film.rgba.size() != n * 4)
        throw InputError(path, 0,
                         "cannot write PNG: film has " + std::to_string(film.rgba.size()) +
                             " RGBA values, expected " + std::to_string(n * 4));
    std::vector<unsigned char> bytes;
    try {
        bytes = encodePng(toneMappedImage(film, exposure));
    } catch (const std::exception& e) {
        throw InputError(path, 0, std::string("cannot write PNG: ") + e.what());
    }
    writeFileAtomically(path, bytes.data(), bytes.size(), group);
}

}  // namespace raylab
