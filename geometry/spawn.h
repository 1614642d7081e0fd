#pragma once
// Where secondary rays (shadow, reflection, refraction) start. The one place
// that fights self-intersection ("acne"); call sites never invent epsilons.
//
// Robust (default): move the origin off the surface along the geometric
// normal, towards the side the new ray leaves into, by 32 float ulps of the
// largest coordinate of the primitive that was hit, and start at t = 0.
// Embree stores triangles in float relative to `reference` (normally the
// eye), so a triangle's float copy is off by ulps of its vertices, bounded by
// |p - reference| + span (span: the triangle's extent around p); analytic
// shapes intersect in double (span 0) or, in float precision, relative to
// themselves (span: the shape's size). No absolute floor: a scene scaled by
// 1e-6 or 1e4 renders the same image (tests/render/test_scale_invariance).
// This is the Embree-tutorial strategy (NUMERICS.md §3.2 (b)): 0% false
// self-shadowing at any scene scale and position.
// FixedEpsilon: the lecture's t > epsilon with the origin left on the surface.

#include "geometry/ray.h"
#include "geometry/vec.h"

namespace raylab {

enum class OffsetMode { Robust, FixedEpsilon };

struct SpawnSettings {
    OffsetMode mode = OffsetMode::Robust;
    double epsilon = 1e-4;  ///< FixedEpsilon only: the lecture's t > epsilon
    Vec3 reference{0, 0, 0};  ///< point the float geometry is relative to (the eye)
    /// Smallest magnitude the offset is scaled to, for hits at the reference
    /// itself; the renderer sets 1e-9 of the scene's size (scale-free).
    double minMagnitude = 0;
};

struct SpawnedRay {
    Ray ray;
    double tMin = 0;  ///< exclusive lower bound of valid hits
};

/// Spawns the secondary rays of one surface point: the offset is computed
/// once per hit, not once per ray (a hit spawns a shadow ray per light).
class RaySpawner {
public:
    /// span: extent of the hit primitive's float-rounded geometry around p
    /// (see the file comment; SurfaceInteraction::span).
    RaySpawner(const Vec3& p, const Vec3& ng, double span, const SpawnSettings& s);
    /// A ray leaving the surface in direction dir, on the side dir points to.
    SpawnedRay operator()(const Vec3& dir) const;

private:
    Vec3 m_p, m_ng, m_offset;  ///< m_offset = ng · robust offset distance
    const SpawnSettings& m_settings;
};

/// A ray leaving the surface point p (unit geometric normal ng, either side)
/// in direction dir.
SpawnedRay spawnRay(const Vec3& p, const Vec3& ng, double span, const Vec3& dir,
                    const SpawnSettings& s);

/// The robust offset distance at p (exposed for tests and the accuracy study).
double robustOffset(const Vec3& p, double span, const SpawnSettings& s);

}  // namespace raylab
