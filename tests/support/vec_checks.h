#pragma once
// Component-wise vector comparison for doctest, shared by the test suites.
// Header-only, included as "support/vec_checks.h".

#include <doctest/doctest.h>

#include "geometry/vec.h"

namespace raylab::test {

/// Each component of `a` equals `b`'s within relative tolerance `eps`
/// (doctest's Approx, which also allows an absolute error near 0).
inline void checkVec(const Vec3& a, const Vec3& b, double eps = 1e-12) {
    CHECK(a.x == doctest::Approx(b.x).epsilon(eps));
    CHECK(a.y == doctest::Approx(b.y).epsilon(eps));
    CHECK(a.z == doctest::Approx(b.z).epsilon(eps));
}

}  // namespace raylab::test
