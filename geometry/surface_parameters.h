#pragma once
// The parametrisations the analytic primitives share, written once: the
// azimuth around an axis, polar coordinates in a plane (disks, cone caps) and
// spherical angles (spheres, quadrics). Each returns (u, v) and the partial
// derivatives in the primitive's local frame; docs/scene-format.md lists which
// primitive uses which.

#include <cmath>

#include "geometry/hypot.h"
#include "geometry/vec.h"
#include "geometry/vec2.h"

namespace raylab {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kPi = 3.1415926535897932384626433832795;

/// Direction of the point (x, y) around the origin: cos φ, sin φ and φ/2π in
/// [0, 1), φ measured counter-clockwise from +x, and the distance ρ from the
/// origin (the callers need it too: one hypot). At the origin φ = 0, so
/// every quantity stays finite.
struct Azimuth {
    double u = 0;
    double cosPhi = 1, sinPhi = 0;
    double rho;

    /// withAngle = false leaves u = 0 (no atan2); the rest is the same.
    Azimuth(double x, double y, bool withAngle = true) : rho(fastHypot(x, y)) {
        if (!(rho > 0)) return;
        cosPhi = x / rho;
        sinPhi = y / rho;
        if (!withAngle) return;
        double phi = std::atan2(y, x);
        if (phi < 0) phi += kTwoPi;
        u = phi / kTwoPi;
        if (!(u < 1)) u = 0;  // -tiny + 2π rounds to 2π: the seam is u = 0
    }
};

/// Surface parameters with their derivatives, in a primitive's local frame.
struct LocalParameters {
    Vec2 uv;
    Vec3 dpdu, dpdv;
};

/// Polar coordinates of the plane point (x, y, 0) in a disk of radius R:
/// u = φ/2π, v = ρ/R, so p = (R v cos 2πu, R v sin 2πu, 0).
inline LocalParameters polarParameters(double x, double y, double radius) {
    const Azimuth a(x, y);
    LocalParameters l;
    l.uv = {a.u, a.rho / radius};
    l.dpdu = Vec3{-y, x, 0} * kTwoPi;
    l.dpdv = Vec3{a.cosPhi, a.sinPhi, 0} * radius;
    return l;
}

/// Spherical angles of the unit direction w (local frame, pole +z), as pbrt
/// parametrises its sphere: u = φ/2π, v = 1 - θ/π with θ the angle from the
/// pole (v = 0 at the south pole, 1 at the north pole, so an image's top row
/// lands at the top). dpdu and dpdv are the derivatives of w itself; a sphere
/// scales them by its radius.
/// withUv = false skips uv (left zero): the derivatives are the same bits.
inline LocalParameters sphericalParameters(const Vec3& w, bool withUv = true) {
    const Azimuth a(w.x, w.y, withUv);
    const double sinTheta = a.rho;
    const double cosTheta = std::clamp(w.z, -1.0, 1.0);
    LocalParameters l;
    if (withUv) l.uv = {a.u, 1.0 - std::acos(cosTheta) / kPi};
    l.dpdu = Vec3{-w.y, w.x, 0} * kTwoPi;
    // dθ/dv = -π.
    l.dpdv = Vec3{cosTheta * a.cosPhi, cosTheta * a.sinPhi, -sinTheta} * -kPi;
    return l;
}

}  // namespace raylab
