#pragma once
// SplitMix64 (Steele, Lea & Flood 2014): a tiny generator whose sequence is
// the same on every platform and standard library, unlike the <random>
// distributions. Used wherever a seed must always give the same rays or the
// same scene: procedural benchmark scenes, test ray sets, per-pixel seeds.
// Not the sampler: image samples come from PCG32 streams (renderer/sampler.h).

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "geometry/vec.h"

namespace raylab {

/// SplitMix64's output function: a bijective 64-bit mix with full avalanche.
constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

class SplitMix64 {
public:
    static constexpr uint64_t kGamma = 0x9E3779B97F4A7C15ull;  // 2^64 / golden ratio

    explicit SplitMix64(uint64_t seed) : m_state(seed) {}

    uint64_t next() { return mix64(m_state += kGamma); }
    /// Uniform in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    /// Uniform in the cube [lo, hi)^3.
    Vec3 point(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    /// Uniform direction on the unit sphere (Archimedes: z uniform in [-1, 1]).
    Vec3 direction() {
        constexpr double kTwoPi = 6.28318530717958647692;
        const double z = uniform(-1, 1);
        const double phi = uniform(0, kTwoPi);
        const double s = std::sqrt(std::max(0.0, 1 - z * z));
        return {s * std::cos(phi), s * std::sin(phi), z};
    }

private:
    uint64_t m_state;
};

}  // namespace raylab
