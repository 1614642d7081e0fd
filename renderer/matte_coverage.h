#pragma once
// The object coverage of one pixel, gathered sample by sample for the
// Cryptomatte layers: each sample's first-hit object gets the sample's
// weight (its share of the pixel), so the coverages are exact for any
// supersampling, adaptive subdivision or SPD corner averaging.

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "renderer/film.h"
#include "renderer/render_options.h"

namespace raylab {

/// The most objects one pixel's coverage can hold with `options`' sampling:
/// one per sample (--spp N: N; --spd: the four corners), kMatteRanks with
/// --adaptive (its subdivided squares have many corners). It depends on the
/// settings only, not on the picture, so every frame of a sequence writes the
/// same Cryptomatte layers, as the specification asks.
inline int matteRanksOfSampling(const RenderOptions& options) {
    const int samples = options.adaptiveThreshold > 0 ? kMatteRanks
                        : options.spd                  ? 4
                                                       : options.spp;
    return std::clamp(samples, 1, kMatteRanks);
}

/// A pixel's `count` entries of Film::mattes (Film::matteRanks of them).
struct MatteSpan {
    MatteEntry* out;
    size_t count;
};

class MatteCoverage {
public:
    /// Adds `weight` (a fraction of the pixel) to `object`; a miss (object < 0) adds nothing.
    void add(int object, double weight) {
        if (object < 0) return;
        for (size_t i = 0; i < m_count; ++i)
            if (m_inline[i].object == object) {
                m_inline[i].weight += weight;
                return;
            }
        for (Entry& e : m_spill)
            if (e.object == object) {
                e.weight += weight;
                return;
            }
        if (m_count < m_inline.size()) m_inline[m_count++] = {object, weight};
        else m_spill.push_back({object, weight});
    }

    /// Forgets every object, for the next pixel. Entries past the count are
    /// never read, so they are left as they are (a fresh MatteCoverage{} per
    /// pixel rewrote all eight).
    void clear() {
        m_count = 0;
        m_spill.clear();
    }

    /// Writes out.count entries: coverage = weight / divisor, the largest
    /// first (ties: lower object index first), unused ranks {-1, 0}; objects
    /// beyond out.count ranks are dropped (none when the count is
    /// matteRanksOfSampling's).
    void store(MatteSpan span, double divisor = 1.0) const {
        MatteEntry* out = span.out;
        const auto before = [](const Entry& a, const Entry& b) {
            return a.weight != b.weight ? a.weight > b.weight : a.object < b.object;
        };
        const auto write = [&](const Entry* sorted, size_t n) {
            for (size_t r = 0; r < span.count; ++r)
                out[r] = r < n ? MatteEntry{sorted[r].object, float(sorted[r].weight / divisor)}
                               : MatteEntry{};
        };
        if (m_count <= 1 && m_spill.empty()) {
            // Most pixels see one object or none: nothing to sort. (Bit for
            // bit the general path's output; 60% of finishRow's instructions
            // on balls --spd went to the copy and sort below.)
            if (m_count == 1)
                storeSingle(span, m_inline[0].object, float(m_inline[0].weight / divisor));
            else
                storeSingle(span, -1, 0.f);
            return;
        }
        if (m_spill.empty()) {  // no allocation on the common path
            // Insertion sort of at most 8 entries (std::sort trips GCC 12's
            // -Warray-bounds on a small std::array).
            std::array<Entry, 8> sorted = m_inline;
            for (size_t i = 1; i < m_count; ++i)
                for (size_t j = i; j > 0 && before(sorted[j], sorted[j - 1]); --j)
                    std::swap(sorted[j], sorted[j - 1]);
            write(sorted.data(), m_count);
            return;
        }
        std::vector<Entry> all(m_inline.begin(), m_inline.begin() + m_count);
        all.insert(all.end(), m_spill.begin(), m_spill.end());
        std::sort(all.begin(), all.end(), before);
        write(all.data(), all.size());
    }

    /// What store() writes for a pixel whose coverage is all `object`'s
    /// (`coverage` of it; object < 0: no object): without gathering one,
    /// for callers that know it already (an SPD pixel with four equal corners).
    static void storeSingle(MatteSpan span, int object, float coverage) {
        span.out[0] = object >= 0 ? MatteEntry{object, coverage} : MatteEntry{};
        for (size_t r = 1; r < span.count; ++r) span.out[r] = MatteEntry{};
    }

private:
    struct Entry {
        int object = -1;
        double weight = 0;  // sample counts or dyadic fractions: sums are exact in double
    };
    std::array<Entry, 8> m_inline{};  // most pixels see one or two objects
    size_t m_count = 0;
    std::vector<Entry> m_spill;
};

}  // namespace raylab
