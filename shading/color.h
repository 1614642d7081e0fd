#pragma once
// Linear RGB radiance / reflectance.

#include <algorithm>
#include <cmath>

namespace raylab {

struct Color {
    double r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Color(double v) : r(v), g(v), b(v) {}

    constexpr Color operator+(const Color& o) const { return {r + o.r, g + o.g, b + o.b}; }
    constexpr Color operator-(const Color& o) const { return {r - o.r, g - o.g, b - o.b}; }
    constexpr Color operator*(const Color& o) const { return {r * o.r, g * o.g, b * o.b}; }
    constexpr Color operator*(double s) const { return {r * s, g * s, b * s}; }
    constexpr Color operator/(double s) const { return {r / s, g / s, b / s}; }
    Color& operator+=(const Color& o) { r += o.r; g += o.g; b += o.b; return *this; }
    Color& operator*=(double s) { r *= s; g *= s; b *= s; return *this; }
    constexpr bool operator==(const Color& o) const { return r == o.r && g == o.g && b == o.b; }
    constexpr bool operator!=(const Color& o) const { return !(*this == o); }

    constexpr bool isBlack() const { return r == 0 && g == 0 && b == 0; }
    constexpr double maxComponent() const { return std::max(r, std::max(g, b)); }
    bool isFinite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
};

constexpr Color operator*(double s, const Color& c) { return c * s; }

}  // namespace raylab
