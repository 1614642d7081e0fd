#pragma once
// Render settings that override the defaults: the scene file's "render" block
// and, on top of it, the command-line flags. Unset fields leave the value
// below them in place.

#include <cstdint>
#include <optional>

#include "geometry/shape.h"
#include "renderer/accel/accel_options.h"
#include "renderer/accelerator_kind.h"
#include "renderer/alpha_mode.h"
#include "renderer/shadow_mode.h"
#include "renderer/texture_options.h"

namespace raylab {

/// --effects: only the effects the scene calls for (auto), or the general
/// kernel that traces every ray type at every hit (all).
enum class EffectsMode { Auto, All };

/// Every field is parsed from its words (renderer/render_option_names.h) where
/// it is typed, so an unknown word never reaches the renderer.
struct RenderOverrides {
    std::optional<int> width, height, spp, maxDepth, threads, adaptiveMaxLevel;
    std::optional<double> adaptiveThreshold, minWeight, epsilon;
    std::optional<uint64_t> seed;
    std::optional<uint64_t> maxRaysPerSample;  ///< --max-rays, JSON render.max_rays
    std::optional<AcceleratorKind> accel;
    std::optional<AccelOptions::BvhQuality> bvhQuality;
    std::optional<Precision> precision;
    std::optional<EffectsMode> effects;
    std::optional<PolygonTest> polygonTest;  ///< --polygons projected|watertight
    std::optional<ShadowMode> shadows;       ///< --shadows opaque|filtered
    std::optional<AlphaMode> alpha;          ///< --alpha background|transparent|opaque
    std::optional<double> alphaCutoff;       ///< --alpha-cutoff, JSON render.alpha_cutoff
    std::optional<TextureFilter> textureFilter;        ///< --texture-filter
    std::optional<TextureFootprint> textureFootprint;  ///< --texture-footprint
    bool spd = false;
    std::optional<bool> robust;  ///< --robust / --no-robust, JSON render.robust
};

}  // namespace raylab
