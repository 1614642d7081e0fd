#pragma once
// Ray-sphere intersection, robust at extreme size ratios (NUMERICS.md §3.1):
// the discriminant is evaluated as (r - |f|)(r + |f|) with f the vector from
// the centre to the closest point of the ray line (accurate for a tiny sphere
// far away), the roots use the cancellation-free form c/q, q/a, and when the
// origin is close to the surface relative to the radius (|c| << r², a huge
// sphere seen from nearby) c = |o - centre|² - r² is evaluated in doubled
// precision, so the near root stays within a few ulps in double.

#include <optional>

#include "geometry/shape.h"

namespace raylab {

class Sphere final : public Shape {
public:
    /// A sphere; parameters are validated by makeSphere().
    Sphere(const Vec3& centre, double radius);

    /// The box centre ± radius, padded.
    Bounds3 bounds() const override;
    /// Closest accepted root with tMin < t < tMax. The near root is a front-face
    /// hit (entering) when the ray properly crosses the sphere; the far root and a
    /// tangent double root are back-face hits. u, v = x and y components of the
    /// unit outward normal at the hit (in [-1, 1]; z follows up to its sign).
    std::optional<ShapeHit> intersect(const Ray& ray, double tMin, double tMax) const override;
    /// Hit point (reprojected onto the sphere) and outward normal (p - centre) / r.
    SurfaceGeometry surfaceAt(const Ray& ray, const ShapeHit& hit) const override;
    const char* kind() const override { return "sphere"; }

    const Vec3& centre() const { return m_centre; }
    double radius() const { return m_radius; }

private:
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax) const;

    Vec3 m_centre;
    double m_radius;
};

}  // namespace raylab
