#pragma once
// Ideal reflection and refraction directions, and the Fresnel reflectance.
// Conventions: `d` is the incoming direction (towards the surface), `n` a unit
// normal on the side the ray arrives from (dot(d, n) < 0).

#include <optional>

#include "geometry/vec.h"

namespace raylab {

/// Mirror direction r = d − 2 (d·n) n. Keeps |d|.
Vec3 reflect(const Vec3& d, const Vec3& n);

/// Snell refraction of the unit direction d from a medium of index etaI into
/// one of index etaT. Returns nothing on total internal reflection. The
/// cosine under the root is clamped, so the critical angle itself never
/// produces NaN.
std::optional<Vec3> refract(const Vec3& d, const Vec3& n, double etaI, double etaT);

/// Unpolarised Fresnel reflectance for a dielectric interface; cosI = |d·n|.
/// Returns 1 under total internal reflection.
double fresnelDielectric(double cosI, double etaI, double etaT);

}  // namespace raylab
