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

void surfaceParameterChange(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dp, double& du,
                            double& dv) {
    Vec2 d, unused;
    detail::TangentSystem(dpdu, dpdv).solve(dpdu, dpdv, Vec3Pair(dp, dp), d, unused);
    du = d.x;
    dv = d.y;
}

void surfaceParameterChanges(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dpdx, const Vec3& dpdy,
                             Vec2& duvdx, Vec2& duvdy) {
    surfaceParameterChanges(dpdu, dpdv, Vec3Pair(dpdx, dpdy), duvdx, duvdy);
}

}  // namespace raylab
