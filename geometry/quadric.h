#pragma once
// General implicit quadric
//   Q(p) = A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0
// clipped to an axis-aligned box. In matrix form Q(p) = pᵀ M p + gᵀ p + J;
// the intersector works in coordinates centred on the quadric (its centre
// when it is an ellipsoid, the clip box centre otherwise), so a quadric far
// from the world origin keeps its digits. Along a ray Q is a t² + 2 h t + c
// with a = dᵀ M d, which is 0 for real hits (a paraboloid hit along its axis,
// a plane): the stable root form then gives the linear root -c / (2h).
// The outward normal is the gradient 2 M p + g (the side where Q > 0 is
// outside): negate all coefficients to turn a surface inside out.

#include <array>
#include <optional>

#include "geometry/primitives.h"
#include "geometry/analytic_shape.h"
#include "geometry/frame.h"

namespace raylab {

class Quadric final : public AnalyticShape<Quadric> {
public:
    /// Validation rules (std::invalid_argument naming the problem):
    /// - all ten coefficients finite, and not all of A..I zero;
    /// - a clip box, when given, finite and non-empty;
    /// - without a clip box the surface must be bounded: an ellipsoid (M
    ///   definite with a real surface), whose box is derived; otherwise
    ///   "quadric: unbounded surface needs a clip box";
    /// - a definite M whose surface has no real point (x² + y² + z² + 1 = 0) or
    ///   only one point is rejected as empty.
    static std::unique_ptr<Quadric> create(const QuadricParams& params);

    /// Clip box ∩ derived ellipsoid box (whichever exist), padded; always finite.
    Bounds3 bounds() const override;
    /// Closest accepted root whose point lies in the clip box (inclusive); both
    /// roots are tested, so a near root outside the box does not hide the far
    /// one. Facing from the exact root structure (the sign of dQ/dt at the root).
    /// ShapeHit u = v = 0.
    template <class T>
    std::optional<ShapeHit> intersectT(const Ray& ray, double tMin, double tMax,
                                       const IntersectOptions& opt) const;
    /// Hit point and the normalised gradient; at a singular point (a cone's
    /// apex, gradient 0) the normal faces the ray (-d / |d|) so it stays finite.
    /// uv: a general quadric has no natural parametrisation; raylab uses the
    /// spherical angles of the direction from centre() to the hit (as a
    /// sphere's, pole +y), so an ellipsoid is mapped like a sphere. The
    /// derivatives follow the surface point along that direction (implicit
    /// differentiation of Q = 0); where the direction grazes the surface they
    /// fall back to a tangent frame.
    SurfaceGeometry surface(const Ray& ray, const ShapeHit& hit, SurfaceDetail detail) const;
    const char* kind() const override { return "quadric"; }

    /// Q at a world point (for tests and diagnostics).
    double evaluate(const Vec3& p) const;
    /// Origin of the centred coordinates and of the (u, v) parametrisation: the
    /// ellipsoid's centre, else the clip box's centre.
    const Vec3& centre() const { return m_centre; }

    /// Use create(); public for std::make_unique.
    Quadric(const std::array<double, 6>& m, const Vec3& g, double j, const Vec3& centre,
            const Bounds3& clip, bool hasClip, const Bounds3& bounds);

private:
    /// Fills uv and the derivatives of a hit at centred point q with gradient ∇Q.
    void surfaceParameters(SurfaceGeometry& g, const Vec3& q, const Vec3& gradient) const;

    /// Symmetric M in centred coordinates: xx, yy, zz, xy, xz, yz.
    std::array<double, 6> m_m;
    Vec3 m_g;        ///< linear part in centred coordinates: 2 M c + g
    double m_j;      ///< Q at the centre
    Vec3 m_centre;   ///< origin of the centred coordinates
    Bounds3 m_clip;  ///< clip box in world coordinates (when m_hasClip)
    bool m_hasClip;
    Bounds3 m_bounds;
};

}  // namespace raylab
