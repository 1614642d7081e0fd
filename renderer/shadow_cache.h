#pragma once
// Haines' shadow cache (Haines & Greenberg, "The Light Buffer", IEEE CG&A
// 1986, in its simplest form): per worker thread, the primitive that last
// blocked each light at each ray depth. Neighbouring shading points are
// mostly shadowed by the same primitive, so the accelerator asks that one
// first (one exact Shape::occluded) and walks its BVH only when it does not
// block. The answers are the accelerator's own (Accelerator::occluded with an
// OcclusionHint); only the work to find them changes.

#include <cstddef>
#include <vector>

#include "renderer/accel/accelerator.h"

namespace raylab {

class ShadowCache {
public:
    /// Room for `lights` lights at depths 0..maxDepth (keeps the hints when
    /// the size is already right: called for every camera ray).
    void prepare(size_t lights, int maxDepth) {
        const size_t size = lights * (size_t(maxDepth) + 1);
        if (m_hints.size() != size || m_lights != lights) {
            m_hints.assign(size, OcclusionHint{});
            m_lights = lights;
        }
    }
    /// The hint for `light` at ray depth `depth` (after prepare).
    OcclusionHint& at(size_t light, int depth) { return m_hints[size_t(depth) * m_lights + light]; }

private:
    size_t m_lights = 0;
    std::vector<OcclusionHint> m_hints;  ///< [depth][light]
};

}  // namespace raylab
