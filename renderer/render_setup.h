#pragma once
// Merging the scene file's settings with command-line overrides, and the
// checks that must pass before a render starts.

#include <cstdint>
#include <optional>
#include <string>

#include "renderer/render_options.h"
#include "renderer/render_overrides.h"
#include "renderer/scene.h"

namespace raylab {

/// The render options: defaults, then the scene file's image settings and
/// "render" block, then the command-line flags `o`. --spd first applies the
/// SPD procedure's settings (512x512, depth 5), which explicit flags still override.
RenderOptions resolveRenderOptions(const Scene& scene, const RenderOverrides& o);

/// Refuses (InputError) a render whose image buffers would not fit in the
/// machine's memory, instead of letting the OOM killer end it half-way.
void checkMemoryBudget(const Scene& scene, const RenderOptions& options);

/// Sets the arithmetic of every analytic shape.
void applyPrecision(Scene& scene, Precision precision);

}  // namespace raylab
