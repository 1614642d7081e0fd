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

double robustOffset(const Vec3& p, double span, const SpawnSettings& s) {
    const double magnitude = std::max(s.minMagnitude, maxComponent(abs(p - s.reference)) + span);
    return kOffsetUlps * FLT_EPSILON * magnitude;
}

RaySpawner::RaySpawner(const Vec3& p, const Vec3& ng, double span, const SpawnSettings& s)
    : m_p(p), m_ng(ng), m_settings(s) {
    if (s.mode == OffsetMode::Robust) m_offset = ng * robustOffset(p, span, s);
}

SpawnedRay RaySpawner::operator()(const Vec3& dir) const {
    if (m_settings.mode == OffsetMode::FixedEpsilon)
        return {Ray{m_p, dir}, m_settings.epsilon / std::max(length(dir), 1e-300)};
    return {Ray{dot(dir, m_ng) >= 0 ? m_p + m_offset : m_p - m_offset, dir}, 0.0};
}

SpawnedRay spawnRay(const Vec3& p, const Vec3& ng, double span, const Vec3& dir,
                    const SpawnSettings& s) {
    return RaySpawner(p, ng, span, s)(dir);
}

}  // namespace raylab
