#pragma once
// The interface every analytic primitive implements (sphere, plane, disk,
// polygon, cylinder/cone, quadric). Pure math: no Embree, no materials. The
// Embree user-geometry callbacks and the naive all-objects loop both call it,
// so the two accelerators see identical hits.
//
// Two-step intersection (pbrt's BasicIntersect / InteractionFromIntersection):
// intersect() returns only t and two primitive-local parameters; surfaceAt()
// computes point and normals once, for the hit that wins.

#include <optional>

#include "geometry/bounds.h"
#include "geometry/ray.h"

namespace raylab {

/// Which side of a surface can be hit. Normals always point "outward"
/// (the side a one-sided object shows); sidedness only filters hits.
enum class Sidedness {
    Outside,  ///< default: only hits from the outward side count (one-sided)
    Inside,   ///< only hits from the inside count (NFF's negative radius)
    Both,     ///< two-sided, required for transmitters
};

/// Arithmetic used by the analytic intersectors (accuracy study knob).
enum class Precision { Float, Double };

/// Minimal record of a candidate hit.
struct ShapeHit {
    double t = 0;  ///< ray parameter, in units of |d|
    double u = 0;  ///< primitive-local parameters (meaning per shape)
    double v = 0;
};

/// Full geometry of the winning hit.
struct SurfaceGeometry {
    Vec3 p;                ///< hit point
    Vec3 ng;               ///< unit geometric normal, pointing outward
    Vec3 ns;               ///< unit shading normal, pointing outward
    bool frontFace = true; ///< true when the ray arrives from the outward side
};

/// True when a hit with the given facing is accepted under the sidedness rule.
inline bool acceptsFacing(Sidedness s, bool frontFace) {
    return s == Sidedness::Both || (s == Sidedness::Outside) == frontFace;
}

class Shape {
public:
    virtual ~Shape() = default;

    /// Tight, finite world-space box (never infinite: Embree drops such boxes).
    virtual Bounds3 bounds() const = 0;

    /// Closest accepted hit with tMin < t < tMax (strict, NaN-safe), or nothing.
    virtual std::optional<ShapeHit> intersect(const Ray& ray, double tMin, double tMax) const = 0;

    /// Any accepted hit with tMin < t < tMax.
    virtual bool occluded(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }

    /// Point and normals of a hit previously returned by intersect().
    virtual SurfaceGeometry surfaceAt(const Ray& ray, const ShapeHit& hit) const = 0;

    /// Human-readable kind, for statistics and error messages ("sphere").
    virtual const char* kind() const = 0;

    Sidedness sidedness() const { return m_sides; }
    void setSidedness(Sidedness s) { m_sides = s; }
    Precision precision() const { return m_precision; }
    void setPrecision(Precision p) { m_precision = p; }

protected:
    Sidedness m_sides = Sidedness::Outside;
    Precision m_precision = Precision::Double;
};

}  // namespace raylab
