#include "geometry/spawn.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace raylab {

namespace {
/// Offset in float ulps of the largest coordinate; 32 as in Embree's
/// tutorials, which keeps the new origin clear of float-rounded triangles.
constexpr double kOffsetUlps = 32.0;
}  // namespace

double robustOffset(const Vec3& p, const SpawnSettings& s) {
    const double magnitude = std::max(1.0, maxComponent(abs(p - s.reference)));
    return kOffsetUlps * FLT_EPSILON * magnitude;
}

SpawnedRay spawnRay(const Vec3& p, const Vec3& ng, const Vec3& dir, const SpawnSettings& s) {
    if (s.mode == OffsetMode::FixedEpsilon) return {Ray{p, dir}, s.epsilon / std::max(length(dir), 1e-300)};
    const double side = dot(dir, ng) >= 0 ? 1.0 : -1.0;
    return {Ray{p + ng * (side * robustOffset(p, s)), dir}, 0.0};
}

}  // namespace raylab
