#pragma once
// Ray-sphere intersection, robust at extreme size ratios (NUMERICS.md §3.1):
// the discriminant is evaluated as (r - |f|)(r + |f|) with f the vector from
// the centre to the closest point of the ray line (accurate for a tiny sphere
// far away), the roots use the cancellation-free form c/q, q/a, and when the
// origin is close to the surface relative to the radius (|c| << r², a huge
// sphere seen from nearby) c = |o - centre|² - r² is evaluated in doubled
// precision, so the near root stays within a few ulps in double.

#include <optional>

#include "geometry/analytic_shape.h"
#include "geometry/frame.h"

namespace raylab {

class Sphere final : public AnalyticShape<Sphere> {
public:
    /// A sphere whose parametrisation has its north pole along the unit vector
    /// `pole`; parameters are validated by makeSphere().
    Sphere(const Vec3& centre, double radius, const Vec3& pole);

    /// The box centre ± radius, padded.
    Bounds3 bounds() const override;
    /// Closest accepted root with tMin < t < tMax. The near root is a front-face
    /// hit (entering) when the ray properly crosses the sphere; the far root and a
    /// tangent double root are back-face hits. ShapeHit u, v = x and y components of
    /// the unit outward normal at the hit (in [-1, 1]; z follows up to its sign).
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Hit point (reprojected onto the sphere) and outward normal (p - centre) / r;
    /// uv = spherical angles about the pole (surface_parameters.h): u = φ/2π from
    /// the frame's first tangent, v = 1 - θ/π.
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    const char* kind() const override { return "sphere"; }
    /// A ball is convex: only a ray leaving inwards can meet its sphere again.
    Revisit revisit() const override { return Revisit::Inward; }

    const Vec3& centre() const { return m_centre; }
    double radius() const { return m_radius; }
    const Vec3& pole() const { return m_frame.n; }

private:
    Vec3 m_centre;
    double m_radius;
    Frame m_frame;  ///< n = pole of the parametrisation
};

}  // namespace raylab
