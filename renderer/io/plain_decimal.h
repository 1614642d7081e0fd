#pragma once
// The fast path of the scene readers' number parsing (OBJ, MTL, NFF): the
// plain decimals exporters write, read exactly without from_chars.

#include <cstddef>
#include <cstdint>
#include <optional>

namespace raylab {

/// Exact powers of ten: every 10^k with k <= 22 is a double (5^22 < 2^53).
inline constexpr double kExactPowersOf10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                              1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};

/// \brief The value of the plain decimal at the start of [p, last) ("-12.345678":
/// an optional '-', digits, optionally '.' and more digits, at most 15 digits
/// in all), with `stop` set where that form ends; nothing when [p, last) does
/// not start with one ("-", ".5", "1.", 16 digits). What follows `stop` is the
/// caller's to judge: plainDecimal asks for the end of its token, the NFF
/// tokenizer for whitespace or '#'.
///
/// Clinger's fast path (PLDI 1990): the digits are an integer m < 10^15 <
/// 2^53 and the scale 10^k (k fraction digits) is exact, so the one rounding
/// of the division m / 10^k is the correctly rounded value of the decimal,
/// the value from_chars gives, bit for bit.
inline std::optional<double> plainDecimalPrefix(const char* p, const char* last, const char*& stop) {
    const bool negative = p < last && *p == '-';
    if (negative) ++p;
    uint64_t m = 0;  // wraps past 19 digits, which are refused below
    const char* const integerStart = p;
    for (; p < last && unsigned(*p - '0') < 10u; ++p) m = m * 10 + uint64_t(*p - '0');
    size_t digits = size_t(p - integerStart);
    if (digits == 0) return std::nullopt;  // ".5", "-", "nan": from_chars decides
    size_t fraction = 0;
    if (p < last && *p == '.') {
        const char* const fractionStart = ++p;
        for (; p < last && unsigned(*p - '0') < 10u; ++p) m = m * 10 + uint64_t(*p - '0');
        fraction = size_t(p - fractionStart);
        if (fraction == 0) return std::nullopt;  // "1.": from_chars decides
        digits += fraction;
    }
    if (digits > 15) return std::nullopt;
    stop = p;
    const double v = double(m) / kExactPowersOf10[fraction];
    return negative ? -v : v;
}

/// \brief The value of a plain decimal token (the whole of [p, last) in
/// plainDecimalPrefix's form), or nothing for any other form. Mesh exporters
/// write nearly every number this way ("%f", six decimals); from_chars cost
/// ~200 instructions a number, a third of an OBJ's parse. Callers use
/// from_chars (and their own error rules) where this gives nothing.
inline std::optional<double> plainDecimal(const char* p, const char* last) {
    const char* stop = nullptr;
    const std::optional<double> v = plainDecimalPrefix(p, last, stop);
    if (!v || stop != last) return std::nullopt;
    return v;
}

}  // namespace raylab
