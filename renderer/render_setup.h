#pragma once
// Merging the scene file's settings with command-line overrides, and the
// checks that must pass before a render starts.

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/memory_limit.h"
#include "renderer/render_options.h"
#include "renderer/render_overrides.h"
#include "renderer/scene.h"

namespace raylab {

/// The render options: defaults, then the scene file's image settings and
/// "render" block, then the command-line flags `o`. --spd first applies the
/// SPD procedure's settings (512x512, depth 5), which explicit flags still override.
RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& o);

/// What a render will still allocate once its scene is loaded.
struct MemoryEstimate {
    double filmBytes = 0;   ///< film layers and the output encoders' copies
    double accelBytes = 0;  ///< the accelerator: Embree's float copy and BVH
    double total() const { return filmBytes + accelBytes; }
};

/// Film: 12 floats per pixel (RGBA, Z, N, albedo, objectId), twice (the
/// encoders copy it). Accelerator: 128 bytes per entry (acceleratorEntries),
/// from a measured 138 bytes per triangle of a 524k-triangle checkerboard
/// including raylab's own double mesh (already allocated when this is asked).
MemoryEstimate estimateRenderMemory(int width, int height, size_t entries);

/// What the accelerator indexes: a box per triangle, and the covering boxes
/// (Shape::appendCoveringBoxes with `opt`) of every other primitive, up to
/// four for a long slanted cylinder. The memory estimate counts these, not
/// primitives.
size_t acceleratorEntries(const Scene& scene, const IntersectOptions& opt);

/// Refuses (InputError) a render whose film and acceleration structure would
/// not fit in what this process may still allocate (tightestMemoryLimit:
/// physical memory, MemAvailable, cgroup limit, ulimit -v), before either is
/// allocated, instead of letting the OOM killer end it half-way.
void checkMemoryBudget(const Scene& scene, const RenderOptions& options);

/// The same against a given limit (nullopt: nothing known, nothing refused).
void checkMemoryBudget(const Scene& scene, const RenderOptions& options,
                       const std::optional<MemoryLimit>& limit);

}  // namespace raylab
