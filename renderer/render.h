#pragma once
// The TBB-parallel tile loop: camera rays → integrator → film.

#include <atomic>
#include <functional>

#include "renderer/accel/accelerator.h"
#include "renderer/effects.h"
#include "renderer/film.h"
#include "renderer/render_options.h"
#include "renderer/render_stats.h"
#include "renderer/scene.h"

namespace raylab {

/// Called from worker threads with the fraction of tiles finished (0..1);
/// calls are serialised by the renderer.
using ProgressCallback = std::function<void(double fraction)>;

struct RenderResult {
    Film film;
    RayCounters rays;
    double renderSeconds = 0;
    uint64_t nonFiniteSamples = 0;  ///< samples that were NaN/Inf and were replaced by black
    bool cancelled = false;
};

/// Renders the scene. Deterministic: the film and the counters are
/// bit-identical for any thread count. `cancel` (may be null) stops the render
/// promptly between tiles; the result then has cancelled = true.
RenderResult render(const Scene& scene, const Accelerator& accel, const RenderOptions& options,
                    const EffectSet& effects, const ProgressCallback& progress = {},
                    const std::atomic<bool>* cancel = nullptr);

}  // namespace raylab
