#include "renderer/io/exr_planes.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/exr_writer.h"
#include "renderer/io/finite_clamp.h"
#include "renderer/io/half_convert.h"
#include "renderer/thread_arena.h"

namespace raylab {

namespace {

/// Pixels per task: large enough that a task's overhead is noise, small
/// enough that two threads share a 512x512 frame evenly.
constexpr size_t kGrain = 8192;

constexpr float kFloatMax = std::numeric_limits<float>::max();

/// Calls body(begin, end) over [0, count) in TBB tasks.
template <class Body>
void forRanges(size_t count, size_t grain, const Body& body) {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, count, grain),
                      [&](const tbb::blocked_range<size_t>& r) { body(r.begin(), r.end()); });
}

/// Whether every value of src[0, count) is finite (needs no fix for a FLOAT channel).
bool allFinite(const FilmPlane& src, size_t count) {
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, count, kGrain * 4), true,
        [&](const tbb::blocked_range<size_t>& r, bool ok) {
            for (size_t i = r.begin(); ok && i != r.end(); ++i) ok = std::isfinite(src[i]);
            return ok;
        },
        [](bool a, bool b) { return a && b; });
}

/// The values to write for a FLOAT layer: `src` itself when it is already safe
/// (always, for a rendered film: this saves a copy of megabytes), else a safe
/// copy in `storage` (with `isDepth` NaN and ±inf become kNoHitDepth, "no hit"
/// as Blender writes it; otherwise NaN -> 0 and ±inf clamped to ±FLT_MAX), or
/// `count` copies of `fallback` when src is empty.
const float* floatPlane(const FilmPlane& src, size_t count, float fallback, bool isDepth,
                        FilmPlane& storage) {
    if (src.empty()) {
        storage.assign(count, fallback);
        return storage.data();
    }
    if (allFinite(src, count)) return src.data();
    storage.resize(count);
    forRanges(count, kGrain * 4, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            const float v = src[i];
            storage[i] = isDepth && !std::isfinite(v) ? kNoHitDepth : finiteClamp(v, kFloatMax);
        }
    });
    return storage.data();
}

/// Half bits of src[0, count) (floatsToHalf: NaN -> 0, clamped to ±65504);
/// zeros when src is empty.
HugeArray<uint16_t> halfPlane(const FilmPlane& src, size_t count) {
    HugeArray<uint16_t> out(count);  // zero bytes: half 0
    if (src.empty()) return out;
    forRanges(count, kGrain * 4, [&](size_t begin, size_t end) {
        floatsToHalf(src.data() + begin, out.data() + begin, end - begin);
    });
    return out;
}

/// Over all pixels: the most ranks one pixel uses (an object with coverage)
/// and the highest object index named by any entry.
struct MatteExtent {
    int usedRanks = 0;
    int maxObject = -1;
};

MatteExtent matteExtent(const Film& film) {
    const size_t pixels = film.mattes.size() / kMatteRanks;
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, pixels, kGrain), MatteExtent{},
        [&](const tbb::blocked_range<size_t>& r, MatteExtent e) {
            for (size_t i = r.begin(); i != r.end(); ++i) {
                int used = 0;
                for (int k = 0; k < kMatteRanks; ++k) {
                    const MatteEntry& m = film.mattes[i * kMatteRanks + size_t(k)];
                    used += m.object >= 0 && m.coverage > 0;
                    e.maxObject = std::max(e.maxObject, int(m.object));
                }
                e.usedRanks = std::max(e.usedRanks, used);
            }
            return e;
        },
        [](MatteExtent a, const MatteExtent& b) {
            a.usedRanks = std::max(a.usedRanks, b.usedRanks);
            a.maxObject = std::max(a.maxObject, b.maxObject);
            return a;
        });
}

/// The Cryptomatte plane: per pixel `ranks` (id, coverage) pairs, the ids
/// hashed from the object names. Objects that share a name share an id, so
/// their coverages are merged; ranks stay sorted by decreasing coverage.
/// `ranks` is at least the most any pixel uses: no pixel loses a rank.
HugeArray<float> cryptomattePlane(const Film& film, size_t n,
                                  const std::vector<std::string>& objectNames, int ranks,
                                  int maxObject) {
    HugeArray<float> out(n * 2 * size_t(ranks));  // zero bytes: unused ranks are (0, 0)
    if (film.mattes.size() != n * kMatteRanks) return out;
    // Object index -> id float, hashed once per object.
    std::vector<float> idOf(size_t(maxObject + 1));
    forRanges(idOf.size(), 256, [&](size_t begin, size_t end) {
        for (size_t k = begin; k < end; ++k)
            idOf[k] = cryptomatteIdFloat(cryptomatteIdBits(matteName(objectNames, int(k))));
    });
    struct Rank {
        float id;
        float coverage;
    };
    forRanges(n, kGrain, [&](size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            Rank merged[kMatteRanks];
            int count = 0;
            for (int r = 0; r < kMatteRanks; ++r) {
                const MatteEntry& e = film.mattes[i * kMatteRanks + size_t(r)];
                if (e.object < 0 || !(e.coverage > 0)) continue;
                const float value = idOf[size_t(e.object)];
                int k = 0;
                while (k < count && std::memcmp(&merged[k].id, &value, sizeof value) != 0) ++k;
                if (k == count) merged[count++] = {value, 0.f};
                merged[k].coverage += finiteClamp(e.coverage, 1.f);
            }
            // Stable insertion sort by decreasing coverage: at most kMatteRanks
            // entries, already in order unless shared names merged some
            // (std::stable_sort allocated a buffer per pixel).
            for (int a = 1; a < count; ++a)
                for (int b = a; b > 0 && merged[b].coverage > merged[b - 1].coverage; --b)
                    std::swap(merged[b], merged[b - 1]);
            float* o = out.data() + i * size_t(ranks) * 2;
            for (int k = 0; k < count; ++k) {  // count <= ranks
                o[2 * k + 0] = merged[k].id;
                o[2 * k + 1] = merged[k].coverage;
            }
        }
    });
    return out;
}

ExrPlanes prepare(const Film& film, bool floatPixels, const std::vector<std::string>& objectNames,
                  int wantedRanks) {
    const size_t n = size_t(film.width) * size_t(film.height);
    ExrPlanes p;
    // Independent planes side by side; the large ones split further inside.
    tbb::parallel_invoke(
        [&] {
            if (floatPixels)
                p.rgbaF = floatPlane(film.rgba, n * 4, 0.f, false, p.rgbaCopy);
            else
                p.rgbaH = halfPlane(film.rgba, n * 4);
        },
        [&] {
            p.z = floatPlane(film.z, n, kNoHitDepth, true, p.zCopy);
            p.distance = floatPlane(film.distance, n, kNoHitDepth, true, p.distanceCopy);
            p.objectId = floatPlane(film.objectId, n, -1.f, false, p.objectIdCopy);
        },
        [&] { p.normal = floatPlane(film.normal, n * 3, 0.f, false, p.normalCopy); },
        [&] { p.albedo = halfPlane(film.albedo, n * 3); },
        [&] {
            const MatteExtent extent = matteExtent(film);
            // Rounded up to a whole layer of two ranks.
            const int ranks = std::max(std::clamp(wantedRanks, 1, kMatteRanks), extent.usedRanks);
            p.matteRanks = (ranks + 1) / 2 * 2;
            p.maxMatteObject = extent.maxObject;
            p.crypto = cryptomattePlane(film, n, objectNames, p.matteRanks, extent.maxObject);
        });
    return p;
}

}  // namespace

ExrPlanes prepareExrPlanes(const Film& film, bool floatPixels,
                           const std::vector<std::string>& objectNames, int wantedRanks,
                           int threads) {
    return runWithThreads(threads,
                          [&] { return prepare(film, floatPixels, objectNames, wantedRanks); });
}

}  // namespace raylab
