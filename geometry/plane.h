#pragma once
// Ray-plane intersection. The plane is "infinite" in the scene description
// but has finite bounds (Embree silently drops infinite boxes), so it is the
// square of half-size halfExtent around its point, in the frame of its normal;
// hits outside the square are rejected so that every accelerator sees the
// same surface.

#include <optional>

#include "geometry/frame.h"
#include "geometry/analytic_shape.h"

namespace raylab {

class Plane final : public AnalyticShape<Plane> {
public:
    /// Plane through `point` with unit outward `normal`, clipped to the square
    /// |u|, |v| <= halfExtent; parameters are validated by makePlane().
    Plane(const Vec3& point, const Vec3& normal, double halfExtent);

    /// The box of the square's four corners, padded (finite).
    Bounds3 bounds() const override;
    /// t = n·(p0 - o) / n·d; a ray parallel to the plane (n·d == 0, including
    /// a ray lying in it) misses. ShapeHit u, v = in-plane coordinates of the
    /// hit relative to the point, along the frame tangents.
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Hit point (projected onto the plane) and the outward normal; uv = the
    /// hit's coordinates along the frame tangents t, b relative to the point,
    /// in scene units (not [0,1]²: the plane is unbounded in the scene's eyes).
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    const char* kind() const override { return "plane"; }
    Revisit revisit() const override { return Revisit::None; }  // planar

    const Vec3& point() const { return m_point; }
    const Vec3& normal() const { return m_frame.n; }
    double halfExtent() const { return m_halfExtent; }

    const Frame& frame() const { return m_frame; }

private:
    Vec3 m_point;
    Frame m_frame;  ///< tangents t, b and the unit normal n
    double m_halfExtent;
};

}  // namespace raylab
