#pragma once
// Render settings that override the defaults: the scene file's "render" block
// and, on top of it, the command-line flags. Unset fields leave the value
// below them in place.

#include <cstdint>
#include <optional>
#include <string>

#include "geometry/shape.h"
#include "renderer/shadow_mode.h"

namespace raylab {

struct RenderOverrides {
    std::optional<int> width, height, spp, maxDepth, threads, adaptiveMaxLevel;
    std::optional<double> adaptiveThreshold, minWeight, epsilon;
    std::optional<uint64_t> seed;
    std::optional<std::string> accel, bvhQuality, precision, effects;
    std::optional<PolygonTest> polygonTest;  ///< --polygons projected|watertight
    std::optional<ShadowMode> shadows;       ///< --shadows opaque|filtered
    bool spd = false;
    bool robust = false;
};

}  // namespace raylab
