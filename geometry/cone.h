#pragma once
// Cylinders, cones and truncated cones between two end points, open or with
// disk caps. One class: the radius varies linearly along the axis,
//   r(z) = baseRadius + k·z,  k = (apexRadius - baseRadius) / height,
// in a local frame with the base at the origin and z along the axis, so the
// side is x² + y² = r(z)² restricted to 0 <= z <= height (which also rejects
// hits on a cone's mirror nappe). The quadratic in t uses the stable root
// form, so a ray along a cone's generator line (a = 0, one real root) and a
// ray along the axis (a = b = 0: caps only) need no special NaN handling.

#include <optional>

#include "geometry/frame.h"
#include "geometry/primitives.h"
#include "geometry/analytic_shape.h"

namespace raylab {

class Cone final : public AnalyticShape<Cone> {
public:
    /// Validated by makeCone(): base and apex finite and distinct, radii finite
    /// and >= 0, not both 0.
    explicit Cone(const ConeParams& params);

    /// Box of the two end disks (r·sqrt(1 - a_i²) per axis around each end), padded.
    Bounds3 bounds() const override;
    /// Double precision: boxes of equal lengths of the axis, each the box of
    /// its two end disks and grown by the margin of bounds(): the count of 2
    /// to kMaxCoveringBoxes with the least total surface area when that total
    /// is at most kCoveringAreaGain of the one box's, else the one box. About
    /// four for a long thin cylinder at 45° to two axes, one for an upright
    /// one or a short fat one. Float precision: bounds() alone, because a float
    /// hit may stray from the surface by about FLT_EPSILON times the ray
    /// origin's distance, which no margin fixed here bounds, and the slices'
    /// boxes meet the surface at their shared ends (one loose box keeps what
    /// float renders always had).
    void appendCoveringBoxes(uint32_t prim, const IntersectOptions& opt,
                             std::vector<Bounds3>& out) const override;
    static constexpr int kMaxCoveringBoxes = 4;
    static constexpr double kCoveringAreaGain = 0.7;
    /// Closest accepted hit on the side (0 <= z <= height, rim included) or on a
    /// cap (distance from the axis <= the end radius). Facing is the sign of
    /// dot(d, outward normal), taken exactly from the root structure for the
    /// side. ShapeHit u, v: side u = 0, v = z / height in [0, 1]; base cap
    /// u = ρ / baseRadius, v = -1; apex cap u = ρ / apexRadius, v = 2 (surface()
    /// uses v to tell them apart).
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Point and outward normal: the side's (x, y, -ρ·k) in the local frame,
    /// -axis on the base cap and +axis on the apex cap. At a cone's apex
    /// (ρ = 0) the normal is the mean of the side normals there, ±axis.
    /// uv: side (φ/2π, z / height); caps polar (φ/2π, ρ / cap radius); φ from
    /// the frame's first tangent around the axis.
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    /// "cylinder" when the radii are equal, "cone" otherwise.
    const char* kind() const override;
    /// The side (and caps) bound a convex solid, the truncated cone, with
    /// outward normals: only a ray leaving inwards can meet them again.
    Revisit revisit() const override { return Revisit::Inward; }

    const Vec3& base() const { return m_base; }
    const Vec3& axis() const { return m_frame.n; }
    double height() const { return m_height; }
    double baseRadius() const { return m_r0; }
    double apexRadius() const { return m_r1; }
    bool capped() const { return m_capped; }

private:
    /// Box of the part of the solid between heights z0 <= z1 along the axis
    /// (the box of its two end disks), unpadded.
    Bounds3 sliceBox(double z0, double z1) const;
    /// Radius of the solid at height z (exactly r0 and r1 at the ends).
    double radiusAt(double z) const;

    Vec3 m_base;
    Frame m_frame;  ///< n = unit axis from base to apex
    double m_height;
    double m_r0, m_r1;
    double m_slope;  ///< k = (r1 - r0) / height, exactly 0 for a cylinder
    bool m_capped;
};

}  // namespace raylab
