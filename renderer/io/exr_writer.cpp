#include "renderer/io/exr_writer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>

#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/half_convert.h"

namespace raylab {

namespace {

using Imath::half;

constexpr float kFloatMax = std::numeric_limits<float>::max();

/// NaN -> 0, |v| > FLT_MAX -> ±FLT_MAX (that is, ±Inf).
float finiteClamp(float v) {
    if (std::isnan(v)) return 0.f;
    return v > kFloatMax ? kFloatMax : (v < -kFloatMax ? -kFloatMax : v);
}

/// Checks that an AOV vector is either absent (empty) or holds `expected` values.
void checkLayerSize(const std::string& path, const char* name, size_t size, size_t expected) {
    if (size != 0 && size != expected)
        throw InputError(path, 0,
                         std::string("cannot write EXR: film layer '") + name + "' has " +
                             std::to_string(size) + " values, expected " +
                             std::to_string(expected));
}

/// Whether v must change to be stored in a FLOAT channel: NaN, or an
/// infinity other than the "no hit" +inf of a depth layer.
bool needsFloatFix(float v, bool isDepth) {
    return std::isnan(v) || (std::isinf(v) && !(isDepth && v > 0));
}

/// The values to write for a FLOAT layer: `src` itself when it is already safe
/// (always, for a rendered film: this saves a copy of megabytes), else a safe
/// copy in `storage` (NaN -> 0, or +inf for depth; ±inf clamped to ±FLT_MAX
/// except depth's +inf), or `count` copies of `fallback` when src is empty.
const float* floatPlane(const FilmPlane& src, size_t count, float fallback, bool isDepth,
                        FilmPlane& storage) {
    constexpr float inf = std::numeric_limits<float>::infinity();
    if (src.empty()) {
        storage.assign(count, fallback);
        return storage.data();
    }
    bool safe = true;
    for (size_t i = 0; i < count && safe; ++i) safe = !needsFloatFix(src[i], isDepth);
    if (safe) return src.data();
    storage.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const float v = src[i];
        if (isDepth && (v == inf || std::isnan(v)))
            storage[i] = inf;
        else
            storage[i] = finiteClamp(v);
    }
    return storage.data();
}

using HalfPlane = std::vector<half, HugePageAllocator<half>>;

HalfPlane halfPlane(const FilmPlane& src, size_t count) {
    HalfPlane out(count, half(0.f));
    if (src.empty()) return out;
    static_assert(sizeof(half) == sizeof(uint16_t), "half is 16 bits");
    floatsToHalf(src.data(), reinterpret_cast<uint16_t*>(out.data()), count);
    return out;
}

Imf::Compression toImf(ExrCompression c) {
    switch (c) {
        case ExrCompression::None: return Imf::NO_COMPRESSION;
        case ExrCompression::Rle: return Imf::RLE_COMPRESSION;
        case ExrCompression::Zips: return Imf::ZIPS_COMPRESSION;
        case ExrCompression::Zip: return Imf::ZIP_COMPRESSION;
        case ExrCompression::Piz: return Imf::PIZ_COMPRESSION;
    }
    return Imf::ZIP_COMPRESSION;
}

/// Slice wants a mutable char pointer even for output.
template <class T>
char* bytes(const T* p) {
    return reinterpret_cast<char*>(const_cast<T*>(p));
}

/// The film's pixels in full-image coordinates.
Imath::Box2i exrDataWindow(const Film& film) {
    return Imath::Box2i({film.originX, film.originY},
                        {film.originX + film.width - 1, film.originY + film.height - 1});
}

/// A slice whose first element is the data window's top-left pixel
/// (OpenEXR addresses slices from pixel (0, 0) of the display window).
Imf::Slice sliceIn(const Imath::Box2i& dataWindow, Imf::PixelType type, char* first, size_t xStride,
                   size_t yStride) {
    return Imf::Slice::Make(type, first, dataWindow, xStride, yStride);
}

}  // namespace

void writeExr(const std::string& path, const Film& film, const ExrOptions& opts,
              AtomicFileGroup* group) {
    if (film.width <= 0 || film.height <= 0)
        throw InputError(path, 0,
                         "cannot write EXR: empty image (" + std::to_string(film.width) + "x" +
                             std::to_string(film.height) + ")");
    const size_t n = size_t(film.width) * size_t(film.height);
    if (film.rgba.size() != n * 4)
        throw InputError(path, 0,
                         "cannot write EXR: film has " + std::to_string(film.rgba.size()) +
                             " RGBA values, expected " + std::to_string(n * 4));
    checkLayerSize(path, "depth", film.depth.size(), n);
    checkLayerSize(path, "normal", film.normal.size(), n * 3);
    checkLayerSize(path, "albedo", film.albedo.size(), n * 3);
    checkLayerSize(path, "objectId", film.objectId.size(), n);

    // Planes to write; interleaved layers keep the Film's layout and use strides.
    const Imf::PixelType rgbaType = opts.floatPixels ? Imf::FLOAT : Imf::HALF;
    FilmPlane rgbaCopy, zCopy, normalCopy, objectIdCopy;
    const float* rgbaF =
        opts.floatPixels ? floatPlane(film.rgba, n * 4, 0.f, false, rgbaCopy) : nullptr;
    HalfPlane rgbaH;
    if (!opts.floatPixels) rgbaH = halfPlane(film.rgba, n * 4);
    const float* z =
        floatPlane(film.depth, n, std::numeric_limits<float>::infinity(), true, zCopy);
    const float* normal = floatPlane(film.normal, n * 3, 0.f, false, normalCopy);
    HalfPlane albedo = halfPlane(film.albedo, n * 3);
    const float* objectId = floatPlane(film.objectId, n, -1.f, false, objectIdCopy);

    // A crop render is the data window inside the full image's display window.
    const Imath::Box2i dataWindow = exrDataWindow(film);
    Imf::Header header(Imath::Box2i({0, 0}, {film.displayWidth() - 1, film.displayHeight() - 1}),
                       dataWindow);
    header.compression() = toImf(opts.compression);
    header.insert("raylab/command", Imf::StringAttribute(opts.commandLine));
    header.insert("raylab/spp", Imf::IntAttribute(opts.spp));
    header.insert("raylab/maxDepth", Imf::IntAttribute(opts.maxDepth));
    if (!opts.scenePath.empty())
        header.insert("raylab/scene", Imf::StringAttribute(opts.scenePath));
    if (!opts.accel.empty()) header.insert("raylab/accel", Imf::StringAttribute(opts.accel));

    Imf::ChannelList& channels = header.channels();
    Imf::FrameBuffer fb;
    const size_t w = size_t(film.width);
    const char* rgbaNames[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        channels.insert(rgbaNames[c], Imf::Channel(rgbaType));
        if (opts.floatPixels)
            fb.insert(rgbaNames[c], sliceIn(dataWindow, Imf::FLOAT, bytes(rgbaF + c),
                                               4 * sizeof(float), 4 * sizeof(float) * w));
        else
            fb.insert(rgbaNames[c], sliceIn(dataWindow, Imf::HALF, bytes(rgbaH.data() + c),
                                               4 * sizeof(half), 4 * sizeof(half) * w));
    }
    channels.insert("Z", Imf::Channel(Imf::FLOAT));
    fb.insert("Z", sliceIn(dataWindow, Imf::FLOAT, bytes(z), sizeof(float), sizeof(float) * w));
    const char* normalNames[3] = {"N.X", "N.Y", "N.Z"};
    const char* albedoNames[3] = {"albedo.R", "albedo.G", "albedo.B"};
    for (int c = 0; c < 3; ++c) {
        channels.insert(normalNames[c], Imf::Channel(Imf::FLOAT));
        fb.insert(normalNames[c], sliceIn(dataWindow, Imf::FLOAT, bytes(normal + c),
                                             3 * sizeof(float), 3 * sizeof(float) * w));
        channels.insert(albedoNames[c], Imf::Channel(Imf::HALF));
        fb.insert(albedoNames[c], sliceIn(dataWindow, Imf::HALF, bytes(albedo.data() + c),
                                             3 * sizeof(half), 3 * sizeof(half) * w));
    }
    channels.insert("objectId", Imf::Channel(Imf::FLOAT));
    fb.insert("objectId", sliceIn(dataWindow, Imf::FLOAT, bytes(objectId), sizeof(float),
                                     sizeof(float) * w));

    // Compression dominates the write; blocks are compressed in parallel
    // but always written in scan-line order, so the bytes stay deterministic.
    const int threads =
        opts.threads > 0 ? opts.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // OpenEXR runs compression tasks on its global pool (empty by default, i.e.
    // everything on the calling thread); the per-file count alone adds no workers.
    if (Imf::globalThreadCount() < threads) Imf::setGlobalThreadCount(threads);
    writeFileAtomically(path, [&](const std::string& tmp) {
        // The OutputFile is closed (offset table written) when it goes out of
        // scope, before writeFileAtomically renames the file.
        Imf::OutputFile file(tmp.c_str(), header, threads);
        file.setFrameBuffer(fb);
        file.writePixels(film.height);  // every scan line of the data window
    }, group);
}

}  // namespace raylab
