#pragma once
// Parameter checks shared by the primitive factories. Each throws
// std::invalid_argument with a message naming the shape, the parameter and
// the offending value: "cylinder: radius must be > 0 (got -1)".

#include <sstream>
#include <stdexcept>
#include <string>

#include "geometry/vec.h"

namespace raylab {

/// Formats a value for an error message (enough digits to tell values apart).
inline std::string formatValue(double v) {
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

/// Formats a vector as "(x, y, z)" for an error message.
inline std::string formatValue(const Vec3& v) {
    return "(" + formatValue(v.x) + ", " + formatValue(v.y) + ", " + formatValue(v.z) + ")";
}

/// Throws std::invalid_argument("<shape>: <message>").
[[noreturn]] inline void throwInvalid(const char* shape, const std::string& message) {
    throw std::invalid_argument(std::string(shape) + ": " + message);
}

/// Requires a finite scalar parameter.
inline void requireFinite(const char* shape, const char* what, double v) {
    if (!std::isfinite(v)) {
        throwInvalid(shape, std::string(what) + " must be finite (got " + formatValue(v) + ")");
    }
}

/// Requires a finite vector parameter.
inline void requireFinite(const char* shape, const char* what, const Vec3& v) {
    if (!isFinite(v)) {
        throwInvalid(shape, std::string(what) + " must be finite (got " + formatValue(v) + ")");
    }
}

/// Requires a finite, strictly positive scalar parameter.
inline void requirePositive(const char* shape, const char* what, double v) {
    requireFinite(shape, what, v);
    if (!(v > 0)) {
        throwInvalid(shape, std::string(what) + " must be > 0 (got " + formatValue(v) + ")");
    }
}

/// Requires a finite, non-zero direction and returns it normalised.
inline Vec3 requireDirection(const char* shape, const char* what, const Vec3& v) {
    requireFinite(shape, what, v);
    // Scale first so that |v|² cannot overflow or underflow.
    const double m = maxComponent(abs(v));
    if (!(m > 0)) {
        throwInvalid(shape,
                     std::string(what) + " must be a non-zero vector (got " + formatValue(v) + ")");
    }
    const Vec3 s = v / m;
    return s / length(s);
}

}  // namespace raylab
