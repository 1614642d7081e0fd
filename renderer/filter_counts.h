#pragma once
// What the surface filter (renderer/surface_filter.h) decided, for --stats.

#include <cstdint>

namespace raylab {

/// Candidate hits the filter decided about (--stats).
struct FilterCounts {
    /// Candidates ignored as holes. Every candidate the accelerator examined
    /// counts, so the number depends on its traversal order.
    uint64_t cutOut = 0;
    /// Transmitter crossings of shadow feelers that reached their light,
    /// dimmed (the same in both accelerators).
    uint64_t attenuated = 0;
    FilterCounts& operator+=(const FilterCounts& o) {
        cutOut += o.cutOut;
        attenuated += o.attenuated;
        return *this;
    }
    FilterCounts operator-(const FilterCounts& o) const {
        return {cutOut - o.cutOut, attenuated - o.attenuated};
    }
};

}  // namespace raylab
