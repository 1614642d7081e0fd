#include "geometry/quadratic.h"

namespace raylab {

namespace detail {

double sumSquaresMinusSquarePortable(double x, double y, double z, double lx, double ly,
                                     double lz, double r) {
    return sumSquaresMinusSquareBody(x, y, z, lx, ly, lz, r);
}

#if defined(__x86_64__) || defined(__i386__)
// The same body compiled for FMA3: std::fma becomes one vfmadd instruction.
// -ffp-contract=off (CMakeLists.txt) still keeps every other a·b + c unfused;
// GCC fuses them in C++ without it, even with -std=c++17 (a review counted
// 7 fused operations instead of 4 and 407 different results in 2 M inputs),
// and test_quadratic.cpp's comparison of the variants then fails.
__attribute__((target("fma"))) double sumSquaresMinusSquareFma(double x, double y, double z,
                                                                double lx, double ly, double lz,
                                                                double r) {
    return sumSquaresMinusSquareBody(x, y, z, lx, ly, lz, r);
}

bool fmaHardware() {
    static const bool has = __builtin_cpu_supports("fma");
    return has;
}
#else
double sumSquaresMinusSquareFma(double x, double y, double z, double lx, double ly, double lz,
                                double r) {
    return sumSquaresMinusSquareBody(x, y, z, lx, ly, lz, r);
}

bool fmaHardware() { return false; }
#endif

}  // namespace detail

template <>
double sumSquaresMinusSquare<double>(double x, double y, double z, double lx, double ly, double lz,
                                     double r) {
    return detail::fmaHardware() ? detail::sumSquaresMinusSquareFma(x, y, z, lx, ly, lz, r)
               : detail::sumSquaresMinusSquarePortable(x, y, z, lx, ly, lz, r);
}

}  // namespace raylab
