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

constexpr float kFloatMax = std::numeric_limits<float>::max();

/// The values to write for a FLOAT layer of `components` per pixel, pixels
/// [begin, end): `src` itself when they are already safe (always, for a
/// rendered film: this saves a copy), else a safe copy in `storage` (with
/// `isDepth` NaN and ±inf become kNoHitDepth, "no hit" as Blender writes it;
/// otherwise NaN -> 0 and ±inf clamped to ±FLT_MAX), or copies of `fallback`
/// when src is empty.
const float* floatPlane(const FilmPlane& src, size_t begin, size_t end, size_t components,
                        float fallback, bool isDepth, FilmPlane& storage) {
    const size_t count = (end - begin) * components;
    if (src.empty()) {
        storage.assign(count, fallback);
        return storage.data();
    }
    const float* in = src.data() + begin * components;
    size_t i = 0;
    while (i < count && std::isfinite(in[i])) ++i;
    if (i == count) return in;
    storage.resize(count);
    for (i = 0; i < count; ++i) {
        const float v = in[i];
        storage[i] = isDepth && !std::isfinite(v) ? kNoHitDepth : finiteClamp(v, kFloatMax);
    }
    return storage.data();
}

/// Half bits of pixels [begin, end) of `src` (floatsToHalf: NaN -> 0, clamped
/// to ±65504); zeros when src is empty.
const uint16_t* halfPlane(const FilmPlane& src, size_t begin, size_t end, size_t components,
                          ExrPlanes::HalfPlane& storage) {
    const size_t count = (end - begin) * components;
    if (src.empty()) {
        storage.assign(count, 0);  // half 0
    } else {
        storage.resize(count);
        floatsToHalf(src.data() + begin * components, storage.data(), count);
    }
    return storage.data();
}

/// Over all pixels: the most ranks one pixel uses (an object with coverage)
/// and the highest object index named by any entry.
struct MatteExtent {
    int usedRanks = 0;
    int maxObject = -1;
};

/// matteExtent over pixels [begin, end) with the rank count a compile-time
/// constant: the loops unroll into branch-free counts and maxima.
template <size_t Ranks>
MatteExtent matteExtentOf(const MatteEntry* entries, size_t begin, size_t end, MatteExtent e) {
    for (size_t i = begin; i != end; ++i) {
        const MatteEntry* m = entries + i * Ranks;
        int used = 0;
        for (size_t k = 0; k < Ranks; ++k) {
            used += int(m[k].object >= 0) & int(m[k].coverage > 0);
            e.maxObject = std::max(e.maxObject, int(m[k].object));
        }
        e.usedRanks = std::max(e.usedRanks, used);
    }
    return e;
}

MatteExtent matteExtentOf(const MatteEntry* entries, size_t ranks, size_t begin, size_t end,
                          MatteExtent e) {
    static_assert(kMatteRanks == 6, "one case per rank count");
    switch (ranks) {  // Film::matteRanks is 1..kMatteRanks (writeExr checks)
        case 1: return matteExtentOf<1>(entries, begin, end, e);
        case 2: return matteExtentOf<2>(entries, begin, end, e);
        case 3: return matteExtentOf<3>(entries, begin, end, e);
        case 4: return matteExtentOf<4>(entries, begin, end, e);
        case 5: return matteExtentOf<5>(entries, begin, end, e);
        case 6: return matteExtentOf<6>(entries, begin, end, e);
    }
    return e;  // no such film (writeExr refuses it before the scan)
}

/// The extent of the film's mattes. Without `countRanks` usedRanks stays 0:
/// when the film holds no more ranks per pixel than the file writes anyway,
/// no pixel can use more, and the highest object index is all the scan must
/// find: a plain maximum the compiler vectorises (balls --spd's scan:
/// 14.4 M instructions counting, 3.2 M without).
MatteExtent matteExtent(const Film& film, bool countRanks) {
    const size_t ranks = size_t(film.matteRanks);
    const size_t pixels = film.mattes.size() / ranks;
    const MatteEntry* entries = film.mattes.data();
    return tbb::parallel_reduce(
        tbb::blocked_range<size_t>(0, pixels, 8192), MatteExtent{},
        [&](const tbb::blocked_range<size_t>& r, MatteExtent e) {
            if (countRanks) return matteExtentOf(entries, ranks, r.begin(), r.end(), e);
            int maxObject = e.maxObject;
            for (size_t j = r.begin() * ranks; j != r.end() * ranks; ++j)
                maxObject = std::max(maxObject, int(entries[j].object));
            e.maxObject = maxObject;
            return e;
        },
        [](MatteExtent a, const MatteExtent& b) {
            a.usedRanks = std::max(a.usedRanks, b.usedRanks);
            a.maxObject = std::max(a.maxObject, b.maxObject);
            return a;
        });
}

/// The Cryptomatte plane of pixels [begin, end): per pixel `ranks` (id,
/// coverage) pairs. Objects that share a name share an id, so their coverages
/// are merged; ranks stay sorted by decreasing coverage. `ranks` is at least
/// the most any pixel uses: no pixel loses a rank.
const float* cryptomattePlane(const Film& film, size_t begin, size_t end,
                              const ExrMatteLayout& layout, FilmPlane& storage) {
    const size_t ranks = size_t(layout.ranks);
    storage.resize((end - begin) * 2 * ranks);
    if (film.mattes.empty()) {  // no coverage anywhere: every rank (0, 0)
        std::fill(storage.begin(), storage.end(), 0.f);
        return storage.data();
    }
    struct Rank {
        float id;
        float coverage;
    };
    for (size_t i = begin; i < end; ++i) {
        Rank merged[kMatteRanks];
        size_t count = 0;
        const MatteEntry* entries = film.mattesOf(i);
        for (int r = 0; r < film.matteRanks; ++r) {  // <= kMatteRanks (writeExr checks)
            const MatteEntry& e = entries[r];
            if (e.object < 0 || !(e.coverage > 0)) continue;
            const float value = layout.idOf[size_t(e.object)];
            size_t k = 0;
            while (k < count && std::memcmp(&merged[k].id, &value, sizeof value) != 0) ++k;
            if (k == count) merged[count++] = {value, 0.f};
            merged[k].coverage += finiteClamp(e.coverage, 1.f);
        }
        // Stable insertion sort by decreasing coverage: at most kMatteRanks
        // entries, already in order unless shared names merged some
        // (std::stable_sort allocated a buffer per pixel).
        for (size_t a = 1; a < count; ++a)
            for (size_t b = a; b > 0 && merged[b].coverage > merged[b - 1].coverage; --b)
                std::swap(merged[b], merged[b - 1]);
        float* o = storage.data() + (i - begin) * ranks * 2;
        for (size_t k = 0; k < count; ++k) {  // count <= ranks
            o[2 * k + 0] = merged[k].id;
            o[2 * k + 1] = merged[k].coverage;
        }
        std::fill(o + 2 * count, o + 2 * ranks, 0.f);  // the storage is reused
    }
    return storage.data();
}

}  // namespace

ExrMatteLayout exrMatteLayout(const Film& film, const std::vector<std::string>& objectNames,
                              int wantedRanks, int threads) {
    return runWithThreads(threads, [&] {
        const int wanted = std::clamp(wantedRanks, 1, kMatteRanks);
        const MatteExtent extent = matteExtent(film, film.matteRanks > wanted);
        ExrMatteLayout layout;
        // Rounded up to a whole layer of two ranks.
        const int ranks = std::max(wanted, extent.usedRanks);
        layout.ranks = (ranks + 1) / 2 * 2;
        layout.maxObject = extent.maxObject;
        // Object index -> id float, hashed once per object.
        layout.idOf.resize(size_t(extent.maxObject + 1));
        tbb::parallel_for(tbb::blocked_range<size_t>(0, layout.idOf.size(), 256),
                          [&](const tbb::blocked_range<size_t>& r) {
                              for (size_t k = r.begin(); k < r.end(); ++k)
                                  layout.idOf[k] = cryptomatteIdFloat(
                                      cryptomatteIdBits(matteName(objectNames, int(k))));
                          });
        return layout;
    });
}

namespace {

/// Pixels [begin, end)'s planes, the independent groups handed to `invoke`
/// (called with all of them: one after the other, or in parallel).
template <class Invoke>
void preparePlanes(const Film& film, size_t begin, size_t end, bool floatPixels,
                   const ExrMatteLayout& mattes, ExrPlanes& out, const Invoke& invoke) {
    out.rgbaF = nullptr;
    out.rgbaH = nullptr;
    invoke(
        [&] {
            if (floatPixels)
                out.rgbaF = floatPlane(film.rgba, begin, end, 4, 0.f, false, out.rgbaCopy);
            else
                out.rgbaH = halfPlane(film.rgba, begin, end, 4, out.rgbaHalf);
        },
        [&] {
            out.z = floatPlane(film.z, begin, end, 1, kNoHitDepth, true, out.zCopy);
            out.distance =
                floatPlane(film.distance, begin, end, 1, kNoHitDepth, true, out.distanceCopy);
            out.objectId = floatPlane(film.objectId, begin, end, 1, -1.f, false, out.objectIdCopy);
        },
        [&] { out.normal = floatPlane(film.normal, begin, end, 3, 0.f, false, out.normalCopy); },
        [&] { out.albedo = halfPlane(film.albedo, begin, end, 3, out.albedoHalf); },
        [&] { out.crypto = cryptomattePlane(film, begin, end, mattes, out.cryptoValues); });
}

}  // namespace

void prepareExrPlanes(const Film& film, size_t begin, size_t end, bool floatPixels,
                      const ExrMatteLayout& mattes, ExrPlanes& out) {
    preparePlanes(film, begin, end, floatPixels, mattes, out,
                  [](const auto&... group) { (group(), ...); });
}

void prepareExrFramePlanes(const Film& film, bool floatPixels, const ExrMatteLayout& mattes,
                           ExrPlanes& out, int threads) {
    const size_t n = size_t(film.width) * size_t(film.height);
    runWithThreads(threads, [&] {
        preparePlanes(film, 0, n, floatPixels, mattes, out,
                      [](const auto&... group) { tbb::parallel_invoke(group...); });
    });
}

}  // namespace raylab
