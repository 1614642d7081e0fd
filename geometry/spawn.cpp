#include "geometry/spawn.h"

#include <cfloat>
#include <cmath>

namespace raylab {

namespace {
/// Offset in float ulps of the largest float coordinate; 32 as in Embree's
/// tutorials, which keeps the new origin clear of float-rounded triangles.
constexpr double kOffsetUlps = 32.0;
/// Offset in double ulps of the largest absolute coordinate: a double hit
/// point is off by one or two (measured: a micrometre scene 1e6 from the
/// origin, 286 -> 2 visibly wrong pixels; 32 ulps would cost contact
/// shadows, 16 wrong pixels).
constexpr double kDoubleUlps = 4.0;
}  // namespace

double robustOffset(const Vec3& p, double span, const SpawnSettings& s) {
    // Float geometry (Embree's copy relative to the reference, float-precision
    // shapes) is off by ulps of its float magnitude; every double is off by
    // ulps of the absolute coordinates, which matters for a tiny scene far from
    // the world origin. No absolute length anywhere: the offset scales with
    // the scene.
    const double floatMagnitude = maxComponent(abs(p - s.reference)) + span;
    const double doubleMagnitude = maxComponent(abs(p));
    return kOffsetUlps * FLT_EPSILON * floatMagnitude + kDoubleUlps * DBL_EPSILON * doubleMagnitude;
}

RaySpawner::RaySpawner(const Vec3& p, const Vec3& ng, double span, const SpawnSettings& s)
    : m_p(p), m_ng(ng), m_settings(s) {
    if (s.mode == OffsetMode::Robust) m_offset = ng * robustOffset(p, span, s);
}

double RaySpawner::fixedEpsilonTMin(const Vec3& dir) const {
    return m_settings.epsilon / std::max(length(dir), 1e-300);
}

SpawnedRay spawnRay(const Vec3& p, const Vec3& ng, double span, const Vec3& dir,
                    const SpawnSettings& s) {
    return RaySpawner(p, ng, span, s)(dir);
}

}  // namespace raylab
