#include "renderer/io/exr_writer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <thread>
#include <utility>
#include <vector>

#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfThreading.h>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/atomic_file.h"
#include "renderer/io/errors.h"
#include "renderer/io/exr_planes.h"
#include "renderer/io/exr_string_attribute.h"
#include "renderer/io/exr_zip_file.h"

namespace raylab {

namespace {

using Imath::half;

/// Checks that an AOV vector is either absent (empty) or holds `expected` values.
void checkLayerSize(const std::string& path, const char* name, size_t size, size_t expected) {
    if (size != 0 && size != expected)
        throw InputError(path, 0,
                         std::string("cannot write EXR: film layer '") + name + "' has " +
                             std::to_string(size) + " values, expected " +
                             std::to_string(expected));
}

Imath::M44f toM44f(const Matrix44& m) {
    Imath::M44f r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = float(m[size_t(i)][size_t(j)]);
    return r;
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
    checkLayerSize(path, "mattes", film.mattes.size(), n * kMatteRanks);

    // Planes to write, prepared on every core the render had (exr_planes.h);
    // interleaved layers keep the Film's layout and use strides.
    const Imf::PixelType rgbaType = opts.floatPixels ? Imf::FLOAT : Imf::HALF;
    const ExrPlanes planes =
        prepareExrPlanes(film, opts.floatPixels, opts.objectNames, opts.matteRanks, opts.threads);
    const int matteRanks = planes.matteRanks;
    // A crop render is the data window inside the full image's display window.
    const Imath::Box2i dataWindow = exrDataWindow(film);
    Imf::Header header(Imath::Box2i({0, 0}, {film.displayWidth() - 1, film.displayHeight() - 1}),
                       dataWindow);
    header.compression() = toImf(opts.compression);
    if (!opts.software.empty()) header.insert("software", ExrStringAttribute(opts.software));
    if (opts.camera) {
        header.insert("worldToCamera", Imf::M44fAttribute(toM44f(opts.camera->worldToCamera)));
        header.insert("worldToNDC", Imf::M44fAttribute(toM44f(opts.camera->worldToNDC)));
    }
    const std::string cryptoPrefix = "cryptomatte/" + cryptomatteLayerKey(kCryptoObjectLayer) + "/";
    std::vector<std::string> names;
    {
        const int maxObject = std::max(int(opts.objectNames.size()) - 1, planes.maxMatteObject);
        names.reserve(size_t(maxObject + 1));
        for (int k = 0; k <= maxObject; ++k) names.push_back(matteName(opts.objectNames, k));
    }
    header.insert(cryptoPrefix + "name", ExrStringAttribute(kCryptoObjectLayer));
    header.insert(cryptoPrefix + "hash", ExrStringAttribute("MurmurHash3_32"));
    header.insert(cryptoPrefix + "conversion", ExrStringAttribute("uint32_to_float32"));
    header.insert(cryptoPrefix + "manifest", ExrStringAttribute(cryptomatteManifest(names)));
    if (!opts.settings.empty())
        header.insert("raylab/settings", ExrStringAttribute(opts.settings));
    if (!opts.alpha.empty()) header.insert("raylab/alpha", ExrStringAttribute(opts.alpha));
    header.insert("raylab/spp", Imf::IntAttribute(opts.spp));
    header.insert("raylab/maxDepth", Imf::IntAttribute(opts.maxDepth));
    if (!opts.scenePath.empty())
        header.insert("raylab/scene", ExrStringAttribute(opts.scenePath));
    if (!opts.accel.empty()) header.insert("raylab/accel", ExrStringAttribute(opts.accel));
    if (opts.frame != 0) header.insert("raylab/frame", Imf::IntAttribute(opts.frame));

    Imf::ChannelList& channels = header.channels();
    Imf::FrameBuffer fb;
    const size_t w = size_t(film.width);
    const char* rgbaNames[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        channels.insert(rgbaNames[c], Imf::Channel(rgbaType));
        if (opts.floatPixels)
            fb.insert(rgbaNames[c], sliceIn(dataWindow, Imf::FLOAT, bytes(planes.rgbaF + c),
                                               4 * sizeof(float), 4 * sizeof(float) * w));
        else
            fb.insert(rgbaNames[c], sliceIn(dataWindow, Imf::HALF,
                                            bytes(planes.rgbaH.data() + c), 4 * sizeof(half),
                                            4 * sizeof(half) * w));
    }
    channels.insert("Z", Imf::Channel(Imf::FLOAT));
    fb.insert("Z",
              sliceIn(dataWindow, Imf::FLOAT, bytes(planes.z), sizeof(float), sizeof(float) * w));
    channels.insert("distance", Imf::Channel(Imf::FLOAT));
    fb.insert("distance",
              sliceIn(dataWindow, Imf::FLOAT, bytes(planes.distance), sizeof(float),
                      sizeof(float) * w));
    const char* normalNames[3] = {"N.X", "N.Y", "N.Z"};
    const char* albedoNames[3] = {"albedo.R", "albedo.G", "albedo.B"};
    for (int c = 0; c < 3; ++c) {
        channels.insert(normalNames[c], Imf::Channel(Imf::FLOAT));
        fb.insert(normalNames[c], sliceIn(dataWindow, Imf::FLOAT, bytes(planes.normal + c),
                                             3 * sizeof(float), 3 * sizeof(float) * w));
        channels.insert(albedoNames[c], Imf::Channel(Imf::HALF));
        fb.insert(albedoNames[c], sliceIn(dataWindow, Imf::HALF, bytes(planes.albedo.data() + c),
                                             3 * sizeof(half), 3 * sizeof(half) * w));
    }
    channels.insert("objectId", Imf::Channel(Imf::FLOAT));
    fb.insert("objectId", sliceIn(dataWindow, Imf::FLOAT, bytes(planes.objectId), sizeof(float),
                                     sizeof(float) * w));
    // CryptoObject0L.R/G/B/A = id and coverage of ranks 2L and 2L+1.
    const size_t cryptoStride = 2 * size_t(matteRanks) * sizeof(float);
    for (int layer = 0; layer < matteRanks / 2; ++layer) {
        const std::string base = std::string(kCryptoObjectLayer) + (layer < 10 ? "0" : "") +
                                 std::to_string(layer) + ".";
        const char* components[4] = {"R", "G", "B", "A"};
        for (int c = 0; c < 4; ++c) {
            const std::string name = base + components[c];
            channels.insert(name, Imf::Channel(Imf::FLOAT));
            fb.insert(name, sliceIn(dataWindow, Imf::FLOAT,
                                    bytes(planes.crypto.data() + 4 * layer + c), cryptoStride,
                                    cryptoStride * w));
        }
    }

    // ZIP and ZIPS (the default): raylab's own chunk writer, igzip on
    // every core the render had (exr_zip_file.h). Blocks are compressed in
    // parallel and written in scan-line order, so the bytes stay deterministic.
    if (opts.compression == ExrCompression::Zip || opts.compression == ExrCompression::Zips) {
        writeFileAtomically(path, encodeExrZipFile(header, fb, opts.threads), group);
        return;
    }
    // The other compressions go through OpenEXR, on its worker pool.
    const int threads =
        opts.threads > 0 ? opts.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    // OpenEXR runs compression tasks on its global pool (empty by default, i.e.
    // everything on the calling thread); the per-file count alone adds no workers.
    if (Imf::globalThreadCount() < threads) Imf::setGlobalThreadCount(threads);
    // The file's count sets how many blocks are in flight: two per thread
    // (OpenEXR's rule) would give each thread a second 16-row buffer with its
    // compressor's buffers, ~1.7 MB of fresh memory on balls.nff's 25 channels
    // (~430 page faults of ~10 us on this project's VMs) for no faster write:
    // one per thread (rounded up to a pair) measured 5-10 ms less on balls
    // --spd with 2 threads (docs/benchmarks.md, bar 3).
    const int blocksInFlight = (threads + 1) / 2;  // OpenEXR keeps 2 per count
    writeFileAtomically(path, [&](const std::string& tmp) {
        // The OutputFile is closed (offset table written) when it goes out of
        // scope, before writeFileAtomically renames the file.
        Imf::OutputFile file(tmp.c_str(), header, blocksInFlight);
        file.setFrameBuffer(fb);
        file.writePixels(film.height);  // every scan line of the data window
    }, group);
}

}  // namespace raylab
