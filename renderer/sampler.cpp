#include "renderer/sampler.h"

#include <cmath>

namespace raylab {

int squareGridSide(int n) {
    const int m = int(std::lround(std::sqrt(double(n))));
    return m * m == n ? m : 0;
}

std::pair<double, double> stratifiedSample(int k, int n, int gridSide, Pcg32& rng,
                                           const int* rookPermutation) {
    if (n <= 1) return {0.5, 0.5};
    if (gridSide > 0) {
        const int m = gridSide;
        const int sx = k % m, sy = k / m;
        const double jx = rng.uniform(), jy = rng.uniform();
        return {(sx + jx) / m, (sy + jy) / m};
    }
    const double jx = rng.uniform(), jy = rng.uniform();
    return {(k + jx) / n, (rookPermutation[k] + jy) / n};
}

}  // namespace raylab
