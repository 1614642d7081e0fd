// Vector helpers whose edge cases matter to the validators: length and
// normalize must not overflow or underflow for representable vectors.
#include <doctest/doctest.h>

#include <cmath>

#include "geometry/vec.h"

using namespace raylab;

TEST_CASE("vec: length and normalize near the ends of the double range") {
    // Squaring 1e300 overflows and 1e-300 underflows; the scaled path gives
    // the hand-computed values |(3, 4, 0)·s| = 5s and the unit (0.6, 0.8, 0).
    for (double s : {1e300, 1e-300, 1e-310 /* subnormal */, 1.0}) {
        CAPTURE(s);
        const Vec3 v{3 * s, 4 * s, 0};
        // Relative: doctest's Approx also has an absolute tolerance near 0.
        CHECK(length(v) / s == doctest::Approx(5).epsilon(1e-15));
        const Vec3 u = normalize(v);
        CHECK(u.x == doctest::Approx(0.6).epsilon(1e-15));
        CHECK(u.y == doctest::Approx(0.8).epsilon(1e-15));
        CHECK(u.z == 0);
    }
    // Every component at 1.5e308: the length 2.6e308 is not representable
    // and overflows to +inf, but the direction is still a unit vector.
    const Vec3 huge{1.5e308, 1.5e308, 1.5e308};
    CHECK(std::isinf(length(huge)));
    CHECK(normalize(huge).x == doctest::Approx(1 / std::sqrt(3.0)));
    CHECK(length(Vec3{1e308, 1e308, 1e308}) == doctest::Approx(std::sqrt(3.0) * 1e308));
    // Zero stays zero; Inf and NaN are not turned into finite garbage.
    CHECK(length(Vec3{0, 0, 0}) == 0);
    CHECK(normalize(Vec3{0, 0, 0}) == Vec3{0, 0, 0});
    CHECK(std::isinf(length(Vec3{INFINITY, 0, 0})));
    CHECK(std::isnan(length(Vec3{NAN, 1, 0})));
    // float: 1e30f squared overflows float.
    const Vec3f f{3e30f, 4e30f, 0};
    CHECK(length(f) / 1e30f == doctest::Approx(5).epsilon(1e-6));
    CHECK(normalize(f).y == doctest::Approx(0.8).epsilon(1e-6));
}
