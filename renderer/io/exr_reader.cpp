#include "renderer/io/exr_reader.h"

#include <algorithm>
#include <exception>
#include <new>
#include <optional>
#include <vector>

#include "renderer/io/errors.h"
#include "renderer/io/exr_module_loader.h"

namespace raylab {

namespace {

// Refuse absurd data windows before allocating (a corrupt header could ask
// for terabytes): 2^28 pixels is 16k x 16k.
constexpr long long kMaxPixels = 1LL << 28;

/// FLOAT slices for `names` into `data` (interleaved, `names.size()` per
/// pixel) when at least one of the channels exists; the layer is left empty
/// otherwise. Absent channels of a present layer are filled with `fill` by
/// OpenEXR.
void addLayer(std::vector<exr_module::Slice>& slices, const std::vector<std::string>& present,
              std::vector<const char*> names, FilmPlane& data, size_t pixels, size_t width,
              double fill) {
    const bool any = std::any_of(names.begin(), names.end(), [&](const char* name) {
        return std::find(present.begin(), present.end(), name) != present.end();
    });
    if (!any) {
        data.clear();
        return;
    }
    const size_t k = names.size();
    data.assign(pixels * k, float(fill));
    for (size_t c = 0; c < k; ++c)
        slices.push_back({names[c], 2, reinterpret_cast<char*>(data.data() + c),
                          ptrdiff_t(k * sizeof(float)), ptrdiff_t(k * sizeof(float) * width), fill});
}

}  // namespace

Film readExr(const std::string& path) {
    const exr_module::Api* openExr = nullptr;
    try {
        openExr = &exrModule();
    } catch (const ExrModuleUnavailable& e) {
        throw InputError(path, 0, std::string("cannot read EXR: ") + e.what());
    }
    Film film;
    std::optional<std::string> refused;  // a window refused, or no memory for it
    const auto slicesOf = [&](const exr_module::ReadInfo& info) {
        std::vector<exr_module::Slice> slices;
        const long long w = (long long)info.dataWindow[2] - info.dataWindow[0] + 1;
        const long long h = (long long)info.dataWindow[3] - info.dataWindow[1] + 1;
        if (w <= 0 || h <= 0 || w * h > kMaxPixels) {
            refused = "unsupported EXR data window " + std::to_string(w) + "x" + std::to_string(h);
            return slices;
        }
        film.width = int(w);
        film.height = int(h);
        // A crop render's data window inside the display window.
        film.originX = info.dataWindow[0] - info.displayWindow[0];
        film.originY = info.dataWindow[1] - info.displayWindow[1];
        film.fullWidth = info.displayWindow[2] - info.displayWindow[0] + 1;
        film.fullHeight = info.displayWindow[3] - info.displayWindow[1] + 1;
        const size_t n = size_t(w) * size_t(h);
        // RGBA is always present in the Film. Missing colour reads as black,
        // missing alpha as opaque (OpenEXR's convention).
        film.rgba.assign(n * 4, 0.f);
        const char* rgbaNames[4] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            slices.push_back({rgbaNames[c], 2, reinterpret_cast<char*>(film.rgba.data() + c),
                              ptrdiff_t(4 * sizeof(float)), ptrdiff_t(4 * sizeof(float) * size_t(w)),
                              c == 3 ? 1.0 : 0.0});
        const std::vector<std::string>& present = info.channels;
        addLayer(slices, present, {"Z"}, film.z, n, size_t(w), 0.0);
        addLayer(slices, present, {"distance"}, film.distance, n, size_t(w), 0.0);
        addLayer(slices, present, {"N.X", "N.Y", "N.Z"}, film.normal, n, size_t(w), 0.0);
        addLayer(slices, present, {"albedo.R", "albedo.G", "albedo.B"}, film.albedo, n, size_t(w),
                 0.0);
        addLayer(slices, present, {"objectId"}, film.objectId, n, size_t(w), 0.0);
        return slices;
    };
    // Nothing is thrown across the module's boundary (exr_module.h): a
    // failure here is reported once the module has returned.
    const exr_module::SlicesFor slicesFor = [&](const exr_module::ReadInfo& info) {
        try {
            return slicesOf(info);
        } catch (const std::bad_alloc&) {
            refused = "cannot read EXR: out of memory for its pixels";
        } catch (const std::exception& e) {
            refused = std::string("cannot read EXR: ") + e.what();
        }
        return std::vector<exr_module::Slice>{};
    };
    std::string error;
    // OpenEXR reports missing files and corrupt data as its exceptions: the
    // module returns their text.
    if (!openExr->read(path, slicesFor, error))
        throw InputError(path, 0, "cannot read EXR: " + error);
    if (refused) throw InputError(path, 0, *refused);
    return film;
}

}  // namespace raylab
