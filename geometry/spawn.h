#pragma once
// Where secondary rays (shadow, reflection, refraction) start. The one place
// that fights self-intersection ("acne"); call sites never invent epsilons.
//
// Robust (default): move the origin off the surface along the geometric
// normal, towards the side the new ray leaves into, by a distance scaled to
// the float resolution of the hit point (Embree stores geometry in float,
// relative to `reference`, normally the eye), and start at t = 0. This is the
// Embree-tutorial strategy (NUMERICS.md §3.2 (b)): 0% false self-shadowing at
// any scene scale, measured offsets ~1e-5 of |p|.
// FixedEpsilon: the lecture's t > epsilon with the origin left on the surface.

#include "geometry/ray.h"
#include "geometry/vec.h"

namespace raylab {

enum class OffsetMode { Robust, FixedEpsilon };

struct SpawnSettings {
    OffsetMode mode = OffsetMode::Robust;
    double epsilon = 1e-4;  ///< FixedEpsilon only: the lecture's t > epsilon
    Vec3 reference{0, 0, 0};  ///< point the float geometry is relative to (the eye)
};

struct SpawnedRay {
    Ray ray;
    double tMin = 0;  ///< exclusive lower bound of valid hits
};

/// Spawns the secondary rays of one surface point: the offset is computed
/// once per hit, not once per ray (a hit spawns a shadow ray per light).
class RaySpawner {
public:
    RaySpawner(const Vec3& p, const Vec3& ng, const SpawnSettings& s);
    /// A ray leaving the surface in direction dir, on the side dir points to.
    SpawnedRay operator()(const Vec3& dir) const;

private:
    Vec3 m_p, m_ng, m_offset;  ///< m_offset = ng · robust offset distance
    const SpawnSettings& m_settings;
};

/// A ray leaving the surface point p (unit geometric normal ng, either side)
/// in direction dir.
SpawnedRay spawnRay(const Vec3& p, const Vec3& ng, const Vec3& dir, const SpawnSettings& s);

/// The robust offset distance at p (exposed for tests and the accuracy study).
double robustOffset(const Vec3& p, const SpawnSettings& s);

}  // namespace raylab
