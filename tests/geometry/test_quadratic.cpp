// The stable quadratic solver and the error-free helpers (quadratic.h).

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "geometry/quadratic.h"
#include "geometry/random.h"
#include "support/float_bits.h"

using namespace raylab;

TEST_CASE("quadratic: two real roots ascending") {
    // (t - 2)(t - 3) = t² - 5t + 6.
    const auto r = solveQuadratic(1.0, -5.0, 6.0);
    REQUIRE(r.count == 2);
    CHECK(r.t0 == 2.0);
    CHECK(r.t1 == 3.0);
    // Negative leading coefficient: -(t + 1)(t - 4) = -t² + 3t + 4, roots -1 and 4.
    const auto n = solveQuadratic(-1.0, 3.0, 4.0);
    REQUIRE(n.count == 2);
    CHECK(n.t0 == -1.0);
    CHECK(n.t1 == 4.0);
}

TEST_CASE("quadratic: no roots, double root, NaN") {
    CHECK(solveQuadratic(1.0, 0.0, 1.0).count == 0);  // t² + 1
    const auto d = solveQuadratic(1.0, -2.0, 1.0);    // (t - 1)²
    REQUIRE(d.count == 2);
    CHECK(d.t0 == 1.0);
    CHECK(d.t1 == 1.0);
    const auto z = solveQuadratic(1.0, 0.0, 0.0);  // t²: q = 0, must not give 0/0
    REQUIRE(z.count == 2);
    CHECK(z.t0 == 0.0);
    CHECK(z.t1 == 0.0);
    CHECK(solveQuadratic(std::nan(""), 1.0, 1.0).count == 0);
    CHECK(solveQuadratic(1.0, std::nan(""), 1.0).count == 0);
}

TEST_CASE("quadratic: linear fallback when a == 0") {
    // 2t - 6 = 0 -> t = 3; 0·t + 1 = 0 -> none.
    const auto l = solveQuadratic(0.0, 2.0, -6.0);
    REQUIRE(l.count == 1);
    CHECK(l.t0 == 3.0);
    CHECK(solveQuadratic(0.0, 0.0, 1.0).count == 0);
    CHECK(solveQuadratic(0.0f, 4.0f, -2.0f).t0 == 0.5f);
}

TEST_CASE("quadratic: small root accurate where the textbook formula cancels") {
    // t² - 1e8 t + 1 = 0: roots ≈ 1e8 and 1e-8 (product 1). Textbook (-b - sqrt)/2a gives
    // 7.45e-9 in double; the stable c/q gives 1e-8 to full precision.
    const auto r = solveQuadratic(1.0, -1e8, 1.0);
    REQUIRE(r.count == 2);
    CHECK(r.t0 == doctest::Approx(1e-8).epsilon(1e-15));
    CHECK(r.t1 == doctest::Approx(1e8).epsilon(1e-15));
    // Float: t² - 1e4 t + 1: small root 1e-4 (1.0000000100e-4) accurate to float precision.
    const auto f = solveQuadratic(1.0f, -1e4f, 1.0f);
    CHECK(f.t0 == doctest::Approx(1.00000001e-4).epsilon(1e-6));
}

TEST_CASE("quadratic: error-free transformations") {
    double e = 0;
    const double p = twoProduct(1.0 + 0x1p-30, 1.0 + 0x1p-30, e);  // 1 + 2^-29 + 2^-60
    CHECK(p == 1.0 + 0x1p-29);
    CHECK(e == 0x1p-60);
    const double s = twoSum(1.0, 0x1p-60, e);
    CHECK(s == 1.0);
    CHECK(e == 0x1p-60);
    // (1e4 + 1)² + 0 + 0 - 1e4² = 20001 exactly; with a non-representable offset
    // x = 1e4 + 0.1 split as hi + lo the result is 2·1e4·0.1 + 0.01 = 2000.01.
    CHECK(sumSquaresMinusSquare(1e4 + 1, 0.0, 0.0, 0.0, 0.0, 0.0, 1e4) == 20001.0);
    double lo = 0;
    const double hi = twoSum(1e4, 0.1, lo);
    CHECK(sumSquaresMinusSquare(hi, 0.0, 0.0, lo, 0.0, 0.0, 1e4) ==
          doctest::Approx(2000.01).epsilon(1e-15));
}

TEST_CASE("quadratic: sumSquaresMinusSquare's FMA and portable variants give the same bits") {
    // The FMA variant is what spheres use on FMA hardware; without it there is
    // nothing to compare (both names then run the portable code).
    if (!detail::fmaHardware()) {
        MESSAGE("no FMA hardware: only the portable variant runs here");
        return;
    }
    SplitMix64 rng(7);
    // Random magnitudes over the whole exponent range, where the products'
    // rounding errors are exact (no underflow of the error terms) and also
    // where they underflow or the sum overflows: std::fma is exactly rounded
    // in every case, so the bits must match everywhere.
    const auto value = [&]() {
        const double m = rng.uniform(1, 2) * (rng.next() % 2 ? 1 : -1);
        const int e = int(rng.next() % 2100) - 1075;
        return std::ldexp(m, e);
    };
    long differ = 0, finite = 0;
    for (int i = 0; i < 200000; ++i) {
        double a[7];
        if (i % 2) {
            for (double& x : a) x = value();
        } else {
            // A ray origin just off a sphere (the case the function exists for).
            const double r = std::ldexp(rng.uniform(1, 2), int(rng.next() % 40) - 20);
            const double d = r * rng.uniform(-1, 1);
            double hi[3] = {d, r * rng.uniform(-1, 1), 0};
            hi[2] = std::sqrt(std::max(0.0, r * r - hi[0] * hi[0] - hi[1] * hi[1]));
            for (int k = 0; k < 3; ++k) {
                a[k] = hi[k];
                a[3 + k] = hi[k] * 0x1p-60 * rng.uniform(-1, 1);
            }
            a[6] = r;
        }
        const double p = detail::sumSquaresMinusSquarePortable(a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
        const double f = detail::sumSquaresMinusSquareFma(a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
        const double used = sumSquaresMinusSquare(a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
        finite += std::isfinite(p);
        // NaN results compare by being NaN (their payloads may differ, and a
        // NaN c gives the sphere no hit either way), everything else by its bits.
        differ += !(std::isnan(p) && std::isnan(f)) && test::bitsOf(p) != test::bitsOf(f);
        differ += !(std::isnan(p) && std::isnan(used)) && test::bitsOf(p) != test::bitsOf(used);
    }
    CHECK(differ == 0);
    CHECK(finite > 100000);
    // Hand-picked: exact squares, an error term at the subnormal boundary, signed zeros.
    for (const double x : {3.0, 0x1.0000001p-511, 0x1p-537, -0.0, 1e300, 0x1.fffffffffffffp+511}) {
        CHECK(test::bitsOf(detail::sumSquaresMinusSquareFma(x, x, 0.0, 0.0, 0.0, 0.0, x)) ==
              test::bitsOf(detail::sumSquaresMinusSquarePortable(x, x, 0.0, 0.0, 0.0, 0.0, x)));
    }
}
