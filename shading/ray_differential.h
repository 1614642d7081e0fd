#pragma once
// Ray differentials (Igehy, "Tracing Ray Differentials", SIGGRAPH 1999): how
// a ray's origin and unit direction change from one image sample to the
// next, carried from the camera through transfer, mirror reflection and
// refraction, and turned into the change of the hit point (dp/dx, dp/dy) from
// which texture lookups get their footprint. pbrt-v4 carries the same
// quantities as offset rays; the formulas here are Igehy's, in derivatives.

#include <algorithm>
#include <cmath>

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
/// Inline: it runs at every textured hit, whose caller keeps the pair in registers.
inline Vec3Pair transferDifferentials(const RayDifferential& rd, const Vec3& d, double t,
                                      const Vec3& n) {
    const double dn = dot(d, n);
    if (!(std::abs(dn) > 0)) return Vec3Pair(Vec3{0, 0, 0}, Vec3{0, 0, 0});
    // Per step: moved = do + t dd, dt = -(moved·n) / (d·n), dp = moved + dt d.
    const Vec3Pair moved = Vec3Pair(rd.dodx, rd.dody) + Vec3Pair(rd.dddx, rd.dddy) * both(t);
    const StepPair dt = -dot(moved, n) / both(dn);
    return moved + d * dt;
}

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
namespace detail {

/// The 2x2 normal equations of surfaceParameterChange, set up once for the
/// tangents and solved for any dp.
struct TangentSystem {
    double a00, a01, a11, det;
    bool solvable;

    TangentSystem(const Vec3& dpdu, const Vec3& dpdv)
        : a00(dot(dpdu, dpdu)), a01(dot(dpdu, dpdv)), a11(dot(dpdv, dpdv)),
          det(a00 * a11 - a01 * a01), solvable(std::abs(det) > 0 && std::isfinite(det)) {}

    /// (du, dv) for both steps: b0 = dpdu·dp, b1 = dpdv·dp per lane,
    /// du = (a11 b0 - a01 b1) / det, dv = (a00 b1 - a01 b0) / det.
    void solve(const Vec3& dpdu, const Vec3& dpdv, const Vec3Pair& dp, Vec2& first,
               Vec2& second) const {
        if (!solvable) {
            first = second = Vec2{0, 0};
            return;
        }
        const StepPair b0 = dot(dp, dpdu), b1 = dot(dp, dpdv);
        const StepPair du = (both(a11) * b0 - both(a01) * b1) / both(det);
        const StepPair dv = (both(a00) * b1 - both(a01) * b0) / both(det);
        const auto clampFinite = [](double x) {
            return std::isfinite(x) ? std::clamp(x, -1e8, 1e8) : 0.0;
        };
        first = Vec2{clampFinite(du[0]), clampFinite(dv[0])};
        second = Vec2{clampFinite(du[1]), clampFinite(dv[1])};
    }
};

}  // namespace detail

/// The same for (dp/dx, dp/dy) as a pair, both solved in lockstep (inline,
/// like transferDifferentials: once per textured hit).
inline void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3Pair& dp,
                                    Vec2& duvdx, Vec2& duvdy) {
    detail::TangentSystem(dpdu, dpdv).solve(dpdu, dpdv, dp, duvdx, duvdy);
}

}  // namespace raylab
