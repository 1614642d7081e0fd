#include "renderer/io/exr_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_invoke.h>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_planes.h"
#include "renderer/io/exr_header.h"
#include "renderer/io/exr_module_loader.h"
#include "renderer/io/exr_zip_file.h"
#include "renderer/thread_arena.h"

namespace raylab {

namespace {


/// Checks that an AOV vector is either absent (empty) or holds `expected` values.
void checkLayerSize(const std::string& path, const char* name, size_t size, size_t expected) {
    if (size != 0 && size != expected)
        throw InputError(path, 0,
                         std::string("cannot write EXR: film layer '") + name + "' has " +
                             std::to_string(size) + " values, expected " +
                             std::to_string(expected));
}

/// A camera matrix as the file's m44f attribute holds it.
void setMatrix(ExrHeader& header, const std::string& name, const Matrix44& m) {
    float f[4][4];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) f[i][j] = float(m[size_t(i)][size_t(j)]);
    header.setM44f(name, f);
}

ExrCompressionId compressionId(ExrCompression c) {
    switch (c) {
        case ExrCompression::None: return ExrCompressionId::None;
        case ExrCompression::Rle: return ExrCompressionId::Rle;
        case ExrCompression::Zips: return ExrCompressionId::Zips;
        case ExrCompression::Zip: return ExrCompressionId::Zip;
        case ExrCompression::Piz: return ExrCompressionId::Piz;
    }
    return ExrCompressionId::Zip;
}

/// The film's pixels in full-image coordinates.
ExrBox exrDataWindow(const Film& film) {
    return {film.originX, film.originY, film.originX + film.width - 1,
            film.originY + film.height - 1};
}

/// Whether raylab writes files of this compression itself (ZIP, ZIPS), or
/// through OpenEXR's module.
bool writtenByRaylab(ExrCompression c) {
    return c == ExrCompression::Zip || c == ExrCompression::Zips;
}

/// The OpenEXR module, loaded now if it is not yet (exr_module.h): ZIP and
/// ZIPS files never map it.
const exr_module::Api& openExrWriter(const std::string& path) {
    try {
        return exrModule();
    } catch (const ExrModuleUnavailable& e) {
        throw InputError(path, 0, std::string("cannot write EXR: ") + e.what());
    }
}

/// The planes of ExrPlanes a channel can come from.
enum class Plane { RgbaF, RgbaH, Z, Distance, Normal, Albedo, ObjectId, Crypto };

/// One channel of the file: value `component` of the `components` that
/// plane `plane` holds per pixel.
struct FilmChannel {
    std::string name;
    ExrPixelType type;
    Plane plane;
    int component;
    int components;
};

/// Where channel `c`'s values are in `planes` (`width` pixels per line).
ExrChannelSource sourceOf(const FilmChannel& c, const ExrPlanes& planes, size_t width) {
    const void* data = nullptr;
    switch (c.plane) {
        case Plane::RgbaF: data = planes.rgbaF; break;
        case Plane::RgbaH: data = planes.rgbaH; break;
        case Plane::Z: data = planes.z; break;
        case Plane::Distance: data = planes.distance; break;
        case Plane::Normal: data = planes.normal; break;
        case Plane::Albedo: data = planes.albedo; break;
        case Plane::ObjectId: data = planes.objectId; break;
        case Plane::Crypto: data = planes.crypto; break;
    }
    ExrChannelSource s;
    s.size = exrPixelTypeSize(c.type);
    s.base = static_cast<const char*>(data) + s.size * size_t(c.component);
    s.xStride = ptrdiff_t(s.size * size_t(c.components));
    s.yStride = s.xStride * ptrdiff_t(width);
    return s;
}

/// One thread's block: its planes and the channels' sources in them.
struct BlockPlanes {
    ExrPlanes planes;
    std::vector<ExrChannelSource> sources;
};

}  // namespace

std::string matteName(const std::vector<std::string>& objectNames, int index) {
    if (index >= 0 && size_t(index) < objectNames.size() && !objectNames[size_t(index)].empty())
        return objectNames[size_t(index)];
    return "object" + std::to_string(index);
}

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
    checkLayerSize(path, "z", film.z.size(), n);
    checkLayerSize(path, "distance", film.distance.size(), n);
    checkLayerSize(path, "normal", film.normal.size(), n * 3);
    checkLayerSize(path, "albedo", film.albedo.size(), n * 3);
    checkLayerSize(path, "objectId", film.objectId.size(), n);
    if (film.matteRanks < 1 || film.matteRanks > kMatteRanks)
        throw InputError(path, 0,
                         "cannot write EXR: film has " + std::to_string(film.matteRanks) +
                             " Cryptomatte ranks per pixel, expected 1 to " +
                             std::to_string(kMatteRanks));
    checkLayerSize(path, "mattes", film.mattes.size(), n * size_t(film.matteRanks));

    // The Cryptomatte layout needs the whole film (how many ranks, which
    // objects) before the header can be written; the planes are prepared
    // block by block below (exr_planes.h). The manifest needs only the
    // objects' names: made beside the film's scan, not after it (on balls
    // --spd each was 1-2 ms of the write's serial head).
    ExrMatteLayout mattes;
    std::vector<std::string> names;  // object index -> its name in the manifest
    std::string manifest;
    const auto nameObjectsUpTo = [&](int last) {
        names.reserve(size_t(std::max(last + 1, 0)));
        for (int k = int(names.size()); k <= last; ++k)
            names.push_back(matteName(opts.objectNames, k));
    };
    runWithThreads(opts.threads, [&] {
        tbb::parallel_invoke(
            // 0: in this arena, already limited to opts.threads (a nested
            // arena of its own could add threads).
            [&] { mattes = exrMatteLayout(film, opts.objectNames, opts.matteRanks, 0); },
            [&] {
                nameObjectsUpTo(int(opts.objectNames.size()) - 1);
                manifest = cryptomatteManifest(names);
            });
    });
    // The film may name objects the scene did not ("objectN"): rare, redone.
    if (mattes.maxObject >= int(names.size())) {
        nameObjectsUpTo(mattes.maxObject);
        manifest = cryptomatteManifest(names);
    }
    const int matteRanks = mattes.ranks;
    // A crop render is the data window inside the full image's display window.
    const ExrBox dataWindow = exrDataWindow(film);
    ExrHeader header({0, 0, film.displayWidth() - 1, film.displayHeight() - 1}, dataWindow);
    header.setCompression(compressionId(opts.compression));
    if (!opts.software.empty()) header.setString("software", opts.software);
    if (opts.camera) {
        setMatrix(header, "worldToCamera", opts.camera->worldToCamera);
        setMatrix(header, "worldToNDC", opts.camera->worldToNDC);
    }
    const std::string cryptoPrefix = "cryptomatte/" + cryptomatteLayerKey(kCryptoObjectLayer) + "/";
    header.setString(cryptoPrefix + "name", kCryptoObjectLayer);
    header.setString(cryptoPrefix + "hash", "MurmurHash3_32");
    header.setString(cryptoPrefix + "conversion", "uint32_to_float32");
    header.setString(cryptoPrefix + "manifest", manifest);
    if (!opts.settings.empty()) header.setString("raylab/settings", opts.settings);
    if (!opts.alpha.empty()) header.setString("raylab/alpha", opts.alpha);
    header.setInt("raylab/spp", opts.spp);
    header.setInt("raylab/maxDepth", opts.maxDepth);
    if (!opts.scenePath.empty()) header.setString("raylab/scene", opts.scenePath);
    if (!opts.accel.empty()) header.setString("raylab/accel", opts.accel);
    if (opts.frame != 0) header.setInt("raylab/frame", opts.frame);

    // Every channel and the plane it comes from, interleaved layers with
    // strides (the Film's layout).
    const ExrPixelType rgbaType = opts.floatPixels ? ExrPixelType::Float : ExrPixelType::Half;
    const Plane rgbaPlane = opts.floatPixels ? Plane::RgbaF : Plane::RgbaH;
    std::vector<FilmChannel> layout;
    for (const char* c : {"R", "G", "B", "A"})
        layout.push_back({c, rgbaType, rgbaPlane, int(layout.size()), 4});
    layout.push_back({"Z", ExrPixelType::Float, Plane::Z, 0, 1});
    layout.push_back({"distance", ExrPixelType::Float, Plane::Distance, 0, 1});
    const char* normalNames[3] = {"N.X", "N.Y", "N.Z"};
    const char* albedoNames[3] = {"albedo.R", "albedo.G", "albedo.B"};
    for (int c = 0; c < 3; ++c) {
        layout.push_back({normalNames[c], ExrPixelType::Float, Plane::Normal, c, 3});
        layout.push_back({albedoNames[c], ExrPixelType::Half, Plane::Albedo, c, 3});
    }
    layout.push_back({"objectId", ExrPixelType::Float, Plane::ObjectId, 0, 1});
    // CryptoObject0L.R/G/B/A = id and coverage of ranks 2L and 2L+1.
    for (int layer = 0; layer < matteRanks / 2; ++layer) {
        const std::string base = std::string(kCryptoObjectLayer) + (layer < 10 ? "0" : "") +
                                 std::to_string(layer) + ".";
        const char* components[4] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c)
            layout.push_back({base + components[c], ExrPixelType::Float, Plane::Crypto,
                              4 * layer + c, 2 * matteRanks});
    }
    for (const FilmChannel& c : layout) header.addChannel(c.name, c.type);

    const size_t w = size_t(film.width);
    // ZIP and ZIPS (the default): raylab's own chunk writer, igzip on
    // every core the render had (exr_zip_file.h). Blocks are compressed in
    // parallel and written in scan-line order, so the bytes stay deterministic.
    if (opts.compression == ExrCompression::Zip || opts.compression == ExrCompression::Zips) {
        // The channels in the file's order (the header's list is sorted by name).
        std::vector<const FilmChannel*> fileOrder;
        for (const ExrHeader::Channel& channel : header.channels())
            fileOrder.push_back(&*std::find_if(layout.begin(), layout.end(), [&](const FilmChannel& c) {
                return c.name == channel.name;
            }));
        // Each thread prepares the planes of the block it compresses, a line
        // at a time, in buffers it reuses (70 bytes per pixel of one line,
        // not of the frame).
        tbb::enumerable_thread_specific<BlockPlanes> scratch;
        const size_t bytesPerLine = [&] {
            size_t bytes = 0;
            for (const FilmChannel* c : fileOrder) bytes += exrPixelTypeSize(c->type) * w;
            return bytes;
        }();
        const ExrBlockLines lines = [&](int y0, int y1, unsigned char* raw) {
            BlockPlanes& b = scratch.local();
            for (int y = y0; y < y1; ++y, raw += bytesPerLine) {
                const size_t row = size_t(y - film.originY);
                prepareExrPlanes(film, row * w, (row + 1) * w, opts.floatPixels, mattes, b.planes);
                b.sources.clear();
                for (const FilmChannel* c : fileOrder)
                    b.sources.push_back(sourceOf(*c, b.planes, w));
                gatherExrLines(b.sources, film.width, 1, raw);
            }
        };
        writeFileAtomically(path, [&](const std::string& tmp) {
            writeExrZipFile(tmp, header, lines, opts.threads);
        }, group);
        return;
    }
    // Other compressions: the whole frame's planes, handed to OpenEXR.
    const exr_module::Api& openExr = openExrWriter(path);
    ExrPlanes planes;
    prepareExrFramePlanes(film, opts.floatPixels, mattes, planes, opts.threads);
    exr_module::WriteRequest request;
    request.attributes = header.attributes();
    for (const FilmChannel& c : layout) {
        const ExrChannelSource s = sourceOf(c, planes, w);
        request.slices.push_back({c.name, int32_t(c.type), const_cast<char*>(s.base), s.xStride,
                                  s.yStride, 0.0});
    }
    // OpenEXR compresses on its worker pool.
    request.threads =
        opts.threads > 0 ? opts.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // The file's count sets how many blocks are in flight: two per thread
    // (OpenEXR's rule) would give each thread a second 16-row buffer with its
    // compressor's buffers, ~1.7 MB of fresh memory on balls.nff's 25 channels
    // (~430 page faults of ~10 us on this project's VMs) for no faster write:
    // one per thread (rounded up to a pair) measured 5-10 ms less on balls
    // --spd with 2 threads (docs/benchmarks.md, bar 3).
    request.blocksInFlight = (request.threads + 1) / 2;  // OpenEXR keeps 2 per count
    writeFileAtomically(path, [&](const std::string& tmp) {
        request.path = tmp;
        std::string error;
        // The file is closed (offset table written) before writeFileAtomically renames it.
        if (!openExr.write(request, error)) throw std::runtime_error(error);
    }, group);
}

void prepareExrWriter(const std::string& path, ExrCompression compression) {
    if (!writtenByRaylab(compression)) (void)openExrWriter(path);
}

}  // namespace raylab
