#pragma once
// Deterministic per-pixel random numbers and stratified sample positions.
// Every pixel seeds its own stream from (seed, pixel index), so the image does
// not depend on which thread renders which tile, nor in what order.

#include <cstdint>
#include <utility>

namespace raylab {

/// PCG32 (O'Neill 2014): small, fast, statistically sound.
class Pcg32 {
public:
    Pcg32(uint64_t seed, uint64_t stream) {
        m_inc = (stream << 1u) | 1u;
        next();
        m_state += seed;
        next();
    }
    uint32_t next() {
        const uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_inc;
        const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
        const uint32_t rot = uint32_t(old >> 59u);
        return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
    }
    /// Uniform in [0, 1): 24 random bits, so it never rounds up to 1.
    double uniform() { return double(next() >> 8) * (1.0 / 16777216.0); }

private:
    uint64_t m_state = 0;
    uint64_t m_inc = 0;
};

/// m when n = m², else 0: which stratification stratifiedSample uses.
int squareGridSide(int n);

/// Sample k of n inside the unit pixel, stratified: an m×m jittered grid when
/// n = m² (gridSide = m), otherwise n-rooks (Latin hypercube: stratified along
/// x and y, gridSide = 0). n == 1 gives the pixel centre (rays through pixel centres).
std::pair<double, double> stratifiedSample(int k, int n, int gridSide, Pcg32& rng,
                                           const int* rookPermutation);

}  // namespace raylab
