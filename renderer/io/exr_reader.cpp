#include "renderer/io/exr_reader.h"

#include <exception>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>

#include "renderer/io/errors.h"

namespace raylab {

namespace {

// Refuse absurd data windows before allocating (a corrupt header could ask
// for terabytes): 2^28 pixels is 16k x 16k.
constexpr long long kMaxPixels = 1LL << 28;

/// Adds FLOAT slices for `names` into `data` (interleaved, `names.size()` per
/// pixel) when at least one of the channels exists; returns whether it did.
/// Absent channels of a present layer are filled with `fill` by OpenEXR.
bool addLayer(Imf::FrameBuffer& fb, const Imf::Header& header, const Imath::Box2i& dw,
              std::vector<const char*> names, FilmPlane& data, size_t pixels,
              double fill) {
    bool any = false;
    for (const char* name : names) any = any || header.channels().findChannel(name) != nullptr;
    if (!any) {
        data.clear();
        return false;
    }
    const size_t k = names.size();
    data.assign(pixels * k, float(fill));
    for (size_t c = 0; c < k; ++c)
        fb.insert(names[c], Imf::Slice::Make(Imf::FLOAT, data.data() + c, dw, k * sizeof(float),
                                             k * sizeof(float) * size_t(dw.max.x - dw.min.x + 1),
                                             1, 1, fill));
    return true;
}

}  // namespace

Film readExr(const std::string& path) {
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i dw = header.dataWindow();
        const long long w = (long long)dw.max.x - dw.min.x + 1;
        const long long h = (long long)dw.max.y - dw.min.y + 1;
        if (w <= 0 || h <= 0 || w * h > kMaxPixels)
            throw InputError(path, 0,
                             "unsupported EXR data window " + std::to_string(w) + "x" +
                                 std::to_string(h));
        Film film;
        film.width = int(w);
        film.height = int(h);
        // A crop render's data window inside the display window.
        const Imath::Box2i display = header.displayWindow();
        film.originX = dw.min.x - display.min.x;
        film.originY = dw.min.y - display.min.y;
        film.fullWidth = display.max.x - display.min.x + 1;
        film.fullHeight = display.max.y - display.min.y + 1;
        const size_t n = size_t(w) * size_t(h);

        Imf::FrameBuffer fb;
        // RGBA is always present in the Film. Missing colour reads as black,
        // missing alpha as opaque (OpenEXR's convention).
        film.rgba.assign(n * 4, 0.f);
        const char* rgbaNames[4] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            fb.insert(rgbaNames[c],
                      Imf::Slice::Make(Imf::FLOAT, film.rgba.data() + c, dw, 4 * sizeof(float),
                                       4 * sizeof(float) * size_t(w), 1, 1, c == 3 ? 1.0 : 0.0));
        addLayer(fb, header, dw, {"Z"}, film.z, n, 0.0);
        addLayer(fb, header, dw, {"distance"}, film.distance, n, 0.0);
        addLayer(fb, header, dw, {"N.X", "N.Y", "N.Z"}, film.normal, n, 0.0);
        addLayer(fb, header, dw, {"albedo.R", "albedo.G", "albedo.B"}, film.albedo, n, 0.0);
        addLayer(fb, header, dw, {"objectId"}, film.objectId, n, 0.0);

        file.setFrameBuffer(fb);
        file.readPixels(dw.min.y, dw.max.y);
        return film;
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& e) {
        // OpenEXR reports missing files and corrupt data as Iex exceptions.
        throw InputError(path, 0, std::string("cannot read EXR: ") + e.what());
    }
}

}  // namespace raylab
