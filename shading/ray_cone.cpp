#include "shading/ray_cone.h"

#include <cmath>

namespace raylab {

void coneFootprint(double width, const Vec3& d, const Vec3& n, const Vec3& tangent, Vec3& axisX,
                   Vec3& axisY) {
    const double w = std::abs(width);
    const double cosTheta = std::abs(dot(d, n));
    // The ray's direction projected onto the plane: the ellipse's long axis.
    Vec3 along = d - n * dot(d, n);
    if (!(lengthSquared(along) > 1e-24)) along = tangent - n * dot(tangent, n);
    if (!(lengthSquared(along) > 0)) {
        axisX = axisY = Vec3{0, 0, 0};
        return;
    }
    along = normalize(along);
    const Vec3 across = cross(n, along);
    // A grazing hit stretches without bound; 1e-6 keeps the axis finite.
    axisX = across * w;
    axisY = along * (w / std::max(cosTheta, 1e-6));
}

double meanCurvature(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dndu, const Vec3& dndv) {
    const double lu = lengthSquared(dpdu), lv = lengthSquared(dpdv);
    const double ku = lu > 0 ? dot(dndu, dpdu) / lu : 0.0;
    const double kv = lv > 0 ? dot(dndv, dpdv) / lv : 0.0;
    const double k = 0.5 * (ku + kv);
    return std::isfinite(k) ? k : 0.0;
}

RayCone reflectCone(const RayCone& in, double widthAtHit, double curvature) {
    return RayCone{widthAtHit, in.spread + 2 * curvature * widthAtHit};
}

RayCone refractCone(const RayCone& in, double widthAtHit, double curvature, double eta) {
    return RayCone{widthAtHit, eta * in.spread + (eta - 1) * curvature * widthAtHit};
}

}  // namespace raylab
