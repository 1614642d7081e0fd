#include "shading/optics.h"

#include <algorithm>
#include <cmath>

namespace raylab {

Vec3 reflect(const Vec3& d, const Vec3& n) { return d - n * (2.0 * dot(d, n)); }

std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double etaI, double etaT) {
    const double eta = etaI / etaT;
    const double cosI = std::clamp(-dot(d, n), 0.0, 1.0);
    const double sin2T = eta * eta * std::max(0.0, 1.0 - cosI * cosI);
    if (sin2T > 1.0) return std::nullopt;  // total internal reflection
    // At exactly the critical angle sin2T == 1 and the ray grazes the surface.
    const double cosT = std::sqrt(std::max(0.0, 1.0 - sin2T));
    return normalize(d * eta + n * (eta * cosI - cosT));
}

double fresnelDielectric(double cosI, double etaI, double etaT) {
    cosI = std::clamp(cosI, 0.0, 1.0);
    const double sinT = etaI / etaT * std::sqrt(std::max(0.0, 1.0 - cosI * cosI));
    if (sinT >= 1.0) return 1.0;
    const double cosT = std::sqrt(std::max(0.0, 1.0 - sinT * sinT));
    const double rPar = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
    const double rPerp = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
    return 0.5 * (rPar * rPar + rPerp * rPerp);
}

}  // namespace raylab
