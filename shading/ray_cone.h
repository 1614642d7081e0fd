#pragma once
// Ray cones (Amanatides 1984; Akenine-Möller et al., "Texture Level of Detail
// Strategies for Real-Time Ray Tracing", Ray Tracing Gems ch. 20, 2019): a ray
// carries a cone of signed width w and spread angle γ; after a distance t its
// width is w + γ t. At a hit the cone's circular cross-section lands on the
// surface as an ellipse, stretched by 1 / |cos θ| along the ray's projection
// (the anisotropic footprint of JCGT 2021's cones). Curved mirrors and
// refracting surfaces change the spread; this file uses the paraxial
// (normal-incidence) rules derived in docs/accuracy.md:
//   reflection  γ' = γ + 2 κ w
//   refraction  γ' = η γ + (η - 1) κ w,   η = etaI / etaT
// with κ the surface's mean curvature, positive where it bulges towards the
// ray (a sphere seen from outside: 1/r).

#include "geometry/vec.h"

namespace raylab {

struct RayCone {
    double width = 0;   ///< signed width at the ray's origin (negative after a focus)
    double spread = 0;  ///< spread angle γ in radians (negative: converging)

    /// Width after travelling t along a unit direction.
    double widthAt(double t) const { return width + spread * t; }
};

/// The two axes of the cone's footprint on the plane with unit normal n hit
/// by unit direction d with cone width w: |w| across the ray, |w| / |cos θ|
/// along the ray's projection onto the plane. `tangent` picks the axes when
/// the ray arrives head-on.
void coneFootprint(double width, const Vec3& d, const Vec3& n, const Vec3& tangent, Vec3& axisX,
                   Vec3& axisY);

/// Mean curvature of a surface from its tangents and normal derivatives,
/// (dn/du·dp/du / |dp/du|² + dn/dv·dp/dv / |dp/dv|²) / 2, for the normal n
/// the derivatives belong to (0 where a tangent vanishes).
double meanCurvature(const Vec3& dpdu, const Vec3& dpdv, const Vec3& dndu, const Vec3& dndv);

/// The cone leaving a mirror hit, width `widthAtHit`, curvature κ as above.
RayCone reflectCone(const RayCone& in, double widthAtHit, double curvature);

/// The cone leaving a refracting hit, η = etaI / etaT.
RayCone refractCone(const RayCone& in, double widthAtHit, double curvature, double eta);

}  // namespace raylab
