#pragma once
// Helpers shared by the geometry tests: a deterministic random generator (the
// same sequence on every platform, unlike std::uniform_real_distribution) and
// ulp distances.

#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <xmmintrin.h>
#endif

#include "geometry/vec.h"
#include "shape_queries.h"
#include "geometry/random.h"

namespace raylab::test {

/// Deterministic test directions and points (geometry/random.h).
using Rng = SplitMix64;

/// Sets flush-to-zero and denormals-are-zero (what Embree asks of render
/// threads) on the calling thread for the object's lifetime, when the platform
/// has them; restores MXCSR afterwards.
class FlushDenormals {
public:
    explicit FlushDenormals(bool on) {
#if defined(__SSE2__)
        m_saved = _mm_getcsr();
        if (on) _mm_setcsr(m_saved | 0x8040u);  // FTZ (bit 15) | DAZ (bit 6)
#else
        (void)on;
#endif
    }
    ~FlushDenormals() {
#if defined(__SSE2__)
        _mm_setcsr(m_saved);
#endif
    }
    FlushDenormals(const FlushDenormals&) = delete;
    FlushDenormals& operator=(const FlushDenormals&) = delete;

private:
    unsigned m_saved = 0;
};

/// Distance in units in the last place between two doubles of the same sign.
inline double ulpDistance(double a, double b) {
    if (a == b) return 0;
    const double ulp = std::nextafter(std::abs(b), HUGE_VAL) - std::abs(b);
    return std::abs(a - b) / ulp;
}

/// Any unit vector perpendicular to the unit vector n.
inline Vec3 perpendicular(const Vec3& n) {
    const Vec3 a = std::abs(n.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    return normalize(cross(n, a));
}

}  // namespace raylab::test
