#pragma once
// Ray-disk intersection: the plane through the centre, clipped to the radius.

#include <optional>

#include "geometry/frame.h"
#include "geometry/analytic_shape.h"

namespace raylab {

class Disk final : public AnalyticShape<Disk> {
public:
    /// Disk of `radius` around `centre` with unit outward `normal`; parameters
    /// are validated by makeDisk().
    Disk(const Vec3& centre, const Vec3& normal, double radius);

    /// Box of the disk: centre ± r·sqrt(1 - n_i²) per axis, padded.
    Bounds3 bounds() const override;
    /// Plane hit accepted when its distance from the centre is <= radius (the
    /// rim belongs to the disk). ShapeHit u, v = in-plane coordinates of the hit
    /// relative to the centre along the frame tangents, divided by the radius.
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Hit point (projected onto the plane) and the outward normal; uv = polar
    /// coordinates (φ/2π from the frame's first tangent, ρ / radius).
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    const char* kind() const override { return "disk"; }
    Revisit revisit() const override { return Revisit::None; }  // planar

    const Vec3& centre() const { return m_centre; }
    const Vec3& normal() const { return m_frame.n; }
    double radius() const { return m_radius; }

private:
    Vec3 m_centre;
    Frame m_frame;
    double m_radius;
};

}  // namespace raylab
