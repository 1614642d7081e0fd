#pragma once
// Where secondary rays (shadow, reflection, refraction) start. The one place
// that fights self-intersection ("acne"); call sites never invent epsilons.
//
// Robust (default): move the origin off the surface along the geometric
// normal, towards the side the new ray leaves into, and start at t = 0. The
// distance is 32 float ulps of the largest float coordinate involved plus 4
// double ulps of the largest absolute coordinate of p:
//  - Embree stores triangles in float relative to `reference` (normally the
//    eye), so a triangle's float copy is off by ulps of its vertices, bounded
//    by |p - reference| + span (span: the triangle's extent around p);
//  - float-precision shapes work relative to a point of their own (span: the
//    distance from p to the centre of the shape's bounds);
//  - double-precision shapes have span 0; their error is ulps of |p|.
// No absolute length: a scene scaled by 2^-20 .. 2^14 renders bit-identical
// images (tests/numerics/test_whole_renders.cpp). This is the Embree-tutorial
// strategy (NUMERICS.md §3.2 (b)): 0% false self-shadowing at any scene scale
// and position. What it cannot cover: a hit within ~1e-9 of a double shape's
// size from the reference point itself (the eye on the surface).
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
    /// span: extent of the hit primitive's float-rounded geometry around p
    /// (see the file comment; SurfaceInteraction::span).
    RaySpawner(const Vec3& p, const Vec3& ng, double span, const SpawnSettings& s);
    /// A ray leaving the surface in direction dir, on the side dir points to.
    /// Inline (only the fixed-epsilon bound, a double in a register, is
    /// not): returned through memory, the ray was written by a call as 8-
    /// and 16-byte stores that its callers read back at other offsets, and
    /// those reads waited for the stores to reach the cache (the hottest
    /// instruction of WhittedIntegrator::prepareCameraHits).
    SpawnedRay operator()(const Vec3& dir) const { return {Ray{origin(dir), dir}, tMin(dir)}; }
    /// operator()'s ray origin and lower bound, for a caller that stores the
    /// ray's parts apart (a packet's arrays).
    Vec3 origin(const Vec3& dir) const {
        if (m_settings.mode == OffsetMode::FixedEpsilon) return m_p;
        return dot(dir, m_ng) >= 0 ? m_p + m_offset : m_p - m_offset;
    }
    double tMin(const Vec3& dir) const {
        return m_settings.mode == OffsetMode::FixedEpsilon ? fixedEpsilonTMin(dir) : 0.0;
    }

private:
    double fixedEpsilonTMin(const Vec3& dir) const;

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
