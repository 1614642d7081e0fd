#include "shading/ray_differential.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

Vec3 reflectOne(const Vec3& dddx, const Vec3& d, const Vec3& n, const Vec3& dndx) {
    // d/dx [d - 2 (d·n) n] = dd - 2 [(d·n) dn + (dd·n + d·dn) n]
    const double dDotN = dot(d, n);
    const double dDotNdx = dot(dddx, n) + dot(d, dndx);
    return dddx - (dndx * dDotN + n * dDotNdx) * 2.0;
}

Vec3 refractOne(const Vec3& dddx, const Vec3& d, const Vec3& n, const Vec3& t, double eta,
                const Vec3& dndx) {
    // μ = η (d·n) - (t·n); dμ = (η - η² (d·n) / (t·n)) d(d·n);
    // dt = η dd - (μ dn + dμ n)
    const double dDotN = dot(d, n), tDotN = dot(t, n);
    const double mu = eta * dDotN - tDotN;
    const double dDotNdx = dot(dddx, n) + dot(d, dndx);
    const double dmu = tDotN != 0 ? (eta - eta * eta * dDotN / tDotN) * dDotNdx : 0.0;
    return dddx * eta - (dndx * mu + n * dmu);
}

}  // namespace

void transferDifferential(const RayDifferential& rd, const Vec3& d, double t, const Vec3& n,
                          Vec3& dpdx, Vec3& dpdy) {
    const Vec3Pair dp = transferDifferentials(rd, d, t, n);
    dpdx = dp.first();
    dpdy = dp.second();
}

Vec3Pair transferDifferentials(const RayDifferential& rd, const Vec3& d, double t, const Vec3& n) {
    const double dn = dot(d, n);
    if (!(std::abs(dn) > 0)) return Vec3Pair(Vec3{0, 0, 0}, Vec3{0, 0, 0});
    // Per step: moved = do + t dd, dt = -(moved·n) / (d·n), dp = moved + dt d.
    const Vec3Pair moved = Vec3Pair(rd.dodx, rd.dody) + Vec3Pair(rd.dddx, rd.dddy) * both(t);
    const StepPair dt = -dot(moved, n) / both(dn);
    return moved + d * dt;
}

RayDifferential reflectDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& dpdx, const Vec3& dpdy, const Vec3& dndx,
                                    const Vec3& dndy) {
    // Built in place: a default RayDifferential would be zeroed first.
    return RayDifferential{dpdx, dpdy, reflectOne(rd.dddx, d, n, dndx), reflectOne(rd.dddy, d, n, dndy)};
}

RayDifferential refractDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& refracted, double eta, const Vec3& dpdx,
                                    const Vec3& dpdy, const Vec3& dndx, const Vec3& dndy) {
    return RayDifferential{dpdx, dpdy, refractOne(rd.dddx, d, n, refracted, eta, dndx),
                           refractOne(rd.dddy, d, n, refracted, eta, dndy)};
}

namespace {

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

}  // namespace

void surfaceParameterChange(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp, double& du,
                            double& dv) {
    Vec2 d, unused;
    TangentSystem(dpdu, dpdv).solve(dpdu, dpdv, Vec3Pair(dp, dp), d, unused);
    du = d.x;
    dv = d.y;
}

void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dpdx, const Vec3& dpdy,
                             Vec2& duvdx, Vec2& duvdy) {
    surfaceParameterChanges(dpdu, dpdv, Vec3Pair(dpdx, dpdy), duvdx, duvdy);
}

void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3Pair& dp, Vec2& duvdx,
                             Vec2& duvdy) {
    TangentSystem(dpdu, dpdv).solve(dpdu, dpdv, dp, duvdx, duvdy);
}

}  // namespace raylab
