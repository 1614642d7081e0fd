#pragma once
// Radiance that overflows a double saturates at the largest double instead of
// becoming Inf (which the film would have to replace, and black would hide the
// light). Every input is finite and non-negative, so with these two rules no
// Inf ever enters an operation and no NaN can come out of one:
//   - a sum or a product of two finite values is finite or +Inf: saturate it;
//   - a product of three (k · I · f) may overflow in its first step and then
//     meet a zero (0 · Inf = NaN): when the plain product is not finite it is
//     recomputed in long double, whose exponent range holds any product of
//     three doubles, and saturated.
// Finite results are the plain double arithmetic, bit for bit.

#include <algorithm>
#include <cfloat>
#include <limits>

#include "shading/color.h"

namespace raylab {

static_assert(std::numeric_limits<long double>::max_exponent >= 4 * DBL_MAX_EXP,
              "the overflow fallback needs a long double with a wider exponent than double");

/// +Inf (an overflow) as the largest double; NaN is left for the film to find.
inline double saturated(double v) {
    if (v > DBL_MAX) return DBL_MAX;
    if (v < -DBL_MAX) return -DBL_MAX;
    return v;
}

inline Color saturated(const Color& c) { return {saturated(c.r), saturated(c.g), saturated(c.b)}; }

/// The overflow path of saturatedProduct, out of line: it is rare, and kept
/// inline its long double code would make every caller too large to inline
/// the common case.
template <class WideF>
[[gnu::noinline]] Color saturatedProductWide(const Color& k, const Color& I,
                                             const WideF& wideFactor) {
    const long double wideF = wideFactor();
    const auto wide = [wideF](double a, double b) {
        // Clamped before the conversion: a long double beyond the double range
        // does not convert (undefined behaviour).
        return double(std::min<long double>((long double)a * b * wideF, DBL_MAX));
    };
    return {wide(k.r, I.r), wide(k.g, I.g), wide(k.b, I.b)};
}

/// (k · I) · f in double when that is finite; otherwise the same product in
/// long double, saturated. `wideF()` gives f in long double (called only then),
/// so that a factor which underflows a double keeps its size.
template <class WideF>
inline Color saturatedProduct(const Color& k, const Color& I, double f, const WideF& wideFactor) {
    const Color c = k * I * f;
    if (c.isFinite()) [[likely]] return c;
    return saturatedProductWide(k, I, wideFactor);
}

}  // namespace raylab
