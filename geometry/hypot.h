#pragma once
// std::hypot inlined, bit for bit. Every filtered texture lookup and every
// textured sphere or disk hit takes a hypot, and glibc's is an out-of-line
// call with special-case tests before its arithmetic. fastHypot does that
// arithmetic inline for the common case (both values finite, neither huge,
// tiny nor negligible against the other) and calls std::hypot for the rest,
// so it returns std::hypot's bits everywhere.
//
// The common case is glibc's (2.35 and later, sysdeps/ieee754/dbl-64/e_hypot.c,
// as built for baseline x86-64, without FMA): h = sqrt(ax² + ay²), then one
// correction step for the rounding of the sum (Borges, "An Improved Algorithm
// for hypot(a, b)", 2019). The project builds without FMA contraction
// (-ffp-contract=off), so the operations round exactly as glibc's do.
// tests/textures/test_bit_exact_speedups.cpp compares the two on a million
// values; a libm with another algorithm fails that test, not a picture.

#include <cmath>

namespace raylab {

inline double fastHypot(double x, double y) {
    const double fx = std::abs(x), fy = std::abs(y);
    const double ax = fx < fy ? fy : fx;  // the larger
    const double ay = fx < fy ? fx : fy;  // the smaller
    // glibc's bounds: 2^511 (squares may overflow above), 2^-459 (may lose
    // precision below), 2^-54 (ay is below half an ulp of ax: h = ax + ay).
    // NaN and infinity fail the first test.
    if (!(ax <= 0x1p511 && ay >= 0x1p-459 && ay > ax * 0x1p-54)) return std::hypot(x, y);
    double h = std::sqrt(ax * ax + ay * ay);
    double t1, t2;
    if (h <= 2.0 * ay) {
        const double delta = h - ay;
        t1 = ax * (2.0 * delta - ax);
        t2 = (delta - 2.0 * (ax - ay)) * delta;
    } else {
        const double delta = h - ax;
        t1 = 2.0 * delta * (ax - 2.0 * ay);
        t2 = (4.0 * delta - ay) * ay + delta * delta;
    }
    h -= (t1 + t2) / (2.0 * h);
    return h;
}

}  // namespace raylab
