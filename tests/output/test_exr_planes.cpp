// prepareExrPlanes prepares the EXR writer's planes one range of pixels at a
// time (a 16-line block, in the thread that compresses it), into buffers it
// reuses: every plane must be the bytes a one-pixel-at-a-time reference gives
// (the writer's former serial code, restated here) for any split of the
// frame, with NaN, Inf, out-of-half-range values, shared object names and
// unnamed objects in the film; exrMatteLayout's whole-film scan must not
// depend on the thread count.

#include <Imath/half.h>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "renderer/cryptomatte_id.h"
#include "renderer/io/exr_planes.h"
#include "renderer/io/exr_writer.h"
#include "renderer/sampler.h"

using namespace raylab;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

uint16_t halfReference(float v) {
    if (std::isnan(v)) v = 0.f;
    v = std::fmax(-65504.f, std::fmin(65504.f, v));
    return Imath::half(v).bits();
}

/// NaN -> 0, ±Inf and beyond -> ±FLT_MAX; depth: NaN and ±Inf -> 1e10.
float floatReference(float v, bool isDepth) {
    if (isDepth && !std::isfinite(v)) return kNoHitDepth;
    if (std::isnan(v)) return 0.f;
    return std::fmax(-std::numeric_limits<float>::max(),
                     std::fmin(std::numeric_limits<float>::max(), v));
}

/// One pixel's Cryptomatte ranks, as the writer computed them serially.
std::vector<float> cryptoReference(const Film& film, size_t i,
                                   const std::vector<std::string>& names, int ranks) {
    std::vector<std::pair<float, float>> merged;  // (id, coverage) in first-seen order
    for (int r = 0; r < kMatteRanks; ++r) {
        const MatteEntry& e = film.mattes[i * kMatteRanks + size_t(r)];
        if (e.object < 0 || !(e.coverage > 0)) continue;
        const float id = cryptomatteIdFloat(cryptomatteIdBits(matteName(names, e.object)));
        auto it = std::find_if(merged.begin(), merged.end(), [&](const auto& m) {
            return std::memcmp(&m.first, &id, sizeof id) == 0;
        });
        if (it == merged.end()) it = merged.insert(merged.end(), {id, 0.f});
        it->second += std::isnan(e.coverage) ? 0.f : std::min(e.coverage, 1.f);
    }
    std::stable_sort(merged.begin(), merged.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    std::vector<float> out(2 * size_t(ranks), 0.f);
    for (size_t k = 0; k < merged.size(); ++k) {
        out[2 * k] = merged[k].first;
        out[2 * k + 1] = merged[k].second;
    }
    return out;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/// 300x200 (60,000 pixels: several tasks' worth) with every kind of value.
Film makeFilm(uint64_t seed) {
    Film f(300, 200, 7, 11, 400, 300);
    Pcg32 rng(seed, 1);
    const auto uniform = [&] { return float(rng.next()) / 4294967296.f; };
    const auto value = [&](float scale) {
        switch (rng.next() % 16) {
            case 0:
                return kNaN;
            case 1:
                return kInf;
            case 2:
                return -kInf;
            case 3:
                return 70000.f;  // beyond half's range
            case 4:
                return -65520.f;  // rounds to Inf as a half unless clamped first
            default:
                return (uniform() - 0.25f) * scale;
        }
    };
    for (float& v : f.rgba) v = value(4.f);
    for (float& v : f.albedo) v = value(1.f);
    for (float& v : f.normal) v = value(2.f);
    for (float& v : f.z) v = value(100.f);
    for (float& v : f.distance) v = value(100.f);
    for (float& v : f.objectId) v = value(50.f);
    const size_t pixels = size_t(f.width) * size_t(f.height);
    for (size_t i = 0; i < pixels; ++i) {
        const int used = int(rng.next() % (kMatteRanks + 1));
        for (int r = 0; r < used; ++r) {
            MatteEntry& e = f.mattes[i * kMatteRanks + size_t(r)];
            e.object = int32_t(rng.next() % 40) - 2;  // -2, -1: unused; 30..37: no name
            e.coverage = rng.next() % 9 == 0 ? 0.f : uniform();
        }
    }
    return f;
}

/// Names with duplicates ("b" twice, "a" three times: merged ids) and gaps
/// (empty: "object<k>"); objects 30 and up have none.
std::vector<std::string> makeNames() {
    std::vector<std::string> names;
    for (int k = 0; k < 30; ++k)
        names.push_back(k % 7 == 0    ? "a"
                        : k % 11 == 1 ? "b"
                        : k % 5 == 3  ? ""
                                      : "obj" + std::to_string(k));
    return names;
}

/// Checks pixels [begin, end) of `p` (prepared for that range) against the
/// reference; returns the number of wrong values.
size_t wrongValues(const Film& film, const std::vector<std::string>& names, bool floatPixels,
                   int ranks, size_t begin, size_t end, const ExrPlanes& p) {
    size_t wrong = 0;
    const auto expect = [&](bool ok) { wrong += !ok; };
    expect(floatPixels ? p.rgbaH == nullptr : p.rgbaF == nullptr);
    for (size_t i = begin; i < end; ++i) {
        const size_t j = i - begin;
        for (size_t c = 0; c < 4; ++c) {
            if (floatPixels)
                expect(sameBits(p.rgbaF[4 * j + c], floatReference(film.rgba[4 * i + c], false)));
            else
                expect(p.rgbaH[4 * j + c] == halfReference(film.rgba[4 * i + c]));
        }
        for (size_t c = 0; c < 3; ++c) {
            expect(p.albedo[3 * j + c] == halfReference(film.albedo[3 * i + c]));
            expect(sameBits(p.normal[3 * j + c], floatReference(film.normal[3 * i + c], false)));
        }
        expect(sameBits(p.z[j], floatReference(film.z[i], true)));
        expect(sameBits(p.distance[j], floatReference(film.distance[i], true)));
        expect(sameBits(p.objectId[j], floatReference(film.objectId[i], false)));
        const std::vector<float> crypto = cryptoReference(film, i, names, ranks);
        for (int k = 0; k < 2 * ranks; ++k)
            expect(sameBits(p.crypto[j * size_t(2 * ranks) + size_t(k)], crypto[size_t(k)]));
    }
    return wrong;
}

void checkAgainstReference(const Film& film, const std::vector<std::string>& names,
                           bool floatPixels, int wanted, int threads) {
    CAPTURE(floatPixels);
    CAPTURE(wanted);
    CAPTURE(threads);
    const ExrMatteLayout layout = exrMatteLayout(film, names, wanted, threads);
    const size_t n = size_t(film.width) * size_t(film.height);

    int used = 0, maxObject = -1;
    for (size_t i = 0; i < n; ++i) {
        int u = 0;
        for (int r = 0; r < kMatteRanks; ++r) {
            const MatteEntry& e = film.mattes[i * kMatteRanks + size_t(r)];
            u += e.object >= 0 && e.coverage > 0;
            maxObject = std::max(maxObject, int(e.object));
        }
        used = std::max(used, u);
    }
    const int ranks = (std::max(std::clamp(wanted, 1, kMatteRanks), used) + 1) / 2 * 2;
    REQUIRE(layout.ranks == ranks);
    CHECK(layout.maxObject == maxObject);
    REQUIRE(layout.idOf.size() == size_t(maxObject + 1));

    // The whole frame at once, then one ExrPlanes reused for 16-line blocks,
    // single lines and ranges that cut lines (a longer range first, so stale
    // values of a reused buffer would show).
    ExrPlanes whole;
    prepareExrPlanes(film, 0, n, floatPixels, layout, whole);
    CHECK(wrongValues(film, names, floatPixels, ranks, 0, n, whole) == 0);
    ExrPlanes frame;  // the whole frame's planes side by side on `threads` threads
    prepareExrFramePlanes(film, floatPixels, layout, frame, threads);
    CHECK(wrongValues(film, names, floatPixels, ranks, 0, n, frame) == 0);
    const size_t w = size_t(film.width);
    for (size_t step : {16 * w, w, size_t(7777)}) {
        CAPTURE(step);
        ExrPlanes reused;
        size_t wrong = 0;
        for (size_t begin = 0; begin < n; begin += step) {
            const size_t end = std::min(n, begin + step);
            prepareExrPlanes(film, begin, end, floatPixels, layout, reused);
            wrong += wrongValues(film, names, floatPixels, ranks, begin, end, reused);
        }
        CHECK(wrong == 0);
    }
}

}  // namespace

TEST_CASE("exr planes: every range's planes equal the one-pixel-at-a-time reference") {
    const Film film = makeFilm(20261202);
    const std::vector<std::string> names = makeNames();
    for (int threads : {1, 2, 0})
        for (bool floatPixels : {false, true})
            // The film holds 6 ranks: wanted 1 and 4 make the scan count the
            // ranks pixels use; 6 and 7 let it find the highest object alone.
            for (int wanted : {1, 4, 6, 7})
                checkAgainstReference(film, names, floatPixels, wanted, threads);
}

TEST_CASE("exr planes: a rendered film's FLOAT layers are lent, not copied") {
    Film film(256, 160);  // 40,960 pixels
    for (size_t i = 0; i < film.z.size(); ++i) film.z[i] = float(i % 97);
    const ExrMatteLayout layout = exrMatteLayout(film, {}, 2, 2);
    CHECK(layout.maxObject == -1);  // the Film default: no coverage anywhere
    CHECK(layout.ranks == 2);
    ExrPlanes p;
    const size_t begin = 16 * 256, end = 32 * 256;
    prepareExrPlanes(film, begin, end, true, layout, p);
    CHECK(p.rgbaF == film.rgba.data() + 4 * begin);
    CHECK(p.z == film.z.data() + begin);
    CHECK(p.distance == film.distance.data() + begin);
    CHECK(p.normal == film.normal.data() + 3 * begin);
    CHECK(p.objectId == film.objectId.data() + begin);
    for (size_t i = 0; i < 2 * 2 * (end - begin); ++i) REQUIRE(p.crypto[i] == 0.f);
}

TEST_CASE("exr planes: a film without AOV planes gets the Film defaults in every plane") {
    Film film(130, 70);
    film.z.clear();
    film.distance.clear();
    film.normal.clear();
    film.albedo.clear();
    film.objectId.clear();
    film.mattes.clear();
    const ExrMatteLayout layout = exrMatteLayout(film, {"x"}, 1, 2);
    CHECK(layout.ranks == 2);
    CHECK(layout.maxObject == -1);
    const size_t n = 130 * 70;
    ExrPlanes p;
    prepareExrPlanes(film, 0, n, false, layout, p);
    size_t wrong = 0;
    for (size_t i = 0; i < n; ++i) {
        wrong += p.z[i] != kNoHitDepth || p.distance[i] != kNoHitDepth || p.objectId[i] != -1.f;
        wrong += p.normal[3 * i] != 0.f || p.albedo[3 * i] != 0 || p.crypto[2 * i] != 0.f;
    }
    CHECK(wrong == 0);
}
