#pragma once
// Ray differentials (Igehy, "Tracing Ray Differentials", SIGGRAPH 1999): how
// a ray's origin and unit direction change from one image sample to the
// next, carried from the camera through transfer, mirror reflection and
// refraction, and turned into the change of the hit point (dp/dx, dp/dy) from
// which texture lookups get their footprint. pbrt-v4 carries the same
// quantities as offset rays; the formulas here are Igehy's, in derivatives.

#include "geometry/vec.h"
#include "geometry/vec2.h"
#include "shading/step_pair.h"

namespace raylab {

/// ∂o/∂x, ∂o/∂y, ∂d/∂x, ∂d/∂y of a ray o + t·d with unit d, per sample step.
struct RayDifferential {
    Vec3 dodx, dody;
    Vec3 dddx, dddy;
};

/// Change of the hit point p = o + t·d on the plane through p with normal n
/// (transfer, Igehy eq. 10-12): dp = do + t·dd + dt·d, dt = -(do + t·dd)·n / (d·n).
/// d must be unit length; a ray parallel to the plane gives zero.
void transferDifferential(const RayDifferential& rd, const Vec3& d, double t, const Vec3& n,
                          Vec3& dpdx, Vec3& dpdy);
/// The same, (dp/dx, dp/dy) as a pair: both steps in lockstep (step_pair.h).
Vec3Pair transferDifferentials(const RayDifferential& rd, const Vec3& d, double t, const Vec3& n);

/// The mirror ray's differential, r = d - 2 (d·n) n, from the hit's dp/dx,
/// dp/dy and the normal's change dn/dx, dn/dy (n on the side d arrives from).
RayDifferential reflectDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& dpdx, const Vec3& dpdy, const Vec3& dndx,
                                    const Vec3& dndy);

/// The refracted ray's differential, t = η d - μ n with η = etaI / etaT and
/// μ = η (d·n) - (t·n) (Igehy eq. 18-19); `refracted` is the unit direction t.
RayDifferential refractDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& refracted, double eta, const Vec3& dpdx,
                                    const Vec3& dpdy, const Vec3& dndx, const Vec3& dndy);

/// Least-squares (du, dv) with du·dpdu + dv·dpdv = dp (pbrt-v4's
/// ComputeDifferentials): zero when the tangents span no area, clamped to ±1e8.
void surfaceParameterChange(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp, double& du,
                            double& dv);
/// The same for the two steps of a hit, the system set up once:
/// duvdx = (du, dv) of dpdx, duvdy of dpdy.
void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dpdx, const Vec3& dpdy,
                             Vec2& duvdx, Vec2& duvdy);
/// The same for (dp/dx, dp/dy) as a pair, both solved in lockstep.
void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3Pair& dp, Vec2& duvdx,
                             Vec2& duvdy);

}  // namespace raylab
