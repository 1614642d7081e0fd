#pragma once
// The lecture's local shading terms, as pure functions of unit vectors.

#include <algorithm>
#include <cmath>

#include "geometry/vec.h"
#include "shading/color.h"
#include "shading/radiance_range.h"

namespace raylab {

/// Lambert: kd · I · max(0, N·L), given N·L (a caller that has it already:
/// the integrator asks it first to skip feelers from faces turned away).
inline Color lambert(const Color& kd, const Color& lightIntensity, double nDotL) {
    const double cosine = std::max(0.0, nDotL);
    return saturatedProduct(kd, lightIntensity, cosine, [cosine] { return (long double)cosine; });
}

/// Lambert: kd · I · max(0, N·L).
inline Color lambert(const Color& kd, const Color& lightIntensity, const Vec3& n, const Vec3& l) {
    return lambert(kd, lightIntensity, dot(n, l));
}

/// x^s: by repeated squaring when s is a whole number up to 1024 (the usual
/// case, several times cheaper than std::pow), std::pow otherwise.
/// (Also in long double, for the overflow fallback of radiance_range.h.)
template <class Real>
Real specularPower(Real x, double s) {
    // Whole means s == unsigned(s): two conversions, where std::floor has no
    // instruction of its own in the x86-64 baseline (no SSE4.1 round).
    if (s >= 0 && s <= 1024 && s == double(unsigned(s))) {
        unsigned e = unsigned(s);
        Real result = 1, base = x;
        while (e) {
            if (e & 1u) result *= base;
            base *= base;
            e >>= 1u;
        }
        return result;
    }
    return std::pow(x, Real(s));
}

/// Blinn-Phong: ks · I · max(0, N·H)^s with H the unit half vector of L and V
/// (V points from the surface towards the viewer).
inline Color blinnPhong(const Color& ks, double shininess, const Color& lightIntensity,
                        const Vec3& n, const Vec3& l, const Vec3& v) {
    const Vec3 h = normalize(l + v);
    const double nh = dot(n, h);
    if (!(nh > 0)) return Color{};  // pow(0, s) = 0 for s > 0: skip the pow
    return saturatedProduct(ks, lightIntensity, specularPower(nh, shininess),
                            [&] { return specularPower<long double>(nh, shininess); });
}

/// Phong: ks · I · max(0, R·V)^s with R = 2(N·L)N − L, the mirror direction of
/// L. The model of Haines' SPD (NFF's "Shine" is a Phong cosine power); for the
/// same exponent its highlight is wider than Blinn-Phong's (R·V ≤ N·H).
inline Color phong(const Color& ks, double shininess, const Color& lightIntensity, const Vec3& n,
                   const Vec3& l, const Vec3& v) {
    const Vec3 r = n * (2 * dot(n, l)) - l;
    const double rv = dot(r, v);
    if (!(rv > 0)) return Color{};
    return saturatedProduct(ks, lightIntensity, specularPower(rv, shininess),
                            [&] { return specularPower<long double>(rv, shininess); });
}

}  // namespace raylab
