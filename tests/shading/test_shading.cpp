// The shading terms and the optics of reflection and refraction, against
// hand-computed values.
#include <doctest/doctest.h>

#include <cfloat>
#include <cmath>

#include "shading/brdf.h"
#include "shading/optics.h"

using namespace raylab;

TEST_CASE("lambert: kd * I * max(0, N.L)") {
    const Vec3 n{0, 0, 1};
    // L at 60° from N: cos = 0.5, so 0.8 * 2 * 0.5 = 0.8.
    const Vec3 l = normalize(Vec3{std::sqrt(3.0), 0, 1});
    const Color c = lambert(Color(0.8), Color(2.0), n, l);
    CHECK(c.r == doctest::Approx(0.8));
    // A light below the surface contributes nothing.
    CHECK(lambert(Color(0.8), Color(2.0), n, Vec3{0, 0, -1}).isBlack());
}

TEST_CASE("blinn-phong: ks * I * max(0, N.H)^s") {
    const Vec3 n{0, 0, 1};
    // Mirror configuration: H = N, so the term is ks * I.
    const Vec3 l = normalize(Vec3{1, 0, 1}), v = normalize(Vec3{-1, 0, 1});
    CHECK(blinnPhong(Color(0.5), 100, Color(1), n, l, v).r == doctest::Approx(0.5));
    // L = N and V at 90° from N: H at 45°, N.H = cos 45° = 1/sqrt(2); ^2 = 0.5.
    const Color c = blinnPhong(Color(1), 2, Color(1), n, Vec3{0, 0, 1}, Vec3{1, 0, 0});
    CHECK(c.r == doctest::Approx(0.5));
}

TEST_CASE("phong: ks * I * max(0, R.V)^s, R the mirror direction of L") {
    const Vec3 n{0, 0, 1};
    // Mirror configuration: R = V, so the term is ks * I, as for Blinn-Phong.
    const Vec3 l = normalize(Vec3{1, 0, 1}), v = normalize(Vec3{-1, 0, 1});
    CHECK(phong(Color(0.5), 100, Color(1), n, l, v).r == doctest::Approx(0.5));
    // L at 30° from N in the xz plane: R at -30°, i.e. (-1/2, 0, sqrt(3)/2).
    // V = N: R.V = cos 30° = sqrt(3)/2, squared 3/4; times ks = 0.4 and I = 2: 0.6.
    const Vec3 l30{0.5, 0, std::sqrt(3.0) / 2};
    CHECK(phong(Color(0.4), 2, Color(2), n, l30, n).r == doctest::Approx(0.6));
    // Blinn-Phong of the same configuration: H at 15°, cos² 15° = (1 + cos 30°)/2.
    CHECK(blinnPhong(Color(0.4), 2, Color(2), n, l30, n).r ==
          doctest::Approx(0.8 * (1 + std::sqrt(3.0) / 2) / 2));
    // V beyond 90° from R: nothing (no negative power).
    CHECK(phong(Color(1), 3, Color(1), n, l30, normalize(Vec3{1, 0, 0.01})).isBlack());
}

TEST_CASE("reflect: mirror direction about the normal") {
    const Vec3 r = reflect(normalize(Vec3{1, -1, 0}), {0, 1, 0});
    CHECK(r.x == doctest::Approx(std::sqrt(0.5)));
    CHECK(r.y == doctest::Approx(std::sqrt(0.5)));
    CHECK(r.z == 0);
}

TEST_CASE("refract: Snell's law") {
    const Vec3 n{0, 1, 0};
    // 45° incidence from air into glass 1.5: sin t = sin 45° / 1.5 = 0.4714.
    const Vec3 d = normalize(Vec3{1, -1, 0});
    const auto t = refract(d, n, 1.0, 1.5);
    REQUIRE(t);
    CHECK(t->x == doctest::Approx(std::sqrt(0.5) / 1.5));
    CHECK(t->y == doctest::Approx(-std::sqrt(1 - 0.5 / 2.25)));
    CHECK(length(*t) == doctest::Approx(1.0));
    // Normal incidence passes straight through.
    const auto s = refract(Vec3{0, -1, 0}, n, 1.0, 1.5);
    REQUIRE(s);
    CHECK(s->y == doctest::Approx(-1.0));
}

TEST_CASE("refract: ior 1 leaves the direction unchanged") {
    const Vec3 d = normalize(Vec3{0.3, -0.8, 0.2});
    const auto t = refract(d, {0, 1, 0}, 1.0, 1.0);
    REQUIRE(t);
    CHECK(t->x == doctest::Approx(d.x).epsilon(1e-15));
    CHECK(t->y == doctest::Approx(d.y).epsilon(1e-15));
    CHECK(t->z == doctest::Approx(d.z).epsilon(1e-15));
}

TEST_CASE("refract: total internal reflection at and beyond the critical angle") {
    // Glass (1.5) to air: critical angle asin(1/1.5) = 41.81°.
    const double critical = std::asin(1.0 / 1.5);
    const Vec3 n{0, 1, 0};  // on the incoming (glass) side
    auto dirAt = [](double theta) { return Vec3{std::sin(theta), -std::cos(theta), 0}; };
    // Just below: refracts, nearly grazing.
    const auto below = refract(dirAt(critical - 1e-7), n, 1.5, 1.0);
    REQUIRE(below);
    CHECK(isFinite(*below));
    CHECK(below->x > 0.999);
    // Just beyond: total internal reflection.
    CHECK_FALSE(refract(dirAt(critical + 1e-7), n, 1.5, 1.0));
    CHECK_FALSE(refract(dirAt(1.2), n, 1.5, 1.0));
    // Exactly at the critical angle (to double rounding): finite, never NaN.
    const auto at = refract(dirAt(critical), n, 1.5, 1.0);
    if (at) CHECK(isFinite(*at));
}

TEST_CASE("fresnel: normal incidence and TIR") {
    // ((1.5 - 1) / (1.5 + 1))^2 = 0.04
    CHECK(fresnelDielectric(1.0, 1.0, 1.5) == doctest::Approx(0.04));
    CHECK(fresnelDielectric(1.0, 1.5, 1.0) == doctest::Approx(0.04));
    CHECK(fresnelDielectric(0.1, 1.5, 1.0) == 1.0);   // beyond critical: TIR
    CHECK(fresnelDielectric(0.0, 1.0, 1.5) == doctest::Approx(1.0));  // grazing
}

TEST_CASE("specularPower: whole exponents by squaring, the rest through pow") {
    CHECK(specularPower(0.5, 0) == 1.0);
    CHECK(specularPower(0.5, 1) == 0.5);
    CHECK(specularPower(0.5, 3) == 0.125);      // exact in binary
    CHECK(specularPower(0.5, 10) == 1.0 / 1024);
    CHECK(specularPower(0.9, 37) == doctest::Approx(std::pow(0.9, 37)).epsilon(1e-14));
    CHECK(specularPower(0.9, 2.5) == std::pow(0.9, 2.5));
    // The boundary of the squaring path: 1024 is squared, 1025 and 1023.5
    // go through pow. 0.999 is a base where the two routes round apart
    // (0.999^1024: squaring 0.35897147818971331, pow 0.35897147818971004).
    CHECK(specularPower(0.999, 1024) == 0.35897147818971331);
    CHECK(std::pow(0.999, 1024.0) != 0.35897147818971331);
    CHECK(specularPower(0.999, 1025) == std::pow(0.999, 1025.0));
    CHECK(specularPower(0.999, 1023.5) == std::pow(0.999, 1023.5));
    CHECK(specularPower(0.999, 1023) == 0.35933080899871195);  // squared
    CHECK(std::isnan(specularPower(0.5, std::nan(""))));         // pow's answer
}

TEST_CASE("radiance overflow: saturates at the largest double, never Inf, NaN or black") {
    const Vec3 n{0, 0, 1};
    // Lambert, cos 1: 1.7e308 * 1 fits; * 10 overflows and saturates.
    CHECK(lambert(Color(1), Color(1.7e308), n, n).r == 1.7e308);
    CHECK(lambert(Color(10), Color(1.7e308), n, n).r == DBL_MAX);
    // kd * I overflows a double, the cosine 0.5 brings it back into range:
    // 1e200 * 1e200 * 0.5 = 5e399 -> the largest double (not Inf).
    const Vec3 l60 = normalize(Vec3{std::sqrt(3.0), 0, 1});  // cos = 0.5
    CHECK(lambert(Color(1e200), Color(1e200), n, l60).r == DBL_MAX);
    // Blinn-Phong at the peak with s = 100 and N.H = 0.1 would be 0.1^100 =
    // 1e-100: ks * I = 1e200 * 1e200 overflows first, then the product is
    // exactly representable: 1e300 (long double path, within rounding).
    const Vec3 v{0, 0, 1};
    // H = normalize(l + v) with N.H = 0.1: pick l so that the half vector is at
    // N.H = 0.1 and check against the plain formula in long double.
    const Vec3 h = normalize(Vec3{std::sqrt(1 - 0.01), 0, 0.1});
    const Vec3 l = normalize(h * (2 * dot(h, v)) - v);
    const double nh = dot(n, normalize(l + v));
    const long double expected = 1e200L * 1e200L * std::pow((long double)nh, 100.0L);
    const Color c = blinnPhong(Color(1e200), 100, Color(1e200), n, l, v);
    CHECK(std::isfinite(c.r));
    CHECK(c.r == doctest::Approx(double(expected)).epsilon(1e-12));
    CHECK(c.r > 1e299);
    // Where the factor underflows a double (0.01^200 = 1e-400 -> 0) while
    // ks * I overflows (1e600), the plain product is Inf * 0 = NaN; the wide
    // path gives the true 1e200, not black.
    CHECK(std::isnan(1e300 * 1e300 * specularPower(0.01, 200)));
    const Color w = saturatedProduct(Color(1e300), Color(1e300), specularPower(0.01, 200),
                                     [] { return specularPower<long double>(0.01L, 200); });
    CHECK(w.r == doctest::Approx(1e200).epsilon(1e-9));
    // A genuine zero stays zero; finite products are the plain ones, bit for bit.
    CHECK(saturatedProduct(Color(0), Color(1e308), 2.0, [] { return 2.0L; }).r == 0);
    CHECK(saturatedProduct(Color(0.3), Color(0.7), 0.9, [] { return 0.9L; }).r == 0.3 * 0.7 * 0.9);
    CHECK(saturated(Color(INFINITY, -INFINITY, 1)) == Color(DBL_MAX, -DBL_MAX, 1));
    CHECK(std::isnan(saturated(NAN)));
}
