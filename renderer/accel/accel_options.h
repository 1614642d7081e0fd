#pragma once
// How an accelerator is built: the Embree build settings and the accuracy
// knobs of the analytic intersectors, fixed for the accelerator's lifetime.

#include <optional>

#include "geometry/shape.h"
#include "geometry/vec.h"

namespace raylab {

struct AccelOptions {
    enum class BvhQuality { Low, Medium, High };
    BvhQuality quality = BvhQuality::Medium;  ///< Embree only
    /// Embree only: RTC_SCENE_FLAG_ROBUST, watertight on triangle edges. The
    /// default: Embree's fast traversal misses 5-15% of rays aimed exactly at
    /// a shared edge (tests/accel/test_edge_hits.cpp), a crack the naive loop
    /// does not have; robust traversal costs no measurable render time here
    /// (docs/benchmarks.md). --no-robust selects the fast one.
    bool robust = true;
    /// Geometry is handed to Embree in float relative to this point (normally
    /// the eye), so far-from-origin scenes keep their precision near the camera.
    Vec3 origin{0, 0, 0};
    /// Handed to every shape query (precision, polygon inside test).
    IntersectOptions intersect;
    /// --alpha-cutoff (JSON render.alpha_cutoff): the cut-off of every
    /// material's alpha (renderer/surface_filter.h); unset, each material's own.
    std::optional<double> alphaCutoff;
};

/// "low", "medium" or "high": the spelling of --bvh-quality and the JSON key.
inline const char* bvhQualityName(AccelOptions::BvhQuality q) {
    switch (q) {
        case AccelOptions::BvhQuality::Low:
            return "low";
        case AccelOptions::BvhQuality::High:
            return "high";
        default:
            return "medium";
    }
}

}  // namespace raylab
