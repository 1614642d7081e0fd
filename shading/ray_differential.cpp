#include "shading/ray_differential.h"

#include <algorithm>
#include <cmath>

namespace raylab {

namespace {

Vec3 transferOne(const Vec3& dodx, const Vec3& dddx, const Vec3& d, double t, const Vec3& n,
                 double dn) {
    const Vec3 moved = dodx + dddx * t;
    const double dt = -dot(moved, n) / dn;
    return moved + d * dt;
}

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
    const double dn = dot(d, n);
    if (!(std::abs(dn) > 0)) {
        dpdx = dpdy = Vec3{0, 0, 0};
        return;
    }
    dpdx = transferOne(rd.dodx, rd.dddx, d, t, n, dn);
    dpdy = transferOne(rd.dody, rd.dddy, d, t, n, dn);
}

RayDifferential reflectDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& dpdx, const Vec3& dpdy, const Vec3& dndx,
                                    const Vec3& dndy) {
    RayDifferential out;
    out.dodx = dpdx;
    out.dody = dpdy;
    out.dddx = reflectOne(rd.dddx, d, n, dndx);
    out.dddy = reflectOne(rd.dddy, d, n, dndy);
    return out;
}

RayDifferential refractDifferential(const RayDifferential& rd, const Vec3& d, const Vec3& n,
                                    const Vec3& refracted, double eta, const Vec3& dpdx,
                                    const Vec3& dpdy, const Vec3& dndx, const Vec3& dndy) {
    RayDifferential out;
    out.dodx = dpdx;
    out.dody = dpdy;
    out.dddx = refractOne(rd.dddx, d, n, refracted, eta, dndx);
    out.dddy = refractOne(rd.dddy, d, n, refracted, eta, dndy);
    return out;
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

    Vec2 solve(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp) const {
        if (!solvable) return Vec2{0, 0};
        const double b0 = dot(dpdu, dp), b1 = dot(dpdv, dp);
        const auto clampFinite = [](double x) {
            return std::isfinite(x) ? std::clamp(x, -1e8, 1e8) : 0.0;
        };
        return Vec2{clampFinite((a11 * b0 - a01 * b1) / det), clampFinite((a00 * b1 - a01 * b0) / det)};
    }
};

}  // namespace

void surfaceParameterChange(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp, double& du,
                            double& dv) {
    const Vec2 d = TangentSystem(dpdu, dpdv).solve(dpdu, dpdv, dp);
    du = d.x;
    dv = d.y;
}

void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dpdx, const Vec3& dpdy,
                             Vec2& duvdx, Vec2& duvdy) {
    const TangentSystem system(dpdu, dpdv);
    duvdx = system.solve(dpdu, dpdv, dpdx);
    duvdy = system.solve(dpdu, dpdv, dpdy);
}

}  // namespace raylab
