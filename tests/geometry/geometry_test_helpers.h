#pragma once
// Helpers shared by the geometry tests: a deterministic random generator (the
// same sequence on every platform, unlike std::uniform_real_distribution) and
// ulp distances.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "geometry/vec.h"

namespace raylab::test {

/// SplitMix64: tiny, deterministic, good enough for test directions.
class Rng {
public:
    explicit Rng(uint64_t seed) : m_state(seed) {}

    uint64_t next() {
        uint64_t z = (m_state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform direction on the unit sphere.
    Vec3 direction() {
        const double z = uniform(-1, 1);
        const double phi = uniform(0, 2 * 3.14159265358979323846);
        const double s = std::sqrt(std::max(0.0, 1 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    uint64_t m_state;
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
