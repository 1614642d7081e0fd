#pragma once
// Surfaces that let light through, as the accelerators see candidate hits:
// alpha cut-outs (a hit where the mask is below the cut-off is no hit at all,
// for every ray) and transmitters (a shadow feeler keeps their kt: filtered
// shadows, Hall & Greenberg 1983). Built from the scene alone; an accelerator
// asks it only about objects for which filters(object) is true, so a scene
// without masks or transmitters costs nothing (docs/effects.md).

#include <tbb/enumerable_thread_specific.h>

#include <cstdint>
#include <vector>

#include "geometry/shape.h"
#include "renderer/accel/accel_options.h"
#include "renderer/accel/hit.h"
#include "renderer/filter_counts.h"
#include "renderer/scene.h"
#include "shading/color.h"

namespace raylab {

class SurfaceFilter {
public:
    /// `options`: the accelerator's settings: its intersector settings, with
    /// which a candidate's surface parameters are recomputed for its alpha
    /// lookup, and the cut-off override (--alpha-cutoff).
    explicit SurfaceFilter(const Scene& scene, const AccelOptions& options = {});

    /// Whether any object needs the filter (else accelerators install none).
    bool active() const { return m_transmits || m_cutsOut; }
    /// Whether some object transmits light (filtered shadows have work).
    bool transmits() const { return m_transmits; }
    /// Whether some object has an alpha cut-out.
    bool cutsOut() const { return m_cutsOut; }
    /// Whether candidate hits on `object` may need the filter: it cuts out
    /// (every query) or transmits (filtered-shadow feelers only).
    bool filters(uint32_t object) const { return m_filtered[object] != 0; }
    /// Whether some material of `object` has an alpha cut-out: the only
    /// objects whose candidates closest-hit queries and opaque shadow feelers
    /// must show to the filter (for all others cutOut() is false).
    bool cutsOut(uint32_t object) const { return (m_filtered[object] & kCutsOut) != 0; }

    /// Whether the candidate is a hole: ignored by every ray, as if the
    /// surface were not there.
    bool cutOut(const Ray& ray, const Hit& candidate) const;
    /// What a shadow feeler keeps of the light crossing the candidate: the
    /// material's kt for a transmitter (no refraction of shadow rays), black
    /// for an opaque surface.
    Color transmission(const Ray& ray, const Hit& candidate) const;

    /// A shadow feeler reached its light through `crossings` transmitters.
    void countCrossings(uint64_t crossings) const {
        if (crossings) m_counts.local().attenuated += crossings;
    }
    /// Counts since construction, summed over threads.
    FilterCounts counts() const;

private:
    const Scene& m_scene;
    IntersectOptions m_options;
    std::optional<double> m_cutoff;  ///< --alpha-cutoff, else each material's
    static constexpr uint8_t kTransmits = 1, kCutsOut = 2;
    std::vector<uint8_t> m_filtered;  ///< per object: kTransmits | kCutsOut
    bool m_transmits = false, m_cutsOut = false;
    // Per-instance native thread-local keys: local() is asked once per
    // filtered shadow feeler, and the default key (a hash of the thread id
    // in a table) cost more than the feeler's own bookkeeping.
    mutable tbb::enumerable_thread_specific<FilterCounts, tbb::cache_aligned_allocator<FilterCounts>,
                                            tbb::ets_key_per_instance>
        m_counts;
};

}  // namespace raylab
