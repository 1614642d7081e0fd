#pragma once
// The lecture's local shading terms, as pure functions of unit vectors.

#include <algorithm>
#include <cmath>

#include "geometry/vec.h"
#include "shading/color.h"

namespace raylab {

/// Lambert: kd · I · max(0, N·L).
inline Color lambert(const Color& kd, const Color& lightIntensity, const Vec3& n, const Vec3& l) {
    return kd * lightIntensity * std::max(0.0, dot(n, l));
}

/// Blinn-Phong: ks · I · max(0, N·H)^s with H the unit half vector of L and V
/// (V points from the surface towards the viewer).
inline Color blinnPhong(const Color& ks, double shininess, const Color& lightIntensity,
                        const Vec3& n, const Vec3& l, const Vec3& v) {
    const Vec3 h = normalize(l + v);
    const double nh = std::max(0.0, dot(n, h));
    return ks * lightIntensity * std::pow(nh, shininess);
}

}  // namespace raylab
