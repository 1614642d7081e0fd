#pragma once
// Merging the scene file's settings with command-line overrides, and the
// checks that must pass before a render starts.

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/render_options.h"
#include "renderer/scene.h"

namespace raylab {

/// Settings given on the command line; unset ones fall back to the scene.
struct RenderOverrides {
    std::optional<int> width, height, spp, maxDepth, threads, adaptiveMaxLevel;
    std::optional<double> adaptiveThreshold, minWeight, epsilon;
    std::optional<uint64_t> seed;
    std::optional<std::string> accel, bvhQuality, precision, effects;
    bool spd = false;
    bool robust = false;
};

/// Scene settings overridden by the flags; --spd first applies the SPD
/// procedure's settings (512x512, depth 5), which explicit flags still override.
RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& o);

/// Refuses (InputError) a render whose image buffers would not fit in the
/// machine's memory, instead of letting the OOM killer end it half-way.
void checkMemoryBudget(const Scene& scene, const RenderOptions& options);

/// Sets the arithmetic of every analytic shape.
void applyPrecision(Scene& scene, Precision precision);

}  // namespace raylab
