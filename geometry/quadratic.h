#pragma once
// Numerically stable quadratic solver and the error-free arithmetic the
// analytic intersectors use where a formula is ill-conditioned.
//
// The roots of a t² + 2 h t + c = 0 ("half-b" form, h = b/2) are computed as
//   q = -(h + sign(h) sqrt(h² - a c)),   t = q / a  and  t = c / q,
// which never subtracts two nearly equal numbers (NUMERICS.md §3.1, Numerical
// Recipes §5.6). When a == 0 the equation is linear and the second formula,
// c / q with q = -2h, is exactly its root -c / (2h): no special case for NaN.

#include <cmath>
#include <utility>

namespace raylab {

/// Real roots of a quadratic, ascending (t0 <= t1). `count` is 0, 1 or 2; with
/// one root (linear equation) only t0 is meaningful and t1 == t0.
template <class T>
struct QuadraticRoots {
    int count = 0;
    T t0 = 0;
    T t1 = 0;
};

/// Roots of a t² + 2 h t + c = 0 given the precomputed discriminant
/// `disc` = h² - a c (callers that can evaluate it more accurately than the
/// naive formula, such as the sphere, pass their own). No roots when
/// disc < 0 or any input is NaN. A tangent ray (disc == 0) yields a double
/// root reported twice. a == 0 falls back to the linear root -c / (2h).
template <class T>
QuadraticRoots<T> solveQuadraticHalfB(T a, T h, T c, T disc) {
    QuadraticRoots<T> r;
    if (!(disc >= T(0))) return r;  // negative or NaN
    if (a == T(0)) {
        // Linear: 2 h t + c = 0. h == 0 means no equation in t (or all t).
        if (h == T(0)) return r;
        r.count = 1;
        r.t0 = r.t1 = -c / (T(2) * h);
        return r;
    }
    const T s = std::sqrt(disc);
    const T q = -(h + std::copysign(s, h));
    T x0, x1;
    if (q == T(0)) {
        // Only when h == 0 and disc == 0, i.e. c == 0: the double root 0.
        x0 = x1 = T(0);
    } else {
        x0 = q / a;
        x1 = c / q;
    }
    if (x0 > x1) std::swap(x0, x1);
    r.count = 2;
    r.t0 = x0;
    r.t1 = x1;
    return r;
}

/// Roots of a t² + 2 h t + c = 0 with the discriminant h² - a c evaluated
/// directly (two products, one subtraction).
template <class T>
QuadraticRoots<T> solveQuadraticHalfB(T a, T h, T c) {
    return solveQuadraticHalfB(a, h, c, h * h - a * c);
}

/// Roots of the textbook form a t² + b t + c = 0 (delegates to the half-b form).
template <class T>
QuadraticRoots<T> solveQuadratic(T a, T b, T c) {
    return solveQuadraticHalfB(a, b / T(2), c);
}

/// Error-free product: returns p = fl(a·b) and sets err so that a·b = p + err
/// exactly (fused multiply-add; valid barring overflow/underflow).
template <class T>
T twoProduct(T a, T b, T& err) {
    const T p = a * b;
    err = std::fma(a, b, -p);
    return p;
}

/// Error-free sum (Knuth's TwoSum): returns s = fl(a+b), a+b = s + err exactly.
template <class T>
T twoSum(T a, T b, T& err) {
    const T s = a + b;
    const T bb = s - a;
    err = (a - (s - bb)) + (b - bb);
    return s;
}

namespace detail {
/// The body of sumSquaresMinusSquare, inlined into each variant so that the
/// fused multiply-adds compile for that variant's target.
template <class T>
[[gnu::always_inline]] inline T sumSquaresMinusSquareBody(T x, T y, T z, T lx, T ly, T lz, T r) {
    // The variants agree bit for bit only while no a·b + c is fused behind the
    // source's back: the build says so for every file (-ffp-contract=off,
    // CMakeLists.txt); clang, whose default fuses, also hears it here.
#if defined(__clang__)
#pragma clang fp contract(off)
#endif
    T ex, ey, ez, er, e1, e2, e3;
    const T px = twoProduct(x, x, ex);
    const T py = twoProduct(y, y, ey);
    const T pz = twoProduct(z, z, ez);
    const T pr = twoProduct(r, r, er);
    T s = twoSum(px, py, e1);
    s = twoSum(s, pz, e2);
    s = twoSum(s, -pr, e3);
    // Cross terms 2·hi·lo are of the order of the rounding errors: plain products suffice.
    const T cross = T(2) * ((x * lx + y * ly) + z * lz);
    return s + ((((ex + ey) + (ez - er)) + ((e1 + e2) + e3)) + cross);
}

/// The double variants behind sumSquaresMinusSquare<double> (geometry/quadratic.cpp),
/// public for the test that they agree bit for bit.
double sumSquaresMinusSquarePortable(double x, double y, double z, double lx, double ly,
                                     double lz, double r);
/// Compiled for FMA hardware; call only when fmaHardware() is true.
double sumSquaresMinusSquareFma(double x, double y, double z, double lx, double ly, double lz,
                                double r);
/// Whether this CPU has fused multiply-add instructions (x86 FMA3; always
/// false elsewhere, where the portable variant is used).
bool fmaHardware();
}  // namespace detail

/// (x+lx)² + (y+ly)² + (z+lz)² - r² evaluated as if in twice the working
/// precision and then rounded (Ogita-Rump-Oishi Dot2). (x, lx) etc. are
/// double-word values, e.g. the exact difference of two points from twoSum;
/// pass 0 for the low parts of exact inputs. The lo² terms are below the
/// result's resolution and dropped. Used where the difference cancels
/// catastrophically: a ray origin very close to a large sphere.
template <class T>
T sumSquaresMinusSquare(T x, T y, T z, T lx, T ly, T lz, T r) {
    return detail::sumSquaresMinusSquareBody(x, y, z, lx, ly, lz, r);
}

/// In double, the variant for the CPU it runs on: without -mfma (Debian's
/// x86-64 baseline) every std::fma is a call into libm, four per evaluation,
/// and this sits on the path of every ray leaving a sphere. std::fma is
/// exactly rounded whoever computes it, so both variants give the same bits.
template <>
double sumSquaresMinusSquare<double>(double x, double y, double z, double lx, double ly, double lz,
                                     double r);

}  // namespace raylab
